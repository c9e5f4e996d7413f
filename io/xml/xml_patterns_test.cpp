// XML procedural textures: a scene using <pigment> (solid, map, list, layers, average, image),
// <normal>, <switch>, the material's pigment/normal/switch, <sky> and <fog> loads into the
// Scene arrays it describes (to_pattern the inverse of the placement), and renders as it
// should: a checker gives two colours, fog darkens what is far, the sky colours misses.
#include "io/xml/xml_scene.h"

#include "core/backend/backend.h"
#include "io/image/texture_sampler.h"
#include "io/scene/scene_file.h"
#include "tests/support/mesh_test_files.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>

namespace sheaf {
namespace {

const char* kProcedural = R"(<?xml version="1.0"?>
<scene version="1">
  <texture name="photo" file="checker.png" mapping="planar">
    <scale value="2"/>
  </texture>
  <pigment name="white" color="1"/>
  <pigment name="glassy" color="0.9 1 0.9" filter="0.5" transmit="0.25"/>
  <pigment name="veins" pattern="marble" turbulence="0.6" octaves="4" omega="0.4" lambda="3"
           frequency="2" phase="0.1">
    <entry value="0" color="0.9 0.9 0.85"/>
    <entry value="0.8" color="0.3" filter="0.1" transmit="0.2"/>
    <entry value="1" pigment="white"/>
    <scale value="0.5"/>
    <translate value="1 2 3"/>
  </pigment>
  <pigment name="grid" pattern="checker">
    <entry color="1 0 0"/>
    <entry pigment="veins"/>
  </pigment>
  <pigment name="ramp" pattern="gradient" vector="0 0 2" wave="poly" wave_exponent="2"
           turbulence="0.1 0.2 0.3">
    <entry value="0" color="0"/>
    <entry value="1" color="1"/>
  </pigment>
  <pigment name="stack" layers="true">
    <entry pigment="grid"/>
    <entry color="0 0 1" transmit="0.5"/>
  </pigment>
  <pigment name="mean" average="true">
    <entry pigment="white"/>
    <entry color="0"/>
  </pigment>
  <pigment name="picture" pattern="image" texture="photo" transmit="0.3"/>
  <pigment name="wall" pattern="brick" brick_size="2 1 1" mortar="0.1">
    <entry color="0.5"/> <entry color="0.7 0.2 0.1"/>
  </pigment>
  <pigment name="swirl" pattern="spiral2" arms="5" wave="sine">
    <entry value="0" color="0"/> <entry value="1" color="1"/>
  </pigment>
  <pigment name="stone" pattern="agate" agate_turb="0.5">
    <entry value="0.5" color="0.2"/>
  </pigment>
  <normal name="bumpy" pattern="bumps" amount="0.4">
    <scale value="0.2"/>
  </normal>
  <material name="red" color="1 0 0"/>
  <material name="blue" color="0 0 1"/>
  <material name="floor" pigment="grid" normal="bumpy" diffuse="0.6"/>
  <switch name="tiles" pattern="hexagon">
    <entry material="red"/> <entry material="blue"/> <entry material="floor"/>
    <rotate axis="0 1 0" angle="90"/>
  </switch>
  <switch name="bands" pattern="wood" wave="ramp">
    <entry value="0" material="red"/> <entry value="0.5" material="blue"/>
  </switch>
  <material name="tiled" switch="tiles"/>
  <material name="plain" base="tiled" switch="" color="0.5"/>
  <sky pigment="ramp"/>
  <fog distance="30" color="0.7 0.7 0.8" transmit="0.1"/>
  <sphere material="tiled"/>
</scene>
)";

void write_checker_png(const std::filesystem::path& path) {
    const int n = 16;
    std::vector<unsigned char> px(n * n * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c) px[(y * n + x) * 3 + c] = ((x / 8 + y / 8) % 2) ? 255 : 0;
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(n, n, 3, OIIO::TypeDesc::UINT8)));
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
}

void expect_near(Vec3 a, Vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(XmlPatterns, EveryElementLoadsIntoTheSceneArrays) {
    const auto dir = test::temp_folder("xml_patterns_load");
    write_checker_png(dir / "checker.png");
    const io::SceneFile f =
        io::load_scene_file(test::write_text(dir / "procedural.xml", kProcedural));
    const Scene& s = f.scene;
    ASSERT_EQ(s.pigments.size(), 11u);
    const Pigment &white = s.pigments[0], &glassy = s.pigments[1], &veins = s.pigments[2],
                  &grid = s.pigments[3], &ramp = s.pigments[4], &stack = s.pigments[5],
                  &mean = s.pigments[6], &picture = s.pigments[7], &wall = s.pigments[8],
                  &swirl = s.pigments[9], &stone = s.pigments[10];
    // Solid colours, with filter and transmit.
    EXPECT_TRUE(white.solid);
    EXPECT_FLOAT_EQ(white.color[1], 1.0f);
    EXPECT_TRUE(glassy.solid);
    EXPECT_FLOAT_EQ(glassy.color[0], 0.9f);
    EXPECT_FLOAT_EQ(glassy.color[3], 0.5f);
    EXPECT_FLOAT_EQ(glassy.color[4], 0.25f);

    // A map: pattern, modifiers (marble is triangle-waved by default), entries in order.
    EXPECT_FALSE(veins.solid);
    EXPECT_EQ(veins.pattern.kind, PatternKind::Marble);
    EXPECT_EQ(veins.pattern.wave, Wave::Triangle);
    EXPECT_TRUE(veins.pattern.has_turbulence);
    expect_near(veins.pattern.turbulence, Vec3(0.6f));
    EXPECT_EQ(veins.pattern.octaves, 4);
    EXPECT_FLOAT_EQ(veins.pattern.omega, 0.4f);
    EXPECT_FLOAT_EQ(veins.pattern.lambda, 3.0f);
    EXPECT_FLOAT_EQ(veins.pattern.frequency, 2.0f);
    EXPECT_FLOAT_EQ(veins.pattern.phase, 0.1f);
    ASSERT_EQ(veins.count, 3u);
    const PigmentEntry* ve = &s.pigment_entries[veins.first];
    EXPECT_FLOAT_EQ(ve[1].value, 0.8f);
    EXPECT_FLOAT_EQ(ve[1].color[2], 0.3f);
    EXPECT_FLOAT_EQ(ve[1].color[3], 0.1f);
    EXPECT_FLOAT_EQ(ve[1].color[4], 0.2f);
    EXPECT_EQ(ve[1].pigment, -1);
    EXPECT_EQ(ve[2].pigment, 0); // white
    // Placed by scale 0.5 then translate (1 2 3): world -> pattern is the inverse.
    expect_near(veins.pattern.to_pattern.point(Vec3(1, 2, 3)), Vec3(0, 0, 0));
    expect_near(veins.pattern.to_pattern.point(Vec3(1.5f, 2, 3.5f)), Vec3(1, 0, 1));

    // A list: entries in order, a colour and a pigment; no transform: identity.
    EXPECT_EQ(grid.pattern.kind, PatternKind::Checker);
    ASSERT_EQ(grid.count, 2u);
    EXPECT_FLOAT_EQ(s.pigment_entries[grid.first].color[0], 1.0f);
    EXPECT_EQ(s.pigment_entries[grid.first + 1].pigment, 2); // veins
    expect_near(grid.pattern.to_pattern.point(Vec3(1, 2, 3)), Vec3(1, 2, 3));

    EXPECT_EQ(ramp.pattern.kind, PatternKind::Gradient);
    expect_near(ramp.pattern.vector, Vec3(0, 0, 2));
    EXPECT_EQ(ramp.pattern.wave, Wave::Poly);
    EXPECT_FLOAT_EQ(ramp.pattern.wave_exponent, 2.0f);
    expect_near(ramp.pattern.turbulence, Vec3(0.1f, 0.2f, 0.3f));

    EXPECT_TRUE(stack.layers);
    ASSERT_EQ(stack.count, 2u);
    EXPECT_EQ(s.pigment_entries[stack.first].pigment, 3); // grid at the bottom
    EXPECT_FLOAT_EQ(s.pigment_entries[stack.first + 1].color[4], 0.5f);
    EXPECT_TRUE(mean.average);
    EXPECT_EQ(mean.count, 2u);

    // The image: the texture by index, its placement, one entry with filter and transmit.
    EXPECT_EQ(picture.pattern.kind, PatternKind::Image);
    EXPECT_EQ(picture.pattern.image, 0);
    ASSERT_EQ(picture.count, 1u);
    EXPECT_FLOAT_EQ(s.pigment_entries[picture.first].color[0], 1.0f);
    EXPECT_FLOAT_EQ(s.pigment_entries[picture.first].color[4], 0.3f);
    // Placed by the texture's transform, from the pattern's space (here the world's).
    expect_near(s.textures[0].transform.point(Vec3(2, 4, 6)), Vec3(1, 2, 3));
    expect_near(picture.pattern.to_pattern.point(Vec3(2, 4, 6)), Vec3(2, 4, 6));

    // The patterns' own parameters.
    EXPECT_EQ(wall.pattern.kind, PatternKind::Brick);
    EXPECT_FLOAT_EQ(wall.pattern.param[0], 2.0f);
    EXPECT_FLOAT_EQ(wall.pattern.param[1], 1.0f);
    EXPECT_FLOAT_EQ(wall.pattern.param[3], 0.1f);
    EXPECT_EQ(swirl.pattern.kind, PatternKind::Spiral2);
    EXPECT_FLOAT_EQ(swirl.pattern.param[0], 5.0f);
    EXPECT_EQ(swirl.pattern.wave, Wave::Sine);
    EXPECT_EQ(stone.pattern.kind, PatternKind::Agate);
    EXPECT_FLOAT_EQ(stone.pattern.param[0], 0.5f);
    EXPECT_FALSE(stone.pattern.has_turbulence);

    // The normal: bumps is bozo; scale 0.2 makes pattern space 5 times finer.
    ASSERT_EQ(s.normal_patterns.size(), 1u);
    EXPECT_EQ(s.normal_patterns[0].pattern.kind, PatternKind::Bozo);
    EXPECT_FLOAT_EQ(s.normal_patterns[0].amount, 0.4f);
    expect_near(s.normal_patterns[0].pattern.to_pattern.point(Vec3(1, 0, 0)), Vec3(5, 0, 0));

    // Materials: pigment and normal; switches by list and by value.
    ASSERT_EQ(s.materials.size(), 5u);
    EXPECT_EQ(s.materials[2].pigment, 3);
    EXPECT_EQ(s.materials[2].normal, 0);
    EXPECT_FLOAT_EQ(s.materials[2].diffuse, 0.6f);
    ASSERT_EQ(s.material_switches.size(), 2u);
    const MaterialSwitch &tiles = s.material_switches[0], &bands = s.material_switches[1];
    EXPECT_EQ(tiles.pattern.kind, PatternKind::Hexagon);
    ASSERT_EQ(tiles.count, 3u);
    EXPECT_EQ(s.material_entries[tiles.first + 2].material, 2u);
    expect_near(tiles.pattern.to_pattern.point(Vec3(0, 0, -1)), Vec3(1, 0, 0), 1e-5f);
    EXPECT_EQ(bands.pattern.kind, PatternKind::Wood);
    EXPECT_EQ(bands.pattern.wave, Wave::Ramp);
    EXPECT_FLOAT_EQ(s.material_entries[bands.first + 1].value, 0.5f);
    EXPECT_EQ(s.material_entries[bands.first + 1].material, 1u);
    EXPECT_EQ(s.materials[3].select, 0);
    EXPECT_EQ(s.materials[4].select, -1); // switch="" drops the base's
    EXPECT_FLOAT_EQ(s.materials[4].color.x, 0.5f);

    EXPECT_EQ(s.sky, 4);
    ASSERT_EQ(s.fog.count, 1u);
    EXPECT_FLOAT_EQ(s.fog.layer[0].distance, 30.0f);
    EXPECT_FLOAT_EQ(s.fog.layer[0].color.z, 0.8f);
    EXPECT_FLOAT_EQ(s.fog.layer[0].transmit, 0.1f);
}

// ---- Rendering ----

Frame render(const std::string& xml, int width = 32, int height = 32) {
    const io::SceneFile f = io::parse_xml_scene(xml, "render.xml");
    PreparedScene p = prepare_scene(f.scene);
    io::attach_texture_sampler(p);
    RenderSettings rs = RenderSettings::resolve({}, f.scene.settings);
    rs.width = width, rs.height = height;
    return render_frame(p, rs);
}

Vec3 pixel(const Frame& f, int x, int y) {
    const float* p = &f.rgba[4 * (size_t(y) * f.width + x)];
    return Vec3(p[0], p[1], p[2]);
}

// An orthographic view of the unit square x, y in [0, 2] at z = 0, pixel (x, y) at world
// (x + 0.5, 2 - y - 0.5) / 16 in a 32 x 32 frame; materials fully ambient show their colour.
std::string flat_scene(const std::string& defs, const std::string& material) {
    return R"(<scene>
  <camera projection="orthographic" position="1 1 5" look_at="1 1 0" ortho_height="2"/>
  )" + defs +
           R"(
  <material name="m" ambient="1" diffuse="0" )" +
           material + R"(/>
  <box min="0 0 -1" max="2 2 0" material="m"/>
</scene>)";
}

TEST(XmlPatterns, FractalPatternsTakeTheirAttributes) {
    const io::SceneFile file = io::parse_xml_scene(R"(<scene>
  <pigment name="set" pattern="mandel" iterations="50" exponent="3" interior="1 0.5"
           exterior="6 0.01">
    <entry value="0" color="0"/> <entry value="1" color="1"/>
  </pigment>
  <normal name="field" pattern="julia" c="0.3 0.44" magnet="2" amount="0.3"/>
  <pigment name="plain" pattern="mandel"><entry value="0" color="0"/></pigment>
</scene>)",
                                                   "fractals.xml");
    const Scene& s = file.scene;
    ASSERT_EQ(s.pigments.size(), 2u);
    const FractalParams& f = s.pigments[0].pattern.fractal;
    EXPECT_EQ(s.pigments[0].pattern.kind, PatternKind::Mandel);
    EXPECT_EQ(f.iterations, 50);
    EXPECT_EQ(f.exponent, 3);
    EXPECT_EQ(f.interior_type, 1);
    EXPECT_FLOAT_EQ(f.interior_factor, 0.5f);
    EXPECT_EQ(f.exterior_type, 6);
    EXPECT_FLOAT_EQ(f.exterior_factor, 0.01f);
    ASSERT_EQ(s.normal_patterns.size(), 1u);
    const Pattern& julia = s.normal_patterns[0].pattern;
    EXPECT_EQ(julia.kind, PatternKind::Julia);
    EXPECT_EQ(julia.fractal.magnet, 2);
    EXPECT_FLOAT_EQ(julia.fractal.c[0], 0.3f);
    EXPECT_FLOAT_EQ(julia.fractal.c[1], 0.44f);
    // POV-Ray's defaults, with 30 iterations where POV-Ray requires a number.
    const FractalParams& d = s.pigments[1].pattern.fractal;
    EXPECT_EQ(d.iterations, 30);
    EXPECT_EQ(d.exponent, 2);
    EXPECT_EQ(d.interior_type, 0);
    EXPECT_EQ(d.exterior_type, 1);
}

TEST(XmlPatterns, NormalEntriesAreASlopeMap) {
    const io::SceneFile file = io::parse_xml_scene(R"(<scene>
  <normal name="plain" pattern="gradient"/>
  <normal name="triangle" pattern="gradient" amount="0.3">
    <entry value="0" height="0" slope="1"/> <scale value="2"/>
    <entry value="0.5" height="1" slope="1"/> <entry value="0.5" height="1" slope="-1"/>
    <entry value="1" slope="-1"/>
  </normal>
</scene>)",
                                                   "slopes.xml");
    const Scene& s = file.scene;
    ASSERT_EQ(s.normal_patterns.size(), 2u);
    EXPECT_EQ(s.normal_patterns[0].slope_count, 0u);
    const NormalPattern& tri = s.normal_patterns[1];
    ASSERT_EQ(tri.slope_count, 4u);
    ASSERT_EQ(s.slope_entries.size(), 4u);
    EXPECT_FLOAT_EQ(s.slope_entries[2].value, 0.5f);
    EXPECT_FLOAT_EQ(s.slope_entries[2].height, 1.0f);
    EXPECT_FLOAT_EQ(s.slope_entries[2].slope, -1.0f);
    EXPECT_FLOAT_EQ(s.slope_entries[3].height, 0.0f); // the default height
    expect_near(tri.pattern.to_pattern.point(Vec3(1, 0, 0)), Vec3(0.5f, 0, 0));
}

TEST(XmlPatterns, NormalEntriesNamingNormalsAreANormalMap) {
    const io::SceneFile file = io::parse_xml_scene(R"(<scene>
  <normal name="ripples" pattern="ripples" amount="0.3"/>
  <normal name="bumps" pattern="bumps"/>
  <normal name="blend" pattern="gradient">
    <entry value="0.2" normal="ripples"/> <entry value="0.8" normal=""/> <scale value="2"/>
  </normal>
  <normal name="tiles" pattern="checker"> <entry normal="bumps"/> <entry normal=""/> </normal>
  <normal name="mean" average="true"> <entry normal="ripples" weight="3"/> <entry normal="bumps"/> </normal>
</scene>)",
                                                   "normal_maps.xml");
    const Scene& s = file.scene;
    ASSERT_EQ(s.normal_patterns.size(), 5u);
    ASSERT_EQ(s.normal_map_entries.size(), 6u);
    const NormalPattern& blend = s.normal_patterns[2];
    EXPECT_EQ(blend.map_first, 0u);
    EXPECT_EQ(blend.map_count, 2u);
    EXPECT_FLOAT_EQ(s.normal_map_entries[0].value, 0.2f);
    EXPECT_EQ(s.normal_map_entries[0].normal, 0);
    EXPECT_EQ(s.normal_map_entries[1].normal, -1); // the surface's own normal
    const NormalPattern& tiles = s.normal_patterns[3];
    EXPECT_EQ(tiles.map_count, 2u);
    EXPECT_EQ(s.normal_map_entries[2].normal, 1);
    const NormalPattern& mean = s.normal_patterns[4];
    EXPECT_TRUE(mean.average);
    EXPECT_FLOAT_EQ(s.normal_map_entries[4].value, 3.0f);
    EXPECT_FLOAT_EQ(s.normal_map_entries[5].value, 1.0f); // the default weight
}

TEST(XmlPatterns, ACheckerPigmentGivesTwoColours) {
    const Frame f = render(flat_scene(R"(<pigment name="grid" pattern="checker">
    <entry color="1 0 0"/> <entry color="0 0 1"/>
  </pigment>)",
                                      R"(pigment="grid")"));
    int red = 0, blue = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const Vec3 c = pixel(f, x, y);
            if (c.x > 0.99f && c.y < 0.01f && c.z < 0.01f) ++red;
            if (c.z > 0.99f && c.x < 0.01f && c.y < 0.01f) ++blue;
        }
    EXPECT_EQ(red + blue, f.width * f.height); // nothing but the two colours
    EXPECT_EQ(red, blue);
    // Unit cells: (0.5, 0.5) is cell (0, 0, 0), even: the first entry; (1.5, 0.5) the second.
    EXPECT_GT(pixel(f, 8, 24).x, 0.99f);
    EXPECT_GT(pixel(f, 24, 24).z, 0.99f);
    EXPECT_GT(pixel(f, 24, 8).x, 0.99f);
}

// mapping="uv": the pattern reads the mesh's texture coordinates. The quad's u runs against
// x, so a uv gradient darkens to the right where one in space would brighten.
TEST(XmlPatterns, AUvMappedPigmentFollowsTheMeshsCoordinates) {
    auto scene = [](const std::string& mapping) {
        return R"(<scene>
  <camera projection="orthographic" position="1 1 5" look_at="1 1 0" ortho_height="2"/>
  <pigment name="ramp" pattern="gradient" vector="1 0 0" )" +
               mapping + R"(>
    <entry value="0" color="0"/> <entry value="1" color="1"/>
    <scale value="2"/>
  </pigment>
  <material name="m" ambient="1" diffuse="0" pigment="ramp"/>
  <mesh name="quad">
    <positions>0 0 0  2 0 0  2 2 0  0 2 0</positions>
    <uvs>1.5 0  0.5 0  0.5 1  1.5 1</uvs>
    <triangles>0 1 2  0 2 3</triangles>
  </mesh>
  <object mesh="quad" material="m"/>
</scene>)";
    };
    // Pixel x = 8 of 32 is x = 0.5: space gives 0.5 / 2; uv gives u = 1.25, 1.25 / 2.
    const Frame uv = render(scene(R"(mapping="uv")"));
    EXPECT_NEAR(pixel(uv, 8, 16).x, 0.625f, 0.02f);
    EXPECT_NEAR(pixel(uv, 24, 16).x, 0.375f, 0.02f);
    const Frame space = render(scene(""));
    EXPECT_NEAR(pixel(space, 8, 16).x, 0.25f, 0.02f);
    EXPECT_NEAR(pixel(space, 24, 16).x, 0.75f, 0.02f);
}

// A slope pigment: the facing side of the box (normal +z) shows the value of its slope.
TEST(XmlPatterns, ASlopePigmentSeesTheSurfaceNormal) {
    const io::SceneFile file = io::parse_xml_scene(R"(<scene>
  <pigment name="terrain" pattern="slope" direction="0 3 0" range="0 0.5" altitude="0 1 0"
           altitude_range="0.005 0.4">
    <entry value="0" color="0"/> <entry value="1" color="1"/>
  </pigment>
  <normal name="lit" pattern="slope" point_at="0 10 0"/>
</scene>)",
                                                   "slope.xml");
    const Scene& s = file.scene;
    ASSERT_EQ(s.pigments.size(), 1u);
    const Pattern& t = s.pigments[0].pattern;
    EXPECT_EQ(t.kind, PatternKind::Slope);
    expect_near(t.vector, Vec3(0, 1, 0));
    expect_near(t.slope.altitude, Vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(t.slope.slope_weight, 0.75f);
    EXPECT_FLOAT_EQ(t.param[1], 0.5f);
    EXPECT_FLOAT_EQ(t.param[2], 0.005f);
    EXPECT_NEAR(t.param[3], 0.395f, 1e-6);
    const Pattern& lit = s.normal_patterns[0].pattern;
    EXPECT_TRUE(lit.slope.point_at);
    expect_near(lit.vector, Vec3(0, 10, 0));

    auto seen = [](const char* direction) {
        const std::string pigment =
            std::string(R"(<pigment name="p" pattern="slope" direction=")") + direction +
            R"("><entry value="0" color="0"/>
    <entry value="1" color="1"/></pigment>)";
        return pixel(render(flat_scene(pigment, R"(pigment="p")")), 16, 16).x;
    };
    EXPECT_NEAR(seen("0 0 1"), 1.0f, 1e-5);  // facing the direction
    EXPECT_NEAR(seen("1 0 0"), 0.5f, 1e-5);  // across it
    EXPECT_NEAR(seen("0 0 -1"), 0.0f, 1e-5); // away from it
}

TEST(XmlPatterns, ASwitchPicksMaterialsAndAScaleMakesTilesLarger) {
    const Frame f = render(R"(<scene>
  <camera projection="orthographic" position="1 1 5" look_at="1 1 0" ortho_height="2"/>
  <material name="red" color="1 0 0" ambient="1" diffuse="0"/>
  <material name="blue" color="0 0 1" ambient="1" diffuse="0"/>
  <switch name="halves" pattern="checker">
    <entry material="red"/> <entry material="blue"/>
    <scale value="2"/>
    <translate value="1 0 0"/>
  </switch>
  <material name="m" switch="halves"/>
  <box min="0 0 -1" max="2 2 0" material="m"/>
</scene>)");
    // Cells 2 wide starting at x = 1: the left half is cell -1 (blue), the right cell 0 (red).
    EXPECT_GT(pixel(f, 4, 16).z, 0.99f);
    EXPECT_GT(pixel(f, 28, 16).x, 0.99f);
}

TEST(XmlPatterns, AnImagePigmentShowsItsTexture) {
    const auto dir = test::temp_folder("xml_patterns_image");
    write_checker_png(dir / "checker.png");
    const std::string xml = flat_scene(R"(<texture name="photo" file=")" +
                                           (dir / "checker.png").string() + R"(" mapping="planar">
    <scale value="2"/>
  </texture>
  <pigment name="picture" pattern="image" texture="photo"/>)",
                                       R"(pigment="picture")");
    const Frame f = render(xml);
    // The 2 x 2 image cells over the square: bottom left white, bottom right black.
    EXPECT_GT(pixel(f, 8, 24).x, 0.95f);
    EXPECT_LT(pixel(f, 24, 24).x, 0.05f);
}

TEST(XmlPatterns, ANormalTiltsTheShading) {
    auto spread = [](const Frame& f) {
        double sum = 0, sum2 = 0;
        const size_t n = size_t(f.width) * f.height;
        for (size_t i = 0; i < n; ++i)
            sum += f.rgba[4 * i], sum2 += double(f.rgba[4 * i]) * f.rgba[4 * i];
        return std::sqrt(std::max(0.0, sum2 / double(n) - (sum / double(n)) * (sum / double(n))));
    };
    const std::string lit = R"(<scene>
  <camera projection="orthographic" position="1 1 5" look_at="1 1 0" ortho_height="2"/>
  <light type="parallel" direction="0 0 -1"/>
  <normal name="bumpy" pattern="bumps" amount="1"><scale value="0.1"/></normal>
  <material name="m" color="1" ambient="0" diffuse="1" )";
    const std::string rest = R"(/>
  <box min="0 0 -1" max="2 2 0" material="m"/>
</scene>)";
    EXPECT_LT(spread(render(lit + rest)), 1e-4);
    EXPECT_GT(spread(render(lit + R"(normal="bumpy")" + rest)), 0.02);
}

// Two white spheres ahead, 5 and 30 units from the camera, one left and one right of the
// centre (at pixel columns 23 and 40 of 64: x / (-z tan 20 deg * 2) = -+0.275).
std::string fog_scene(const std::string& fog) {
    return R"(<scene>
  <camera position="0 0 0" look_at="0 0 -1" fov="40"/>
  <material name="white" color="1" ambient="1" diffuse="0"/>
  <sphere center="-1 0 -5" radius="0.5" material="white"/>
  <sphere center="6 0 -30" radius="3" material="white"/>
  )" + fog +
           "\n</scene>";
}

TEST(XmlPatterns, FogDarkensDistantObjects) {
    const Frame clear = render(fog_scene(""), 64, 32);
    const Frame foggy = render(fog_scene(R"(<fog distance="15" color="0"/>)"), 64, 32);
    const int y = 16, near_x = 23, far_x = 40;
    EXPECT_NEAR(pixel(clear, near_x, y).x, 1.0f, 1e-4);
    EXPECT_NEAR(pixel(clear, far_x, y).x, 1.0f, 1e-4);
    const float near = pixel(foggy, near_x, y).x, far = pixel(foggy, far_x, y).x;
    EXPECT_GT(near, 0.65f); // about exp(-4.6 / 15)
    EXPECT_LT(far, 0.25f);  // about exp(-27.6 / 15)
    EXPECT_LT(far, near * 0.4f);
    // transmit lets that share of what is behind the fog through.
    const Frame thin =
        render(fog_scene(R"(<fog distance="15" color="0" transmit="0.5"/>)"), 64, 32);
    EXPECT_GT(pixel(thin, far_x, y).x, far + 0.2f);
}

TEST(XmlPatterns, TheSkyColoursMisses) {
    const Frame f = render(R"(<scene>
  <camera position="0 0 0" look_at="0 0 -1" fov="90"/>
  <material name="grey" color="0.5" ambient="1" diffuse="0"/>
  <sphere center="0 -3 -4" radius="1" material="grey"/>
  <pigment name="sky" pattern="gradient" vector="0 1 0">
    <entry value="0" color="1 1 1"/>
    <entry value="1" color="0 0.2 1"/>
  </pigment>
  <sky pigment="sky"/>
</scene>)");
    // Just above the horizon (row 15 of 32) white; higher up the sky turns blue.
    const Vec3 horizon = pixel(f, 16, 15), high = pixel(f, 16, 1);
    EXPECT_GT(horizon.x, 0.9f);
    EXPECT_LT(high.x, 0.5f);
    EXPECT_GT(high.z, 0.9f);
    // A solid sky pigment gives its colour to every miss; the sphere is still seen.
    const Frame solid = render(R"(<scene>
  <camera position="0 0 0" look_at="0 0 -1" fov="90"/>
  <material name="grey" color="0.5" ambient="1" diffuse="0"/>
  <sphere center="0 0 -4" radius="1" material="grey"/>
  <pigment name="sky" color="0.2 0.4 0.6"/>
  <sky pigment="sky"/>
</scene>)");
    expect_near(pixel(solid, 1, 1), Vec3(0.2f, 0.4f, 0.6f));
    expect_near(pixel(solid, 16, 16), Vec3(0.5f));
}

} // namespace
} // namespace sheaf

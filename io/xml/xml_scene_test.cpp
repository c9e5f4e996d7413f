// XML scenes: a scene using every element loads into the Scene it describes and renders with
// each object where it was put; a texture shows as its image; meshes come from files and from
// subdivision; load_scene_file reads .xml.
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

// Orthographic, 8 units tall: in a 64 x 64 frame, world (x, y) is pixel (32 + 8x, 32 - 8y).
const char* kFullScene = R"(<?xml version="1.0"?>
<!-- every element of the schema -->
<scene version="1">
  <settings>
    <set key="trace.depth" value="2"/>
    <set key="aa.samples" value="1"/>
  </settings>
  <camera projection="orthographic" position="0 0 10" look_at="0 0 0" up="0 1 0"
          ortho_height="8" shift="0 0"/>
  <background color="0.1 0.2 0.3"/>
  <light type="parallel" direction="0 0 -1" color="1"/>
  <light type="point" position="0 0 8" color="0.05" fade_distance="10" fade_power="2"
         shadowless="true"/>
  <light type="spot" position="0 0 6" look_at="0 0 0" radius="20" falloff="30" tightness="1"
         color="0.05 0.05 0.05"/>
  <material name="red" color="1 0 0" ambient="0.2" diffuse="0.8" specular="0"
            phong_exponent="40"/>
  <material name="green" base="red" color="0 1 0" inside="red"/>
  <material name="grey" color="0.5" ambient="1" diffuse="0" irid="0.3" irid_thickness="0.5"
            irid_turbulence="0.1" irid_wavelength="0.3 0.2 0.1"/>
  <material name="glass" color="1" transmission="0.9" ior="1.5" mirror="0.05"
            fade_color="0.2 0.4 0.6" fade_distance="2" fade_power="1" fresnel_split="false"/>
  <material name="glow" color="0" emission="1 1 0" ambient="0" diffuse="0"/>
  <mesh name="quad">
    <positions>-1 -1 0  1 -1 0  1 1 0  -1 1 0</positions>
    <normals>0 0 1  0 0 1  0 0 1  0 0 1</normals>
    <uvs>0 0  1 0  1 1  0 1</uvs>
    <triangles>0 1 2  0 2 3</triangles>
  </mesh>
  <object name="left quad" mesh="quad" material="red" no_image="false" no_shadow="true">
    <scale value="0.8"/>
    <translate value="-2.5 2 0"/>
  </object>
  <object name="file quad" material="green">
    <mesh file="quad.obj"/>
    <scale value="0.8 0.8 1"/>
    <translate value="2.5 2 0"/>
  </object>
  <object name="blob" material="glow">
    <subdivision level="2" limit="true" scheme="catmull-clark" boundary="edge-only">
      <positions>-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1</positions>
      <face_sizes>4 4 4 4 4 4</face_sizes>
      <face_indices>0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2  1 3 7 5</face_indices>
      <crease edge="7 3" sharpness="2"/>
    </subdivision>
    <rotate axis="0 1 0" angle="20"/>
    <translate value="2.5 -2 0"/>
  </object>
  <sphere name="ball" center="-2.5 -2 0" radius="1" material="green"/>
  <plane name="backdrop" normal="0 0 1" offset="-3" material="grey"/>
  <difference name="cut" material="red">
    <box min="-0.8 -0.8 -0.8" max="0.8 0.8 0.8"/>
    <cylinder base="0 0 -2" cap="0 0 2" radius="0.4"/>
    <rotate axis="0 0 1" angle="10"/>
  </difference>
  <torus center="0 3 0" major="0.6" minor="0.15" material="red">
    <rotate axis="1 0 0" angle="90"/>
  </torus>
  <union name="stack" material="green">
    <cone base="0 -3.8 0" cap="0 -2.8 0" base_radius="0.4" cap_radius="0" open="false"/>
    <merge inverse="false">
      <disc center="-1.2 -3.3 0" normal="0 0 1" radius="0.3" hole="0.1" material="glow"/>
      <intersection>
        <sphere center="1.2 -3.3 0" radius="0.4"/>
        <box min="0.8 -3.7 -0.2" max="1.6 -2.9 0.2" material="glass"/>
      </intersection>
      <translate value="0 0 0.5"/>
    </merge>
  </union>
  <material name="finish" brilliance="2" blinn="0.5" blinn_exponent="30" metallic="0.5"
            mirror="0.3" mirror_color="1 0.5 0.25" mirror_min="0.1" mirror_falloff="2"
            mirror_fresnel="true" mirror_metallic="true" conserve_energy="true"/>
  <box name="matrix box" min="-0.2 -0.2 -0.2" max="0.2 0.2 0.2" material="finish"
       no_shadow="true" no_reflection="true">
    <matrix value="1 0 0 3.5  0 1 0 0  0 0 1 0"/>
  </box>
</scene>
)";

Vec3 pixel(const Frame& f, float x, float y) {
    const int px = int(32 + 8 * x), py = int(32 - 8 * y);
    const float* p = &f.rgba[4 * (size_t(py) * f.width + px)];
    return Vec3(p[0], p[1], p[2]);
}

TEST(XmlScene, TracedProjectionsTakeTheirAngleAndLengths) {
    const Scene s =
        io::parse_xml_scene("<scene><camera projection=\"spherical\" angle=\"300\" v_angle=\"120\" "
                            "lengths=\"1.5 1 2\"/></scene>",
                            "scene.xml")
            .scene;
    EXPECT_EQ(s.camera.projection, Projection::Spherical);
    EXPECT_FLOAT_EQ(s.camera.angle_degrees, 300);
    EXPECT_FLOAT_EQ(s.camera.v_angle_degrees, 120);
    EXPECT_FLOAT_EQ(s.camera.right_length, 1.5f);
    EXPECT_FLOAT_EQ(s.camera.direction_length, 2);
    // A lens (depth of field) on a perspective camera.
    const Scene l = io::parse_xml_scene("<scene><camera lens_radius=\"0.2\" focal_distance=\"6\"/>"
                                        "</scene>",
                                        "scene.xml")
                        .scene;
    EXPECT_FLOAT_EQ(l.camera.lens_radius, 0.2f);
    EXPECT_FLOAT_EQ(l.camera.focal_distance, 6);
    const Scene c =
        io::parse_xml_scene("<scene><camera projection=\"cylinder3\"/></scene>", "scene.xml").scene;
    EXPECT_EQ(c.camera.projection, Projection::Cylinder3);
    EXPECT_FLOAT_EQ(c.camera.angle_degrees, 90);
    EXPECT_FLOAT_EQ(
        io::parse_xml_scene("<scene><camera projection=\"spherical\"/></scene>", "scene.xml")
            .scene.camera.v_angle_degrees,
        180);
    // A camera normal names an earlier <normal>.
    const Scene n = io::parse_xml_scene("<scene><normal name=\"shatter\" pattern=\"crackle\" "
                                        "amount=\"0.1\"/><camera normal=\"shatter\"/></scene>",
                                        "scene.xml")
                        .scene;
    EXPECT_EQ(n.camera.normal, 0);
    EXPECT_EQ(c.camera.normal, -1);
}

TEST(XmlScene, JuliaFractalsTakeTheirParameters) {
    const Scene s =
        io::parse_xml_scene("<scene><julia c=\"-0.083 0 -0.83 -0.025\" function=\"cube\" "
                            "iterations=\"8\" precision=\"400\" slice=\"0 0 3 4\" "
                            "slice_distance=\"0.5\"><translate value=\"1 0 0\"/></julia>"
                            "<julia c=\"0 0 0 0\" algebra=\"hypercomplex\"/></scene>",
                            "scene.xml")
            .scene;
    ASSERT_EQ(s.shape_objects.size(), 2u);
    const CsgNode& n = s.shape_objects[0].nodes[0];
    ASSERT_EQ(n.shape.kind, ShapeKind::Julia);
    EXPECT_EQ(n.julia->algebra, JuliaAlgebra::QuaternionCube);
    EXPECT_EQ(n.julia->iterations, 8u);
    EXPECT_DOUBLE_EQ(n.julia->min_step, 1.0 / 400);
    EXPECT_NEAR(n.julia->c[2], -0.83, 1e-7);
    EXPECT_DOUBLE_EQ(n.julia->slice[3], 0.8);
    EXPECT_DOUBLE_EQ(n.julia->slice_dist, 0.5);
    EXPECT_FLOAT_EQ((s.shape_objects[0].transform * n.transform).point(Vec3(0)).x, 1);
    const JuliaFractal& h = *s.shape_objects[1].nodes[0].julia;
    EXPECT_EQ(h.algebra, JuliaAlgebra::HypercomplexSqr);
    EXPECT_EQ(h.iterations, 20u);
    EXPECT_DOUBLE_EQ(h.slice[3], 1);
}

TEST(XmlScene, AFullSceneLoadsAsWritten) {
    const auto dir = test::temp_folder("xml_full");
    test::write_text(dir / "quad.obj", test::kQuadObj);
    const io::SceneFile f = io::load_scene_file(test::write_text(dir / "full.xml", kFullScene));
    const Scene& s = f.scene;
    EXPECT_TRUE(f.warnings.empty());
    EXPECT_EQ(s.settings.at("trace.depth"), "2");
    EXPECT_EQ(s.camera.projection, Projection::Orthographic);
    EXPECT_FLOAT_EQ(s.camera.ortho_height, 8.0f);
    EXPECT_FLOAT_EQ(s.background.z, 0.3f);
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].type, LightType::Parallel);
    EXPECT_TRUE(s.lights[1].shadowless);
    EXPECT_FLOAT_EQ(s.lights[1].fade_distance, 10.0f);
    EXPECT_EQ(s.lights[2].type, LightType::Spot);
    EXPECT_FLOAT_EQ(s.lights[2].spot_falloff, 30.0f);
    EXPECT_LT(s.lights[2].direction.z, 0.0f); // towards look_at
    ASSERT_GE(s.materials.size(), 6u);
    EXPECT_FLOAT_EQ(s.materials[1].color.y, 1.0f); // green, based on red
    EXPECT_FLOAT_EQ(s.materials[1].ambient, 0.2f);
    EXPECT_EQ(s.materials[1].inside, 0); // red from inside
    EXPECT_EQ(s.materials[0].inside, -1);
    EXPECT_FLOAT_EQ(s.materials[3].transmission, 0.9f);
    EXPECT_FLOAT_EQ(s.materials[4].emission.x, 1.0f);
    EXPECT_FLOAT_EQ(s.materials[3].fade_color.y, 0.4f);
    EXPECT_FLOAT_EQ(s.materials[2].irid, 0.3f);
    EXPECT_FLOAT_EQ(s.materials[2].irid_thickness, 0.5f);
    EXPECT_FLOAT_EQ(s.materials[2].irid_turbulence, 0.1f);
    EXPECT_FLOAT_EQ(s.materials[2].irid_wavelength.z, 0.1f);
    EXPECT_FLOAT_EQ(s.materials[3].fade_distance, 2.0f);
    EXPECT_FALSE(s.materials[3].fresnel_split);
    const Material& finish = s.materials[5];
    EXPECT_FLOAT_EQ(finish.brilliance, 2.0f);
    EXPECT_FLOAT_EQ(finish.blinn_exponent, 30.0f);
    EXPECT_FLOAT_EQ(finish.metallic, 0.5f);
    EXPECT_FLOAT_EQ(finish.mirror_color.z, 0.25f);
    EXPECT_FLOAT_EQ(finish.mirror_min, 0.1f);
    EXPECT_FLOAT_EQ(finish.mirror_falloff, 2.0f);
    EXPECT_TRUE(finish.mirror_fresnel && finish.mirror_metallic && finish.conserve_energy);
    EXPECT_EQ(s.objects[0].flags, kNoShadow);
    EXPECT_EQ(s.shape_objects[5].flags, kNoShadow | kNoReflection);
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].name, "left quad");
    EXPECT_NEAR(s.objects[0].transform.m[0][3], -2.5f, 1e-6f);
    EXPECT_NEAR(s.objects[0].transform.m[0][0], 0.8f, 1e-6f);
    EXPECT_EQ(s.meshes[s.objects[2].mesh].positions.size(), 98u); // the cube at level 2
    ASSERT_EQ(s.shape_objects.size(), 6u);
    EXPECT_EQ(s.shape_objects[2].name, "cut");
    EXPECT_EQ(s.shape_objects[2].nodes.size(), 3u);
    EXPECT_EQ(s.shape_objects[2].nodes[0].op, CsgOp::Difference);
    // union(cone, merge(disc, intersection(sphere, box))), operations before their operands
    ASSERT_EQ(s.shape_objects[4].nodes.size(), 7u);
    EXPECT_EQ(s.shape_objects[4].nodes[0].op, CsgOp::Union);
    EXPECT_EQ(s.shape_objects[4].nodes[2].op, CsgOp::Merge);
    EXPECT_EQ(s.shape_objects[4].nodes[4].op, CsgOp::Intersection);
    EXPECT_EQ(s.shape_objects[4].nodes[6].material, 3u); // the box's own glass
    EXPECT_EQ(s.shape_objects[4].nodes[5].material, 1u); // the union's green
}

TEST(XmlScene, AFullSceneRendersWithObjectsWhereTheyWerePut) {
    const auto dir = test::temp_folder("xml_render");
    test::write_text(dir / "quad.obj", test::kQuadObj);
    const io::SceneFile f = io::read_xml_scene(test::write_text(dir / "full.xml", kFullScene));
    const PreparedScene p = prepare_scene(f.scene);
    RenderSettings rs = RenderSettings::resolve({}, f.scene.settings);
    EXPECT_EQ(rs.trace_depth, 2);
    rs.width = rs.height = 64;
    const Frame frame = render_frame(p, rs);
    const Vec3 left = pixel(frame, -2.5f, 2), right = pixel(frame, 2.5f, 2),
               ball = pixel(frame, -2.5f, -2), blob = pixel(frame, 2.5f, -2),
               hole = pixel(frame, 0, 0), rim = pixel(frame, 0.6f, 0),
               corner = pixel(frame, -3.9f, 3.9f);
    EXPECT_GT(left.x, 0.5f); // red quad
    EXPECT_LT(left.y, 0.1f);
    EXPECT_GT(right.y, 0.5f); // green quad from the OBJ file
    EXPECT_LT(right.x, 0.1f);
    EXPECT_GT(ball.y, 0.5f); // green sphere
    EXPECT_LT(ball.x, 0.1f);
    EXPECT_GT(blob.x, 0.9f); // yellow emission
    EXPECT_GT(blob.y, 0.9f);
    EXPECT_LT(blob.z, 0.1f);
    EXPECT_NEAR(hole.x, 0.5f, 0.02f); // through the hole: the grey plane
    EXPECT_NEAR(hole.y, 0.5f, 0.02f);
    EXPECT_GT(rim.x, 0.5f); // the box around the hole, red
    EXPECT_LT(rim.y, 0.1f);
    EXPECT_NEAR(corner.x, 0.5f, 0.02f); // the backdrop plane everywhere else
}

std::string write_checker(const std::filesystem::path& path) {
    const int n = 64, cell = 8;
    std::vector<unsigned char> px(n * n * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c)
                px[(y * n + x) * 3 + c] = ((x / cell + y / cell) % 2) ? 255 : 0;
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(n, n, 3, OIIO::TypeDesc::UINT8)));
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    return path.string();
}

std::string textured_scene(const std::string& material_texture, const std::string& mapping) {
    return R"(<scene>
  <camera projection="orthographic" position="0 0 3" look_at="0 0 0" ortho_height="2"/>
  <light type="parallel" direction="0 0 -1"/>
  <texture name="checker" file="textures/checker.png" mapping=")" +
           mapping + R"(" colorspace="srgb">
    <scale value="2"/>
    <translate value="-1 -1 0"/>
  </texture>
  <material name="paper" color="1" ambient="0.2" diffuse="0.8" texture=")" +
           material_texture + R"("/>
  <mesh name="quad">
    <positions>-1 -1 0  1 -1 0  1 1 0  -1 1 0</positions>
    <uvs>0 0  1 0  1 1  0 1</uvs>
    <triangles>0 1 2  0 2 3</triangles>
  </mesh>
  <object mesh="quad" material="paper"/>
</scene>)";
}

void mean_and_spread(const Frame& f, double& mean, double& spread) {
    double sum = 0, sum2 = 0;
    const size_t n = size_t(f.width) * f.height;
    for (size_t i = 0; i < n; ++i)
        sum += f.rgba[4 * i], sum2 += double(f.rgba[4 * i]) * f.rgba[4 * i];
    mean = sum / double(n);
    spread = std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
}

Frame render_xml(const std::string& path) {
    const io::SceneFile f = io::load_scene_file(path);
    PreparedScene p = prepare_scene(f.scene);
    io::attach_texture_sampler(p);
    RenderSettings rs;
    rs.width = rs.height = 64;
    return render_frame(p, rs);
}

TEST(XmlScene, ATextureShowsItsImage) {
    const auto dir = test::temp_folder("xml_texture");
    std::filesystem::create_directories(dir / "textures");
    write_checker(dir / "textures" / "checker.png");
    double mean, spread;
    for (const char* mapping : {"uv", "planar"}) {
        SCOPED_TRACE(mapping);
        const Frame f =
            render_xml(test::write_text(dir / "textured.xml", textured_scene("checker", mapping)));
        mean_and_spread(f, mean, spread);
        EXPECT_NEAR(mean, 0.5, 0.05); // half the cells black, half white: 0 or 0.2 + 0.8
        EXPECT_GT(spread, 0.45);
        // Bottom left is texture (0, 0): the image's bottom-left cell, white.
        EXPECT_GT(f.rgba[4 * (63 * 64 + 0)], 0.95f);
        EXPECT_LT(f.rgba[4 * (63 * 64 + 9)], 0.05f);
    }
    // Without the texture the same quad is uniform.
    const Frame plain = render_xml(test::write_text(dir / "plain.xml", textured_scene("", "uv")));
    mean_and_spread(plain, mean, spread);
    EXPECT_NEAR(mean, 1.0, 1e-3);
    EXPECT_LT(spread, 1e-3);
}

TEST(XmlScene, SubdivisionFromAMeshFileAndShapesWithoutMaterials) {
    const auto dir = test::temp_folder("xml_cage");
    test::write_text(dir / "cage.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const io::SceneFile f = io::read_xml_scene(test::write_text(dir / "cage.xml", R"(<scene>
  <subdivision name="patch" file="cage.obj" level="3" boundary="edge-and-corner"/>
  <object mesh="patch"/>
  <object><mesh file="cage.obj"/></object>
  <sphere/>
</scene>)"));
    ASSERT_EQ(f.scene.meshes.size(), 2u);
    EXPECT_EQ(f.scene.meshes[0].triangle_count(), 2u * 64u);
    ASSERT_EQ(f.scene.materials.size(), 1u); // the default material, made once
    EXPECT_EQ(f.scene.objects[0].material, 0u);
    EXPECT_EQ(f.scene.shape_objects[0].nodes[0].material, 0u);
}

} // namespace
} // namespace sheaf

// POV-Ray textures into the core's procedural textures: patterns with their maps and
// transforms, lists, pigment maps, layers, texture maps, normals, finishes, interiors, image
// maps, sky_sphere; what is not supported warns and falls back to an average.
#include "tests/support/pov_test_util.h"

#include "core/backend/device_stack.h"
#include "core/scene/prepared_scene.h"
#include "core/shading/surface_texture.h"
#include "io/image/texture_sampler.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

const Material& shape_material(const PovResult& r, size_t object = 0) {
    return r.scene.materials[r.scene.shape_objects[object].nodes[0].material];
}

// Writes `name` in d: a w x h image of `channels` float values per pixel, stored as `type`.
std::string write_image(test::TempDir& d, const std::string& name, int w, int h, int channels,
                        const float* px, OIIO::TypeDesc type = OIIO::TypeDesc::UINT8) {
    const std::string path = d.path() + "/" + name;
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(w, h, channels, type)) &&
                out->write_image(OIIO::TypeDesc::FLOAT, px))
        << path;
    if (out) out->close();
    return path;
}

// A 2 x 2 image: red, green / blue, white.
std::string write_tiles(test::TempDir& d) {
    const float px[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    return write_image(d, "tiles.png", 2, 2, 3, px);
}

TEST(PovTextures, PatternsBecomePigmentsInTheirOwnSpace) {
    const PovResult r =
        load_text("sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] }\n"
                  "  scale 2 } translate <3, 0, 0> }\n");
    EXPECT_TRUE(r.warnings.empty());
    const Material& m = shape_material(r);
    ASSERT_GE(m.pigment, 0);
    const Pigment& pg = r.scene.pigments[size_t(m.pigment)];
    EXPECT_FALSE(pg.solid);
    EXPECT_EQ(pg.pattern.kind, PatternKind::Gradient);
    ASSERT_EQ(pg.count, 2u);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[pg.first + 1].color[1], 0.5f);
    // World point x = 4 is pattern point (4 - 3) / 2 = 0.5: the object's translate moved the
    // pigment with it, the pigment's own scale stretched it. z is mirrored (POV-Ray is
    // left-handed): the Sheaf point z = -0.25 is POV-Ray's z = 0.25, invisible to gradient x.
    const Vec3 q = pg.pattern.to_pattern.point(Vec3(4, 0, -0.25f));
    EXPECT_NEAR(q.x, 0.5f, 1e-5);
    EXPECT_NEAR(q.z, 0.125f, 1e-5);
    const PreparedScene p = prepare_scene(r.scene);
    EXPECT_NEAR(evaluate_pigment(p, uint32_t(m.pigment), Vec3(4, 0, 0), 0, 0).rgb.x, 0.5f, 1e-5);
}

TEST(PovTextures, PatternsWithoutColoursTakePovRaysDefaultMaps) {
    // POV-Ray's own maps for agate, bozo, marble, radial, wood and mandel, a grey ramp for
    // the others, and its list colours for brick (textures/pigments/pigmap.pov).
    auto entries = [](const std::string& pigment) {
        const PovResult r = load_text("sphere { 0, 1 pigment { " + pigment + " } }\n");
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
        const Pigment& pg = r.scene.pigments[size_t(shape_material(r).pigment)];
        return std::vector<PigmentEntry>(r.scene.pigment_entries.begin() + pg.first,
                                         r.scene.pigment_entries.begin() + pg.first + pg.count);
    };
    const auto marble = entries("marble");
    ASSERT_EQ(marble.size(), 3u);
    EXPECT_FLOAT_EQ(marble[1].value, 0.9f);
    EXPECT_FLOAT_EQ(marble[1].color[1], 0.08f);
    const auto bozo = entries("bozo");
    ASSERT_EQ(bozo.size(), 6u);
    EXPECT_FLOAT_EQ(bozo[0].value, 0.4f);
    EXPECT_FLOAT_EQ(bozo[5].color[0], 1);
    EXPECT_EQ(entries("radial").size(), 4u);
    EXPECT_EQ(entries("wood").size(), 2u);
    EXPECT_EQ(entries("agate").size(), 6u);
    EXPECT_EQ(entries("mandel 10").size(), 5u);
    const auto spotted = entries("spotted"); // bozo's noise, the grey ramp
    ASSERT_EQ(spotted.size(), 2u);
    EXPECT_FLOAT_EQ(spotted[1].color[0], 1);
    const auto brick = entries("brick");
    ASSERT_EQ(brick.size(), 2u);
    EXPECT_FLOAT_EQ(brick[0].color[0], 0.5f);
    EXPECT_FLOAT_EQ(brick[1].color[1], 0.15f);
}

TEST(PovTextures, MapEntriesMayStartWithADeclaredFloat) {
    // wallstucco.pov's [L2, PWrink]: a declared float is the entry's value, not a grey colour.
    const PovResult r = load_text(
        "#declare L = 0.4; #declare P = pigment { rgb <1, 0, 0> }\n"
        "#declare T = texture { pigment { rgb 1 } }\n"
        "sphere { 0, 1 pigment { bozo pigment_map { [L, P] [(L + 0.2) P] [1, rgb 1] } } }\n"
        "sphere { 0, 1 texture { bozo texture_map { [L T] [L * 2, T] } } }\n"
        "sphere { 0, 1 pigment { average pigment_map { [P] [rgb 1] } } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Pigment& bozo = r.scene.pigments[size_t(shape_material(r, 0).pigment)];
    ASSERT_EQ(bozo.count, 3u);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[bozo.first].value, 0.4f);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[bozo.first + 1].value, 0.6f);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[bozo.first].color[0], 1);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[bozo.first].color[1], 0);
}

// A texture_map that POV-Ray blends (two textures at two values of a continuous pattern) is
// an approximation Sheaf warns about where the map is, also when declared, and --strict
// refuses; steps, one texture at several values and list patterns are exact and say nothing.
TEST(PovTextures, BlendingTextureMapsAreWarnedAsApproximated) {
    const std::string decl = "#declare A = texture { pigment { rgb 1 } }\n"
                             "#declare B = texture { pigment { rgb 0 } }\n";
    const PovResult blend =
        load_text(decl + "sphere { 0, 1 texture { gradient y texture_map { [0 A] [1 B] } } }\n");
    ASSERT_EQ(blend.warnings.size(), 1u);
    EXPECT_NE(blend.warnings[0].find("scene.pov:3:36: warning: approximated texture_map blending"),
              std::string::npos)
        << blend.warnings[0];
    const PovResult exact = load_text(
        decl +
        "sphere { 0, 1 texture { gradient y texture_map { [0 A] [0.5 A] [0.5 B] [1 B] } } }\n"
        "sphere { 0, 1 texture { checker texture { A } texture { B } } }\n");
    EXPECT_TRUE(exact.warnings.empty()) << exact.warnings.front();
    PovOptions strict;
    strict.strict = true;
    EXPECT_NE(
        error_of(decl + "sphere { 0, 1 texture { bozo texture_map { [0 A] [1 B] } } }\n", strict)
            .find("scene.pov:3:30: error: approximated texture_map blending"),
        std::string::npos);
    // Declared: warned where it is used, once.
    const std::string declared =
        decl + "#declare T = texture { bozo texture_map { [0 A] [1 B] } }\n";
    EXPECT_TRUE(load_text(declared + "sphere { 0, 1 }\n").warnings.empty());
    const PovResult used = load_text(declared + "sphere { 0, 1 texture { T } }\n");
    ASSERT_EQ(used.warnings.size(), 1u) << used.warnings.front();
    EXPECT_NE(used.warnings[0].find("scene.pov:3:29: warning: approximated"), std::string::npos)
        << used.warnings[0];
}

// global_settings' number_of_waves reaches every ripples and waves pattern (10 unless set),
// the normals' too; POV-Ray's 1 for less, and at most 1000, both warned.
TEST(PovTextures, NumberOfWavesReachesTheWavePatterns) {
    const std::string body = "sphere { 0, 1 pigment { ripples } normal { waves 0.5 } }\n";
    const PovResult plain = load_text(body);
    EXPECT_EQ(plain.scene.pigments[size_t(shape_material(plain).pigment)].pattern.waves, 10);
    const PovResult three = load_text(body + "global_settings { number_of_waves 3 }\n");
    EXPECT_TRUE(three.warnings.empty()) << three.warnings.front();
    const Material& m = shape_material(three);
    EXPECT_EQ(three.scene.pigments[size_t(m.pigment)].pattern.waves, 3);
    ASSERT_GE(m.normal, 0);
    EXPECT_EQ(three.scene.normal_patterns[size_t(m.normal)].pattern.waves, 3);
    const PovResult none = load_text(body + "global_settings { number_of_waves 0 }\n");
    ASSERT_EQ(none.warnings.size(), 1u);
    EXPECT_NE(none.warnings[0].find("number_of_waves 0 is clamped to 1"), std::string::npos);
    EXPECT_EQ(none.scene.pigments[size_t(shape_material(none).pigment)].pattern.waves, 1);
    const PovResult many = load_text(body + "global_settings { number_of_waves 1e9 }\n");
    EXPECT_EQ(many.scene.pigments[size_t(shape_material(many).pigment)].pattern.waves, 1000);
}

TEST(PovTextures, FractalPatternsTakeTheirArgumentsAndModifiers) {
    const PovResult r = load_text(
        "#declare M = pigment { magnet 2 mandel 40 }\n"
        "sphere { 0, 1 pigment { mandel 50 exponent 4 interior 1, 0.5 exterior 6, 0.01 } }\n"
        "sphere { 0, 1 pigment { julia <0.3, 0.44>, 30 } normal { julia <-.5, .5> 10 0.6 } }\n"
        "sphere { 0, 1 pigment { magnet 1 julia <0.3, 0.44> 30 } }\n"
        "sphere { 0, 1 pigment { M mandel 20 } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Pigment& mandel = r.scene.pigments[size_t(shape_material(r, 0).pigment)];
    EXPECT_EQ(mandel.pattern.kind, PatternKind::Mandel);
    EXPECT_EQ(mandel.pattern.fractal.iterations, 50);
    EXPECT_EQ(mandel.pattern.fractal.exponent, 4);
    EXPECT_EQ(mandel.pattern.fractal.interior_type, 1);
    EXPECT_FLOAT_EQ(mandel.pattern.fractal.interior_factor, 0.5f);
    EXPECT_EQ(mandel.pattern.fractal.exterior_type, 6);
    EXPECT_FLOAT_EQ(mandel.pattern.fractal.exterior_factor, 0.01f);
    const Material& julia = shape_material(r, 1);
    const Pigment& jp = r.scene.pigments[size_t(julia.pigment)];
    EXPECT_EQ(jp.pattern.kind, PatternKind::Julia);
    EXPECT_EQ(jp.pattern.fractal.iterations, 30);
    EXPECT_FLOAT_EQ(jp.pattern.fractal.c[0], 0.3f);
    EXPECT_FLOAT_EQ(jp.pattern.fractal.c[1], 0.44f);
    ASSERT_GE(julia.normal, 0); // a fractal normal tilts the surface
    const Pigment& magnet = r.scene.pigments[size_t(shape_material(r, 2).pigment)];
    EXPECT_EQ(magnet.pattern.kind, PatternKind::Julia);
    EXPECT_EQ(magnet.pattern.fractal.magnet, 1);
    // A declared magnet pigment given another pattern is that pattern, not a magnet.
    const Pigment& redone = r.scene.pigments[size_t(shape_material(r, 3).pigment)];
    EXPECT_EQ(redone.pattern.fractal.magnet, 0);
    EXPECT_EQ(redone.pattern.fractal.iterations, 20);
    // povray refuses these too.
    EXPECT_EQ(
        error_of("sphere { 0, 1 pigment { mandel 30 interior 7, 1 } }"),
        "scene.pov:1:44: error: a fractal pattern's interior type must be a whole number from "
        "0 to 6");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { mandel 30 exponent 34 } }"),
              "scene.pov:1:44: error: a fractal pattern's exponent must lie between 2 and 33");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { magnet 3 mandel 30 } }"),
              "scene.pov:1:32: error: a magnet pattern's type must be 1 or 2");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { magnet 1 30 } }"),
              "scene.pov:1:34: error: found '30', expected mandel or julia");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { mandel 0 } }"),
              "scene.pov:1:32: error: a fractal pattern's iterations must lie between 1 and 65535");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { mandel 9 exterior 7, 0 } }"),
              "scene.pov:1:46: error: exterior type 7 needs a factor of 1 or more");
}

TEST(PovTextures, ListsDefaultsAndPigmentMaps) {
    const PovResult r = load_text(
        "sphere { 0, 1 pigment { checker rgb 1, rgb 0 } }\n"
        "sphere { 0, 1 pigment { hexagon } }\n"
        "sphere { 0, 1 pigment { bozo pigment_map { [0 rgb 1] [1 checker rgb x, rgb y] } } }\n"
        "sphere { 0, 1 pigment { brick pigment { rgb 0.5 }, pigment { marble } } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Pigment& checker = r.scene.pigments[size_t(shape_material(r, 0).pigment)];
    EXPECT_EQ(checker.pattern.kind, PatternKind::Checker);
    EXPECT_EQ(checker.count, 2u);
    const Pigment& hexagon = r.scene.pigments[size_t(shape_material(r, 1).pigment)];
    ASSERT_EQ(hexagon.count, 3u); // POV-Ray's blue, green, red
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[hexagon.first].color[2], 1);
    const Pigment& bozo = r.scene.pigments[size_t(shape_material(r, 2).pigment)];
    ASSERT_EQ(bozo.count, 2u);
    EXPECT_LT(r.scene.pigment_entries[bozo.first].pigment, 0); // a plain colour stays a colour
    const int32_t nested = r.scene.pigment_entries[bozo.first + 1].pigment;
    ASSERT_GE(nested, 0);
    EXPECT_EQ(r.scene.pigments[size_t(nested)].pattern.kind, PatternKind::Checker);
    const Pigment& brick = r.scene.pigments[size_t(shape_material(r, 3).pigment)];
    EXPECT_EQ(brick.pattern.kind, PatternKind::Brick);
    EXPECT_GE(r.scene.pigment_entries[brick.first + 1].pigment, 0);
    EXPECT_NO_THROW(r.scene.validate());
}

TEST(PovTextures, TurbulenceWavesAndModifiers) {
    const PovResult r = load_text("sphere { 0, 1 pigment { wood turbulence 0.3 octaves 4 "
                                  "omega 0.7 lambda 3 frequency 2 phase 0.1 sine_wave } }\n"
                                  "sphere { 0, 1 pigment { marble } }\n");
    const Pattern& wood = r.scene.pigments[size_t(shape_material(r, 0).pigment)].pattern;
    EXPECT_EQ(wood.kind, PatternKind::Wood);
    EXPECT_TRUE(wood.has_turbulence);
    EXPECT_FLOAT_EQ(wood.turbulence.y, 0.3f);
    EXPECT_EQ(wood.octaves, 4);
    EXPECT_FLOAT_EQ(wood.omega, 0.7f);
    EXPECT_FLOAT_EQ(wood.lambda, 3);
    EXPECT_FLOAT_EQ(wood.frequency, 2);
    EXPECT_FLOAT_EQ(wood.phase, 0.1f);
    EXPECT_EQ(wood.wave, Wave::Sine);
    // Marble is triangle-waved unless told otherwise.
    EXPECT_EQ(r.scene.pigments[size_t(shape_material(r, 1).pigment)].pattern.wave, Wave::Triangle);
}

TEST(PovTextures, LayersTextureMapsAndNormals) {
    const PovResult r = load_text(
        "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { bozo color_map {\n"
        "  [0 rgbt <1, 0, 0, 1>] [1 rgb 0] } } normal { bumps 0.4 scale 0.2 } } }\n"
        "sphere { 0, 1 texture { gradient y texture_map { [0 pigment { rgb 1 }]\n"
        "  [1 pigment { rgb 0 } finish { phong 1 }] } } }\n"
        "sphere { 0, 1 texture { checker texture { pigment { rgb x } } texture { pigment { rgb y } "
        "} } }\n");
    // The gradient's map blends in POV-Ray: the one warning.
    ASSERT_EQ(r.warnings.size(), 1u) << r.warnings.front();
    EXPECT_NE(r.warnings[0].find("3:36: warning: approximated texture_map"), std::string::npos);
    const Material& layered = shape_material(r, 0);
    ASSERT_GE(layered.pigment, 0);
    const Pigment& layers = r.scene.pigments[size_t(layered.pigment)];
    EXPECT_TRUE(layers.layers);
    EXPECT_EQ(layers.count, 2u);
    ASSERT_GE(layered.normal, 0);
    EXPECT_FLOAT_EQ(r.scene.normal_patterns[size_t(layered.normal)].amount, 0.4f);
    const Material& mapped = shape_material(r, 1);
    ASSERT_GE(mapped.select, 0);
    const MaterialSwitch& sw = r.scene.material_switches[size_t(mapped.select)];
    ASSERT_EQ(sw.count, 2u);
    EXPECT_FLOAT_EQ(r.scene.materials[r.scene.material_entries[sw.first + 1].material].specular, 1);
    const Material& list = shape_material(r, 2);
    ASSERT_GE(list.select, 0);
    EXPECT_EQ(r.scene.material_switches[size_t(list.select)].pattern.kind, PatternKind::Checker);
    EXPECT_NO_THROW(r.scene.validate());
}

// A declared layered texture moved by transforms moves every layer (woods.inc's T_Wood35 with
// a scale: povray's picture, within one 8-bit level, where the layer below stayed unscaled).
TEST(PovTextures, TransformsMoveEveryLayerOfADeclaredTexture) {
    const PovResult r = load_text(
        "#declare T = texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }\n"
        "  texture { pigment { gradient y color_map { [0 rgbt 1] [1 rgbt <0, 0, 0, 0.5>] } } }\n"
        "sphere { 0, 1 texture { T scale 0.25 } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Pigment& layers = r.scene.pigments[size_t(shape_material(r, 0).pigment)];
    ASSERT_TRUE(layers.layers);
    ASSERT_EQ(layers.count, 2u);
    for (uint32_t i = 0; i < 2; ++i) { // both layers: 0.1 in the world is 0.4 in pattern space
        const Pattern& pt =
            r.scene.pigments[size_t(r.scene.pigment_entries[layers.first + i].pigment)].pattern;
        const Vec3 q = pt.to_pattern.point(Vec3(0.1f, 0.1f, 0));
        EXPECT_NEAR(std::max(q.x, q.y), 0.4f, 1e-5) << i;
    }
}

// A declared texture's transforms come before a pigment or normal block that modifies it:
// POV-Ray applies them to the pigment as they come (interior/ballbox1.pov's floor, T_Stone1
// with pigment { rotate 90*z }).
TEST(PovTextures, ModifyingBlocksTransformAfterTheTexture) {
    const PovResult r = load_text(
        "#declare T = texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }\n"
        "  normal { gradient x } scale <2, 1, 1> }\n"
        "sphere { 0, 1 texture { T pigment { rotate 90 * z } normal { rotate 90 * z } } }\n"
        "sphere { 0, 1 texture { T pigment { rotate 90 * z } } scale 3 }\n");
    ASSERT_TRUE(r.warnings.empty()) << r.warnings.front();
    // Scaled by 2 along x, then turned: the gradient runs along y, two units to a cycle
    // (the other order would run it along y one unit to a cycle).
    const Pattern& pt = r.scene.pigments[size_t(shape_material(r, 0).pigment)].pattern;
    EXPECT_NEAR(pt.to_pattern.point(Vec3(0, 0.5f, 0)).x, 0.25f, 1e-5);
    EXPECT_NEAR(pt.to_pattern.point(Vec3(0.5f, 0, 0)).x, 0, 1e-5);
    const Material& m = shape_material(r, 0);
    ASSERT_GE(m.normal, 0);
    const Pattern& nt = r.scene.normal_patterns[size_t(m.normal)].pattern;
    EXPECT_NEAR(nt.to_pattern.point(Vec3(0, 0.5f, 0)).x, 0.25f, 1e-5);
    // The object's transforms still come after all of them.
    const Pattern& big = r.scene.pigments[size_t(shape_material(r, 1).pigment)].pattern;
    EXPECT_NEAR(big.to_pattern.point(Vec3(0, 1.5f, 0)).x, 0.25f, 1e-5);
}

// Sheaf lights a layered texture with one finish: layers that show with other finishes warn,
// where the texture is written or where a block modifies a declared one.
TEST(PovTextures, LayersLitWithOtherFinishesWarn) {
    const std::string clear = "texture { pigment { rgbf <1, 1, 1, 0.5> } ";
    auto warnings = [](const std::string& text) { return load_text(text).warnings; };
    EXPECT_TRUE(warnings("sphere { 0, 1 texture { pigment { rgb 1 } } " + clear + "} }").empty());
    const auto differ = warnings("sphere { 0, 1 texture { pigment { rgb 1 } }\n" + clear +
                                 "finish { ambient 0.4 } } }");
    ASSERT_EQ(differ.size(), 1u);
    EXPECT_NE(differ[0].find("2:1: warning: approximated layered texture"), std::string::npos);
    // Under an opaque layer nothing shows; a layer clear everywhere shows nothing.
    EXPECT_TRUE(warnings("sphere { 0, 1 texture { pigment { rgb 1 } }\n texture { pigment "
                         "{ rgb 0 } finish { reflection 0.5 } } }")
                    .empty());
    EXPECT_TRUE(warnings("sphere { 0, 1 texture { pigment { rgb 1 } finish { ambient 0 } }\n"
                         "texture { pigment { rgbt 1 } } }")
                    .empty());
    // A declared layered texture lit alike, given another finish where it is used.
    const auto modified = warnings("#declare T = texture { pigment { rgb 1 } } " + clear +
                                   "}\nsphere { 0, 1 texture { T finish { diffuse 0.2 } } }");
    ASSERT_EQ(modified.size(), 1u);
    EXPECT_NE(modified[0].find("2:27: warning: approximated layered texture"), std::string::npos);
    PovOptions strict;
    strict.strict = true;
    EXPECT_NE(error_of("sphere { 0, 1 texture { pigment { rgb 1 } }\n" + clear +
                           "finish { ambient 0.4 } } }",
                       strict)
                  .find("error: approximated layered texture"),
              std::string::npos);
}

// tiles { texture tile2 texture } is a checker of the two textures (each may be layered),
// placed by the transforms after it.
TEST(PovTextures, TilesAreACheckerOfTwoTextures) {
    const PovResult r = load_text(
        "plane { y, 0 texture { tiles { texture { pigment { rgb x } } tile2 texture { pigment "
        "{ rgb y } } texture { pigment { rgbf <1, 1, 1, 0.5> } } } scale 2 } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Material& m = shape_material(r);
    ASSERT_GE(m.select, 0);
    const MaterialSwitch& sw = r.scene.material_switches[size_t(m.select)];
    EXPECT_EQ(sw.pattern.kind, PatternKind::Checker);
    ASSERT_EQ(sw.count, 2u);
    EXPECT_NEAR(sw.pattern.to_pattern.point(Vec3(3, 0, 0)).x, 1.5f, 1e-5);
    const Material& second = r.scene.materials[r.scene.material_entries[sw.first + 1].material];
    ASSERT_GE(second.pigment, 0);
    EXPECT_TRUE(r.scene.pigments[size_t(second.pigment)].layers); // two layers
    EXPECT_NO_THROW(r.scene.validate());
    EXPECT_NE(error_of("plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } "
                       "texture { pigment { rgb 0 } } } } }")
                  .find("1:92: error: found '}', expected tile2"),
              std::string::npos);
}

// A layered texture shines as POV-Ray's: each layer's phong and specular count in full,
// weighed only by what the layers above let through, with the size of the top-most one.
// The rest of the finish is the top-most mostly opaque layer's.
TEST(PovTextures, LayersAddTheirHighlights) {
    const PovResult r = load_text(
        "sphere { 0, 1 texture { pigment { rgb 1 } finish { diffuse 0.9 } }\n"
        "  texture { pigment { rgbf <1, 1, 1, 0.8> } finish { phong 1 phong_size 90 } } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } finish { specular 0.4 roughness 0.01 } }\n"
        "  texture { pigment { rgbt <1, 1, 1, 0.5> } finish { specular 0.2 roughness 0.1 } } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } finish { phong 1 } }\n"
        "  texture { pigment { rgb 0.5 } } }\n");
    // The varnish's own diffuse (the default 0.6) is not the floor's 0.9: lit with one
    // finish, warned; the others differ in highlights only, which are added layer by layer.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("2:3: warning: approximated layered texture whose layers' "
                                 "finishes differ"),
              std::string::npos);
    const Material& varnish = shape_material(r, 0);
    EXPECT_FLOAT_EQ(varnish.diffuse, 0.9f); // the opaque bottom layer's
    EXPECT_FLOAT_EQ(varnish.specular, 1);   // the clear top layer's phong, in full
    EXPECT_FLOAT_EQ(varnish.phong_exponent, 90);
    const Material& both = shape_material(r, 1);
    EXPECT_FLOAT_EQ(both.blinn, 0.2f + 0.4f * 0.5f); // the lower one seen through half
    EXPECT_FLOAT_EQ(both.blinn_exponent, 10);        // 1 / the top one's roughness
    // Under an opaque layer, a layer's highlight does not show.
    EXPECT_FLOAT_EQ(shape_material(r, 2).specular, 0);
}

// POV-Ray adds the reflection of every layer it reaches, each in full (not weighed by the
// layers' opacity), and stops below a layer that lets nothing through (advanced/pawns.pov's
// Rosewood, given reflection 0.3 on its clear top layer).
TEST(PovTextures, LayersAddTheirReflections) {
    const PovResult r =
        load_text("sphere { 0, 1 texture { pigment { rgb 1 } finish { reflection 0.2 } }\n"
                  "  texture { pigment { rgbf <1, 1, 1, 0.8> } finish { reflection 0.3 } } }\n"
                  "sphere { 0, 1 texture { pigment { rgb 1 } finish { reflection 0.2 } }\n"
                  "  texture { pigment { rgb 0.5 } finish { reflection 0.3 } } }\n"
                  "sphere { 0, 1 texture { pigment { rgb 1 } }\n"
                  "  texture { pigment { rgbt 0.5 } finish { reflection { 0.1, 0.4 } } } }\n");
    ASSERT_TRUE(r.warnings.size() == 1) << r.warnings.size(); // the third's variable one
    EXPECT_FLOAT_EQ(shape_material(r, 0).mirror, 0.5f);
    EXPECT_FLOAT_EQ(shape_material(r, 1).mirror, 0.3f); // nothing passes the top one
    EXPECT_FLOAT_EQ(shape_material(r, 2).mirror, 0.4f);
    EXPECT_FLOAT_EQ(shape_material(r, 2).mirror_min, 0.1f);
}

// POV-Ray 3.7's slope pattern: the old form and the block with ranges, altitude and
// point_at; the direction turns into Sheaf's world (z mirrored), the altitude stays in
// pattern space; a zero range warns; nothing to measure is an error at the keyword.
TEST(PovTextures, SlopePatternsTakeTheirArguments) {
    const PovResult r =
        load_text("sphere { 0, 1 texture { slope { -y*3, 0, 0.5 altitude y, 0.005, 0.400 }\n"
                  "  texture_map { [0.45 pigment { rgb x }] [0.55 pigment { rgb y }] } } }\n"
                  "sphere { 0, 1 pigment { slope z color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                  "sphere { 0, 1 pigment { slope { point_at <1, 2, 3> } } }\n"
                  "sphere { 0, 1 normal { slope { x altitude z } 0.5 } }\n");
    ASSERT_EQ(r.warnings.size(), 1u) << r.warnings[0]; // the texture_map blends in POV-Ray
    EXPECT_NE(r.warnings[0].find("warning: approximated texture_map"), std::string::npos);
    const Material& mapped = shape_material(r, 0);
    ASSERT_GE(mapped.select, 0);
    const Pattern& terrain = r.scene.material_switches[size_t(mapped.select)].pattern;
    EXPECT_EQ(terrain.kind, PatternKind::Slope);
    EXPECT_EQ(terrain.vector.y, -1.0f);
    EXPECT_FLOAT_EQ(terrain.slope.slope_weight, 0.75f);
    EXPECT_EQ(terrain.slope.altitude.y, 1.0f);
    EXPECT_FLOAT_EQ(terrain.param[1], 0.5f);
    EXPECT_FLOAT_EQ(terrain.param[2], 0.005f);
    EXPECT_NEAR(terrain.param[3], 0.395f, 1e-6);
    const Pattern& old = r.scene.pigments[size_t(shape_material(r, 1).pigment)].pattern;
    EXPECT_EQ(old.kind, PatternKind::Slope);
    EXPECT_EQ(old.vector.z, -1.0f); // POV-Ray's +z is Sheaf's -z
    EXPECT_EQ(old.slope.slope_weight, 1.0f);
    const Pattern& towards = r.scene.pigments[size_t(shape_material(r, 2).pigment)].pattern;
    EXPECT_TRUE(towards.slope.point_at);
    EXPECT_EQ(towards.vector.x, 1.0f);
    EXPECT_EQ(towards.vector.z, -3.0f);
    const NormalPattern& bumps = r.scene.normal_patterns[size_t(shape_material(r, 3).normal)];
    EXPECT_EQ(bumps.pattern.kind, PatternKind::Slope);
    EXPECT_FLOAT_EQ(bumps.amount, 0.5f); // the bump size
    EXPECT_EQ(bumps.form, NormalForm::Slope);
    EXPECT_EQ(bumps.pattern.slope.altitude.z, 1.0f); // pattern space: not mirrored
    EXPECT_NO_THROW(r.scene.validate());
    // A sphere's top is white and its side grey where the slope points up.
    PreparedScene p = prepare_scene(load_text("sphere { 0, 1 pigment { slope y color_map { "
                                              "[0 rgb 0] [1 rgb 1] } } }\n")
                                        .scene);
    const uint32_t pg = uint32_t(p.materials[p.shape_material[0]].pigment);
    EXPECT_NEAR(evaluate_pigment(p, pg, Vec3(0, 1, 0), 0, 0, Vec3(0, 1, 0)).rgb.x, 1.0f, 1e-6);
    EXPECT_NEAR(evaluate_pigment(p, pg, Vec3(0, 0, -1), 0, 0, Vec3(0, 0, -1)).rgb.x, 0.5f, 1e-6);

    const PovResult zero = load_text("sphere { 0, 1 pigment { slope { y, 0.5, 0.5 } } }\n");
    ASSERT_EQ(zero.warnings.size(), 1u);
    EXPECT_NE(zero.warnings[0].find("scene.pov:1:36: warning: a zero slope range (low = high), "
                                    "ignored"),
              std::string::npos)
        << zero.warnings[0];
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { slope { 0 } } }"),
              "scene.pov:1:25: error: a slope pattern needs a slope or altitude direction other "
              "than zero");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { slope { point_at y altitude y } } }"),
              "scene.pov:1:44: error: a slope with point_at takes no altitude");
}

TEST(PovTextures, FinishAndInterior) {
    const PovResult r = load_text(
        "sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { specular 0.6 roughness 0.01\n"
        "  phong 0.3 phong_size 80 brilliance 2 metallic reflection { 0.1, 0.8 fresnel\n"
        "  falloff 3 metallic } conserve_energy } interior { ior 1.33 fade_distance 2\n"
        "  fade_power 1 fade_color rgb <0, 0.5, 0> } }\n");
    EXPECT_TRUE(r.warnings.empty());
    const Material& m = shape_material(r);
    EXPECT_FLOAT_EQ(m.blinn, 0.6f);
    EXPECT_FLOAT_EQ(m.blinn_exponent, 100);
    EXPECT_FLOAT_EQ(m.specular, 0.3f);
    EXPECT_FLOAT_EQ(m.phong_exponent, 80);
    EXPECT_FLOAT_EQ(m.brilliance, 2);
    EXPECT_FLOAT_EQ(m.metallic, 1);
    EXPECT_FLOAT_EQ(m.mirror, 0.8f);
    EXPECT_FLOAT_EQ(m.mirror_min, 0.1f);
    EXPECT_TRUE(m.mirror_fresnel);
    EXPECT_TRUE(m.mirror_metallic);
    EXPECT_FLOAT_EQ(m.mirror_falloff, 3);
    EXPECT_TRUE(m.conserve_energy);
    EXPECT_FALSE(m.conserve_diffuse); // POV-Ray's: from what passes through only
    EXPECT_FALSE(m.fresnel_split);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.fade_distance, 2);
    EXPECT_FLOAT_EQ(m.fade_color.y, 0.5f);
    EXPECT_FLOAT_EQ(m.transmission, 0.9f); // filter, with a solid colour
}

TEST(PovTextures, IridescenceAndWhatInteriorsLeaveOut) {
    PovResult r = load_text("global_settings { irid_wavelength rgb <0.3, 0.2, 0.1> }\n"
                            "sphere { 0, 1 finish { irid { 0.4 thickness 0.5 turbulence 0.2 } } "
                            "interior { caustics 0 dispersion 1 dispersion_samples 7 } }\n"
                            "sphere { 0, 1 finish { irid { 0.25 } } }");
    EXPECT_TRUE(r.warnings.empty());
    const Material& m = shape_material(r);
    EXPECT_FLOAT_EQ(m.irid, 0.4f);
    EXPECT_FLOAT_EQ(m.irid_thickness, 0.5f);
    EXPECT_FLOAT_EQ(m.irid_turbulence, 0.2f);
    EXPECT_FLOAT_EQ(m.irid_wavelength.x, 0.3f);
    EXPECT_FLOAT_EQ(m.irid_wavelength.z, 0.1f);
    const Material& plain = r.scene.materials[r.scene.shape_objects[1].nodes[0].material];
    EXPECT_FLOAT_EQ(plain.irid, 0.25f);
    EXPECT_FLOAT_EQ(plain.irid_thickness, 0);
    // Without irid_wavelength, POV-Ray 3.7's own <0.70, 0.52, 0.48> (as povray renders).
    const PovResult d = load_text("sphere { 0, 1 finish { irid { 0.25 } } }");
    EXPECT_FLOAT_EQ(shape_material(d).irid_wavelength.x, 0.70f);
    EXPECT_FLOAT_EQ(shape_material(d).irid_wavelength.z, 0.48f);
    EXPECT_NO_THROW(r.scene.validate());
    EXPECT_FLOAT_EQ(m.caustics, 0);
    // Fake caustics are kept as POV-Ray keeps them (45 times the value written); dispersion
    // changes the picture, so Sheaf says it leaves it out.
    r = load_text("sphere { 0, 1 interior { caustics 0.5 dispersion 1.1 } }");
    EXPECT_FLOAT_EQ(shape_material(r).caustics, 22.5f);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:39: warning: unsupported interior dispersion "
                                 "(ignored)"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(test::error_of("sphere { 0, 1 finish { irid { 0.4 width 2 } } }"),
              "scene.pov:1:35: error: found 'width', expected thickness, turbulence or '}'");
    EXPECT_EQ(test::error_of("global_settings { irid_wavelength <0, 1, 1> }"),
              "scene.pov:1:35: error: irid_wavelength's components must be positive numbers");
}

TEST(PovTextures, SkySphereFogAndFlags) {
    const PovResult r = load_text(
        "sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb z] } } rotate x * 10 }\n"
        "fog { distance 30 color rgbt <0.5, 0.5, 0.5, 0.25> }\n"
        "sphere { 0, 1 no_shadow no_reflection }\nbox { 0, 1 no_image }\n");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_GE(r.scene.sky, 0);
    EXPECT_EQ(r.scene.pigments[size_t(r.scene.sky)].pattern.kind, PatternKind::Gradient);
    EXPECT_FLOAT_EQ(r.scene.fog.layer[0].distance, 30);
    EXPECT_FLOAT_EQ(r.scene.fog.layer[0].transmit, 0.25f);
    EXPECT_EQ(r.scene.shape_objects[0].flags & ~kSolid, kNoShadow | kNoReflection);
    EXPECT_EQ(r.scene.shape_objects[1].flags & ~kSolid, kNoImage);
}

TEST(PovTextures, SkyLayersAsTheirVersionWeighsThem) {
    // A red sky under a blue layer with filter 0.5, over a green background: POV-Ray 3.7
    // tints the red by the blue layer's transmitted colour (none of it gets through), 3.6
    // weighs it by the filter alone (half of it). The background shows under a clear sky.
    auto seen = [](const std::string& version, const std::string& sky) {
        const PovResult r = load_text(version + "background { rgb y }\nsky_sphere { " + sky + " }");
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
        const PreparedScene p = prepare_scene(r.scene);
        return sky_color(SceneView(p), Vec3(0, 0, 1));
    };
    const std::string layers = "pigment { rgb x } pigment { rgbf <0, 0, 1, 0.5> }";
    const Vec3 v37 = seen("#version 3.7;\n", layers), v36 = seen("#version 3.6;\n", layers);
    EXPECT_NEAR(v37.x, 0.0f, 1e-6f);
    EXPECT_NEAR(v37.z, 0.5f, 1e-6f);
    EXPECT_NEAR(v36.x, 0.5f, 1e-6f);
    EXPECT_NEAR(v36.z, 0.5f, 1e-6f);
    const Vec3 clear = seen("#version 3.7;\n", "pigment { rgbt <1, 0, 0, 1> }");
    EXPECT_NEAR(clear.y, 1.0f, 1e-6f);
    EXPECT_NEAR(clear.x, 0.0f, 1e-6f);
    const Vec3 half = seen("#version 3.7;\n", "pigment { rgbt <1, 0, 0, 0.5> }");
    EXPECT_NEAR(half.x, 0.5f, 1e-6f);
    EXPECT_NEAR(half.y, 0.5f, 1e-6f);
}

TEST(PovTextures, ImageMapsAreTextures) {
    test::TempDir d;
    const std::string png = write_tiles(d); // red, green / blue, white
    const std::string scene =
        d.write("scene.pov", "plane { z, 0 pigment { image_map { png \"tiles.png\" map_type 0 "
                             "interpolate 2 transmit all 0.25 } scale 2 } }\n");
    const PovResult r = load_pov_scene(scene);
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.textures.size(), 1u);
    EXPECT_EQ(r.scene.textures[0].path, png);
    EXPECT_EQ(r.scene.textures[0].mapping, TextureMapping::Planar);
    EXPECT_NE(r.scene.textures[0].origin.find("scene.pov:1:24"), std::string::npos);
    const Pigment& pg = r.scene.pigments[size_t(shape_material(r).pigment)];
    EXPECT_EQ(pg.pattern.kind, PatternKind::Image);
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[pg.first].color[4], 0.25f);
    // POV-Ray lets the name leave out its extension (image_map { "tiles" }).
    const std::string bare =
        d.write("bare.pov", "plane { z, 0 pigment { image_map { \"tiles\" } } }\n");
    const PovResult br = load_pov_scene(bare);
    ASSERT_EQ(br.scene.textures.size(), 1u);
    EXPECT_EQ(br.scene.textures[0].path, png);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png \"missing.png\" } } }")
                  .find("scene.pov:1:40: error: cannot find image file 'missing.png'"),
              std::string::npos);
    // Seen once: off the image the pigment is clear (as POV-Ray's), so shadows pass there.
    const std::string once =
        d.write("once.pov", "plane { z, 0 pigment { image_map { \"tiles\" once } } }\n");
    const PovResult orr = load_pov_scene(once);
    ASSERT_EQ(orr.scene.textures.size(), 1u);
    EXPECT_TRUE(orr.scene.textures[0].once);
    PreparedScene p = prepare_scene(orr.scene);
    io::attach_texture_sampler(p);
    EXPECT_TRUE(p.prim_flags[0] & kPrimMayPass);
    const SceneView v(p);
    const uint32_t pigment = uint32_t(shape_material(orr).pigment);
    const SurfaceColor in =
        evaluate_pigment(v, pigment, Vec3(0.25f, 0.75f, 0), 0, 0, Vec3(0, 0, 1));
    EXPECT_EQ(in.transmit, 0);
    EXPECT_GT(in.rgb.x, 0.9f); // red, top left
    const SurfaceColor off =
        evaluate_pigment(v, pigment, Vec3(1.25f, 0.75f, 0), 0, 0, Vec3(0, 0, 1));
    EXPECT_EQ(off.transmit, 1);
}

// image_pattern: the grey of the image (0.297 red + 0.589 green + 0.114 blue, its values as
// stored) is the pattern's value, mapped from pattern space, so transforms and warps move it.
TEST(PovTextures, ImagePatternIsTheImagesGrey) {
    test::TempDir d;
    const std::string png = write_tiles(d); // red, green / blue, white
    const PovResult r = load_pov_scene(
        d.write("scene.pov", "plane { z, 0 pigment { image_pattern { png \"tiles.png\" once }\n"
                             "  color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } translate <2, 0, 0> }\n"
                             "  normal { image_pattern { png \"tiles.png\" } 0.5 } }\n"));
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0);
    ASSERT_EQ(r.scene.textures.size(), 2u); // pigment and normal each map it once
    EXPECT_EQ(r.scene.textures[0].colorspace, "data");
    const Pigment& pg = r.scene.pigments[size_t(shape_material(r).pigment)];
    EXPECT_EQ(pg.pattern.kind, PatternKind::ImagePattern);
    EXPECT_EQ(r.scene.normal_patterns.at(0).pattern.kind, PatternKind::ImagePattern);
    PreparedScene p = prepare_scene(r.scene);
    io::attach_texture_sampler(p);
    const SceneView v(p);
    const uint32_t pigment = uint32_t(shape_material(r).pigment);
    auto red = [&](float x, float y) {
        return evaluate_pigment(v, pigment, Vec3(x, y, 0), 0, 0, Vec3(0, 0, -1)).rgb.x;
    };
    EXPECT_NEAR(red(2.25f, 0.75f), 0.297f, 0.01f); // red, top left (moved by the translate)
    EXPECT_NEAR(red(2.75f, 0.75f), 0.589f, 0.01f); // green
    EXPECT_NEAR(red(2.25f, 0.25f), 0.114f, 0.01f); // blue
    EXPECT_NEAR(red(2.75f, 0.25f), 1.0f, 0.01f);   // white
    EXPECT_NEAR(red(3.25f, 0.75f), 0.0f, 0.01f);   // off an image seen once: 0
    // Not in a function: programs run without the image.
    EXPECT_NE(load_text("#declare F = function { pattern { image_pattern { png \"" + png +
                        "\" } } }\nsphere { 0, 1 pigment { function { F(x, y, z) } } }\n")
                  .warnings.at(0)
                  .find("unsupported pigment pattern 'function'"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_pattern { png \"" + png + "\" tile } } }")
                  .find("expected an image_pattern item"),
              std::string::npos);
}

// An image_map is mapped from its pigment's pattern space, so warps and turbulence bend it
// as they bend any pattern (textures/pigments/warp1.pov).
TEST(PovTextures, WarpsBendImageMaps) {
    test::TempDir d;
    const std::string png = write_tiles(d); // red, green / blue, white
    const PovResult r = load_pov_scene(
        d.write("scene.pov",
                "plane { z, 0 pigment { image_map { png \"tiles.png\" } warp { repeat 0.5 * x }"
                " translate 1 * x } }\n"));
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0);
    PreparedScene p = prepare_scene(r.scene);
    io::attach_texture_sampler(p);
    const SceneView v(p);
    const uint32_t pigment = uint32_t(shape_material(r).pigment);
    auto at = [&](float x, float y) {
        return evaluate_pigment(v, pigment, Vec3(x, y, 0), 0, 0, Vec3(0, 0, -1)).rgb;
    };
    // The left half of the image repeats: red where green was, blue where white was.
    EXPECT_GT(at(1.75f, 0.75f).x, 0.9f);
    EXPECT_LT(at(1.75f, 0.75f).y, 0.1f);
    EXPECT_GT(at(1.75f, 0.25f).z, 0.9f);
    EXPECT_LT(at(1.75f, 0.25f).x, 0.1f);
    // A bump_map's image is not warped (warned).
    const PovResult bump = load_pov_scene(
        d.write("bump.pov", "plane { z, 0 normal { bump_map { png \"tiles.png\" } warp { repeat "
                            "0.5 * x } } }\n"));
    ASSERT_EQ(bump.warnings.size(), 1u);
    EXPECT_NE(bump.warnings[0].find("unsupported warp of a bump_map"), std::string::npos);
}

TEST(PovTextures, FacetsAreANormalPattern) {
    const PovResult r = load_text("sphere { 0, 1 normal { facets coords 0.4 } }\n"
                                  "sphere { 0, 1 normal { facets size 0.3 } }\n"
                                  "sphere { 0, 1 normal { facets } }\n");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.normal_patterns.size(), 3u);
    const Pattern& c = r.scene.normal_patterns[0].pattern;
    EXPECT_EQ(c.kind, PatternKind::Facets);
    EXPECT_FLOAT_EQ(c.param[0], 0.1f); // POV-Ray's default size
    EXPECT_FLOAT_EQ(c.param[1], 0.4f);
    EXPECT_FLOAT_EQ(r.scene.normal_patterns[1].pattern.param[0], 0.3f);
    EXPECT_FLOAT_EQ(r.scene.normal_patterns[1].pattern.param[1], 0);
    EXPECT_EQ(error_of("sphere { 0, 1 normal { facets size 0 } }"),
              "scene.pov:1:31: error: a facets size must be above 0");
    for (const std::string& elsewhere : {"sphere { 0, 1 pigment { facets } }",
                                         "sphere { 0, 1 texture { facets texture_map { "
                                         "[0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }"})
        EXPECT_NE(error_of(elsewhere).find(":1:25: error: facets is a normal pattern"),
                  std::string::npos)
            << error_of(elsewhere);
}

// map_type 1, 2 and 5 read the image where POV-Ray does: u is the longitude from +x turning
// toward +z (a cylinder seen from -z shows the image's right half, not mirrored), v the
// latitude, the height, or the angle around the torus's unit ring (3/4 on its top).
TEST(PovTextures, ImageMapTypesReadPovRaysLongitude) {
    test::TempDir d;
    const float px[] = {0, 1, 1, 0};
    write_image(d, "grey.png", 2, 2, 1, px);
    struct Case {
        int map_type;
        TextureMapping mapping;
        Vec3 p;
        float u, v;
    };
    for (const Case& c : {Case{2, TextureMapping::Cylindrical, {0, 0.3f, -1}, 0.75f, 0.3f},
                          Case{2, TextureMapping::Cylindrical, {0, 0.6f, 2}, 0.25f, 0.6f},
                          Case{2, TextureMapping::Cylindrical, {-1, 0, 0}, 0.5f, 0},
                          Case{1, TextureMapping::Spherical, {0, 0, -1}, 0.75f, 0.5f},
                          Case{1, TextureMapping::Spherical, {1, 1, 0}, 0, 0.75f},
                          Case{5, TextureMapping::Torus, {0, 0, -2}, 0.75f, 0.5f},
                          Case{5, TextureMapping::Torus, {1, 0.5f, 0}, 0, 0.75f},
                          Case{5, TextureMapping::Torus, {0, -0.5f, 1}, 0.25f, 0.25f}}) {
        const std::string scene =
            d.write("scene.pov", "sphere { 0, 1 pigment { image_map { png \"grey.png\" map_type " +
                                     std::to_string(c.map_type) + " } } }\n");
        const PovResult r = load_pov_scene(scene);
        SCOPED_TRACE(c.map_type);
        EXPECT_TRUE(r.warnings.empty());
        ASSERT_EQ(r.scene.textures.size(), 1u);
        EXPECT_EQ(r.scene.textures[0].mapping, c.mapping);
        float s = 0, t = 0;
        // c.p is POV-Ray's point; Sheaf's world is POV-Ray's mirrored in z. The image is
        // mapped from the pigment's pattern space.
        const Pattern& pt = r.scene.pigments[size_t(shape_material(r).pigment)].pattern;
        const Vec3 q = pattern_point(pt, Vec3(c.p.x, c.p.y, -c.p.z), r.scene.warps.data());
        texture_coordinates(r.scene.textures[0], q, 0, 0, s, t);
        EXPECT_NEAR(s - std::floor(s), c.u, 1e-5f) << c.p.x << ' ' << c.p.y << ' ' << c.p.z;
        EXPECT_NEAR(t, c.v, 1e-5f) << c.p.x << ' ' << c.p.y << ' ' << c.p.z;
    }
    // The parabolic and hyperbolic mappings POV-Ray never implemented: warned, planar.
    const PovResult para = load_pov_scene(d.write(
        "para.pov", "sphere { 0, 1 pigment { image_map { png \"grey.png\" map_type 3 } } }\n"));
    ASSERT_EQ(para.warnings.size(), 1u);
    EXPECT_NE(para.warnings[0].find("para.pov:1:52: warning: unsupported image map_type 3"),
              std::string::npos)
        << para.warnings[0];
    EXPECT_EQ(para.scene.textures.at(0).mapping, TextureMapping::Planar);
}

// uv_mapping: the pattern reads the mesh's (u, v, 0), placed by the transforms at and inside
// the level that says uv_mapping (texture, pigment or object); the object's transforms, and
// a texture's around a uv-mapped pigment, do not move it (as povray renders them).
TEST(PovTextures, UvMappingReadsTheSurfacesUvCoordinates) {
    const std::string quad =
        "#declare Q = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
        "  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } face_indices { 2, <0,1,2>, <0,2,3> } }\n"
        "#declare G = pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }\n";
    // u = 0.25 is pattern point 0.5 in each: the scale 0.5 counts, the 3 and the 4 do not.
    for (const std::string& object :
         {"object { Q texture { uv_mapping pigment { G } scale 0.5 } scale 3 translate 5 }",
          "object { Q texture { pigment { G uv_mapping scale 0.5 } scale 4 } rotate 30*y }",
          "object { Q uv_mapping texture { pigment { G } scale 0.5 } scale 3 }",
          "object { Q texture { pigment { G } scale 0.5 } uv_mapping scale 3 }"}) {
        SCOPED_TRACE(object);
        const PovResult r = load_text(quad + object + "\n");
        EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
        ASSERT_EQ(r.scene.objects.size(), 1u);
        const Material& m = r.scene.materials[r.scene.objects[0].material];
        ASSERT_GE(m.pigment, 0);
        const Pattern& pt = r.scene.pigments[size_t(m.pigment)].pattern;
        EXPECT_TRUE(pt.uv);
        EXPECT_NEAR(pt.to_pattern.point(Vec3(0.25f, 0.5f, 0)).x, 0.5f, 1e-5);
        const PreparedScene p = prepare_scene(r.scene);
        EXPECT_NEAR(evaluate_pigment(p, uint32_t(m.pigment), Vec3(9), 0.25f, 0.5f).rgb.x, 0.5f,
                    1e-5);
    }
    // Without it, the object's transforms move the pattern as usual.
    const PovResult space = load_text(quad + "object { Q pigment { G } scale 4 }\n");
    const Material& sm = space.scene.materials[space.scene.objects[0].material];
    EXPECT_FALSE(space.scene.pigments[size_t(sm.pigment)].pattern.uv);
    // The mesh's uv coordinates reach the prepared triangles.
    const PovResult r = load_text(quad + "object { Q uv_mapping pigment { G } }\n");
    const PreparedScene p = prepare_scene(r.scene);
    ASSERT_EQ(p.uvs.size(), 2u);
    EXPECT_FLOAT_EQ(p.uvs[0].s[1], 1.0f);

    // Analytic shapes carry no uv coordinates, and normals are evaluated in space: warned.
    const PovResult sphere = load_text("sphere { 0, 1 uv_mapping pigment { checker } }\n");
    ASSERT_EQ(sphere.warnings.size(), 1u);
    EXPECT_NE(sphere.warnings[0].find("uv_mapping on sphere"), std::string::npos);
    const PovResult normal =
        load_text(quad + "object { Q texture { uv_mapping normal { bumps 0.5 } } }\n");
    ASSERT_EQ(normal.warnings.size(), 1u);
    EXPECT_NE(normal.warnings[0].find("uv_mapping of the texture's normal"), std::string::npos);
}

// POV-Ray's bump_map: the grey levels (as stored, 0..1) at the point and one pixel down-left and
// down-right of it are heights times bump_size; the normal leans as the plane through them, in
// POV-Ray's frame. On a ramp rising one level per pixel along x, 16 pixels wide, the heights
// differ by 2 a / 15 across two pixels: the normal (POV-Ray's world) is (2 a / 15, 0, 2)
// normalised, facing +z, leaning towards +x as POV-Ray's does. With `once`, nothing
// changes off the image; without, it repeats.
TEST(PovTextures, BumpMapsTiltTheNormalByTheImage) {
    test::TempDir d;
    const std::string png = d.path() + "/ramp.png";
    constexpr int kW = 16, kH = 4;
    std::vector<float> px;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) px.push_back(float(x) / (kW - 1));
    write_image(d, "ramp.png", kW, kH, 1, px.data(), OIIO::TypeDesc::UINT16);
    const std::string scene = d.write(
        "scene.pov", "plane { z, 0 normal { bump_map { png \"ramp.png\" bump_size 2 } } }\n"
                     "plane { z, 0 normal { bump_map { \"ramp\" once interpolate 2 } } }\n");
    const PovResult r = load_pov_scene(scene);
    ASSERT_TRUE(r.warnings.empty()) << r.warnings[0];
    ASSERT_EQ(r.scene.textures.size(), 2u);
    EXPECT_EQ(r.scene.textures[0].colorspace, "data");
    EXPECT_TRUE(r.scene.textures[1].once);
    PreparedScene p = prepare_scene(r.scene);
    io::attach_texture_sampler(p);
    const SceneView v(p);
    const uint32_t steep = uint32_t(shape_material(r, 0).normal);
    const uint32_t once = uint32_t(shape_material(r, 1).normal);
    EXPECT_FLOAT_EQ(p.normal_patterns[steep].amount, 2);
    EXPECT_FLOAT_EQ(p.normal_patterns[once].amount, 0.5f); // POV-Ray's default
    const Vec3 up(0, 0, -1);                               // POV-Ray's +z in Sheaf's world
    // At pixel (7, 1)'s centre: s = 7.5 / 16, t = 2.5 / 4 (t runs up the image).
    const Vec3 at(7.5f / kW, 2.5f / kH, 0);
    const Vec3 n = perturb_normal(v, steep, at, up);
    const Vec3 want = normalize(Vec3(4.0f / 15, 0, -2)); // POV-Ray's (4/15, 0, 2), z mirrored
    EXPECT_NEAR(n.x, want.x, 1e-3f);
    EXPECT_NEAR(n.y, want.y, 1e-3f);
    EXPECT_NEAR(n.z, want.z, 1e-3f);
    EXPECT_NEAR(perturb_normal(v, steep, at + Vec3(2, 0, 0), up).x, want.x, 1e-3f); // repeats
    EXPECT_GT(perturb_normal(v, once, at, up).x, 0.01f);
    const Vec3 off = perturb_normal(v, once, at + Vec3(2, 0, 0), up);
    EXPECT_EQ(off.x, 0);
    EXPECT_EQ(off.z, -1);
    // use_index reads the grey level, not the palette index: said once.
    EXPECT_NE(error_of("plane { z, 0 normal { bump_map { png \"missing.png\" } } }")
                  .find("error: cannot find image file 'missing.png'"),
              std::string::npos);
    const std::string indexed =
        d.write("index.pov", "plane { z, 0 normal { bump_map { \"ramp\" use_index } } }\n");
    const PovResult ri = load_pov_scene(indexed);
    ASSERT_EQ(ri.warnings.size(), 1u);
    EXPECT_NE(ri.warnings[0].find("index.pov:1:41: warning: unsupported bump_map use_index"),
              std::string::npos)
        << ri.warnings[0];
}

// Function patterns run on the scene: the pigment and pattern functions they call read any
// pigment and pattern (pigment maps, pigment_pattern, warps), as the render evaluates them.
TEST(PovTextures, FunctionPatternsReadAnyPigmentOrPattern) {
    const std::string f = "#declare F = function { pigment { gradient x pigment_map { [0 rgb 0] "
                          "[1 gradient y color_map { [0 rgb 0] [1 rgb 1] }] } } }\n";
    const PovResult r = load_text(
        f +
        "#declare P = function { pattern { pigment_pattern { gradient x color_map { [0 rgb 1] "
        "[1 rgb 0] } } } }\n"
        "#declare W = function { pattern { gradient x warp { repeat 0.5 * x } } }\n"
        "plane { z, 0 pigment { function { F(x, y, z).gray } color_map { [0 rgb 0] [1 rgb 1] } "
        "} }\n"
        "plane { z, 0 pigment { function { P(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
        "plane { z, 0 pigment { function { W(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_NO_THROW(r.scene.validate());
    const PreparedScene p = prepare_scene(r.scene);
    const SceneView v(p);
    auto at = [&](size_t shape, float x, float y) {
        const uint32_t pg = uint32_t(shape_material(r, shape).pigment);
        return evaluate_pigment(v, pg, Vec3(x, y, 0), 0, 0).rgb.x;
    };
    EXPECT_NEAR(at(0, 0.5f, 0.25f), 0.5f * 0.25f, 1e-4); // x * y
    EXPECT_NEAR(at(0, 0.75f, 0.5f), 0.75f * 0.5f, 1e-4);
    EXPECT_NEAR(at(1, 0.25f, 0), 0.75f, 1e-4); // 1 - x
    EXPECT_NEAR(at(2, 0.75f, 0), 0.25f, 1e-4); // 0.75 repeats 0.25
    // Each function that reads a scene pigment is a level of the device's recursion, which
    // its stack holds (core/backend/device_stack.h): one here, two when a pigment function's
    // pigment is itself a function pattern of F.
    EXPECT_EQ(fn_pigment_nesting(p), 1);
    const PovResult nested = load_text(
        f + "#declare G = function { pigment { function { F(x, y, z).gray } color_map { [0 rgb 0] "
            "[1 rgb 1] } } }\n"
            "plane { z, 0 pigment { function { G(x, y, z).red } color_map { [0 rgb 0] [1 rgb 1] } "
            "} }\n");
    const PreparedScene pn = prepare_scene(nested.scene);
    EXPECT_EQ(fn_pigment_nesting(pn), 2);
    EXPECT_EQ(device_stack_bytes(pn), kDeviceStackBase + 2 * kDeviceStackPerFnLevel);
    EXPECT_EQ(fn_pigment_nesting(prepare_scene(load_text("sphere { 0, 1 pigment { function "
                                                         "{ x } } }")
                                                   .scene)),
              0);
    // An isosurface runs programs without the scene: one that reads a pigment map is warned.
    const PovResult iso = load_text(f + "isosurface { function { F(x, y, z).gray - 0.2 } }\n");
    ASSERT_EQ(iso.warnings.size(), 1u);
    EXPECT_NE(
        iso.warnings[0].find("unsupported isosurface of a pigment function (of a pigment map)"),
        std::string::npos)
        << iso.warnings[0];
}

TEST(PovTextures, UnsupportedPatternsWarn) {
    const PovResult r = load_text("sphere { 0, 1 pigment { function { pattern { tiling 3 } } "
                                  "color_map { [0 rgb 0] [1 rgb 1] } } }\n");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("unsupported pigment pattern 'function'"), std::string::npos);
    EXPECT_FLOAT_EQ(shape_material(r, 0).color.x, 0.5f); // the map's average
}

// POV-Ray evaluates a pigment map's entries at the point its pattern's warps and classic
// turbulence moved; marble and wood keep their turbulence to themselves.
TEST(PovTextures, MapEntriesInheritClassicTurbulence) {
    for (const char* kind : {"bozo", "marble"}) {
        const PovResult r = load_text(std::string("plane { y, 0 pigment { ") + kind +
                                      " turbulence 0.5 octaves 3 pigment_map { [0 checker rgb 0 "
                                      "rgb 1] [1 rgb 1] } } }\n");
        EXPECT_TRUE(r.warnings.empty());
        const Pigment& outer = r.scene.pigments[size_t(shape_material(r).pigment)];
        ASSERT_EQ(outer.count, 2u);
        const Pattern& entry =
            r.scene.pigments[size_t(r.scene.pigment_entries[outer.first].pigment)].pattern;
        const Vec3 world(0.4f, 0.1f, -0.3f);
        const Vec3 moved = pattern_point(outer.pattern, world, r.scene.warps.data());
        const Vec3 at = pattern_point(entry, world, r.scene.warps.data());
        if (std::string(kind) == "bozo") {
            ASSERT_EQ(entry.warp_count, 1u);
            EXPECT_EQ(r.scene.warps[entry.warp_first].kind, WarpKind::Turbulence);
            EXPECT_EQ(r.scene.warps[entry.warp_first].octaves, 3);
            EXPECT_NEAR(length(at - moved), 0.0f, 1e-5f); // the checker sees the bozo's point
        } else { // marble bends its band by the turbulence; no point moves
            EXPECT_EQ(entry.warp_count, 0u);
            EXPECT_EQ(at, moved);
            EXPECT_EQ(moved, outer.pattern.to_pattern.point(world));
            EXPECT_GT(std::fabs(pattern_detail::raw_value(outer.pattern, moved) - moved.x), 1e-3);
        }
    }
}

TEST(PovTextures, WarpsChainWithTheTransformsAroundThem) {
    // POV-Ray's order: the translate after the warp is undone first, then the repeat folds x,
    // then the scale before it is undone.
    const PovResult r =
        load_text("plane { y, 0 pigment { gradient x scale 2 warp { repeat x*0.5 offset y } "
                  "translate <1, 0, 0> } }\n");
    EXPECT_TRUE(r.warnings.empty());
    const Pattern& pt = r.scene.pigments[size_t(shape_material(r).pigment)].pattern;
    ASSERT_EQ(pt.warp_count, 1u);
    ASSERT_EQ(r.scene.warps.size(), 1u);
    EXPECT_EQ(r.scene.warps[0].kind, WarpKind::Repeat);
    const Vec3 q = pattern_point(pt, Vec3(1.75f, 0, 0), r.scene.warps.data());
    EXPECT_NEAR(q.x, 0.125f, 1e-5);
    EXPECT_NEAR(q.y, 0.5f, 1e-5);
    EXPECT_NO_THROW(r.scene.validate());
    // The other warps are read with their options.
    const PovResult all = load_text(
        "plane { y, 0 pigment { bozo warp { planar z, 0.5 } warp { cylindrical orientation y "
        "dist_exp 1 } warp { spherical } warp { toroidal major_radius 2 } warp { cubic } "
        "warp { turbulence 0.5 octaves 3 lambda 3 } } }\n");
    EXPECT_TRUE(all.warnings.empty());
    ASSERT_EQ(all.scene.warps.size(), 6u);
    EXPECT_EQ(all.scene.warps[0].kind, WarpKind::Turbulence); // the last declared first
    EXPECT_EQ(all.scene.warps[0].octaves, 3);
    EXPECT_FLOAT_EQ(all.scene.warps[0].f[1], 3.0f);
    EXPECT_FLOAT_EQ(all.scene.warps[2].f[1], 2.0f);
    EXPECT_EQ(all.scene.warps[4].b.y, 1.0f);
    EXPECT_FLOAT_EQ(all.scene.warps[5].f[0], 0.5f);
    EXPECT_NE(error_of("plane { y, 0 pigment { bozo warp { repeat <1, 1, 0> } } }")
                  .find("1:43: error: a repeat warp repeats along one axis only"),
              std::string::npos);
    EXPECT_NE(error_of("plane { y, 0 pigment { bozo warp { repeat 0 } } }")
                  .find("error: a repeat warp needs an axis"),
              std::string::npos);
    EXPECT_NE(error_of("plane { y, 0 pigment { bozo warp { cylindrical orientation 0 } } }")
                  .find("error: a warp's orientation must not be zero"),
              std::string::npos);
    EXPECT_NE(error_of("plane { y, 0 pigment { bozo warp { } } }").find("expected a warp"),
              std::string::npos);
    // A repeated black hole: POV-Ray moves its centre a radius in from the block's edge and
    // widens the blocks to hold it with its jitter.
    const PovResult hole = load_text(
        "plane { y, 0 pigment { bozo warp { black_hole 0, 0.5 falloff 3 strength 0.75 inverse "
        "repeat <2, 1.5, 0> turbulence <1, 0.5, 0> } } }\n");
    EXPECT_TRUE(hole.warnings.empty());
    ASSERT_EQ(hole.scene.warps.size(), 1u);
    const Warp& bh = hole.scene.warps[0];
    EXPECT_EQ(bh.kind, WarpKind::BlackHole);
    EXPECT_EQ(bh.axis, 1); // inverse
    EXPECT_FLOAT_EQ(bh.a.x, 0.5f);
    EXPECT_FLOAT_EQ(bh.b.x, 2.0f);
    EXPECT_FLOAT_EQ(bh.b.y, 1.5f);
    EXPECT_FLOAT_EQ(bh.f[1], 3.0f);
    EXPECT_NO_THROW(hole.scene.validate());
    EXPECT_NE(error_of("plane { y, 0 pigment { bozo warp { black_hole 0, 0 } } }")
                  .find("error: a black hole's radius must be above 0"),
              std::string::npos);
}

// pigment_pattern: the grey of a pigment placed in the pattern's space is the value, for
// pigments and normals alike.
TEST(PovTextures, PigmentPatternsUseAPigmentsGrey) {
    const PovResult r = load_text(
        "plane { y, 0 pigment { pigment_pattern { checker rgb 0, rgb 1 scale 2 } color_map {\n"
        "  [0 rgb x] [1 rgb y] } scale 0.5 } }\n"
        "plane { y, 0 normal { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } "
        "} 1 } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_NO_THROW(r.scene.validate());
    const PreparedScene p = prepare_scene(r.scene);
    const SceneView v(p);
    const uint32_t pg = uint32_t(shape_material(r, 0).pigment);
    ASSERT_EQ(r.scene.pigments[pg].pattern.kind, PatternKind::PigmentPattern);
    // Sheaf (0.5, 0, 0.5) is POV-Ray's (0.5, 0, -0.5): the checker of scale 2 inside the
    // pigment's scale 0.5 has its cell (0, 0, -1) there, white; (1.5, 0, 0.5) is black.
    const SurfaceColor white = evaluate_pigment(v, pg, Vec3(0.5f, 0, 0.5f), 0, 0);
    const SurfaceColor black = evaluate_pigment(v, pg, Vec3(1.5f, 0, 0.5f), 0, 0);
    EXPECT_NEAR(white.rgb.y, 1.0f, 1e-5);
    EXPECT_NEAR(white.rgb.x, 0.0f, 1e-5);
    EXPECT_NEAR(black.rgb.x, 1.0f, 1e-5);
    // A gradient x ramp's grey tilts the normal along x, by POV-Ray's slope normal's 2/15 of
    // the bump size (1 here) per unit of slope.
    const uint32_t normal = uint32_t(shape_material(r, 1).normal);
    const Vec3 n = perturb_normal(v, normal, Vec3(0.3f, 0, 0), Vec3(0, 1, 0));
    const float k = 2.0f / 15.0f;
    EXPECT_NEAR(n.x, -k / std::sqrt(1 + k * k), 1e-3);
    // A warped pigment inside: its entries follow its chain in the pattern's own space (POV-Ray
    // z, no mirror): at POV-Ray's (0.8, 0.5, 0.25) the checker's first entry, gradient z, is
    // 0.25.
    const PovResult w = load_text(
        "plane { y, 0 pigment { pigment_pattern { checker pigment { gradient z color_map { "
        "[0 rgb 0] [1 rgb 1] } }, rgb 0 warp { repeat x*0.5 } } color_map { [0 rgb 0] "
        "[1 rgb 1] } } }\n");
    EXPECT_TRUE(w.warnings.empty()) << w.warnings.front();
    const PreparedScene wp = prepare_scene(w.scene);
    const SurfaceColor c = evaluate_pigment(SceneView(wp), uint32_t(shape_material(w).pigment),
                                            Vec3(0.8f, 0.5f, -0.25f), 0, 0);
    EXPECT_NEAR(c.rgb.x, 0.25f, 1e-4);
    EXPECT_NEAR(n.z, 0.0f, 1e-4);
}

TEST(PovTextures, SlopeMaps) {
    const PovResult r = load_text(
        "#declare SM = slope_map { [1 <0, -1>] [0, <1, 1>] [0.5 0.25] }\n"
        "sphere { 0, 1 normal { gradient x slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] "
        "[1 <0, -1>] } } }\n"
        "sphere { 0, 1 normal { wood 0.3 slope_map { SM } } }\n"
        "sphere { 0, 1 normal { bumps 0.4 slope_map { SM } } }\n");
    ASSERT_TRUE(r.warnings.empty()) << r.warnings[0];
    const Scene& s = r.scene;
    const auto entries = [&](size_t i) {
        const NormalPattern& np = s.normal_patterns[size_t(shape_material(r, i).normal)];
        return std::vector<SlopeEntry>(s.slope_entries.begin() + np.slope_first,
                                       s.slope_entries.begin() + np.slope_first + np.slope_count);
    };
    // In the order given, equal values kept in their order.
    const auto tri = entries(0);
    ASSERT_EQ(tri.size(), 4u);
    EXPECT_FLOAT_EQ(tri[1].slope, 1.0f);
    EXPECT_FLOAT_EQ(tri[2].slope, -1.0f);
    // A declared map, sorted by value; a float promotes to <f, f>.
    const auto sm = entries(1);
    ASSERT_EQ(sm.size(), 3u);
    EXPECT_FLOAT_EQ(sm[0].height, 1.0f);
    EXPECT_FLOAT_EQ(sm[1].value, 0.5f);
    EXPECT_FLOAT_EQ(sm[1].height, 0.25f);
    EXPECT_FLOAT_EQ(sm[1].slope, 0.25f);
    EXPECT_FLOAT_EQ(sm[2].slope, -1.0f);
    // POV-Ray's bumps have a normal of their own that takes no slope map.
    EXPECT_TRUE(entries(2).empty());
    EXPECT_EQ(error_of("sphere { 0, 1 normal { wood slope_map { [0 <0, 1> } } }"),
              "scene.pov:1:51: error: found '}', expected ']'");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { wood slope_map { [0 \"up\"] } } }"),
              "scene.pov:1:44: error: found '\"up\"', expected <height, slope>");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { wood slope_map { } } }"),
              "scene.pov:1:39: error: an empty slope map");
}

TEST(PovTextures, NormalMapsListsAndAverages) {
    const PovResult r =
        load_text("#default { normal { bump_size 1.5 } }\n"
                  "#declare NM = normal_map { [0.7 gradient y] [0.3 marble turbulence 0.5] }\n"
                  "sphere { 0, 1 normal { gradient x normal_map { NM } scale 2 } }\n"
                  "sphere { 0, 1 normal { checker normal { bumps 0.4 } } }\n"
                  "sphere { 0, 1 normal { average normal_map { [gradient x, -5 scallop_wave] "
                  "[3 gradient y, 5] } } }\n");
    ASSERT_TRUE(r.warnings.empty()) << r.warnings[0];
    const Scene& s = r.scene;
    const auto map = [&](size_t i) {
        const NormalPattern& np = s.normal_patterns[size_t(shape_material(r, i).normal)];
        return std::make_pair(np, std::vector<NormalMapEntry>(
                                      s.normal_map_entries.begin() + np.map_first,
                                      s.normal_map_entries.begin() + np.map_first + np.map_count));
    };
    // A declared map, sorted by value; its entries start from #default's bump size and move
    // with the normal's transforms.
    const auto [blend, be] = map(0);
    ASSERT_EQ(be.size(), 2u);
    EXPECT_FLOAT_EQ(be[0].value, 0.3f);
    const NormalPattern& marble = s.normal_patterns[size_t(be[0].normal)];
    EXPECT_EQ(marble.pattern.kind, PatternKind::Marble);
    EXPECT_FLOAT_EQ(marble.amount, 1.5f); // the bump size
    EXPECT_EQ(marble.map_count, 0u);
    EXPECT_NEAR(marble.pattern.to_pattern.point(Vec3(2, 0, 0)).x, 1.0f, 1e-6);
    EXPECT_FALSE(blend.average);
    // A list pattern's normals in order; those not given leave the surface's normal.
    const auto [list, le] = map(1);
    EXPECT_EQ(list.pattern.kind, PatternKind::Checker);
    ASSERT_EQ(le.size(), 2u);
    EXPECT_EQ(s.normal_patterns[size_t(le[0].normal)].pattern.kind, PatternKind::Bozo);
    EXPECT_EQ(s.normal_patterns[size_t(le[0].normal)].form, NormalForm::Bumps);
    EXPECT_EQ(le[1].normal, -1);
    // An average: weights in the order given, 1 where left out.
    const auto [avg, ae] = map(2);
    EXPECT_TRUE(avg.average);
    ASSERT_EQ(ae.size(), 2u);
    EXPECT_FLOAT_EQ(ae[0].value, 1.0f);
    EXPECT_FLOAT_EQ(ae[1].value, 3.0f);
    EXPECT_FLOAT_EQ(s.normal_patterns[size_t(ae[0].normal)].amount, -5.0f);
    EXPECT_EQ(s.normal_patterns[size_t(ae[0].normal)].pattern.wave, Wave::Scallop);

    // A map inside a map is warned and left out.
    const PovResult nested = load_text(
        "sphere { 0, 1 normal { bozo normal_map { [0 gradient x normal_map { [0 bumps] } ] "
        "[1 dents] } } }\n");
    ASSERT_EQ(nested.warnings.size(), 1u);
    EXPECT_NE(nested.warnings[0].find("a normal map inside a normal map"), std::string::npos);
    EXPECT_EQ(error_of("sphere { 0, 1 normal { bozo normal_map { } } }"),
              "scene.pov:1:29: error: an empty normal map");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { bozo normal_map { [bumps] } } }"),
              "scene.pov:1:43: error: found 'bumps', expected the entry's value (a float)");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { checker normal { bumps } normal { dents } "
                       "normal { wrinkles } } }"),
              "scene.pov:1:66: error: a list pattern of 2 entries takes 2 normals");
}

TEST(PovTextures, InteriorTexturesShowFromInside) {
    const PovResult r = load_text(
        "sphere { 0, 1 pigment { rgb x } interior_texture { pigment { rgb z } finish { "
        "ambient 1 } } }\n"
        "intersection { sphere { 0, 1 } sphere { x, 1 pigment { rgb y } } pigment { rgb x }\n"
        "  interior_texture { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } } scale 2 }\n"
        "sphere { 0, 1 pigment { rgb x } }\n");
    ASSERT_TRUE(r.warnings.empty()) << r.warnings[0];
    const Scene& s = r.scene;
    const Material& ball = shape_material(r, 0);
    ASSERT_GE(ball.inside, 0);
    const Material& in = s.materials[size_t(ball.inside)];
    EXPECT_FLOAT_EQ(ball.color.x, 1.0f);
    EXPECT_FLOAT_EQ(in.color.z, 1.0f);
    EXPECT_FLOAT_EQ(in.ambient, 1.0f);
    EXPECT_EQ(in.inside, -1);
    // Every part of a CSG takes it, whatever its own texture; it moves with the object.
    const ShapeObject& cut = s.shape_objects[1];
    ASSERT_EQ(cut.nodes.size(), 3u);
    const Material& a = s.materials[cut.nodes[1].material];
    const Material& b = s.materials[cut.nodes[2].material];
    ASSERT_GE(a.inside, 0);
    ASSERT_GE(b.inside, 0);
    EXPECT_GE(s.materials[size_t(b.inside)].pigment, 0);
    EXPECT_FLOAT_EQ(b.color.y, 1.0f);
    const Material& patterned = s.materials[size_t(a.inside)];
    ASSERT_GE(patterned.pigment, 0);
    EXPECT_NEAR(s.pigments[size_t(patterned.pigment)].pattern.to_pattern.point(Vec3(2, 0, 0)).x,
                1.0f, 1e-6);
    // Objects without one see their own texture from inside.
    EXPECT_EQ(shape_material(r, 2).inside, -1);
    EXPECT_EQ(error_of("sphere { 0, 1 interior_texture { rgb 1 } }"),
              "scene.pov:1:34: error: found 'rgb', expected a texture item (pigment, normal, "
              "finish, a pattern ...)");
}

TEST(PovTextures, ACameraNormalTiltsThePrimaryRays) {
    const PovResult r = load_text(
        "camera { location <0, 0, -5> look_at 0 normal { crackle 0.1 scale 0.2 } rotate y * 30 }\n"
        "sphere { 0, 1 }\n");
    ASSERT_TRUE(r.warnings.empty()) << r.warnings[0];
    ASSERT_GE(r.scene.camera.normal, 0);
    const NormalPattern& n = r.scene.normal_patterns[size_t(r.scene.camera.normal)];
    EXPECT_EQ(n.pattern.kind, PatternKind::Crackle);
    EXPECT_FLOAT_EQ(n.amount, 0.1f); // the bump size
    // Screen space: scaled by its own transforms, not turned with the camera.
    EXPECT_NEAR(n.pattern.to_pattern.point(Vec3(0.2f, 0, 0)).x, 1.0f, 1e-5);
    // Its gradient is a world vector in POV-Ray's world, whose z is Sheaf's -z.
    EXPECT_NEAR(n.pattern.to_pattern.point(Vec3(0, 0, 0.2f)).z, -1.0f, 1e-5);
}

TEST(PovTextures, DeclaredTexturesPigmentsNormalsAndMaps) {
    const PovResult r =
        load_text("#declare P = pigment { granite color_map { [0 rgb 0] [1 rgb 1] } }\n"
                  "#declare N = normal { ripples 0.7 }\n"
                  "#declare F = finish { phong 0.9 }\n"
                  "#declare CM = color_map { [0 rgb x] [1 rgb y] }\n"
                  "#declare T = texture { pigment { P scale 2 } normal { N } finish { F } }\n"
                  "#declare L = texture { T } texture { pigment { rgbt 1 } }\n"
                  "#declare M = material { texture { T } interior { ior 1.2 } }\n"
                  "sphere { 0, 1 texture { T } }\n"
                  "sphere { 0, 1 texture { L } }\n"
                  "sphere { 0, 1 material { M } }\n"
                  "sphere { 0, 1 pigment { onion color_map { CM } } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Material& t = shape_material(r, 0);
    EXPECT_EQ(r.scene.pigments[size_t(t.pigment)].pattern.kind, PatternKind::Granite);
    EXPECT_EQ(r.scene.normal_patterns[size_t(t.normal)].pattern.kind, PatternKind::Ripples);
    EXPECT_FLOAT_EQ(t.specular, 0.9f);
    EXPECT_TRUE(r.scene.pigments[size_t(shape_material(r, 1).pigment)].layers);
    EXPECT_FLOAT_EQ(shape_material(r, 2).ior, 1.2f);
    const Pigment& onion = r.scene.pigments[size_t(shape_material(r, 3).pigment)];
    EXPECT_FLOAT_EQ(r.scene.pigment_entries[onion.first + 1].color[1], 1);
}

TEST(PovTextures, NormalsComeFromArraysAndMayBeDeclaredFlat) {
    // The portfolio's allnormals.pov: normal { normalArr[i] }, of normals whose pattern Sheaf
    // does not have (declared flat, warned where used).
    const PovResult r = load_text("#declare Flat = normal { tiling 3 1 }\n"
                                  "#declare N = normal { ripples 0.7 }\n"
                                  "#declare A = array[2] { Flat, N }\n"
                                  "#declare B = array[2] { N, N }\n"
                                  "sphere { 0, 1 pigment { rgb 1 } normal { B[1] } }\n"
                                  "sphere { 0, 1 pigment { rgb 1 } normal { A[0] } }\n"
                                  "sphere { 0, 1 pigment { rgb 1 } normal { A[1] } }\n"
                                  "#declare C = array[2] { N, Flat }\n" // a flat one after a normal
                                  "sphere { 0, 1 pigment { rgb 1 } normal { C[1] } }\n");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:"), std::string::npos) << r.warnings[0];
    EXPECT_EQ(r.scene.normal_patterns[size_t(shape_material(r, 0).normal)].pattern.kind,
              PatternKind::Ripples);
    EXPECT_LT(shape_material(r, 1).normal, 0);
    EXPECT_EQ(r.scene.normal_patterns[size_t(shape_material(r, 2).normal)].pattern.kind,
              PatternKind::Ripples);
    EXPECT_LT(shape_material(r, 3).normal, 0);
    EXPECT_NE(test::error_of("#declare C = array[1] { 3 }\nsphere { 0, 1 normal { C[0] } }")
                  .find("scene.pov:2:24: error: found 'C', expected a normal, not a float"),
              std::string::npos);
}

} // namespace
} // namespace sheaf::io::pov

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

TEST(PovMedia, InteriorMediaTheirDensitiesAndDeclarations) {
    const PovResult r = load_text(R"(
#declare D = density { spherical density_map { [0 rgb 0] [1 rgb <1, 0.5, 0.2>] } }
#declare M = media { emission 0.1 absorption <0.2, 0.3, 0.4> }
sphere { 0, 1 pigment { rgbf 1 } hollow
  interior { media { M density { D scale 2 } intervals 4 samples 20 method 3 }
             media { emission rgb <0, 1, 0> } }
  translate x
}
sphere { 0, 1 pigment { rgbf 1 } interior { media { emission 1 } } translate -x })");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Scene& s = r.scene;
    ASSERT_EQ(s.media.size(), 3u);
    EXPECT_FLOAT_EQ(s.media[0].emission.y, 0.1f);
    EXPECT_FLOAT_EQ(s.media[0].absorption.z, 0.4f);
    EXPECT_EQ(s.media[0].samples, 80u); // intervals x samples
    EXPECT_EQ(s.media[1].samples, 32u); // at least 32 steps
    ASSERT_EQ(s.media[0].density_count, 1u);
    const Pigment& d = s.pigments[s.medium_densities[s.media[0].density_first]];
    EXPECT_EQ(d.pattern.kind, PatternKind::Spherical);
    ASSERT_EQ(s.shape_objects.size(), 2u);
    // Each sphere has its own material: media are placed with their object, never shared.
    const uint32_t m0 = s.shape_objects[0].nodes[0].material;
    const uint32_t m1 = s.shape_objects[1].nodes[0].material;
    EXPECT_NE(m0, m1);
    EXPECT_EQ(s.materials[m0].media_count, 2u);
    EXPECT_EQ(s.materials[m1].media_count, 1u);
    // hollow: media around it fill it; POV-Ray's objects are solid otherwise.
    EXPECT_FALSE(s.shape_objects[0].flags & kSolid);
    EXPECT_TRUE(s.shape_objects[1].flags & kSolid);
}

TEST(PovMedia, ScatteringIsRead) {
    const PovResult r = load_text(
        "light_source { 0, 1 media_interaction off media_attenuation on }\n"
        "sphere { 0, 1 hollow interior { media { scattering { 1, 0.1 } "
        "density { spherical } } "
        "media { scattering { 5, <0.1, 0.2, 0.3> eccentricity -0.5 extinction 0.25 } } } }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.media.size(), 2u);
    EXPECT_EQ(r.scene.media[0].scatter_type, ScatterType::Isotropic);
    EXPECT_FLOAT_EQ(r.scene.media[0].scattering.y, 0.1f);
    EXPECT_FLOAT_EQ(r.scene.media[0].extinction, 1.0f);
    EXPECT_EQ(r.scene.media[1].scatter_type, ScatterType::HenyeyGreenstein);
    EXPECT_FLOAT_EQ(r.scene.media[1].scattering.z, 0.3f);
    EXPECT_FLOAT_EQ(r.scene.media[1].eccentricity, -0.5f);
    EXPECT_FLOAT_EQ(r.scene.media[1].extinction, 0.25f);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_FALSE(r.scene.lights[0].media_interaction);
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { scattering { 6, 1 } } } }"),
              "scene.pov:1:47: error: a scattering type must be 1 (isotropic), 2 (Mie hazy), 3 "
              "(Mie murky), 4 (Rayleigh) or 5 (Henyey-Greenstein)");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { scattering { 1, -1 } } } }"),
              "scene.pov:1:50: error: a medium's scattering must be finite and not negative");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { scattering { 5, 1 eccentricity 1 } } } }"),
              "scene.pov:1:52: error: eccentricity must lie strictly between -1 and 1");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { scattering { 1, 1 extinction -1 } } } }"),
              "scene.pov:1:52: error: extinction must be finite and not negative");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { scattering { 1, 1 glow } } } }"),
              "scene.pov:1:52: error: found 'glow', expected eccentricity, extinction or '}'");
    const PovResult m = load_text("mesh { triangle { 0, x, y } hollow interior { media { "
                                  "emission 1 } } }");
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("unsupported media in a mesh"), std::string::npos);
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { emission 1e39 } } }"),
              "scene.pov:1:43: error: a medium's emission must be finite");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { absorption -1 } } }"),
              "scene.pov:1:45: error: a medium's absorption must be finite and not negative");
    EXPECT_EQ(error_of("sphere { 0, 1 interior { media { glow 1 } } }"),
              "scene.pov:1:34: error: found 'glow', expected a media item (emission, absorption, "
              "density, samples ...)");
}

} // namespace
} // namespace sheaf::io::pov

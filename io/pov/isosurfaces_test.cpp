// Isosurfaces, function patterns, and the functions they run (internal and pattern ones).
#include "io/pov/builder.h"
#include "tests/support/pov_test_util.h"

#include "core/scene/analytic.h"
#include "core/scene/prepared_scene.h"
#include "core/shading/surface_texture.h"
#include "io/image/texture_sampler.h"

#include <cmath>
#include <fstream>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::first_hit;
using test::load_text;

const char* kInternals = "#declare f_sphere = function { internal(61) }\n"
                         "#declare f_torus = function { internal(70) }\n";

TEST(PovIsosurfaces, TheSurfaceIsWhereTheFunctionMeetsTheThreshold) {
    // An internal function, moved by the object's transform.
    PovResult r =
        load_text(std::string(kInternals) + "isosurface { function { f_sphere(x, y, z, 1) } "
                                            "contained_by { box { -2, 2 } } translate 3*x }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].shape.kind, ShapeKind::Isosurface);
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 7, 1e-4);
    // A user function called inline, its arguments expressions; the default box {-1, 1}.
    r = load_text("#declare F = function(a, b) { a * a + b }\n"
                  "isosurface { function { F(x, y * y + z * z) - 1 } }");
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 4, 1e-4);
    // The threshold.
    r = load_text("isosurface { function { x * x + y * y + z * z } threshold 0.25 }");
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 4.5, 1e-4);
    // A sphere container caps a half-space; open, only the function's surface is left.
    r = load_text("isosurface { function { y } contained_by { sphere { 0, 0.5 } } }");
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 5, 1e-4);
    EXPECT_NEAR(first_hit(r, {-5, -0.3, 0}, {1, 0, 0}), 5 - 0.4, 1e-4);
    r = load_text("isosurface { function { y } contained_by { sphere { 0, 0.5 } } open }");
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 5, 1e-4);
    EXPECT_LT(first_hit(r, {-5, -0.3, 0}, {1, 0, 0}), 0);
    // A torus around y, and a pattern as a function: the checker's 0 cube is inside.
    r = load_text(std::string(kInternals) +
                  "isosurface { function { f_torus(x, y, z, 1, 0.25) } max_gradient 1.2 }");
    EXPECT_NEAR(first_hit(r, {0, 5, 1}, {0, -1, 0}), 5 - 0.25, 1e-4);
    EXPECT_LT(first_hit(r, {0, 5, 0}, {0, -1, 0}), 0);
    r = load_text("#declare P = function { pattern { checker } }\n"
                  "isosurface { function { P(x, y, z) - 0.5 } "
                  "contained_by { box { <0.05, 0.05, 0.05>, <1.95, 0.95, 0.95> } } }");
    EXPECT_NEAR(first_hit(r, {5, 0.5, 0.5}, {-1, 0, 0}), 4, 2e-3);
}

TEST(PovIsosurfaces, ErrorsAndWhatIsLeftOut) {
    EXPECT_EQ(error_of("isosurface { contained_by { box { 0, 1 } } }"),
              "scene.pov:1:1: error: an isosurface needs a function { ... }");
    EXPECT_EQ(error_of("isosurface { function { x } max_gradient 0 }"),
              "scene.pov:1:42: error: an isosurface's max_gradient must be a positive number");
    EXPECT_EQ(error_of("isosurface { function { x } contained_by { box { 0, <1, 0, 1> } } }"),
              "scene.pov:1:44: error: an isosurface's container box is flat or empty");
    EXPECT_EQ(error_of("isosurface { function { x } contained_by { cone { 0, 1, x, 2 } } }"),
              "scene.pov:1:44: error: found 'cone', expected box or sphere");
    EXPECT_EQ(error_of("isosurface { function(a) { a } }"),
              "scene.pov:1:14: error: an isosurface's function must take x, y and z");
    // A function Sheaf cannot run: warned, and the object left out.
    const PovResult r = load_text("isosurface { function { pigment { gradient x pigment_map { "
                                  "[0 checker] [1 rgb 1] } } } }\n"
                                  "isosurface { function { internal(4) } }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 2u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:14: warning: unsupported isosurface of a "
                                 "pigment function (of a pigment map) (left out)"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_NE(r.warnings[1].find("internal function 4"), std::string::npos) << r.warnings[1];
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

TEST(PovIsosurfaces, FunctionPatternsColourByTheFunction) {
    const PovResult r = load_text(
        "#declare G = function { pattern { gradient x } }\n"
        "sphere { 0, 1 pigment { function { x * 0.5 } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
        "sphere { 0, 1 pigment { function { G(x, y, z) } scale 4 "
        "color_map { [0 rgb 0] [1 rgb 1] } } }");
    EXPECT_TRUE(r.warnings.empty());
    const PreparedScene p = prepare_scene(r.scene);
    auto grey = [&](size_t object, float x) {
        const uint32_t m = r.scene.shape_objects[object].nodes[0].material;
        const int32_t pg = r.scene.materials[m].pigment;
        EXPECT_GE(pg, 0);
        EXPECT_EQ(r.scene.pigments[size_t(pg)].pattern.kind, PatternKind::Function);
        return evaluate_pigment(p, uint32_t(pg), Vec3(x, 0.3f, -0.2f), 0, 0).rgb.x;
    };
    EXPECT_NEAR(grey(0, 0.5f), 0.25f, 1e-6);
    EXPECT_NEAR(grey(0, 1.5f), 0.75f, 1e-6);
    EXPECT_NEAR(grey(0, 2.5f), 0.24999f, 1e-6); // 1.25 wraps modulo 1.00001, as in POV-Ray
    EXPECT_NEAR(grey(1, 1.0f), 0.25f, 1e-6);    // the pattern scaled with the pigment
}

TEST(PovIsosurfaces, PigmentFunctionsGiveTheirColoursComponents) {
    const std::string pigment = "#declare P = function { pigment { gradient x "
                                "color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] } } }\n";
    // The isosurface where red exceeds 0.3: x > 0.3.
    PovResult r = load_text(pigment + "isosurface { function { 0.3 - P(x, y, z).red } "
                                      "contained_by { box { <0, -1, -1>, <0.99, 1, 1> } } }");
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 5.3, 1e-4);
    r = load_text(pigment + "isosurface { function { 0.1 - P(x, y, z).blue } "
                            "contained_by { box { <0, -1, -1>, <0.99, 1, 1> } } }");
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 5.4, 1e-4);
    // In the language, the colour, and its components.
    const Value c = test::declared(pigment + "#declare C = P(0.5, 0, 0);", "C");
    EXPECT_NEAR(c.v[0], 0.5, 1e-6);
    EXPECT_NEAR(c.v[1], 0.25, 1e-6);
    EXPECT_NEAR(test::declared(pigment + "#declare G = P(0.8, 0, 0).green;", "G").v[0], 0.4, 1e-6);
    // What Sheaf cannot take apart is warned where it is used.
    r = load_text("#declare Q = function { pigment { gradient x pigment_map { [0 checker] "
                  "[1 rgb 1] } } }\nisosurface { function { Q(x, y, z).red } }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("pigment function (of a pigment map)"), std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(error_of(pigment + "isosurface { function { P(x, y, z).alpha } }"),
              "scene.pov:2:36: error: found 'alpha', expected a colour component (red, green, "
              "blue, filter, transmit, gray, x, y, z, t)");
}

/// The height at (x, z) of the scene's meshes (their own coordinates: POV-Ray's, the
/// object's transform apart), -1 when no vertex lies there.
float height_at(const PovResult& r, float x, float z) {
    for (const Mesh& m : r.scene.meshes)
        for (const Vec3& p : m.positions)
            if (std::fabs(p.x - x) < 1e-5f && std::fabs(p.z - z) < 1e-5f) return p.y;
    return -1;
}

TEST(PovHeightFields, HeightsFromGreyImagesAndFunctions) {
    test::TempDir d;
    PovOptions images;
    images.read_raster = &read_raster;
    // The image's top row lies at z = 1.
    d.write("hf.pgm", "P2\n3 2\n255\n0 0 255\n255 0 0\n");
    PovResult r =
        load_pov_scene(d.write("scene.pov", "height_field { pgm \"hf.pgm\" smooth }"), images);
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].triangle_count(), 4u);
    EXPECT_EQ(r.scene.meshes[0].normals.size(), 6u);
    EXPECT_NEAR(height_at(r, 0, 0), 1, 1e-6);
    EXPECT_NEAR(height_at(r, 1, 1), 1, 1e-6);
    EXPECT_NEAR(height_at(r, 0, 1), 0, 1e-6);
    EXPECT_NEAR(height_at(r, 0.5f, 0), 0, 1e-6);
    // A program that passes no image reader (the CUDA test) gets an error at the file name.
    try {
        load_pov_scene(d.path() + "/scene.pov", {});
        ADD_FAILURE() << "a height field image loaded without an image reader";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "scene.pov:1:20: error: height_field image 'hf.pgm': this program reads "
                      "no images"),
                  std::string::npos)
            << e.what();
    }
    // A function of (x, y) over the grid, y = 1 at the far edge as an image's top row.
    r = load_text("height_field { function 3, 5 { x * 0.5 + y * 0.25 } }");
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].positions.size(), 15u);
    EXPECT_NEAR(height_at(r, 1, 0), 0.75, 1e-6);
    EXPECT_NEAR(height_at(r, 0, 0), 0.25, 1e-6);
    EXPECT_NEAR(height_at(r, 0, 1), 0, 1e-6);
    EXPECT_NEAR(height_at(r, 0.5f, 0.75f), 0.5 * 0.5 + 0.25 * (1 - 0.75), 1e-6);
    // Cells wholly under the water level are left out.
    r = load_text("height_field { function 3, 3 { x } water_level 0.6 }");
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].triangle_count(), 4u);
    // Errors and what is left out.
    EXPECT_EQ(error_of("height_field { function 1, 5 { x } }"),
              "scene.pov:1:25: error: a height field function's grid must be at least 2 x 2 "
              "and at most 16777216 samples");
    r = load_text("height_field { pot \"x.pot\" }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("unsupported height_field from a pot file"), std::string::npos);
}

// The scene language evaluates any pigment (io/pov/function_scene.h): pigment maps of
// patterned pigments, pigment_pattern, average and warps, as the render evaluates them.
TEST(PovHeightFields, HeightsFromAnyPigmentFunction) {
    // gradient x blends black and a gradient y pigment: the grey is x * y.
    PovResult r = load_text("height_field { function 5, 5 { pigment { gradient x pigment_map { "
                            "[0 rgb 0] [1 gradient y color_map { [0 rgb 0] [1 rgb 1] }] } } } }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_NEAR(height_at(r, 0.5f, 0.25f), 0.5 * 0.75, 1e-4); // y = 1 at z = 0
    EXPECT_NEAR(height_at(r, 0.75f, 0.5f), 0.75 * 0.5, 1e-4);
    EXPECT_NEAR(height_at(r, 0.25f, 1), 0, 1e-4);
    // A pigment_pattern's grey through a colour map, repeated every half unit along x.
    r = load_text("height_field { function 5, 5 { pigment { pigment_pattern { gradient x "
                  "color_map { [0 rgb 0] [1 rgb 1] } } color_map { [0 rgb 1] [1 rgb 0] } "
                  "warp { repeat 0.5 * x } } } }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    EXPECT_NEAR(height_at(r, 0.25f, 0.5f), 0.75, 1e-4);
    EXPECT_NEAR(height_at(r, 0.75f, 0.5f), 0.75, 1e-4); // 0.75 repeats 0.25
    // An average, and a call in the language of a function of such a pigment.
    r = load_text("height_field { function 3, 3 { pigment { average pigment_map { "
                  "[1 rgb 0.2] [1 rgb 0.6] } } } }");
    EXPECT_NEAR(height_at(r, 0.5f, 0.5f), 0.4, 1e-4);
    const std::string flip = "#declare F = function { pigment { pigment_pattern { gradient x "
                             "color_map { [0 rgb 0] [1 rgb 1] } } color_map { [0 rgb <1, 0, 0>] "
                             "[1 rgb <0, 0, 1>] } } }\n";
    EXPECT_NEAR(test::declared(flip + "#declare V = F(0.25, 0, 0).red;", "V").v[0], 0.75, 1e-6);
    EXPECT_NEAR(test::declared(flip + "#declare G = function { F(x, y, z).blue * 2 }\n"
                                      "#declare V = G(0.25, 0, 0);",
                               "V")
                    .v[0],
                0.5, 1e-6);
    // The render's programs still cannot run such a pigment: an isosurface of it is warned.
    r = load_text(flip + "isosurface { function { F(x, y, z).red - 0.5 } }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("unsupported isosurface of a pigment function (of an average, "
                                 "image, function or pigment_pattern pigment)"),
              std::string::npos)
        << r.warnings[0];
}

// An image in a function's pigment is sampled through the program's sampler; a program that
// reads no images (the CUDA test, which does not link OpenImageIO) gets an error there.
TEST(PovHeightFields, ImagesInPigmentFunctionsNeedASampler) {
    test::TempDir d;
    d.write("g.pgm", "P2\n2 1\n255\n0 255\n");
    const std::string scene = d.write(
        "scene.pov", "height_field { function 5, 5 { pigment { image_map { pgm \"g.pgm\" } } } }");
    PovOptions images;
    images.attach_sampler = &attach_texture_sampler;
    const PovResult r = load_pov_scene(scene, images);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_NEAR(height_at(r, 0.25f, 0.5f), 0, 0.02); // the black pixel
    EXPECT_NEAR(height_at(r, 0.75f, 0.5f), 1, 0.02); // the white one
    try {
        load_pov_scene(scene, {});
        ADD_FAILURE() << "a function's image loaded without a sampler";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("scene.pov:1:32: error: an image in a function's "
                                             "pigment: this program reads no images"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PovHeightFields, PalettePngsGiveTheirIndices) {
    const std::string path = "/usr/share/povray-3.7/include/fract003.png";
    if (!std::ifstream(path)) GTEST_SKIP() << path << " (povray-includes) is not installed";
    PovOptions images;
    images.read_raster = &read_raster;
    const PovResult r = load_text("height_field { png \"" + path + "\" }", images);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    // Index 1 is the sea: 32,221 of the 320 x 200 pixels (its palette repeats colours, so
    // the colours alone could not give the index).
    size_t sea = 0;
    for (const Vec3& p : r.scene.meshes[0].positions) sea += std::fabs(p.y - 1 / 255.0f) < 1e-6f;
    EXPECT_EQ(sea, 32221u);
}

TEST(PovIsosurfaces, InternalAndPatternFunctionsEvaluateInTheLanguage) {
    auto value = [](const std::string& call) {
        return test::declared("#declare S = function { internal(61) }\n"
                              "#declare C = function { pattern { checker } }\n"
                              "#declare V = " +
                                  call + ";",
                              "V")
            .v[0];
    };
    EXPECT_NEAR(value("S(3, 4, 0, 1)"), 4, 1e-12);
    EXPECT_NEAR(value("C(1.5, 0.5, 0.5)"), 1, 1e-12);
    EXPECT_NEAR(value("C(0.5, 0.5, 0.5)"), 0, 1e-12);
    // A pattern function of a pigment_pattern whose pigment is a function pattern of another
    // pattern function: the grey of the inverted map of y.
    EXPECT_NEAR(test::declared("#declare A = function { pattern { gradient y } }\n"
                               "#declare B = function { pattern { pigment_pattern { function { "
                               "A(x, y, z) } color_map { [0 rgb 1] [1 rgb 0] } } } }\n"
                               "#declare V = B(0.25, 0.75, 0);",
                               "V")
                    .v[0],
                0.25, 1e-6);
    EXPECT_EQ(error_of("#declare S = function { internal(61) }\n#declare V = S(1, 2, 3);"),
              "scene.pov:2:14: error: 'S' takes 4 arguments, not 3");
}

} // namespace
} // namespace sheaf::io::pov

// The text object: fonts found like other files, characters laid out as POV-Ray does (checked
// against povray 3.7: the first character's ink at x = 0, advances, kerning, the offset's x and
// y), one glyph shape per character with ink, and errors at the text's position. Uses the fonts
// of Debian's povray-includes, which the test command installs.
#include "io/pov/builder.h"
#include "tests/support/pov_test_util.h"

#include "core/scene/analytic.h"
#include "core/scene/prepared_scene.h"

#include <filesystem>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::first_hit;
using test::load_text;
using test::TempDir;

const char* kFonts = "/usr/share/povray-3.7/include";

bool have_fonts() {
    return std::filesystem::exists(std::string(kFonts) + "/timrom.ttf");
}

/// Where the glyph of shape object `object` has its origin, in POV-Ray coordinates (a text is
/// a union, which the builder splits into an object per character).
Vec3 glyph_origin(const PovResult& r, size_t object) {
    const ShapeObject& o = r.scene.shape_objects.at(object);
    EXPECT_EQ(o.nodes.at(0).shape.kind, ShapeKind::Glyph);
    return pov_to_sheaf().point(o.transform.point(o.nodes.at(0).transform.point({0, 0, 0})));
}

TEST(PovText, ACharacterIsAnExtrudedGlyph) {
    if (!have_fonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed (povray-includes)";
    // timrom's "I": ink from 23 to 319 of 1000 units, so from x = 0 to 0.296 here; 680 units
    // high; extruded from z = 0 to 0.5.
    const PovResult r = load_text("text { ttf \"timrom.ttf\" \"I\" 0.5, 0 }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects[0].nodes.at(0).shape.kind, ShapeKind::Glyph);
    EXPECT_NEAR(first_hit(r, {0.15f, 0.3f, -5}, {0, 0, 1}), 5.0f, 1e-5);        // the front face
    EXPECT_NEAR(first_hit(r, {0.15f, 0.3f, 5}, {0, 0, -1}), 4.5f, 1e-5);        // the back face
    EXPECT_NEAR(first_hit(r, {0.15f, 5, 0.25f}, {0, -1, 0}), 5 - 0.680f, 1e-5); // the top
    EXPECT_NEAR(first_hit(r, {-5, 0.01f, 0.25f}, {1, 0, 0}), 5.0f, 1e-3);       // the left serif
    EXPECT_LT(first_hit(r, {0.35f, 0.3f, -5}, {0, 0, 1}), 0.0f);                // right of its ink
    EXPECT_LT(first_hit(r, {0.15f, 0.3f, -5}, {0, 1, 0}), 0.0f);                // in front of it
}

TEST(PovText, CharactersAdvanceKernAndShareOutlines) {
    if (!have_fonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed (povray-includes)";
    // "I I": timrom's I advances 342 units, the space 254; the first I's ink starts at 0.
    PovResult r = load_text("text { ttf \"timrom.ttf\" \"I I\" 1, 0 }");
    ASSERT_EQ(r.scene.shape_objects.size(), 2u); // two glyphs: the space has no ink
    EXPECT_NEAR(glyph_origin(r, 0).x, -0.023f, 1e-6);
    EXPECT_NEAR(glyph_origin(r, 1).x, -0.023f + 0.342f + 0.254f, 1e-6);
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].glyph, r.scene.shape_objects[1].nodes[0].glyph);
    EXPECT_EQ(prepare_scene(r.scene).glyphs.size(), 1u);
    // The offset's x and y move every next character; its z is ignored, as POV-Ray does.
    r = load_text("text { ttf \"timrom.ttf\" \"II\" 1, <0.5, 0.25, 3> }");
    const Vec3 second = glyph_origin(r, 1);
    EXPECT_NEAR(second.x, -0.023f + 0.342f + 0.5f, 1e-6);
    EXPECT_NEAR(second.y, 0.25f, 1e-6);
    EXPECT_NEAR(second.z, 0.0f, 1e-6);
    // A float offset is <f, f, f>.
    r = load_text("text { ttf \"timrom.ttf\" \"II\" 1, 0.1 }");
    EXPECT_NEAR(glyph_origin(r, 1).y, 0.1f, 1e-6);
    // timrom kerns "AV" by -187 units: V starts at A's advance (750) less that, after A's ink
    // is moved to 0 (its bearing is 6).
    r = load_text("text { ttf \"timrom.ttf\" \"AV\" 1, 0 }");
    EXPECT_NEAR(glyph_origin(r, 1).x, -0.006f + 0.750f - 0.187f, 1e-6);
}

TEST(PovText, FontsAreFoundWithoutTheirExtensionAndModifiersApply) {
    if (!have_fonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed (povray-includes)";
    const PovResult r = load_text("#declare S = concat(\"O\", \"k\");\n"
                                  "text { ttf \"cyrvetic\", S, 0.2, 0 scale 2 translate y }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 2u);
    // The O's ring: a ray through its middle passes its hole, one through the ring hits it.
    const float o_middle = 2 * (0.749f / 2 - 0.037f), o_top = 1 + 2 * 0.35f;
    EXPECT_LT(first_hit(r, {o_middle, o_top, -5}, {0, 0, 1}), 0.0f);
    EXPECT_NEAR(first_hit(r, {0.05f, o_top, -5}, {0, 0, 1}), 5.0f, 1e-5);
}

TEST(PovText, InternalFontsAreTheFontFilesPovRayShips) {
    if (!have_fonts()) GTEST_SKIP() << "POV-Ray's fonts are not installed (povray-includes)";
    const PovResult a = load_text("text { internal 1 \"AV\" 1, 0 }");
    const PovResult b = load_text("text { ttf \"timrom.ttf\" \"AV\" 1, 0 }");
    ASSERT_EQ(a.scene.shape_objects.size(), 2u);
    EXPECT_EQ(a.scene.shape_objects[1].nodes[0].glyph->segments.size(),
              b.scene.shape_objects[1].nodes[0].glyph->segments.size());
    EXPECT_NEAR(glyph_origin(a, 1).x, glyph_origin(b, 1).x, 1e-7);
}

TEST(PovText, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("text { \"timrom.ttf\" \"A\" 1, 0 }"),
              "scene.pov:1:8: error: found '\"timrom.ttf\"', expected 'ttf' and the font file's "
              "name, or 'internal' and a font number");
    EXPECT_EQ(error_of("text { internal 4 \"A\" 1, 0 }"),
              "scene.pov:1:17: error: an internal font is a number from 0 to 3");
    const std::string missing = error_of("text { ttf \"nofont.ttf\" \"A\" 1, 0 }");
    EXPECT_EQ(missing.rfind("scene.pov:1:12: error: cannot find font 'nofont.ttf'", 0), 0u)
        << missing;
    TempDir d;
    d.write("fake.ttf", "not a font at all");
    const std::string scene = d.write("scene.pov", "\n  text { ttf \"fake.ttf\" \"A\" 1, 0 }");
    try {
        load_pov_scene(scene, {});
        ADD_FAILURE() << "a file that is not a font loaded";
    } catch (const SceneError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("scene.pov:2:14: error: cannot read font '"), std::string::npos) << m;
    }
    if (!have_fonts()) return;
    EXPECT_EQ(error_of("text { ttf \"timrom.ttf\" \"A\" 0, 0 }"),
              "scene.pov:1:29: error: a text's thickness must be a finite number other than 0");
    EXPECT_EQ(error_of("text { ttf \"timrom.ttf\" \"A\" 1, \"x\" }"),
              "scene.pov:1:32: error: found '\"x\"', expected the offset between characters (a "
              "vector)");
    // Nothing to draw is a warning, not an error (also under --strict).
    PovOptions strict;
    strict.strict = true;
    const PovResult r =
        load_text("text { ttf \"timrom.ttf\" \" \" 1, 0 }\nsphere { 0, 1 }", strict);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:25: warning: a text without a visible character"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

} // namespace
} // namespace sheaf::io::pov

// Fonts through FreeType: strings decoded, outlines closed and filled as TrueType fills them,
// metrics in em. Uses the fonts of Debian's povray-includes (the test command installs them).
#include "io/font/font.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace sheaf::io {
namespace {

const std::string kTimes = "/usr/share/povray-3.7/include/timrom.ttf";

TEST(Font, TextIsUtf8WhereItCanBeAndLatin1Elsewhere) {
    EXPECT_EQ(decode_text("Ab"), (std::vector<uint32_t>{'A', 'b'}));
    EXPECT_EQ(decode_text("\xC3\xA9t\xC3\xA9"), (std::vector<uint32_t>{0xE9, 't', 0xE9}));
    EXPECT_EQ(decode_text("\xE2\x82\xAC"), (std::vector<uint32_t>{0x20AC}));      // the euro sign
    EXPECT_EQ(decode_text("\xF0\x9F\x99\x82"), (std::vector<uint32_t>{0x1F642})); // four bytes
    EXPECT_EQ(decode_text("caf\xE9"), (std::vector<uint32_t>{'c', 'a', 'f', 0xE9}));   // Latin-1
    EXPECT_EQ(decode_text("\xC0\xAF"), (std::vector<uint32_t>{0xC0, 0xAF}));           // overlong
    EXPECT_EQ(decode_text("\xED\xA0\x80"), (std::vector<uint32_t>{0xED, 0xA0, 0x80})); // surrogate
    EXPECT_EQ(decode_text("\xE2\x82"), (std::vector<uint32_t>{0xE2, 0x82}));           // cut short
    EXPECT_TRUE(decode_text("").empty());
}

TEST(Font, OutlinesAreClosedAndFillByWinding) {
    if (!std::filesystem::exists(kTimes)) GTEST_SKIP() << "povray-includes is not installed";
    Font font(kTimes);
    for (uint32_t c : {uint32_t('O'), uint32_t('B'), uint32_t('g'), uint32_t('%'), 0xE9u}) {
        const Font::Glyph& g = font.glyph(c);
        ASSERT_TRUE(g.outline) << c;
        const auto& s = g.outline->segments;
        // Contours: each segment ends where the next begins, but for the last of a contour,
        // which ends where its contour began.
        size_t start = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            const bool last = i + 1 == s.size() || s[i].x2 != s[i + 1].x0 || s[i].y2 != s[i + 1].y0;
            if (!last) continue;
            EXPECT_EQ(s[i].x2, s[start].x0) << "character " << c << " segment " << i;
            EXPECT_EQ(s[i].y2, s[start].y0) << "character " << c << " segment " << i;
            start = i + 1;
        }
        EXPECT_GT(g.advance, 0.2);
        EXPECT_LT(g.advance, 1.2);
    }
    // The O's middle is its hole; its left stroke is ink (timrom's O: ink 32..714 of 1000).
    const Font::Glyph& o = font.glyph('O');
    GlyphRef ref;
    ref.count = uint32_t(o.outline->segments.size());
    glyph_detail::Crossing xs[kMaxGlyphCrossings];
    EXPECT_FALSE(glyph_detail::contains(o.outline->segments.data(), ref.count, 0, 0.36, 0.33, xs));
    EXPECT_TRUE(glyph_detail::contains(o.outline->segments.data(), ref.count, 0, 0.06, 0.33, xs));
    EXPECT_FALSE(font.glyph(' ').outline); // a space has no ink, only an advance
    EXPECT_NEAR(font.glyph(' ').advance, 0.254, 1e-9);
    // A character the font lacks gets its missing-character glyph (index 0).
    EXPECT_EQ(font.glyph(0x4E2D).index, 0u);
}

TEST(Font, LayoutDropsTheFirstBearingAdvancesAndKerns) {
    if (!std::filesystem::exists(kTimes)) GTEST_SKIP() << "povray-includes is not installed";
    Font font(kTimes);
    const std::vector<PlacedGlyph> g = layout_text(font, "AV A", Vec3(0.1f, 0.2f, 5));
    ASSERT_EQ(g.size(), 3u);
    EXPECT_NEAR(g[0].position.x, -0.006, 1e-6); // A's bearing (6 units) dropped
    EXPECT_NEAR(g[1].position.x, -0.006 + 0.750 - 0.187 + 0.1, 1e-6); // kerned "AV"
    EXPECT_NEAR(g[1].position.y, 0.2, 1e-6);
    EXPECT_EQ(g[1].position.z, 0);
    // After V (724) and the space (254), each with the offset.
    EXPECT_NEAR(g[2].position.x, -0.006 + 0.750 - 0.187 + 0.724 + 0.254 + 3 * 0.1, 1e-5);
    EXPECT_NEAR(g[2].position.y, 0.6, 1e-6);
    EXPECT_EQ(g[0].outline, g[2].outline);
}

TEST(Font, FilesThatAreNotFontsAreErrors) {
    const auto path = std::filesystem::temp_directory_path() / "sheaf_not_a_font.ttf";
    std::ofstream(path) << "hello";
    try {
        Font f(path.string());
        ADD_FAILURE() << "a text file opened as a font";
    } catch (const FontError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("cannot read font '" + path.string() + "': ", 0), 0u)
            << e.what();
    }
    std::filesystem::remove(path);
    EXPECT_THROW(Font("/nonexistent/font.ttf"), FontError);
}

} // namespace
} // namespace sheaf::io

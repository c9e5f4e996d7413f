// Fonts through FreeType: a TrueType or OpenType file's glyph outlines as quadratic segments in
// em units (the em square is 1 wide: the size POV-Ray gives its text), its advances and its
// kerning, and strings laid out with them (POV-Ray's text object, io/pov/text.cpp).
#pragma once

#include "core/geometry/glyph.h"
#include "core/math/vec3.h"

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sheaf::io {

/// A font file that could not be read, or a glyph that could not be loaded.
struct FontError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Font {
  public:
    /// A character's glyph: its outline (null for one without ink, a space), its advance and
    /// left side bearing (where its ink begins) in em, and its index in the font.
    struct Glyph {
        std::shared_ptr<const GlyphOutline> outline;
        double advance = 0, bearing = 0;
        uint32_t index = 0;
    };

    /// Opens a TrueType or OpenType file (its first face). Throws FontError.
    explicit Font(const std::string& path);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// The glyph of Unicode code point `c`, or the font's missing-character glyph (index 0)
    /// when it has none. Loaded once. Throws FontError.
    const Glyph& glyph(uint32_t c);
    /// The kerning between two glyphs, in em (0 without a kerning table).
    double kerning(uint32_t left_index, uint32_t right_index) const;
    const std::string& path() const { return path_; }

  private:
    struct Face;
    std::unique_ptr<Face> face_;
    std::string path_;
    std::map<uint32_t, Glyph> glyphs_; // by code point
};

/// The fonts a scene's texts use, each opened once by its path. A file that fails to open is
/// not kept: open() throws FontError again for it.
class FontCache {
  public:
    Font& open(const std::string& path);

  private:
    std::map<std::string, std::unique_ptr<Font>> fonts_;
};

/// One character of a laid-out string, with ink: its outline and where its origin goes.
struct PlacedGlyph {
    std::shared_ptr<const GlyphOutline> outline;
    Vec3 position;
};

/// The code points of `text`: UTF-8 where its bytes form it, each other byte as Latin-1.
std::vector<uint32_t> decode_text(const std::string& text);

/// Lays out `text` as POV-Ray's text object does: each character at the pen, which starts so
/// that the first character's ink begins at x = 0 (POV-Ray drops its left side bearing) and
/// moves on by the glyph's advance along x, then by `offset`'s x and y (POV-Ray
/// ignores its z: every character stands on z = 0); kerning between neighbours adjusts it.
/// Characters without ink (spaces) only move the pen.
std::vector<PlacedGlyph> layout_text(Font& font, const std::string& text, Vec3 offset);

} // namespace sheaf::io

#include "io/font/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <cmath>

namespace sheaf::io {

struct Font::Face {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    bool symbol = false; // a symbol font: its characters sit at 0xF000 + the code
    double em = 1;       // font units per em
    ~Face() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

namespace {

// FreeType's error texts, from its own list (FT_Error_String needs a build option that
// Debian's library does not set).
// clang-format off
#undef FTERRORS_H_
#define FT_ERRORDEF(e, v, s) {e, s},
#define FT_ERROR_START_LIST {
#define FT_ERROR_END_LIST {0, nullptr}};
const struct {
    int code;
    const char* message;
} kFtErrors[] =
#include FT_ERRORS_H
// clang-format on

std::string ft_message(FT_Error e) {
    for (const auto& m : kFtErrors)
        if (m.message && m.code == int(e)) return m.message;
    return "FreeType error " + std::to_string(int(e));
}

/// Collects an outline's segments while FreeType walks it (font units; scaled to em after).
struct Collector {
    std::vector<GlyphSegment> segments;
    double x = 0, y = 0; // the pen
    double scale = 1;

    void quad(double cx, double cy, double x2, double y2) {
        if (x2 == x && y2 == y && cx == x && cy == y) return; // nothing drawn
        segments.push_back({float(x * scale), float(y * scale), float(cx * scale),
                            float(cy * scale), float(x2 * scale), float(y2 * scale)});
        x = x2, y = y2;
    }
};

int move_to(const FT_Vector* to, void* user) {
    auto& c = *static_cast<Collector*>(user);
    c.x = double(to->x), c.y = double(to->y);
    return 0;
}

int line_to(const FT_Vector* to, void* user) {
    auto& c = *static_cast<Collector*>(user);
    c.quad(0.5 * (c.x + double(to->x)), 0.5 * (c.y + double(to->y)), double(to->x), double(to->y));
    return 0;
}

int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    static_cast<Collector*>(user)->quad(double(control->x), double(control->y), double(to->x),
                                        double(to->y));
    return 0;
}

// A cubic (OpenType's CFF outlines) as eight quadratics (core/geometry/glyph.h).
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto& c = *static_cast<Collector*>(user);
    const double p[4][2] = {{c.x, c.y},
                            {double(c1->x), double(c1->y)},
                            {double(c2->x), double(c2->y)},
                            {double(to->x), double(to->y)}};
    std::vector<GlyphSegment> pieces;
    cubic_to_quadratics(p, 8, pieces);
    for (const GlyphSegment& q : pieces) c.quad(q.x1, q.y1, q.x2, q.y2);
    return 0;
}

} // namespace

Font::Font(const std::string& path) : face_(std::make_unique<Face>()), path_(path) {
    FT_Error e = FT_Init_FreeType(&face_->library);
    if (e) throw FontError("cannot start FreeType: " + ft_message(e));
    e = FT_New_Face(face_->library, path.c_str(), 0, &face_->face);
    if (e) throw FontError("cannot read font '" + path + "': " + ft_message(e));
    FT_Face f = face_->face;
    if (!FT_IS_SCALABLE(f) || f->units_per_EM == 0)
        throw FontError("font '" + path + "' has no outlines (a bitmap font)");
    face_->em = double(f->units_per_EM);
    if (FT_Select_Charmap(f, FT_ENCODING_UNICODE) != 0) {
        if (FT_Select_Charmap(f, FT_ENCODING_MS_SYMBOL) == 0)
            face_->symbol = true;
        else if (f->num_charmaps > 0)
            FT_Set_Charmap(f, f->charmaps[0]);
    }
}

Font::~Font() = default;

const Font::Glyph& Font::glyph(uint32_t c) {
    const auto found = glyphs_.find(c);
    if (found != glyphs_.end()) return found->second;
    FT_Face f = face_->face;
    FT_UInt index = FT_Get_Char_Index(f, c);
    if (index == 0 && face_->symbol && c < 0x100) index = FT_Get_Char_Index(f, 0xF000 + c);
    const FT_Error e = FT_Load_Glyph(f, index,
                                     FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP |
                                         FT_LOAD_IGNORE_TRANSFORM);
    if (e)
        throw FontError("font '" + path_ + "': cannot load the glyph of character " +
                        std::to_string(c) + ": " + ft_message(e));
    Glyph g;
    g.index = index;
    g.advance = double(f->glyph->metrics.horiAdvance) / face_->em;
    g.bearing = double(f->glyph->metrics.horiBearingX) / face_->em;
    if (f->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
        throw FontError("font '" + path_ + "': the glyph of character " + std::to_string(c) +
                        " is not an outline");
    Collector collect;
    collect.scale = 1 / face_->em;
    FT_Outline_Funcs funcs{};
    funcs.move_to = move_to;
    funcs.line_to = line_to;
    funcs.conic_to = conic_to;
    funcs.cubic_to = cubic_to;
    const FT_Error d = FT_Outline_Decompose(&f->glyph->outline, &funcs, &collect);
    if (d)
        throw FontError("font '" + path_ + "': the outline of character " + std::to_string(c) +
                        " is damaged: " + ft_message(d));
    if (collect.segments.size() > kMaxGlyphSegments)
        throw FontError("font '" + path_ + "': the glyph of character " + std::to_string(c) +
                        " has more than " + std::to_string(kMaxGlyphSegments) + " segments");
    for (const GlyphSegment& s : collect.segments)
        for (float v : {s.x0, s.y0, s.x1, s.y1, s.x2, s.y2})
            if (!std::isfinite(v))
                throw FontError("font '" + path_ + "': the outline of character " +
                                std::to_string(c) + " is not finite");
    if (!collect.segments.empty()) {
        auto outline = std::make_shared<GlyphOutline>();
        outline->segments = std::move(collect.segments);
        g.outline = std::move(outline);
    }
    return glyphs_.emplace(c, std::move(g)).first->second;
}

double Font::kerning(uint32_t left_index, uint32_t right_index) const {
    FT_Face f = face_->face;
    if (!FT_HAS_KERNING(f)) return 0;
    FT_Vector k{0, 0};
    if (FT_Get_Kerning(f, left_index, right_index, FT_KERNING_UNSCALED, &k) != 0) return 0;
    return double(k.x) / face_->em;
}

Font& FontCache::open(const std::string& path) {
    std::unique_ptr<Font>& font = fonts_[path];
    if (!font) {
        try {
            font = std::make_unique<Font>(path);
        } catch (const FontError&) {
            fonts_.erase(path);
            throw;
        }
    }
    return *font;
}

std::vector<uint32_t> decode_text(const std::string& text) {
    std::vector<uint32_t> out;
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const size_t n = text.size();
    for (size_t i = 0; i < n;) {
        const unsigned char b = s[i];
        int extra = 0;
        uint32_t c = b;
        if (b >= 0xC2 && b <= 0xDF)
            extra = 1, c = b & 0x1Fu;
        else if (b >= 0xE0 && b <= 0xEF)
            extra = 2, c = b & 0x0Fu;
        else if (b >= 0xF0 && b <= 0xF4)
            extra = 3, c = b & 0x07u;
        bool ok = extra > 0 && i + size_t(extra) < n;
        for (int k = 1; ok && k <= extra; ++k) {
            if ((s[i + k] & 0xC0) != 0x80)
                ok = false;
            else
                c = (c << 6) | (s[i + k] & 0x3Fu);
        }
        if (ok && ((extra == 2 && c < 0x800) || (extra == 3 && (c < 0x10000 || c > 0x10FFFF)) ||
                   (c >= 0xD800 && c < 0xE000)))
            ok = false; // overlong, out of range, or a surrogate
        if (ok) {
            out.push_back(c);
            i += size_t(extra) + 1;
        } else {
            out.push_back(b); // Latin-1
            ++i;
        }
    }
    return out;
}

std::vector<PlacedGlyph> layout_text(Font& font, const std::string& text, Vec3 offset) {
    std::vector<PlacedGlyph> out;
    double x = 0, y = 0;
    bool first = true;
    uint32_t previous = 0;
    for (uint32_t c : decode_text(text)) {
        const Font::Glyph& g = font.glyph(c);
        if (first) x = -g.bearing;
        if (!first) x += font.kerning(previous, g.index);
        if (g.outline) out.push_back({g.outline, Vec3(float(x), float(y), 0)});
        x += g.advance + offset.x, y += offset.y;
        previous = g.index, first = false;
    }
    return out;
}

} // namespace sheaf::io

// text { ttf FONT | internal N, STRING THICKNESS, OFFSET }: POV-Ray's text object, one glyph shape
// per character with ink (core/geometry/glyph.h), laid out by io/font: the em square 1 wide, the
// baseline on y = 0, the first character's origin at the origin, extruded from z = 0 to
// z = THICKNESS; each next character starts at the last one's advance plus OFFSET's x and y
// (a float is <f, f, f>, as POV-Ray promotes it; POV-Ray ignores the z). POV-Ray's internal
// fonts 0 to 3 are its font files povlogo, timrom, cyrvetic and crystal (checked: the same
// pictures).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

void Parser::parse_text(const Token& kw, PovObject& o) {
    expect_sym("{");
    const Token& ttf = peek();
    if (!is_kw_tok(ttf, "ttf") && !is_kw_tok(ttf, "internal"))
        error_expected(ttf, "'ttf' and the font file's name, or 'internal' and a font number");
    next();
    const Token& font_at = peek();
    std::string font_name;
    if (ttf.text == "internal") { // POV-Ray's built-in fonts: its own font files
        const double n = parse_float();
        static const char* const kInternal[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf",
                                                "crystal.ttf"};
        if (!(n >= 0 && n <= 3) || n != std::floor(n))
            error_at(font_at, "an internal font is a number from 0 to 3");
        font_name = kInternal[int(n)];
    } else {
        font_name = parse_string();
    }
    accept_sym(",");
    const Token& text_at = peek();
    const std::string text = parse_string();
    accept_sym(",");
    const Token& thickness_at = peek();
    const double thickness = parse_float();
    if (!std::isfinite(thickness) || thickness == 0)
        error_at(thickness_at, "a text's thickness must be a finite number other than 0");
    accept_sym(",");
    const Token& offset_at = peek();
    const Value off = parse_expr();
    if (!off.numeric()) error_expected(offset_at, "the offset between characters (a vector)");
    const Vec3 offset = off.type == VType::Float
                            ? Vec3(float(off.v[0]))
                            : Vec3(float(off.v[0]), float(off.v[1]), float(off.v[2]));
    // An object per character (at most one per byte): charged before they are made, so that
    // a string built up in a loop stops at the data budget without first taking the memory.
    charge(text.size() * sizeof(PovObject), text_at);
    const std::string path = find_file(font_name, font_at, "font", {".ttf", ".otf", ".ttc"});
    std::vector<PlacedGlyph> glyphs;
    try {
        glyphs = layout_text(fonts_.open(path), text, offset);
    } catch (const FontError& e) {
        error_at(font_at, e.what());
    }
    o.kind = PovKind::Csg, o.op = CsgOp::Union;
    if (glyphs.empty()) warn(text_at, "a text without a visible character draws nothing");
    for (const PlacedGlyph& g : glyphs) {
        PovObject c;
        c.kind = PovKind::Shape;
        c.shape.kind = ShapeKind::Glyph;
        c.glyph = g.outline;
        c.local = Affine::translate(g.position) * Affine::scale(Vec3(1, 1, float(thickness)));
        c.where = kw;
        o.children.push_back(std::move(c));
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
}

} // namespace sheaf::io::pov

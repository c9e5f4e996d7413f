// The fractal patterns' arguments: `mandel ITERATIONS`, `julia <C>, ITERATIONS`,
// `magnet 1|2 mandel ITERATIONS` or `magnet 1|2 julia <C>, ITERATIONS`, and their
// modifiers `exponent`, `interior TYPE, FACTOR`, `exterior TYPE, FACTOR`, with POV-Ray's ranges
// (povray refuses an interior type 7 or an exponent of 34 as these do).
#include "io/pov/parser.h"

#include <cmath>

namespace sheaf::io::pov {

void Parser::parse_fractal(PovPattern& pt, const std::string& keyword) {
    bool julia = keyword == "julia";
    pt.fractal.magnet = 0;
    if (keyword == "magnet") {
        const Token& at = peek();
        const double type = parse_float();
        if (type != 1 && type != 2) error_at(at, "a magnet pattern's type must be 1 or 2");
        pt.fractal.magnet = uint8_t(type);
        julia = accept_kw("julia");
        if (!julia && !accept_kw("mandel")) error_expected(peek(), "mandel or julia");
    }
    pt.kind = julia ? PatternKind::Julia : PatternKind::Mandel;
    if (julia) {
        const Token& at = peek();
        const Value c = parse_expr();
        if (c.type != VType::Float && c.type != VType::Vector)
            error_expected(at, "julia's complex constant, a 2-vector such as <0.3, 0.44>");
        pt.fractal.c[0] = float(c.v[0]);
        pt.fractal.c[1] = float(c.type == VType::Float ? c.v[0] : c.v[1]);
        accept_sym(",");
    }
    const Token& at = peek();
    const double n = parse_float();
    if (!(n >= 1 && n <= kFractalMaxIterations))
        error_at(at, "a fractal pattern's iterations must lie between 1 and " +
                         std::to_string(kFractalMaxIterations));
    pt.fractal.iterations = uint16_t(n);
}

void Parser::parse_fractal_modifier(const Token& keyword, FractalParams& f) {
    const std::string& k = keyword.text;
    if (k == "exponent") {
        const Token& at = peek();
        const double e = parse_float();
        if (!(e >= kFractalMinExponent && e <= kFractalMaxExponent))
            error_at(at, "a fractal pattern's exponent must lie between " +
                             std::to_string(kFractalMinExponent) + " and " +
                             std::to_string(kFractalMaxExponent));
        f.exponent = uint8_t(e);
        return;
    }
    const bool inside = k == "interior";
    const Token& at = peek();
    const double type = std::trunc(parse_float()); // povray takes the whole part too
    if (const char* why = fractal_type_error(inside, type))
        error_at(at, std::string("a fractal pattern's ") + (why + 4)); // "the " dropped
    accept_sym(",");
    const Token& factor_at = peek();
    const double factor = parse_float();
    if (const char* why = fractal_factor_error(inside, type, factor)) error_at(factor_at, why);
    if (inside) {
        f.interior_type = uint8_t(type);
        f.interior_factor = float(factor);
    } else {
        f.exterior_type = uint8_t(type);
        f.exterior_factor = float(factor);
    }
}

} // namespace sheaf::io::pov

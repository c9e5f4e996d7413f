// The fractal patterns' arguments: `mandel ITERATIONS`, `julia <C>, ITERATIONS`,
// `magnet 1|2 mandel ITERATIONS` or `magnet 1|2 julia <C>, ITERATIONS`, and their
// modifiers `exponent`, `interior TYPE, FACTOR`, `exterior TYPE, FACTOR`, with POV-Ray's ranges
// (povray refuses an interior type 7 or an exponent of 34 as these do).
#include "io/pov/parser.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

constexpr double kMaxIterations = 65535; // FractalParams::iterations

} // namespace

void Parser::parse_fractal(PovPattern& pt, const std::string& keyword) {
    bool julia = keyword == "julia";
    pt.fractal.magnet = 0;
    if (keyword == "magnet") {
        const Token at = peek();
        const double type = parse_float();
        if (type != 1 && type != 2) error_at(at, "a magnet pattern's type must be 1 or 2");
        pt.fractal.magnet = uint8_t(type);
        julia = accept_kw("julia");
        if (!julia && !accept_kw("mandel")) error_expected(peek(), "mandel or julia");
    }
    pt.kind = julia ? PatternKind::Julia : PatternKind::Mandel;
    if (julia) {
        const Token at = peek();
        const Value c = parse_expr();
        if (c.type != VType::Float && c.type != VType::Vector)
            error_expected(at, "julia's complex constant, a 2-vector such as <0.3, 0.44>");
        pt.fractal.c[0] = float(c.v[0]);
        pt.fractal.c[1] = float(c.type == VType::Float ? c.v[0] : c.v[1]);
        accept_sym(",");
    }
    const Token at = peek();
    const double n = parse_float();
    if (!(n >= 1 && n <= kMaxIterations))
        error_at(at, "a fractal pattern's iterations must lie between 1 and 65535");
    pt.fractal.iterations = uint16_t(n);
}

void Parser::parse_fractal_modifier(const Token& keyword, FractalParams& f) {
    const std::string& k = keyword.text;
    if (k == "exponent") {
        const Token at = peek();
        const double e = parse_float();
        if (!(e >= 2 && e <= 33))
            error_at(at, "a fractal pattern's exponent must lie between 2 and 33");
        f.exponent = uint8_t(e);
        return;
    }
    const bool inside = k == "interior";
    const Token at = peek();
    const double type = parse_float();
    const int most = inside ? 6 : 8;
    if (!(type >= 0 && type <= most))
        error_at(at, "a fractal pattern's " + k + " type must lie between 0 and " +
                         std::to_string(most));
    accept_sym(",");
    const Token factor_at = peek();
    const double factor = parse_float();
    if (!std::isfinite(factor)) error_at(factor_at, "the " + k + " factor must be finite");
    // Types 7 and 8 divide the step by the factor (7: modulo its whole part).
    if (!inside && ((type == 7 && !(factor >= 1)) || (type == 8 && !(factor > 0))))
        error_at(factor_at, "exterior type " + std::to_string(int(type)) + " needs a factor " +
                                (type == 7 ? "of 1 or more" : "above 0"));
    if (inside) {
        f.interior_type = uint8_t(type);
        f.interior_factor = float(factor);
    } else {
        f.exterior_type = uint8_t(type);
        f.exterior_factor = float(factor);
    }
}

} // namespace sheaf::io::pov

// Polynomial objects: quadric, cubic, quartic and poly of order 2 to 4, as ShapeKind::Poly
// with their coefficients in the 35-term layout of core/geometry/poly.h. Higher orders of poly
// (up to POV-Ray's 15) are warned about and left out.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

std::vector<double> Parser::parse_coefficients(const Token& kw, size_t count) {
    const Token& open = peek();
    expect_sym("<", "'<' and " + std::to_string(count) + " coefficients");
    std::vector<double> c;
    ++no_gt_;
    for (;;) {
        const Token& at = peek();
        if (c.size() == count)
            error_expected(at, "'>' after " + std::to_string(count) + " coefficients");
        const Value e = parse_expr();
        if (e.type != VType::Float)
            error_expected(at, std::string("a float coefficient, not ") + type_name(e.type));
        if (!std::isfinite(e.v[0])) error_at(at, "a coefficient is not a finite number");
        c.push_back(e.v[0]);
        if (accept_sym(",")) continue;
        if (!is_sym_tok(peek(), ">") && starts_expression(peek())) continue;
        break;
    }
    --no_gt_;
    if (c.size() != count)
        error_at(open, "'" + kw.text + "' needs " + std::to_string(count) +
                           " coefficients, found " + std::to_string(c.size()));
    expect_sym(">", "',' or '>'");
    return c;
}

bool Parser::parse_poly(const Token& kw, PovObject& o) {
    const std::string& k = kw.text;
    expect_sym("{");
    int order = 2;
    if (k == "cubic") order = 3;
    if (k == "quartic") order = 4;
    if (k == "poly") {
        const Token& at = peek();
        ++no_lt_; // POV-Ray takes poly { 4 <...> } without a comma
        const double n = parse_float();
        --no_lt_;
        if (!(n >= 2 && n <= 15) || n != std::floor(n))
            error_at(at, "a poly's order must be a whole number from 2 to 15");
        order = int(n);
        accept_sym(",");
        if (order > kPolyMaxDegree) {
            unsupported(kw, "poly of order " + std::to_string(order) + " (above 4; left out)");
            skip_rest_of_block();
            return false;
        }
    }
    auto coefficients = std::make_shared<PolyCoeffs>();
    if (k == "quadric") {
        // A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J
        const int terms[10][3] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1},
                                  {0, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}};
        double c[10];
        for (int v = 0; v < 3; ++v) {
            const Token& at = peek();
            const Value e = parse_expr();
            if (!e.numeric()) error_expected(at, std::string("a vector, not ") + type_name(e.type));
            for (int i = 0; i < 3; ++i) c[3 * v + i] = e.type == VType::Float ? e.v[0] : e.v[i];
            accept_sym(",");
        }
        c[9] = parse_float();
        for (int t = 0; t < 10; ++t) {
            if (!std::isfinite(c[t])) error_at(kw, "a coefficient is not a finite number");
            coefficients->c[poly_term(terms[t][0], terms[t][1], terms[t][2])] = c[t];
        }
    } else {
        const std::vector<double> c = parse_coefficients(kw, poly_coefficient_count(order));
        *coefficients = poly_from_pov_order(order, c.data());
    }
    if (poly_is_zero(*coefficients)) error_at(kw, "every coefficient of the " + k + " is zero");
    o.kind = PovKind::Shape;
    o.shape = Shape{ShapeKind::Poly};
    o.poly = std::move(coefficients);
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

} // namespace sheaf::io::pov

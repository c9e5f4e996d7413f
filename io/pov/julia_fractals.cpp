// julia_fractal { <C4>  quaternion | hypercomplex  sqr | cube | FUNCTION  max_iteration N
// precision P  slice <S4>, D  modifiers }: the julia shape of core/geometry/julia.h. POV-Ray's
// rules: max_iteration below 1 is 1, precision below 1 is 1, the slice is normalised and needs
// a w component. Quaternions take sqr and cube; hypercomplex numbers also take POV-Ray's
// complex functions (exp, sin, pwr ...), which Sheaf does not render: such a fractal is
// warned and left out.
#include "io/pov/parser.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

const char* const kComplexFunctions[] = {"exp",  "ln",    "sin",  "asin",  "cos",
                                         "acos", "tan",   "atan", "sinh",  "asinh",
                                         "cosh", "acosh", "tanh", "atanh", "reciprocal"};

} // namespace

bool Parser::parse_julia_fractal(const Token& kw, PovObject& o) {
    expect_sym("{");
    auto j = std::make_shared<JuliaFractal>();
    auto vector4 = [&](const char* what, double* out) {
        const Token& at = peek();
        const Value v = parse_expr();
        if (v.type == VType::Float) {
            for (int i = 0; i < 4; ++i) out[i] = v.v[0];
        } else if (v.type == VType::Vector && v.dim == 4) {
            for (int i = 0; i < 4; ++i) out[i] = v.v[i];
        } else {
            error_expected(at, std::string(what) + ", a 4-vector such as <-0.083, 0, -0.83, 0>");
        }
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(out[i])) error_at(at, std::string(what) + " is not finite");
    };
    vector4("the Julia parameter", j->c);
    bool hypercomplex = false, cube = false;
    Token function_at = kw;
    std::string other_function; // a complex function Sheaf leaves out
    bool texture_here = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("quaternion")) {
            hypercomplex = false;
        } else if (accept_kw("hypercomplex")) {
            hypercomplex = true;
        } else if (accept_kw("sqr") || accept_kw("cube")) {
            cube = t.text == "cube", other_function.clear(), function_at = t;
        } else if (accept_kw("pwr")) {
            expect_sym("(");
            parse_float();
            accept_sym(",");
            parse_float();
            expect_sym(")");
            other_function = "pwr", function_at = t;
        } else if (accept_kw("max_iteration")) {
            const Token& at = peek();
            const double n = std::floor(parse_float());
            if (!std::isfinite(n)) error_at(at, "max_iteration is not finite");
            if (n > double(kJuliaMaxIterations))
                error_at(at, "max_iteration above " + std::to_string(kJuliaMaxIterations) +
                                 " (Sheaf keeps every iterate of a point)");
            j->iterations = n < 1 ? 1u : uint32_t(n);
        } else if (accept_kw("precision")) {
            const Token& at = peek();
            const double p = parse_float();
            if (!std::isfinite(p)) error_at(at, "precision is not finite");
            j->min_step = 1.0 / (p < 1 ? 1.0 : p);
        } else if (accept_kw("slice")) {
            const Token& at = peek();
            vector4("the slice's normal", j->slice);
            accept_sym(",");
            const Token& dist_at = peek();
            j->slice_dist = parse_float();
            if (!std::isfinite(j->slice_dist))
                error_at(dist_at, "the slice's distance is not finite");
            double len = 0;
            for (double s : j->slice) len += s * s;
            len = std::sqrt(len);
            if (!(len >= 1e-10)) error_at(at, "the slice's normal is zero");
            if (!(std::fabs(j->slice[3]) >= 1e-10)) error_at(at, "the slice's w component is zero");
            for (double& s : j->slice) s /= len;
        } else {
            bool named = false;
            for (const char* f : kComplexFunctions)
                if (accept_kw(f)) {
                    other_function = f, function_at = t, named = true;
                    break;
                }
            if (!named && !parse_modifier(o, texture_here))
                error_expected(t, "quaternion, hypercomplex, sqr, cube, max_iteration, precision, "
                                  "slice, a modifier or '}'");
        }
    }
    if (!other_function.empty() && !hypercomplex)
        error_at(function_at, "a quaternion julia_fractal takes sqr or cube, not " +
                                  other_function + " (hypercomplex takes more)");
    if (!other_function.empty()) {
        unsupported(function_at, "julia_fractal function '" + other_function + "' (left out)");
        return false;
    }
    // POV-Ray's hypercomplex cube iterates the square too; only its step estimate differs.
    j->algebra = hypercomplex ? JuliaAlgebra::HypercomplexSqr
                 : cube       ? JuliaAlgebra::QuaternionCube
                              : JuliaAlgebra::QuaternionSqr;
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Julia;
    o.julia = std::move(j);
    return true;
}

} // namespace sheaf::io::pov

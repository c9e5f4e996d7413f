// isosurface { function { ... }  contained_by { box { A, B } | sphere { C, R } }
// threshold T  accuracy A  max_gradient G  evaluate P0, P1, P2  open  max_trace N
// all_intersections  modifiers }: the isosurface shape of core/geometry/isosurface.h, its
// function compiled for both backends when the scene is built (io/pov/fn_compile.h).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

bool Parser::parse_isosurface(const Token& kw, PovObject& o) {
    expect_sym("{");
    auto iso = std::make_shared<IsoRef>();
    std::shared_ptr<const PovFunction> fn;
    Token fn_at = kw;
    auto positive = [&](const char* what) {
        const Token& at = peek();
        const double v = parse_float();
        if (!(v > 0) || !std::isfinite(v))
            error_at(at, std::string("an isosurface's ") + what + " must be a positive number");
        return float(v);
    };
    bool texture_here = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (is_kw_tok(t, "function")) {
            advance();
            fn_at = t;
            const Value v = parse_function(t);
            fn = std::static_pointer_cast<const PovFunction>(v.ptr);
            if (fn->params.size() != 3 && fn->scene_unsupported.empty())
                error_at(t, "an isosurface's function must take x, y and z");
        } else if (accept_kw("contained_by")) {
            expect_sym("{");
            const Token& shape = peek();
            if (accept_kw("box")) {
                expect_sym("{");
                const Vec3 a = parse_vector();
                accept_sym(",");
                const Vec3 b = parse_vector();
                expect_sym("}", "'}' (a container takes no modifiers)");
                iso->sphere = false;
                iso->lo = vmin(a, b), iso->hi = vmax(a, b);
                if (!(iso->lo.x < iso->hi.x && iso->lo.y < iso->hi.y && iso->lo.z < iso->hi.z))
                    error_at(shape, "an isosurface's container box is flat or empty");
            } else if (accept_kw("sphere")) {
                expect_sym("{");
                const Vec3 c = parse_vector();
                accept_sym(",");
                const Token& at = peek();
                const double r = parse_float();
                expect_sym("}", "'}' (a container takes no modifiers)");
                if (!(r > 0)) error_at(at, "an isosurface's container sphere needs a radius > 0");
                iso->sphere = true;
                iso->lo = c, iso->hi = Vec3(float(r), 0, 0);
            } else {
                error_expected(shape, "box or sphere");
            }
            expect_sym("}");
        } else if (accept_kw("threshold")) {
            iso->threshold = float(parse_float());
        } else if (accept_kw("accuracy")) {
            iso->accuracy = positive("accuracy");
        } else if (accept_kw("max_gradient")) {
            iso->max_gradient = positive("max_gradient");
        } else if (accept_kw("evaluate")) { // POV-Ray's estimate of the gradient: its minimum
            const float p0 = positive("evaluate minimum");
            accept_sym(",");
            parse_float();
            accept_sym(",");
            parse_float();
            iso->max_gradient = std::max(iso->max_gradient, p0);
        } else if (accept_kw("open")) {
            iso->open = parse_bool_opt(true);
        } else if (accept_kw("max_trace")) {
            parse_float(); // Sheaf finds every crossing up to the shape's span limit
        } else if (accept_kw("all_intersections") || accept_kw("polarity")) {
        } else if (!parse_modifier(o, texture_here)) {
            error_expected(t, "function, contained_by, threshold, accuracy, max_gradient, "
                              "evaluate, open, max_trace, a modifier or '}'");
        }
    }
    if (!fn) error_at(kw, "an isosurface needs a function { ... }");
    if (!fn->unsupported.empty()) {
        unsupported(fn_at, "isosurface of a " + fn->unsupported + " (left out)");
        return false;
    }
    if (!std::isfinite(iso->threshold)) error_at(kw, "an isosurface's threshold is not finite");
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Isosurface;
    o.iso = std::move(iso);
    o.iso_function = std::move(fn);
    return true;
}

} // namespace sheaf::io::pov

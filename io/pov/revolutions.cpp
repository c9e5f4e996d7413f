// lathe { [SPLINE] N, <r, h> ... [sturm] } and sor { N, <r, h> ... [open] [sturm] }: a profile
// in POV-Ray's x-y plane turned about its y axis, as a revolution shape
// (core/geometry/revolution.h), exact; the profiles are built as POV-Ray defines them by
// core/geometry/revolution_profile.h. A lathe whose curve does not enclose a solid is the
// surface POV-Ray draws (Shape::open).
#include "io/pov/parser.h"

#include "core/base/error.h"
#include "core/geometry/revolution_profile.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

/// POV-Ray's y axis as the shape's z: (x, y, z) -> (x, z, y).
Affine about_y() {
    Affine m;
    m.m[1][1] = 0, m.m[2][2] = 0, m.m[1][2] = 1, m.m[2][1] = 1;
    return m;
}

} // namespace

std::vector<Vec3> Parser::parse_profile_points(const Token& count_at, int n, const char* what,
                                               std::vector<Token>& where) {
    charge(size_t(n) * (sizeof(Vec3) + sizeof(RevolutionSegment) + sizeof(Token)), count_at);
    std::vector<Vec3> p(static_cast<size_t>(n));
    where.clear();
    for (int i = 0; i < n; ++i) {
        const Token& at = peek();
        where.push_back(at);
        const Value v = parse_expr();
        if (!v.numeric() || v.type == VType::Float)
            error_expected(at, std::string("the ") + what + "'s point " + std::to_string(i + 1) +
                                   " of " + std::to_string(n) + " (a 2-D vector <r, h>)");
        p[size_t(i)] = Vec3(float(v.v[0]), float(v.v[1]), 0); // checked by the profile's builder
        accept_sym(",");
    }
    return p;
}

int Parser::parse_profile_count(const Token& count_at, int minimum, const char* what) {
    ++no_lt_; // "4 <0, 0> ..." is the count and the first point
    const double count = parse_float();
    --no_lt_;
    accept_sym(",");
    if (!(count >= minimum && count <= 1e6) || count != std::floor(count))
        error_at(count_at, std::string("a ") + what + " needs a whole number of at least " +
                               std::to_string(minimum) + " points");
    return int(count);
}

bool Parser::parse_lathe(const Token& kw, PovObject& o) {
    expect_sym("{");
    LatheSpline spline = LatheSpline::Linear;
    for (;;) {
        const Token& t = peek();
        if (is_kw_tok(t, "linear_spline"))
            spline = LatheSpline::Linear;
        else if (is_kw_tok(t, "quadratic_spline"))
            spline = LatheSpline::Quadratic;
        else if (is_kw_tok(t, "cubic_spline"))
            spline = LatheSpline::Cubic;
        else if (is_kw_tok(t, "bezier_spline"))
            spline = LatheSpline::Bezier;
        else
            break;
        next();
    }
    const Token& count_at = peek();
    const int n = parse_profile_count(count_at, lathe_min_points(spline), "lathe with this spline");
    std::vector<Token> where;
    const std::vector<Vec3> p = parse_profile_points(count_at, n, "lathe", where);
    bool solid = false;
    try {
        o.revolution = std::make_shared<RevolutionProfile>(lathe_profile(p, spline, solid));
    } catch (const ProfileError& e) {
        error_at(e.point >= 0 ? where[size_t(e.point)] : count_at, e.what());
    }
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Revolution;
    o.shape.open = !solid;
    o.local = about_y();
    accept_kw("sturm");
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

bool Parser::parse_sor(const Token& kw, PovObject& o) {
    expect_sym("{");
    const Token& count_at = peek();
    const int n = parse_profile_count(count_at, 4, "sor");
    std::vector<Token> where;
    const std::vector<Vec3> p = parse_profile_points(count_at, n, "sor", where);
    bool open = false;
    for (;;) {
        if (accept_kw("open"))
            open = true;
        else if (!accept_kw("sturm"))
            break;
    }
    try {
        o.revolution = std::make_shared<RevolutionProfile>(sor_profile(p, open));
    } catch (const ProfileError& e) {
        error_at(e.point >= 0 ? where[size_t(e.point)] : count_at, e.what());
    }
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Revolution;
    o.shape.open = open;
    o.local = about_y();
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

} // namespace sheaf::io::pov

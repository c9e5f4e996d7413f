// lathe { [SPLINE] N, <r, h> ... [sturm] } and sor { N, <r, h> ... [open] [sturm] }: a profile
// in POV-Ray's x-y plane turned about its y axis, as a revolution shape
// (core/geometry/revolution.h), exact. A lathe's splines are POV-Ray's: linear_spline through
// the points; quadratic_spline from the second point on, the first only steering; cubic_spline
// (Catmull-Rom) from the second point to the last but one; bezier_spline four points a
// segment. A lathe whose curve comes back to its first point, or starts and ends on the axis,
// is a solid; any other only a surface, as POV-Ray draws it. A sor's radius squared is a cubic
// in the height through the points from the second to the last but one, its slopes there set
// by the neighbours (POV-Ray's definition), closed by flat caps unless `open`.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

/// A Bézier segment of degree `deg` (1 to 3) through control points `p` (x: radius, y: height).
RevolutionSegment segment(std::initializer_list<Vec3> p) {
    RevolutionSegment s;
    uint32_t i = 0;
    for (const Vec3& v : p) s.w[i] = v.x, s.h[i] = v.y, ++i;
    s.wdeg = s.hdeg = i - 1;
    return s;
}

/// a + (b - c) * k in double, rounded once.
Vec3 toward(const Vec3& a, const Vec3& b, const Vec3& c, double k) {
    return Vec3(float(a.x + (double(b.x) - c.x) * k), float(a.y + (double(b.y) - c.y) * k), 0);
}

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
        const Token at = peek();
        where.push_back(at);
        const Value v = parse_expr();
        if (!v.numeric() || v.type == VType::Float)
            error_expected(at, std::string("the ") + what + "'s point " + std::to_string(i + 1) +
                                   " of " + std::to_string(n) + " (a 2-D vector <r, h>)");
        p[size_t(i)] = Vec3(float(v.v[0]), float(v.v[1]), 0);
        if (!std::isfinite(p[size_t(i)].x) || !std::isfinite(p[size_t(i)].y))
            error_at(at, std::string("a ") + what + "'s point is not a finite number");
        accept_sym(",");
    }
    return p;
}

bool Parser::parse_lathe(const Token& kw, PovObject& o) {
    expect_sym("{");
    enum class Spline { Linear, Quadratic, Cubic, Bezier } spline = Spline::Linear;
    for (;;) {
        const Token& t = peek();
        if (is_kw_tok(t, "linear_spline"))
            spline = Spline::Linear;
        else if (is_kw_tok(t, "quadratic_spline"))
            spline = Spline::Quadratic;
        else if (is_kw_tok(t, "cubic_spline"))
            spline = Spline::Cubic;
        else if (is_kw_tok(t, "bezier_spline"))
            spline = Spline::Bezier;
        else
            break;
        next();
    }
    const Token count_at = peek();
    ++no_lt_; // "4 <0, 0> ..." is the count and the first point
    const double count = parse_float();
    --no_lt_;
    accept_sym(",");
    const int minimum = spline == Spline::Linear ? 2 : spline == Spline::Quadratic ? 3 : 4;
    if (!(count >= minimum && count <= 1e6) || count != std::floor(count))
        error_at(count_at, "a lathe with this spline needs a whole number of at least " +
                               std::to_string(minimum) + " points");
    const int n = int(count);
    if (spline == Spline::Bezier && n % 4 != 0)
        error_at(count_at, "a lathe's bezier_spline takes its points four at a time");
    std::vector<Token> where;
    const std::vector<Vec3> p = parse_profile_points(count_at, n, "lathe", where);
    // The points the curve runs through must not lie left of the axis (POV-Ray's rule).
    for (int i = 0; i < n; ++i) {
        const bool on_curve = spline == Spline::Linear      ? true
                              : spline == Spline::Quadratic ? i > 0
                              : spline == Spline::Cubic     ? i > 0 && i < n - 1
                                                            : i % 4 == 0 || i % 4 == 3;
        if (on_curve && p[size_t(i)].x < 0)
            error_at(where[size_t(i)], "the lathe's point " + std::to_string(i + 1) +
                                           " has a negative radius (x < 0)");
    }
    auto profile = std::make_shared<RevolutionProfile>();
    std::vector<RevolutionSegment>& s = profile->segments;
    const auto at = [&](int k) { return p[size_t(k)]; };
    switch (spline) {
    case Spline::Linear:
        for (int i = 0; i + 1 < n; ++i) s.push_back(segment({at(i), at(i + 1)}));
        break;
    case Spline::Quadratic: // from p[i+1] to p[i+2], leaving along (p[i+2] - p[i]) / 2
        for (int i = 0; i + 2 < n; ++i)
            s.push_back(segment({at(i + 1), toward(at(i + 1), at(i + 2), at(i), 0.25), at(i + 2)}));
        break;
    case Spline::Cubic: // Catmull-Rom from p[i+1] to p[i+2]
        for (int i = 0; i + 3 < n; ++i)
            s.push_back(segment({at(i + 1), toward(at(i + 1), at(i + 2), at(i), 1.0 / 6),
                                 toward(at(i + 2), at(i + 1), at(i + 3), 1.0 / 6), at(i + 2)}));
        break;
    case Spline::Bezier:
        for (int i = 0; i + 3 < n; i += 4)
            s.push_back(segment({at(i), at(i + 1), at(i + 2), at(i + 3)}));
        break;
    }
    // A solid when the curve is one closed chain, or one chain from the axis to the axis
    // (closed along it, where no ray crosses); else the surface POV-Ray draws.
    bool chained = true;
    for (size_t i = 1; i < s.size(); ++i) {
        const RevolutionSegment &a = s[i - 1], &b = s[i];
        chained = chained && a.w[a.wdeg] == b.w[0] && a.h[a.hdeg] == b.h[0];
    }
    const RevolutionSegment &first = s.front(), &last = s.back();
    const bool closed = first.w[0] == last.w[last.wdeg] && first.h[0] == last.h[last.hdeg];
    const bool on_axis = first.w[0] == 0 && last.w[last.wdeg] == 0;
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Revolution;
    o.shape.open = !(chained && (closed || on_axis));
    o.revolution = std::move(profile);
    o.local = about_y();
    accept_kw("sturm");
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

bool Parser::parse_sor(const Token& kw, PovObject& o) {
    expect_sym("{");
    const Token count_at = peek();
    ++no_lt_;
    const double count = parse_float();
    --no_lt_;
    accept_sym(",");
    if (!(count >= 4 && count <= 1e6) || count != std::floor(count))
        error_at(count_at, "a sor needs a whole number of at least 4 points");
    const int n = int(count);
    std::vector<Token> where;
    const std::vector<Vec3> p = parse_profile_points(count_at, n, "sor", where);
    for (int i = 0; i < n; ++i) {
        if (p[size_t(i)].x < 0)
            error_at(where[size_t(i)],
                     "the sor's point " + std::to_string(i + 1) + " has a negative radius (x < 0)");
        // The curve's points must rise (POV-Ray's rule; the first and last only steer).
        if (i > 1 && i < n - 1 && !(p[size_t(i)].y > p[size_t(i - 1)].y))
            error_at(where[size_t(i)], "the sor's heights must rise from point to point (point " +
                                           std::to_string(i + 1) + " is not above point " +
                                           std::to_string(i) + ")");
    }
    if (!(p[2].y != p[0].y) || !(p[size_t(n - 1)].y != p[size_t(n - 3)].y))
        error_at(where[p[2].y != p[0].y ? size_t(n - 1) : 0],
                 "the sor's first and last points must differ in height from the "
                 "curve's second and last but one (they set its slopes there)");
    auto profile = std::make_shared<RevolutionProfile>();
    profile->squared = true;
    std::vector<RevolutionSegment>& s = profile->segments;
    // Segment i: r^2 from p[i+1] to p[i+2] as a cubic in the height, with the slopes of
    // the chords p[i] -> p[i+2] and p[i+1] -> p[i+3] there (d r^2 / dh = 2 r dr/dh).
    for (int i = 0; i + 3 < n; ++i) {
        const double x0 = p[size_t(i)].x, x1 = p[size_t(i + 1)].x, x2 = p[size_t(i + 2)].x,
                     x3 = p[size_t(i + 3)].x;
        const double y0 = p[size_t(i)].y, y1 = p[size_t(i + 1)].y, y2 = p[size_t(i + 2)].y,
                     y3 = p[size_t(i + 3)].y;
        const double m1 = 2 * x1 * (x2 - x0) / (y2 - y0), m2 = 2 * x2 * (x3 - x1) / (y3 - y1);
        const double dh = y2 - y1;
        RevolutionSegment g;
        g.wdeg = 3, g.hdeg = 1;
        g.w[0] = float(x1 * x1), g.w[3] = float(x2 * x2);
        g.w[1] = float(x1 * x1 + m1 * dh / 3), g.w[2] = float(x2 * x2 - m2 * dh / 3);
        g.h[0] = float(y1), g.h[1] = float(y2);
        s.push_back(g);
    }
    o.kind = PovKind::Shape;
    o.shape.kind = ShapeKind::Revolution;
    o.local = about_y();
    bool open = false;
    for (;;) {
        if (accept_kw("open"))
            open = true;
        else if (!accept_kw("sturm"))
            break;
    }
    if (!open) { // the caps: flat, from the axis to the curve's first and last radius
        RevolutionSegment bottom, top;
        bottom.w[0] = 0, bottom.w[1] = s.front().w[0];
        bottom.h[0] = bottom.h[1] = s.front().h[0];
        top.w[0] = s.back().w[3], top.w[1] = 0;
        top.h[0] = top.h[1] = s.back().h[1];
        s.insert(s.begin(), bottom);
        s.push_back(top);
    }
    o.shape.open = open;
    o.revolution = std::move(profile);
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

} // namespace sheaf::io::pov

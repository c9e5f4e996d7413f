// prism { [linear_sweep | conic_sweep] [SPLINE] H1, H2, N, <u, v> ... [open] [sturm] }: the
// region its splines enclose in POV-Ray's x-z plane (even-odd, as POV-Ray fills it: a contour
// inside another is a hole), swept along y from H1 to H2, as a glyph shape
// (core/geometry/glyph.h). The splines become quadratic segments as POV-Ray defines them:
// linear_spline runs through the points, each contour closed when a point repeats its first;
// quadratic_spline (exact as quadratic Béziers) and cubic_spline (Catmull-Rom, 16 quadratics a
// segment) run from the second point of each group, the first and last only steering it;
// bezier_spline takes the points four at a time (16 quadratics a segment). conic_sweep scales
// the outline by the height (the point (x, y, z) is inside where (x / y, z / y) is), as a
// conic glyph; heights on both sides of 0 (two cones meeting at the apex) are warned and left
// out.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

constexpr double kSame = 1e-10; // POV-Ray's EPSILON: a point that closes its contour
constexpr int kCubicPieces = 16;

bool same(const Vec3& a, const Vec3& b) {
    return std::fabs(double(a.x) - b.x) < kSame && std::fabs(double(a.y) - b.y) < kSame;
}

void line(std::vector<GlyphSegment>& out, const Vec3& a, const Vec3& b) {
    out.push_back({a.x, a.y, 0.5f * (a.x + b.x), 0.5f * (a.y + b.y), b.x, b.y});
}

/// The cubic Bézier with control points p0 .. p3, as kCubicPieces quadratics.
void cubic(std::vector<GlyphSegment>& out, const Vec3& p0, const Vec3& p1, const Vec3& p2,
           const Vec3& p3) {
    const double p[4][2] = {{p0.x, p0.y}, {p1.x, p1.y}, {p2.x, p2.y}, {p3.x, p3.y}};
    cubic_to_quadratics(p, kCubicPieces, out);
}

} // namespace

bool Parser::parse_prism(const Token& kw, PovObject& o) {
    expect_sym("{");
    enum class Spline { Linear, Quadratic, Cubic, Bezier } spline = Spline::Linear;
    bool conic = false;
    for (;;) {
        const Token& t = peek();
        if (is_kw_tok(t, "linear_sweep") || is_kw_tok(t, "conic_sweep")) {
            conic = t.text == "conic_sweep";
        } else if (is_kw_tok(t, "linear_spline")) {
            spline = Spline::Linear;
        } else if (is_kw_tok(t, "quadratic_spline")) {
            spline = Spline::Quadratic;
        } else if (is_kw_tok(t, "cubic_spline")) {
            spline = Spline::Cubic;
        } else if (is_kw_tok(t, "bezier_spline")) {
            spline = Spline::Bezier;
        } else {
            break;
        }
        next();
    }
    double h1 = parse_float();
    accept_sym(",");
    double h2 = parse_float();
    accept_sym(",");
    const Token& count_at = peek();
    ++no_lt_; // POV-Ray reads "4 <-1, 0> ..." as the count and the first point
    const double count = parse_float();
    --no_lt_;
    accept_sym(",");
    const int minimum = spline == Spline::Linear      ? 3
                        : spline == Spline::Quadratic ? 5
                        : spline == Spline::Cubic     ? 6
                                                      : 4;
    if (!(count >= minimum && count <= 1e6) || count != std::floor(count))
        error_at(count_at, "a prism with this spline needs a whole number of at least " +
                               std::to_string(minimum) + " points");
    if (spline == Spline::Bezier && int(count) % 4 != 0)
        error_at(count_at, "a prism's bezier_spline takes its points four at a time");
    const int n = int(count);
    charge(size_t(n) * (sizeof(Vec3) + kCubicPieces * sizeof(GlyphSegment)), count_at);
    std::vector<Vec3> p(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Token& at = peek();
        // Fewer points than the count says: name the point that is missing.
        if (at.kind == TokKind::End || is_sym_tok(at, "}"))
            error_expected(at, "the prism's point " + std::to_string(i + 1) + " of " +
                                   std::to_string(n) + " (a 2-D vector <u, v>)");
        const Value v = parse_expr();
        if (!v.numeric() || v.type == VType::Float)
            error_expected(at, "the prism's point " + std::to_string(i + 1) + " of " +
                                   std::to_string(n) + " (a 2-D vector <u, v>)");
        p[size_t(i)] = Vec3(float(v.v[0]), float(v.v[1]), 0);
        if (!std::isfinite(p[size_t(i)].x) || !std::isfinite(p[size_t(i)].y))
            error_at(at, "a prism's point is not a finite number");
        accept_sym(",");
    }
    auto outline = std::make_shared<GlyphOutline>();
    outline->even_odd = true;
    std::vector<GlyphSegment>& s = outline->segments;
    // The segments, as POV-Ray walks the points: a contour ends where a point comes back to
    // its first one, and the next contour starts after it.
    Vec3 first = spline == Spline::Linear ? p[0] : p[1];
    bool closed = spline == Spline::Bezier; // its segments are not chained by the points
    int left = 0;                           // points that make no segment (a contour left open)
    for (int i = 0; i + 1 < n; ++i) {
        const auto at = [&](int k) { return p[size_t(k)]; };
        const int needed = spline == Spline::Linear ? 1 : spline == Spline::Quadratic ? 2 : 3;
        if (i + needed >= n) {
            left = n - 1 - i;
            break;
        }
        closed = spline == Spline::Bezier;
        switch (spline) {
        case Spline::Linear:
            line(s, at(i), at(i + 1));
            if (same(at(i + 1), first)) {
                closed = true, ++i;
                if (i + 1 < n) first = at(i + 1);
            }
            break;
        case Spline::Quadratic: {
            // Through p[i+1] and p[i+2], leaving p[i+1] along (p[i+2] - p[i]) / 2.
            const Vec3 a = at(i + 1), b = at(i + 2), c = a + (b - at(i)) * 0.25f;
            s.push_back({a.x, a.y, c.x, c.y, b.x, b.y});
            if (same(b, first)) {
                closed = true, i += 2;
                if (i + 2 < n) first = at(i + 2);
            }
            break;
        }
        case Spline::Cubic: {
            // Catmull-Rom from p[i+1] to p[i+2].
            const Vec3 a = at(i + 1), b = at(i + 2);
            cubic(s, a, a + (b - at(i)) * (1.0f / 6), b - (at(i + 3) - a) * (1.0f / 6), b);
            if (same(b, first)) {
                closed = true, i += 3;
                if (i + 2 < n) first = at(i + 2);
            }
            break;
        }
        case Spline::Bezier:
            cubic(s, at(i), at(i + 1), at(i + 2), at(i + 3));
            i += 3;
            break;
        }
    }
    if (!closed || left > 0) {
        // POV-Ray stops with "too few points" where a spline's contour does not come back to
        // its first point; a linear one it leaves open, which fills nothing sensible.
        error_at(count_at, "the prism's points do not close its last contour (a contour ends "
                           "where a point repeats the contour's first; " +
                               std::string(spline == Spline::Linear
                                               ? "its first point"
                                               : "its second point, the first only steers") +
                               ")");
    }
    if (h1 > h2) std::swap(h1, h2);
    o.kind = PovKind::Shape;
    if (s.empty() || !(h2 - h1 > 0)) { // POV-Ray's degenerate prism: nothing to draw
        unsupported(kw, "degenerate prism (no area or no height; left out)");
        o.kind = PovKind::Csg, o.op = CsgOp::Union;
    } else if (conic && h1 < 0 && h2 > 0) {
        unsupported(kw, "prism with conic_sweep from below to above height 0 (left out)");
        o.kind = PovKind::Csg, o.op = CsgOp::Union;
    } else if (conic) {
        o.shape.kind = ShapeKind::Glyph;
        o.glyph = std::move(outline);
        // Below 0 the outline is turned through the apex: the prism between -h2 and -h1,
        // mirrored through the origin.
        const double sign = h2 <= 0 ? -1 : 1;
        const double lo = sign > 0 ? h1 : -h2, hi = sign > 0 ? h2 : -h1;
        // Local (x, y, z): the outline's plane scaled by 1 / hi, and the sweep from lo (z = 0,
        // the outline at base scale lo / hi) to hi (z = 1, at scale 1).
        o.shape.a = float(lo / hi), o.shape.b = 1;
        Affine m;
        m.m[0][0] = float(sign * hi), m.m[2][1] = float(sign * hi);
        m.m[1][2] = float(sign * (hi - lo)), m.m[1][3] = float(sign * lo);
        m.m[1][1] = 0, m.m[2][2] = 0;
        o.local = m;
    } else {
        o.shape.kind = ShapeKind::Glyph;
        o.glyph = std::move(outline);
        // The outline's plane is POV-Ray's x-z, the sweep its y from h1 to h2.
        Affine m;
        m.m[0][0] = 1, m.m[2][1] = 1, m.m[1][2] = float(h2 - h1), m.m[1][3] = float(h1);
        m.m[1][1] = 0, m.m[2][2] = 0;
        o.local = m;
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

} // namespace sheaf::io::pov

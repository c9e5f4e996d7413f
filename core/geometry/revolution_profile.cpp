#include "core/geometry/revolution_profile.h"

#include <cmath>

namespace sheaf {

namespace {

/// A Bézier segment through control points `p` (x: radius, y: height), of their degree.
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

void check_finite(const std::vector<Vec3>& p, const char* what) {
    for (size_t i = 0; i < p.size(); ++i)
        if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y))
            throw ProfileError(int(i), std::string("the ") + what + "'s point " +
                                           std::to_string(i + 1) + " is not a finite number");
}

/// The segments' control points, computed in double, must fit single precision.
void check_segments(const RevolutionProfile& prof, const char* what) {
    for (const RevolutionSegment& s : prof.segments)
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(s.w[i]) || !std::isfinite(s.h[i]))
                throw ProfileError(-1, std::string("the ") + what +
                                           "'s points are too large (its curve overflows "
                                           "single precision)");
}

} // namespace

int lathe_min_points(LatheSpline spline) {
    return spline == LatheSpline::Linear ? 2 : spline == LatheSpline::Quadratic ? 3 : 4;
}

RevolutionProfile lathe_profile(const std::vector<Vec3>& p, LatheSpline spline, bool& solid) {
    const int n = int(p.size());
    if (n < lathe_min_points(spline))
        throw ProfileError(-1, "a lathe with this spline needs at least " +
                                   std::to_string(lathe_min_points(spline)) + " points");
    if (spline == LatheSpline::Bezier && n % 4 != 0)
        throw ProfileError(-1, "a lathe's bezier_spline takes its points four at a time");
    check_finite(p, "lathe");
    // The points the curve runs through must not lie left of the axis (POV-Ray's rule).
    for (int i = 0; i < n; ++i) {
        const bool on_curve = spline == LatheSpline::Linear      ? true
                              : spline == LatheSpline::Quadratic ? i > 0
                              : spline == LatheSpline::Cubic     ? i > 0 && i < n - 1
                                                                 : i % 4 == 0 || i % 4 == 3;
        if (on_curve && p[size_t(i)].x < 0)
            throw ProfileError(i, "the lathe's point " + std::to_string(i + 1) +
                                      " has a negative radius (x < 0)");
    }
    RevolutionProfile profile;
    std::vector<RevolutionSegment>& s = profile.segments;
    const auto at = [&](int k) { return p[size_t(k)]; };
    switch (spline) {
    case LatheSpline::Linear:
        for (int i = 0; i + 1 < n; ++i) s.push_back(segment({at(i), at(i + 1)}));
        break;
    case LatheSpline::Quadratic: // from p[i+1] to p[i+2], leaving along (p[i+2] - p[i]) / 2
        for (int i = 0; i + 2 < n; ++i)
            s.push_back(segment({at(i + 1), toward(at(i + 1), at(i + 2), at(i), 0.25), at(i + 2)}));
        break;
    case LatheSpline::Cubic: // Catmull-Rom from p[i+1] to p[i+2]
        for (int i = 0; i + 3 < n; ++i)
            s.push_back(segment({at(i + 1), toward(at(i + 1), at(i + 2), at(i), 1.0 / 6),
                                 toward(at(i + 2), at(i + 1), at(i + 3), 1.0 / 6), at(i + 2)}));
        break;
    case LatheSpline::Bezier:
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
    solid = chained && (closed || on_axis);
    check_segments(profile, "lathe");
    return profile;
}

RevolutionProfile sor_profile(const std::vector<Vec3>& p, bool open) {
    const int n = int(p.size());
    if (n < 4) throw ProfileError(-1, "a sor needs at least 4 points");
    check_finite(p, "sor");
    for (int i = 0; i < n; ++i) {
        if (p[size_t(i)].x < 0)
            throw ProfileError(i, "the sor's point " + std::to_string(i + 1) +
                                      " has a negative radius (x < 0)");
        // The curve's points must rise (POV-Ray's rule; the first and last only steer).
        if (i > 1 && i < n - 1 && !(p[size_t(i)].y > p[size_t(i - 1)].y))
            throw ProfileError(i, "the sor's heights must rise from point to point (point " +
                                      std::to_string(i + 1) + " is not above point " +
                                      std::to_string(i) + ")");
    }
    if (!(p[2].y != p[0].y) || !(p[size_t(n - 1)].y != p[size_t(n - 3)].y))
        throw ProfileError(p[2].y != p[0].y ? n - 1 : 0,
                           "the sor's first and last points must differ in height from the "
                           "curve's second and last but one (they set its slopes there)");
    RevolutionProfile profile;
    profile.squared = true;
    std::vector<RevolutionSegment>& s = profile.segments;
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
    if (!open) { // the caps: flat, from the axis to the curve's first and last radius
        RevolutionSegment bottom, top;
        bottom.w[0] = 0, bottom.w[1] = s.front().w[0];
        bottom.h[0] = bottom.h[1] = s.front().h[0];
        top.w[0] = s.back().w[3], top.w[1] = 0;
        top.h[0] = top.h[1] = s.back().h[1];
        s.insert(s.begin(), bottom);
        s.push_back(top);
    }
    check_segments(profile, "sor");
    return profile;
}

} // namespace sheaf

// Splines of the scene language (see splines.h): their parsing, and their values as POV-Ray
// 3.7 computes them (checked against povray's #debug output in splines_test.cpp).
#include "io/pov/splines.h"

#include "io/pov/parser.h"

#include <algorithm>
#include <cmath>

namespace sheaf::io::pov {

namespace {

using Point = std::array<double, 5>;

/// The second derivatives of the natural cubic spline through the entries, component by
/// component: zero at both ends, the rest from the tridiagonal system of its continuity.
std::vector<Point> natural_moments(const std::vector<PovSpline::Entry>& e) {
    const size_t n = e.size();
    std::vector<Point> m(n, Point{});
    if (n < 3) return m;
    std::vector<double> diag(n), rhs(n), h(n - 1), slope(n - 1);
    for (int k = 0; k < 5; ++k) {
        for (size_t i = 0; i + 1 < n; ++i) {
            h[i] = e[i + 1].time - e[i].time;
            slope[i] = (e[i + 1].point[size_t(k)] - e[i].point[size_t(k)]) / h[i];
        }
        // Forward elimination of h[i-1] m[i-1] + 2 (h[i-1] + h[i]) m[i] + h[i] m[i+1] =
        // 6 (slope[i] - slope[i-1]), for i = 1 .. n-2.
        for (size_t i = 1; i + 1 < n; ++i) {
            diag[i] = 2 * (h[i - 1] + h[i]);
            rhs[i] = 6 * (slope[i] - slope[i - 1]);
            if (i > 1) {
                diag[i] -= h[i - 1] * h[i - 1] / diag[i - 1];
                rhs[i] -= h[i - 1] * rhs[i - 1] / diag[i - 1];
            }
        }
        for (size_t i = n - 2; i >= 1; --i)
            m[i][size_t(k)] = (rhs[i] - h[i] * m[i + 1][size_t(k)]) / diag[i];
    }
    return m;
}

} // namespace

void PovSpline::insert(double time, const Point& point, int components) {
    dim = std::max(dim, components);
    // POV-Ray 3.7 drops a point at the last time given again (measured: 0, 1, 1, 2, 1, 5
    // gives 1.5 at 0.5); elsewhere a time given again replaces its point.
    if (!entries.empty() && time == entries.back().time) return;
    auto it = std::lower_bound(entries.begin(), entries.end(), time,
                               [](const Entry& e, double t) { return e.time < t; });
    if (it != entries.end() && it->time == time)
        it->point = point;
    else
        entries.insert(it, Entry{time, point});
}

void PovSpline::finish() {
    moments = natural_moments(entries);
}

std::array<double, 5> PovSpline::at(double t, SplineKind how) const {
    const std::vector<Entry>& e = entries;
    const size_t n = e.size();
    if (n == 0) return Point{};
    if (n == 1) return e[0].point;
    // The first entry whose time is past t: 0 before the first time, n from the last on.
    size_t hi = size_t(std::upper_bound(e.begin(), e.end(), t,
                                        [](double v, const Entry& x) { return v < x.time; }) -
                       e.begin());
    if (t <= e.front().time) hi = 0;
    Point out{};
    if (how == SplineKind::Cubic) { // Catmull-Rom: the first and last points only steer
        for (size_t k = 0; k < 5; ++k) {
            if (n == 2) {
                out[k] = (e[0].point[k] + e[1].point[k]) / 2;
            } else if (hi < 2) {
                out[k] = e[1].point[k];
            } else if (hi >= n - 1) {
                out[k] = e[n - 2].point[k];
            } else {
                const size_t i = hi - 1;
                const double dt = e[i + 1].time - e[i].time, u = (t - e[i].time) / dt;
                const auto rate = [&](size_t a) {
                    return (e[a + 1].point[k] - e[a].point[k]) / (e[a + 1].time - e[a].time);
                };
                const double d0 = (rate(i - 1) + rate(i)) / 2 * dt;
                const double d1 = (rate(i + 1) + rate(i)) / 2 * dt;
                const double u2 = u * u, u3 = u2 * u;
                out[k] = e[i].point[k] * (2 * u3 - 3 * u2 + 1) +
                         e[i + 1].point[k] * (3 * u2 - 2 * u3) + d0 * (u3 - 2 * u2 + u) +
                         d1 * (u3 - u2);
            }
        }
        return out;
    }
    if (hi == 0) return e.front().point; // outside the times: the end's point
    if (hi >= n) return e.back().point;
    const size_t i = hi - 1; // t lies in [e[i].time, e[i+1].time)
    if (how == SplineKind::Quadratic && n > 2) {
        // The parabola through three neighbours: the segment's and the one before it (the
        // one after it for the first segment).
        const size_t a = i > 0 ? i - 1 : 0;
        const double p1 = e[a].time, p2 = e[a + 1].time, p3 = e[a + 2].time;
        for (size_t k = 0; k < 5; ++k) {
            const double v1 = e[a].point[k], v2 = e[a + 1].point[k], v3 = e[a + 2].point[k];
            // Lagrange's form of the same parabola.
            out[k] = v1 * (t - p2) * (t - p3) / ((p1 - p2) * (p1 - p3)) +
                     v2 * (t - p1) * (t - p3) / ((p2 - p1) * (p2 - p3)) +
                     v3 * (t - p1) * (t - p2) / ((p3 - p1) * (p3 - p2));
        }
        return out;
    }
    if (how == SplineKind::Natural) {
        std::vector<Point> computed; // a spline not finished yet
        const std::vector<Point>& m =
            moments.size() == n ? moments : (computed = natural_moments(e));
        const double h = e[i + 1].time - e[i].time, s = t - e[i].time;
        for (size_t k = 0; k < 5; ++k) {
            const double m0 = m[i][k], m1 = m[i + 1][k];
            const double slope = (e[i + 1].point[k] - e[i].point[k]) / h - h / 6 * (m1 + 2 * m0);
            out[k] = e[i].point[k] + s * (slope + s * (m0 / 2 + s * (m1 - m0) / (6 * h)));
        }
        return out;
    }
    const double u = (t - e[i].time) / (e[i + 1].time - e[i].time); // linear
    for (size_t k = 0; k < 5; ++k) out[k] = e[i].point[k] + u * (e[i + 1].point[k] - e[i].point[k]);
    return out;
}

bool Parser::accept_spline_kind(SplineKind& kind) {
    static const std::pair<const char*, SplineKind> kinds[] = {
        {"linear_spline", SplineKind::Linear},
        {"quadratic_spline", SplineKind::Quadratic},
        {"cubic_spline", SplineKind::Cubic},
        {"natural_spline", SplineKind::Natural}};
    for (const auto& [name, k] : kinds)
        if (accept_kw(name)) {
            kind = k;
            return true;
        }
    return false;
}

PovSpline Parser::parse_spline() {
    const Token& open = peek();
    expect_sym("{");
    PovSpline s;
    Value declared;
    if (accept_declared(VType::Other, declared, "a spline") && declared.str == "spline")
        s = declared.as<PovSpline>();
    // A point with fewer components than one before it keeps that one's others: POV-Ray
    // reads each point over the last (measured: after <3, 1, 5>, a point <4, 4> is
    // <4, 4, 5>).
    std::array<double, 5> p{};
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_spline_kind(s.kind)) continue;
        const double time = parse_float();
        expect_sym(",", "','");
        const Token& at = peek();
        const Value v = parse_expr();
        if (!v.numeric()) error_expected(at, "a float or vector (the spline's point)");
        const int n = v.type == VType::Float ? 1 : v.dim;
        for (int i = 0; i < n && i < 5; ++i) p[size_t(i)] = v.v[i];
        if (!std::isfinite(time)) error_at(t, "a spline's time must be finite");
        charge(sizeof(PovSpline::Entry), t);
        s.insert(time, p, std::min(n, 5));
        accept_sym(",");
    }
    if (s.entries.empty()) error_at(open, "a spline needs at least one point");
    s.finish();
    return s;
}

Value Parser::call_spline(const PovSpline& s) {
    expect_sym("(");
    const double time = parse_float();
    SplineKind kind = s.kind;
    if (accept_sym(",") && !accept_spline_kind(kind))
        error_expected(peek(), "a spline type (linear_spline, quadratic_spline, cubic_spline, "
                               "natural_spline)");
    expect_sym(")", "')'");
    const std::array<double, 5> p = s.at(time, kind);
    return Value::vec(s.dim, p.data());
}

} // namespace sheaf::io::pov

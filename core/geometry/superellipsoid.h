// POV-Ray's superellipsoid { <e, n> }: the solid where
//   f(p) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1 < 0,
// inside the box [-1, 1]^3 (e: the exponent around z, n: the one along z). For e, n <= 2 f is
// convex, so along a ray it falls to one minimum and rises again: a golden-section search
// finds that minimum and a bracketed search (root_between) the two crossings on its sides,
// with no step to choose and no thin crossing to miss. Above 2 the solid is star-shaped but not convex: the ray's
// piece inside the box is then sampled (always at its cusps, where it crosses a coordinate
// plane) for changes of sign, each refined by root_between, and for dips between samples.
// Powers are hdm::pow: the same bits on the CPU and the GPU.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <cfloat>
#include <cmath>

namespace sheaf {

namespace superellipsoid_detail {

struct Exponents {
    double a, b, c; // 2/e, e/n, 2/n
};

SHEAF_HD_INLINE Exponents exponents(float e, float n) {
    return {2.0 / e, double(e) / n, 2.0 / n};
}

SHEAF_HD_INLINE double value(const Exponents& k, double x, double y, double z) {
    const double s = hdm::pow(fabs(x), k.a) + hdm::pow(fabs(y), k.a);
    return hdm::pow(s, k.b) + hdm::pow(fabs(z), k.c) - 1;
}

/// (f + 1)^(n/2) - 1, of f's sign: f + 1 grows as the distance from the centre to the power
/// 2/n, so this gauge grows as the distance itself, near linearly along a ray, where f (powers
/// up to 2/e and 2/n, 40 for a rounded box) is flat inside and steep at the surface.
SHEAF_HD_INLINE double gauge(double f, double half_n) {
    return hdm::pow(f + 1, half_n) - 1;
}

/// The crossing of g in [lo, hi], where g(lo) = glo and g(hi) = ghi differ in sign: regula
/// falsi with the Illinois rule (the end that stays has its value halved), every fourth step a
/// bisection, down to the same width as bisection alone; near-linear g takes a few steps.
template <class F>
SHEAF_HD_INLINE double root_between(const F& g, double lo, double hi, double glo, double ghi) {
    if (glo == 0) return lo; // on the surface (a rounded box's face lies on its box's)
    if (ghi == 0) return hi;
    const bool lo_inside = glo < 0;
    int moved = 0; // the end moved last: -1 lo, 1 hi
    for (int it = 0; it < 80; ++it) {
        if (hi - lo <= 1e-9 * (1 + fabs(lo) + fabs(hi))) break; // far below a float's step
        double mid = 0.5 * (lo + hi);
        if ((it & 3) != 3 && fabs(glo) < 1e300 && fabs(ghi) < 1e300 && glo != ghi) {
            const double s = lo + (hi - lo) * (glo / (glo - ghi));
            if (s > lo && s < hi) mid = s;
        }
        if (mid <= lo || mid >= hi) break;
        const double gm = g(mid);
        if (fabs(gm) < 1e-13) return mid; // within 1e-13 of the radius: on the surface
        if ((gm < 0) == lo_inside) {
            lo = mid, glo = gm;
            if (moved < 0) ghi *= 0.5;
            moved = -1;
        } else {
            hi = mid, ghi = gm;
            if (moved > 0) glo *= 0.5;
            moved = 1;
        }
    }
    return 0.5 * (lo + hi);
}

/// The minimum of a unimodal f on [lo, hi] by golden-section search: its place, and its
/// value in `fm`. Stops at the first point below zero: the callers want a point inside, from
/// which root_between finds the crossings on both sides.
template <class F> SHEAF_HD_INLINE double golden_min(const F& f, double lo, double hi, double& fm) {
    const double g = 0.3819660112501051;
    double a = lo, b = hi, x1 = a + g * (b - a), x2 = b - g * (b - a);
    double f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 100 && x1 < x2; ++it) {
        if (f1 < 0 || f2 < 0 || b - a <= 1e-9 * (1 + fabs(a) + fabs(b))) break;
        if (f1 < f2)
            b = x2, x2 = x1, f2 = f1, x1 = a + g * (b - a), f1 = f(x1);
        else
            a = x1, x1 = x2, f1 = f2, x2 = b - g * (b - a), f2 = f(x2);
    }
    fm = f1 < f2 ? f1 : f2;
    return f1 < f2 ? x1 : x2;
}

} // namespace superellipsoid_detail

/// The outward gradient of f at local point p (finite; the point's direction where f has
/// none, on the axes of a pinched solid).
SHEAF_HD_INLINE Vec3 superellipsoid_normal(float e, float n, Vec3 p) {
    using namespace superellipsoid_detail;
    const Exponents k = exponents(e, n);
    const double x = fabs(double(p.x)), y = fabs(double(p.y)), z = fabs(double(p.z));
    const double s = hdm::pow(x, k.a) + hdm::pow(y, k.a);
    const double outer = s > 0 ? k.b * hdm::pow(s, k.b - 1) : 0;
    double g[3] = {x > 0 ? outer * k.a * hdm::pow(x, k.a - 1) : 0,
                   y > 0 ? outer * k.a * hdm::pow(y, k.a - 1) : 0,
                   z > 0 ? k.c * hdm::pow(z, k.c - 1) : 0};
    const double m = fmax(g[0], fmax(g[1], g[2]));
    if (!(m > 0 && m < 1e300)) return p;
    return Vec3(float(copysign(g[0] / m, double(p.x))), float(copysign(g[1] / m, double(p.y))),
                float(copysign(g[2] / m, double(p.z))));
}

/// The pieces [t0[i], t1[i]] of the local ray inside the superellipsoid, at most `max`,
/// ascending; returns their count.
SHEAF_HD_INLINE int superellipsoid_pieces(float e, float n, const Ray& r, double* t0, double* t1,
                                          int max) {
    using namespace superellipsoid_detail;
    // The ray's piece inside the box.
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.dir.x, r.dir.y, r.dir.z};
    double lo = -DBL_MAX, hi = DBL_MAX;
    for (int i = 0; i < 3; ++i) {
        if (fabs(d[i]) < 1e-30) {
            if (o[i] < -1 || o[i] > 1) return 0;
            continue;
        }
        double a = (-1 - o[i]) / d[i], b = (1 - o[i]) / d[i];
        if (a > b) {
            const double t = a;
            a = b, b = t;
        }
        lo = fmax(lo, a), hi = fmin(hi, b);
    }
    if (!(lo < hi)) return 0;
    const Exponents k = exponents(e, n);
    auto f = [&](double t) { return value(k, o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t); };
    const double half_n = 0.5 * double(n);
    auto g = [&](double t) { return gauge(f(t), half_n); };
    // The crossing between t0 and t1, where f is f0 and f1.
    auto crossing = [&](double t0, double t1, double f0, double f1) {
        return root_between(g, t0, t1, gauge(f0, half_n), gauge(f1, half_n));
    };
    if (e <= 2 && n <= 2) { // convex: one minimum
        double fm;
        const double tm = golden_min(f, lo, hi, fm);
        if (!(fm < 0)) return 0;
        const double flo = f(lo), fhi = f(hi);
        t0[0] = flo < 0 ? lo : crossing(lo, tm, flo, fm);
        t1[0] = fhi < 0 ? hi : crossing(tm, hi, fm, fhi);
        return 1;
    }
    // Not convex: f has cusps where the ray crosses a coordinate plane (|x|^p with p < 1), so
    // those points are always sampled; between them f is smooth, and a sampled dip that stays
    // outside is searched for a minimum below zero (a thin piece between two samples).
    double cuts[5];
    int ncut = 0;
    cuts[ncut++] = lo;
    for (int i = 0; i < 3; ++i) {
        if (fabs(d[i]) < 1e-30) continue;
        const double t = -o[i] / d[i];
        if (!(t > lo && t < hi)) continue;
        int at = ncut++;
        for (; at > 1 && cuts[at - 1] > t; --at) cuts[at] = cuts[at - 1];
        cuts[at] = t;
    }
    cuts[ncut++] = hi;
    int count = 0;
    double start = lo;
    bool in = false;
    auto cross = [&](double t, bool entering) {
        if (entering) {
            start = t, in = true;
        } else if (in) {
            if (count < max) t0[count] = start, t1[count] = t, ++count;
            in = false;
        }
    };
    double tp = lo, fp = -1, ta = lo, fa = f(lo);
    if (fa < 0) start = lo, in = true;
    for (int c = 0; c + 1 < ncut; ++c) {
        const double a = cuts[c], b = cuts[c + 1];
        int steps = int(128 * (b - a) / (hi - lo));
        steps = steps < 8 ? 8 : steps;
        for (int i = 1; i <= steps; ++i) {
            const double tb = i == steps ? b : a + (b - a) * i / steps, fb = f(tb);
            if ((fa < 0) != (fb < 0)) {
                cross(crossing(ta, tb, fa, fb), fb < 0);
            } else if (fa >= 0 && fp >= 0 && fa < fp && fa < fb) {
                double fm;
                const double tm = golden_min(f, tp, tb, fm);
                if (fm < 0) {
                    cross(crossing(tp, tm, fp, fm), true);
                    cross(crossing(tm, tb, fm, fb), false);
                }
            }
            tp = ta, fp = fa, ta = tb, fa = fb;
        }
    }
    if (in && count < max) t0[count] = start, t1[count] = hi, ++count;
    return count;
}

} // namespace sheaf

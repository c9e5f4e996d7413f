// A solid of revolution about the local z axis (POV-Ray's lathe and sor): a profile curve in
// the half-plane of (radius, height) pairs, made of polynomial segments, turned about the axis.
// A lathe's segments give the radius w(s) and the height h(s) as Bézier curves of degree 1 to
// 3 in the segment's parameter s; a sor's give the radius squared w(s) (POV-Ray's cubic in the
// height) with h(s) linear. The solid is the region the profile encloses by the even-odd rule,
// as POV-Ray counts it; open, only its surface (a lathe whose curve does not close, a sor's
// `open`).
//
// Exact: a ray's points at height h lie at squared distance rho(h)^2 from the axis, a quadratic
// in h. Where the profile meets that trace, F(s) = A u^2 + B dz u + dz^2 (C - W(s)) vanishes,
// with u = h(s) - oz, W the squared radius and A, B, C the ray's squared distance A t^2 + B t
// + C; F is a polynomial of degree at most 6 in s, and its roots in [0, 1] are isolated by
// those of its derivatives (core/geometry/poly.h). Each crossing toggles inside and outside. The
// signs of F at the segments' end points, computed from the shared vertices themselves, decide
// how many crossings each segment has, so segments that share a vertex never count a crossing
// twice or miss one. A ray nearly level (|dz| <= 1e-5 |d|) meets the profile where h(s) is its
// height instead, twice for each crossing its closest approach to the axis lies inside.
#pragma once

#include "core/geometry/poly.h"
#include "core/geometry/ray.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sheaf {

/// One segment of a profile: w(s) and h(s) for s in [0, 1] as Bézier curves with control
/// points w[0..wdeg] and h[0..hdeg]; w[0], h[0] and w[wdeg], h[hdeg] are its end vertices.
struct RevolutionSegment {
    float w[4] = {0, 0, 0, 0}, h[4] = {0, 0, 0, 0};
    uint32_t wdeg = 1, hdeg = 1;
};

/// A profile of a prepared scene: segments [first, first + count) of the scene's revolution
/// segments; `squared`: w is the radius squared (sor), else the radius (lathe); the largest
/// radius and the heights its control points reach.
struct RevolutionRef {
    uint32_t first = 0, count = 0;
    uint32_t squared = 0;
    float r_max = 0, h_lo = 0, h_hi = 0;
};

/// A profile as the scene model holds it (host only): a sor's caps are segments of it.
struct RevolutionProfile {
    std::vector<RevolutionSegment> segments;
    bool squared = false;
};

/// Widens w2 (the largest squared radius) and [lo, hi] (the heights) to segment s's control
/// points: the segment lies in their hull. `squared`: w is the radius squared.
SHEAF_HD_INLINE void widen_to_segment(const RevolutionSegment& s, bool squared, double& w2,
                                      double& lo, double& hi) {
    for (uint32_t i = 0; i <= s.wdeg; ++i) {
        const double w = s.w[i], ww = squared ? w : w * w;
        if (ww > w2) w2 = ww;
    }
    for (uint32_t i = 0; i <= s.hdeg; ++i) {
        if (s.h[i] < lo) lo = s.h[i];
        if (s.h[i] > hi) hi = s.h[i];
    }
}

/// The bounds a RevolutionRef records, from the profile's control points.
inline void revolution_bounds(const RevolutionProfile& p, float& r_max, float& h_lo, float& h_hi) {
    double w2 = 0, lo = INFINITY, hi = -INFINITY;
    for (const RevolutionSegment& s : p.segments) widen_to_segment(s, p.squared, w2, lo, hi);
    if (p.segments.empty()) lo = hi = 0;
    r_max = float(std::sqrt(w2)) * (1 + 1e-6f), h_lo = float(lo), h_hi = float(hi);
}

/// The most crossings of one ray with one profile that are kept (the nearest ones).
constexpr int kMaxRevolutionCrossings = 48;

namespace revolution_detail {

struct Crossing {
    double t;
    Vec3 n; // the surface's normal there (either way; oriented by the caller)
};

/// Power-basis coefficients c[0..deg] of the Bézier curve with control points p[0..deg].
SHEAF_HD_INLINE void power_basis(const float* p, uint32_t deg, double* c) {
    const double p0 = p[0], p1 = p[1], p2 = deg >= 2 ? p[2] : 0, p3 = deg >= 3 ? p[3] : 0;
    c[0] = p0;
    if (deg == 1) {
        c[1] = p1 - p0;
    } else if (deg == 2) {
        c[1] = 2 * (p1 - p0), c[2] = p0 - 2 * p1 + p2;
    } else {
        c[1] = 3 * (p1 - p0), c[2] = 3 * (p0 - 2 * p1 + p2), c[3] = p3 - p0 + 3 * (p1 - p2);
    }
}

/// c (degree n) at s and its derivative there.
SHEAF_HD_INLINE double value(const double* c, uint32_t n, double s, double& slope) {
    double v = c[n], d = 0;
    for (int m = int(n) - 1; m >= 0; --m) d = d * s + v, v = v * s + c[m];
    slope = d;
    return v;
}

} // namespace revolution_detail

/// The pieces of the local ray inside the solid of revolution, sorted, at most `max`: piece i
/// is [t0[i], t1[i]] with outward normals n0[i], n1[i] at its ends. `open`: the surface only,
/// each crossing a piece of zero length facing the ray. Out of line on the device, so that
/// CSG's per-level frame does not carry the crossing list.
SHEAF_HD_NOINLINE int revolution_pieces(const RevolutionRef& g, const RevolutionSegment* segs,
                                        bool open, const Ray& r, double* t0, double* t1, Vec3* n0,
                                        Vec3* n1, int max) {
    using namespace revolution_detail;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    const double A = dx * dx + dy * dy, len2 = A + dz * dz;
    if (!(len2 > 0)) return 0;
    // From the ray's closest approach to the axis (unless the ray runs nearly along it): there
    // B is zero and C the squared distance.
    const double tc =
        A > 1e-4 * len2 ? -(double(r.origin.x) * dx + double(r.origin.y) * dy) / A : 0;
    const double px = r.origin.x + dx * tc, py = r.origin.y + dy * tc, pz = r.origin.z + dz * tc;
    const double B = 2 * (px * dx + py * dy), C = px * px + py * py;
    const double r0sq = A > 0 ? fmax(0.0, C - B * B / (4 * A)) : C; // nearest to the axis
    if (r0sq > double(g.r_max) * g.r_max) return 0; // never as near as the profile reaches
    const bool level = dz * dz <= 1e-10 * len2;
    if (level && (pz < g.h_lo || pz > g.h_hi)) return 0;
    const bool sq = g.squared != 0;

    Crossing xs[kMaxRevolutionCrossings];
    int nx = 0;
    auto add = [&](const RevolutionSegment& sg, const double* wc, const double* hc, double s,
                   double t) {
        double dw, dh;
        const double w = value(wc, sg.wdeg, s, dw);
        value(hc, sg.hdeg, s, dh);
        const double x = r.origin.x + dx * t, y = r.origin.y + dy * t;
        const double half_dW = sq ? 0.5 * dw : w * dw; // (d/ds W) / 2, W = radius squared
        Vec3 n(float(dh * x), float(dh * y), float(-half_dW));
        if (!(dot(n, n) > 0)) n = Vec3(float(-dx), float(-dy), float(-dz));
        insert_nearest(xs, nx, kMaxRevolutionCrossings, Crossing{t, n});
    };
    const RevolutionSegment* s0 = segs + g.first;
    for (uint32_t k = 0; k < g.count; ++k) {
        const RevolutionSegment& sg = s0[k];
        double wmax2 = 0, hlo = sg.h[0], hhi = sg.h[0];
        widen_to_segment(sg, sq, wmax2, hlo, hhi);
        // Wholly nearer the axis than the ray ever comes: F > 0 all along, no crossing.
        if (wmax2 < r0sq * (1 - 1e-9)) continue;
        // Within the segment's radius only along a stretch of the ray whose heights miss the
        // segment's: no crossing (most segments of a tall profile, for a ray across it).
        if (!level && A > 1e-4 * len2) {
            const double u_near = -B / (2 * A), half = sqrt(fmax(0.0, wmax2 - r0sq) / A);
            const double zc = pz + dz * u_near, reach = fabs(dz) * half;
            const double room = 1e-7 * (1 + fabs(zc) + reach + fabs(hlo) + fabs(hhi));
            if (zc + reach < hlo - room || zc - reach > hhi + room) continue;
        }
        double wc[4], hc[4];
        power_basis(sg.w, sg.wdeg, wc);
        power_basis(sg.h, sg.hdeg, hc);
        const uint32_t we = sg.wdeg, he = sg.hdeg;
        double roots[8];
        if (level) {
            // Level: where h(s) is the ray's height, at radius w(s) if the ray gets there.
            if (pz < hlo || pz > hhi) continue; // the same sign at every vertex
            double q[4];
            for (uint32_t i = 0; i <= he; ++i) q[i] = hc[i];
            q[0] = double(sg.h[0]) - pz;
            int deg = int(he);
            while (deg > 0 && q[deg] == 0) --deg;
            int nr = poly_roots_in<3>(q, deg, 0.0, 1.0, roots);
            nr = reconcile_roots(roots, nr, double(sg.h[0]) - pz, double(sg.h[he]) - pz);
            for (int i = 0; i < nr; ++i) {
                double slope;
                const double w = value(wc, we, roots[i], slope), W = sq ? w : w * w;
                if (!(W > C)) continue;
                const double dt = sqrt((W - C) / A);
                add(sg, wc, hc, roots[i], tc - dt);
                add(sg, wc, hc, roots[i], tc + dt);
            }
            continue;
        }
        // F(s) = A u^2 + B dz u + dz^2 (C - W(s)), u = h(s) - pz.
        double u[4];
        for (uint32_t i = 0; i <= he; ++i) u[i] = hc[i];
        u[0] -= pz;
        double f[7] = {0, 0, 0, 0, 0, 0, 0};
        for (uint32_t i = 0; i <= he; ++i) {
            for (uint32_t j = 0; j <= he; ++j) f[i + j] += A * u[i] * u[j];
            f[i] += B * dz * u[i];
        }
        f[0] += dz * dz * C;
        if (sq) {
            for (uint32_t i = 0; i <= we; ++i) f[i] -= dz * dz * wc[i];
        } else {
            for (uint32_t i = 0; i <= we; ++i)
                for (uint32_t j = 0; j <= we; ++j) f[i + j] -= dz * dz * wc[i] * wc[j];
        }
        auto at_vertex = [&](double w, double h) {
            const double uu = h - pz, W = sq ? w : w * w;
            return A * uu * uu + B * dz * uu + dz * dz * (C - W);
        };
        const double fa = at_vertex(sg.w[0], sg.h[0]), fb = at_vertex(sg.w[we], sg.h[he]);
        f[0] = fa;
        int deg = int(2 * (he > we ? he : we));
        while (deg > 0 && f[deg] == 0) --deg;
        int nr = poly_roots_in<6>(f, deg, 0.0, 1.0, roots);
        nr = reconcile_roots(roots, nr, fa, fb);
        for (int i = 0; i < nr; ++i) {
            double slope;
            const double h = value(hc, he, roots[i], slope);
            add(sg, wc, hc, roots[i], tc + (h - pz) / dz);
        }
    }

    const Vec3 d = Vec3(float(dx), float(dy), float(dz));
    int count = 0;
    if (open) {
        for (int i = 0; i < nx && count < max; ++i) {
            const Vec3 n = dot(xs[i].n, d) > 0 ? -xs[i].n : xs[i].n;
            t0[count] = t1[count] = xs[i].t, n0[count] = n1[count] = n;
            ++count;
        }
        return count;
    }
    // Outside before the first crossing; each one toggles.
    for (int i = 0; i + 1 < nx && count < max; i += 2) {
        t0[count] = xs[i].t, t1[count] = xs[i + 1].t;
        n0[count] = dot(xs[i].n, d) > 0 ? -xs[i].n : xs[i].n;
        n1[count] = dot(xs[i + 1].n, d) < 0 ? -xs[i + 1].n : xs[i + 1].n;
        ++count;
    }
    return count;
}

} // namespace sheaf

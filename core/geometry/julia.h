// Julia fractals (POV-Ray's julia_fractal): the 3D slice of a 4D Julia set. A local point
// (x, y, z) becomes q = (x, y, z, w) with w on the slice hyperplane s . q = d; q belongs to the
// set when |q| stays within the exit radius over `iterations` steps of q -> f(q) + c, where f
// squares or cubes in the quaternions, or squares in the hypercomplex numbers.
//
// Along a ray the set is searched as POV-Ray 3.7 does: march from the bounding sphere, by a
// distance estimate where the point escapes and by the minimum step (1 / precision) where it
// does not, then bisect a change of membership to 1e-7. The surface normal is the gradient of
// the last iterate's norm, carried through the iterations (the derivative chain), at the
// crossing's inner side. Thin parts narrower than the minimum step may be missed, as in
// POV-Ray.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <cfloat>
#include <cmath>
#include <cstdint>

namespace sheaf {

enum class JuliaAlgebra : uint8_t { QuaternionSqr, QuaternionCube, HypercomplexSqr };

/// One julia_fractal of a prepared scene, in its local space.
struct JuliaFractal {
    double c[4] = {1, 0, 0, 0};     // the Julia parameter
    double slice[4] = {0, 0, 0, 1}; // unit normal of the 3D slice; slice[3] != 0
    double slice_dist = 0;
    double min_step = 1.0 / 20; // 1 / precision
    uint32_t iterations = 20;
    JuliaAlgebra algebra = JuliaAlgebra::QuaternionSqr;
};

/// The iterations a julia fractal may run per point (POV-Ray has no limit; the iterates are
/// kept on the stack, so the device needs one).
constexpr uint32_t kJuliaMaxIterations = 64;

/// Marching steps one ray may spend on one julia fractal; past them it sees nothing more.
constexpr int kJuliaMaxSteps = 8192;

namespace julia_detail {

constexpr double kTolerance = 1e-7;

/// The radius of the bounding sphere at the origin, and the squared norm beyond which a point
/// escapes.
SHEAF_HD_INLINE double bound_radius(const JuliaFractal& j) {
    if (j.algebra == JuliaAlgebra::HypercomplexSqr) return 4.0;
    const double r = 1.0 +
                     sqrt(j.c[0] * j.c[0] + j.c[1] * j.c[1] + j.c[2] * j.c[2] + j.c[3] * j.c[3]) +
                     kTolerance;
    return r < 2.0 ? r : 2.0;
}
SHEAF_HD_INLINE double exit_value(const JuliaFractal& j) {
    const double r = bound_radius(j);
    return j.algebra == JuliaAlgebra::HypercomplexSqr ? 16.0 : r * r + kTolerance;
}

/// The iterates q_0 .. q_n of one point; `n` is the number of steps taken.
struct Orbit {
    double q[kJuliaMaxIterations + 1][4];
    uint32_t n = 0;
    bool inside = false;
    double norm = 0; // |q_n|^2 when the point escaped
};

// One step of the map from q into out.
SHEAF_HD_INLINE void step(const JuliaFractal& j, const double* q, double* out) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    switch (j.algebra) {
    case JuliaAlgebra::QuaternionSqr: {
        const double d = y * y + z * z + w * w;
        out[0] = x * x - d + j.c[0];
        out[1] = 2 * x * y + j.c[1];
        out[2] = 2 * x * z + j.c[2];
        out[3] = 2 * x * w + j.c[3];
        return;
    }
    case JuliaAlgebra::QuaternionCube: {
        const double d = y * y + z * z + w * w, x2 = x * x, k = 3 * x2 - d;
        out[0] = x * (x2 - 3 * d) + j.c[0];
        out[1] = y * k + j.c[1];
        out[2] = z * k + j.c[2];
        out[3] = w * k + j.c[3];
        return;
    }
    case JuliaAlgebra::HypercomplexSqr:
        out[0] = x * x + w * w - y * y - z * z + j.c[0];
        out[1] = 2 * (x * y - z * w) + j.c[1];
        out[2] = 2 * (x * z - w * y) + j.c[2];
        out[3] = 2 * (x * w + y * z) + j.c[3];
        return;
    }
}

/// Runs the map from local point p until the point escapes or the iterations end.
SHEAF_HD_INLINE void iterate(const JuliaFractal& j, double px, double py, double pz, Orbit& o) {
    o.q[0][0] = px, o.q[0][1] = py, o.q[0][2] = pz;
    o.q[0][3] = (j.slice_dist - j.slice[0] * px - j.slice[1] * py - j.slice[2] * pz) / j.slice[3];
    const double exit = exit_value(j);
    const uint32_t n = j.iterations < kJuliaMaxIterations ? j.iterations : kJuliaMaxIterations;
    for (uint32_t i = 0; i < n; ++i) {
        const double* q = o.q[i];
        const double norm = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (!(norm <= exit)) { // escaped (or overflowed)
            o.n = i, o.inside = false, o.norm = norm;
            return;
        }
        step(j, q, o.q[i + 1]);
    }
    o.n = n, o.inside = true, o.norm = 0;
}

// The hypercomplex (commutative) product a * b.
SHEAF_HD_INLINE void hmul(const double* a, const double* b, double* out) {
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] + a[3] * b[3];
    out[1] = a[1] * b[0] + a[0] * b[1] - a[3] * b[2] - a[2] * b[3];
    out[2] = a[2] * b[0] - a[3] * b[1] + a[0] * b[2] - a[1] * b[3];
    out[3] = a[3] * b[0] + a[2] * b[1] + a[1] * b[2] + a[0] * b[3];
}

/// The gradient (up to a positive factor) of |q_m|^2 with respect to the local point, from the
/// orbit's first m steps, into g.
SHEAF_HD_INLINE void gradient(const JuliaFractal& j, const Orbit& o, uint32_t m, double* g) {
    const double* qm = o.q[m];
    if (j.algebra == JuliaAlgebra::HypercomplexSqr) {
        // The product is commutative and the derivative of q^2 is 2q, so the chain is the
        // product of the iterates (the factor 2^m left out), paired with q_m.
        double p[4] = {o.q[0][0], o.q[0][1], o.q[0][2], o.q[0][3]}, t[4];
        for (uint32_t i = 1; i < m; ++i) {
            hmul(o.q[i], p, t);
            p[0] = t[0], p[1] = t[1], p[2] = t[2], p[3] = t[3];
        }
        g[0] = p[0] * qm[0] + p[1] * qm[1] + p[2] * qm[2] + p[3] * qm[3];
        g[1] = -p[1] * qm[0] + p[0] * qm[1] - p[3] * qm[2] + p[2] * qm[3];
        g[2] = -p[2] * qm[0] - p[3] * qm[1] + p[0] * qm[2] + p[1] * qm[3];
        return;
    }
    // Quaternions: the tangents of the local axes pushed through each step's derivative, then
    // paired with q_m. They start without a w part, as POV-Ray's do (a tilted slice's w
    // follows x, y and z, which both leave out).
    double n[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    for (uint32_t i = 0; i < m; ++i) {
        const double x = o.q[i][0], y = o.q[i][1], z = o.q[i][2], w = o.q[i][3];
        for (int k = 0; k < 3; ++k) {
            double* v = n[k];
            if (j.algebra == JuliaAlgebra::QuaternionSqr) {
                const double a = v[0] * x - v[1] * y - v[2] * z - v[3] * w;
                v[1] = v[0] * y + x * v[1];
                v[2] = v[0] * z + x * v[2];
                v[3] = v[0] * w + x * v[3];
                v[0] = a;
            } else {
                const double d = y * y + z * z + w * w, x2 = x * x;
                const double x3 = x2 - d, x4 = 3 * x2 - d;
                const double e = 2 * (v[1] * y + v[2] * z + v[3] * w);
                const double e2 = 6 * x * v[0] - e;
                v[0] = (v[0] * x3 - x * e) * 3;
                v[1] = v[1] * x4 + y * e2;
                v[2] = v[2] * x4 + z * e2;
                v[3] = v[3] * x4 + w * e2;
            }
        }
    }
    for (int k = 0; k < 3; ++k)
        g[k] = n[k][0] * qm[0] + n[k][1] * qm[1] + n[k][2] * qm[2] + n[k][3] * qm[3];
}

/// The outward unit normal at a point whose orbit stayed inside: the last iterate's gradient,
/// or an earlier one's where the iterates shrank to nothing (c near 0: points inside fall to
/// 0), or `fallback` where none is usable.
SHEAF_HD_INLINE Vec3 surface_normal(const JuliaFractal& j, const Orbit& o, Vec3 fallback) {
    for (uint32_t m = o.n; m > 0; --m) {
        double g[3];
        gradient(j, o, m, g);
        const double l = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (l > 1e-150 && l < 1e300)
            return Vec3(float(g[0] / l), float(g[1] / l), float(g[2] / l));
    }
    return fallback;
}

/// A lower bound of the distance from an escaped point to the set along unit direction `dir`,
/// in local units, or the minimum step where none is known.
SHEAF_HD_INLINE double escape_distance(const JuliaFractal& j, const Orbit& o, const double* dir) {
    const double norm = o.norm;
    if (!(norm < 1e300)) return j.min_step;
    if (j.algebra == JuliaAlgebra::HypercomplexSqr) {
        // The norm over twice its rate of decrease along the ray, where that rate lies in the
        // range POV-Ray trusts.
        double g[3];
        gradient(j, o, o.n, g);
        const double scale = ldexp(1.0, int(o.n > 1 ? o.n : 1));
        const double s = -2.0 * scale * (g[0] * dir[0] + g[1] * dir[1] + g[2] * dir[2]);
        if (s > 1e-8 && norm > j.min_step * s && norm < 30 * j.min_step * s) return norm / s;
        return j.min_step;
    }
    // |q_n| log|q_n|^2 / (p^(n+1) |q_0 q_1 ... q_n|): the map's derivative is about p times
    // the iterate per step, and quaternion norms multiply.
    const double p = j.algebra == JuliaAlgebra::QuaternionCube ? 3.0 : 2.0;
    double dd = 1.0, pw = 1.0 / p;
    for (uint32_t i = 0; i <= o.n; ++i) {
        const double* q = o.q[i];
        dd *= q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (i > 0) pw /= p;
    }
    if (!(dd > 0)) return j.min_step;
    const double est = pw * sqrt(norm / dd) * hdm::log(norm);
    return est > 0 ? est : j.min_step;
}

} // namespace julia_detail

/// Whether local point p lies in the julia fractal.
SHEAF_HD_INLINE bool julia_inside(const JuliaFractal& j, Vec3 p) {
    julia_detail::Orbit o;
    julia_detail::iterate(j, p.x, p.y, p.z, o);
    return o.inside;
}

/// The pieces of the ray inside the set, at most `max`, sorted, with outward local normals at
/// both ends; a piece begun before the searched part starts at -FLT_MAX, one running past the
/// search ends at FLT_MAX. Out of line on the device: the orbit is large.
SHEAF_HD_NOINLINE int julia_pieces(const JuliaFractal& j, const Ray& r, double* t0, double* t1,
                                   Vec3* n0, Vec3* n1, int max) {
    using namespace julia_detail;
    const double speed = sqrt(double(r.dir.x) * r.dir.x + double(r.dir.y) * r.dir.y +
                              double(r.dir.z) * r.dir.z); // local units per unit of t
    if (!(speed > 0)) return 0;
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
    const double d[3] = {r.dir.x / speed, r.dir.y / speed, r.dir.z / speed};
    const Vec3 ahead{float(d[0]), float(d[1]), float(d[2])};
    // The bounding sphere, in local units s along the unit direction.
    const double rad = bound_radius(j);
    const double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
    const double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - rad * rad;
    const double disc = b * b - c;
    if (!(disc > 0)) return 0;
    const double root = sqrt(disc);
    const double smin = double(r.tmin) * speed;
    // The march never depends on tmax (it stops after passing it), so that the same ray with a
    // nearer tmax finds the same crossings, as the isosurface's does.
    double s = -b - root > smin ? -b - root : smin;
    const double s_end = -b + root;
    if (!(s <= s_end)) return 0;
    Orbit orbit; // one, reused: it is 2 KiB
    auto at = [&](double u) {
        iterate(j, o[0] + d[0] * u, o[1] + d[1] * u, o[2] + d[2] * u, orbit);
        return orbit.inside;
    };
    bool inside = at(s);
    int n = 0;
    // Inside at the start: the set began before the searched part, or reaches the bounding
    // sphere (a single iteration keeps the whole ball), which then caps it.
    const bool on_sphere = s > smin;
    double start = on_sphere ? s : -FLT_MAX;
    Vec3 start_n = -ahead;
    if (on_sphere) {
        const double u[3] = {o[0] + d[0] * s, o[1] + d[1] * s, o[2] + d[2] * s};
        start_n = Vec3{float(u[0] / rad), float(u[1] / rad), float(u[2] / rad)};
    }
    double next = inside ? j.min_step : escape_distance(j, orbit, d);
    int steps = 1;
    while (s < s_end && n < max && steps < kJuliaMaxSteps) {
        const double sn = s + (next > j.min_step ? next : j.min_step); // also NaN
        ++steps;
        if (at(sn) != inside) {
            // A crossing between s and sn: bisected to the tolerance, lo on s's side.
            double lo = s, hi = sn;
            while (hi - lo > kTolerance && steps < kJuliaMaxSteps) {
                const double mid = 0.5 * (lo + hi);
                ++steps;
                (at(mid) == inside ? lo : hi) = mid;
            }
            at(inside ? lo : hi); // the normal is taken on the inner side
            const Vec3 g = surface_normal(j, orbit, inside ? ahead : -ahead);
            const double cross = 0.5 * (lo + hi);
            if (inside) {
                t0[n] = start <= -FLT_MAX ? -FLT_MAX : start / speed, t1[n] = cross / speed;
                n0[n] = start_n, n1[n] = g;
                ++n;
            } else {
                start = cross, start_n = g;
            }
            inside = !inside;
            at(sn);
        }
        s = sn;
        next = inside ? j.min_step : escape_distance(j, orbit, d);
        if (s / speed > double(r.tmax)) break;
    }
    if (inside && n < max) { // past tmax, or out of steps
        t0[n] = start <= -FLT_MAX ? -FLT_MAX : start / speed, t1[n] = FLT_MAX;
        n0[n] = start_n, n1[n] = ahead;
        ++n;
    }
    return n;
}

} // namespace sheaf

// Isosurfaces (POV-Ray's isosurface): the solid where a user function (core/scene/function.h)
// is below a threshold, inside a container (a box or a sphere) that also caps it, unless it is
// open.
//
// Along a ray the function is searched with its Lipschitz bound, the scene's max_gradient G:
// where f - threshold = v, no crossing lies nearer than |v| / G, so the march steps by that
// (at least the accuracy) and never steps over one when G holds. A sign change between two
// samples is bisected to a thousandth of the accuracy. A function steeper than G may lose thin
// parts, as it does in POV-Ray. The normal is the function's gradient by central differences.
#pragma once

#include "core/geometry/ray.h"
#include "core/scene/function.h"

#include <cfloat>
#include <cmath>
#include <cstdint>

namespace sheaf {

/// An isosurface of a prepared scene: program `program` of its functions over the local point
/// (x, y, z); inside where it is below `threshold`. The container is the box [lo, hi] or, with
/// `sphere`, the sphere at lo of radius hi[0].
struct IsoRef {
    uint32_t program = 0;
    float threshold = 0;
    float max_gradient = 1.1f;
    float accuracy = 0.001f; // in local units
    bool open = false;       // the container does not cap the solid
    bool sphere = false;
    Vec3 lo{-1, -1, -1}, hi{1, 1, 1};
    float bound[4] = {0, 0, 0, 0}; // a sphere holding the container, in local space
};

/// Function evaluations one ray may spend on one isosurface; past them it sees nothing more.
constexpr int kIsoMaxSteps = 4096;

namespace iso_detail {

// The ray's interval inside the container, with the container's outward normals there.
SHEAF_HD_INLINE bool container(const IsoRef& s, const Ray& r, double& ta, double& tb, Vec3& na,
                               Vec3& nb) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.dir.x, r.dir.y, r.dir.z};
    if (s.sphere) {
        const double c[3] = {s.lo.x, s.lo.y, s.lo.z};
        const double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
        const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
        const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - double(s.hi.x) * s.hi.x;
        const double disc = b * b - a * cc;
        if (!(a > 0) || disc < 0) return false;
        const double q = sqrt(disc);
        ta = (-b - q) / a, tb = (-b + q) / a;
        na = Vec3(float(oc[0] + d[0] * ta), float(oc[1] + d[1] * ta), float(oc[2] + d[2] * ta));
        nb = Vec3(float(oc[0] + d[0] * tb), float(oc[1] + d[1] * tb), float(oc[2] + d[2] * tb));
        return true;
    }
    const double lo[3] = {s.lo.x, s.lo.y, s.lo.z}, hi[3] = {s.hi.x, s.hi.y, s.hi.z};
    ta = -DBL_MAX, tb = DBL_MAX;
    for (int i = 0; i < 3; ++i) {
        if (fabs(d[i]) < 1e-30) {
            if (o[i] < lo[i] || o[i] > hi[i]) return false;
            continue;
        }
        double a = (lo[i] - o[i]) / d[i], b = (hi[i] - o[i]) / d[i];
        float sa = -1, sb = 1;
        if (a > b) {
            const double t = a;
            a = b, b = t, sa = 1, sb = -1;
        }
        if (a > ta) ta = a, na = Vec3(0, 0, 0), na[i] = sa;
        if (b < tb) tb = b, nb = Vec3(0, 0, 0), nb[i] = sb;
    }
    return ta <= tb;
}

} // namespace iso_detail

/// The function's gradient at local point p (the outward normal of the solid there).
SHEAF_HD_INLINE Vec3 iso_gradient(const IsoRef& s, const FnView& fv, Vec3 p) {
    const double h = s.accuracy > 1e-5f ? s.accuracy : 1e-5;
    const double x = p.x, y = p.y, z = p.z;
    auto f = [&](double a, double b, double c) { return fn_eval3(fv, s.program, a, b, c); };
    return Vec3(float(f(x + h, y, z) - f(x - h, y, z)), float(f(x, y + h, z) - f(x, y - h, z)),
                float(f(x, y, z + h) - f(x, y, z - h)));
}

/// The spans of local ray r inside isosurface s, at most max of them, sorted: t0, t1 and the
/// outward normals at both ends. The search starts at r.tmin and stops past r.tmax: a span
/// that goes on before the start or past the stop is reported to -FLT_MAX or FLT_MAX. Open, each
/// crossing of the surface is a span of its own with t0 == t1.
SHEAF_HD_NOINLINE int iso_pieces(const IsoRef& s, const FnView& fv, const Ray& r, double* t0,
                                 double* t1, Vec3* n0, Vec3* n1, int max) {
    double ca, cb;
    Vec3 na, nb;
    if (!iso_detail::container(s, r, ca, cb, na, nb)) return 0;
    // The march never depends on tmax (it stops after passing it), so that the same ray
    // with a nearer tmax finds the same crossings: the renderer tests a hit again that way.
    const double a = ca > r.tmin ? ca : double(r.tmin), b = cb;
    if (!(a <= b) || !(a <= r.tmax)) return 0;
    const double speed = sqrt(double(r.dir.x) * r.dir.x + double(r.dir.y) * r.dir.y +
                              double(r.dir.z) * r.dir.z); // local units per unit of t
    if (!(speed > 0)) return 0;
    const double acc = s.accuracy > 1e-6f ? s.accuracy : 1e-6;
    const double grad = s.max_gradient > 1e-6f ? s.max_gradient : 1e-6;
    const double min_step = acc / speed;
    auto value = [&](double t) {
        return fn_eval3(fv, s.program, r.origin.x + r.dir.x * t, r.origin.y + r.dir.y * t,
                        r.origin.z + r.dir.z * t) -
               s.threshold;
    };
    auto point = [&](double t) {
        return Vec3(float(r.origin.x + r.dir.x * t), float(r.origin.y + r.dir.y * t),
                    float(r.origin.z + r.dir.z * t));
    };
    int n = 0;
    double t = a, v = value(t);
    bool inside = v < 0;
    double start = 0;
    Vec3 start_n;
    if (inside) { // the solid starts at the container's wall, or before the searched part
        start = a == ca ? ca : -FLT_MAX;
        start_n = na;
    }
    int steps = 1;
    while (t < b && n < max && steps < kIsoMaxSteps) {
        double step = fabs(v) / (grad * speed);
        if (!(step >= min_step)) step = min_step; // also NaN
        const double tn = t + step < b ? t + step : b;
        const double vn = value(tn);
        ++steps;
        if ((vn < 0) != inside) {
            // The crossing lies between: bisected well below the accuracy, so that rays
            // leaving the surface (offset by 1e-4 of a unit) start on its outer side.
            double lo = t, hi = tn;
            while ((hi - lo) * speed > acc * 1e-3 && steps < kIsoMaxSteps) {
                const double mid = 0.5 * (lo + hi);
                ((value(mid) < 0) == inside ? lo : hi) = mid;
                ++steps;
            }
            const double root = 0.5 * (lo + hi);
            const Vec3 g = iso_gradient(s, fv, point(root));
            if (s.open) {
                t0[n] = t1[n] = root, n0[n] = n1[n] = g;
                ++n;
            } else if (inside) {
                t0[n] = start, t1[n] = root, n0[n] = start_n, n1[n] = g;
                ++n;
            } else {
                start = root, start_n = g;
            }
            inside = !inside;
        }
        t = tn, v = vn;
        if (t > r.tmax) break;
    }
    if (inside && !s.open && n < max) { // closed by the container's far wall, or past tmax
        t0[n] = start, t1[n] = t >= b ? cb : FLT_MAX, n0[n] = start_n, n1[n] = nb;
        ++n;
    }
    return n;
}

} // namespace sheaf

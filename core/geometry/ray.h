// A ray with its valid parameter interval.
#pragma once

#include "core/math/vec3.h"

#include <cfloat>
#include <cmath>

namespace sheaf {

struct Ray {
    Vec3 origin;
    float tmin = 0;
    Vec3 dir; // unit length
    float tmax = 0;
};

SHEAF_HD_INLINE Vec3 ray_at(const Ray& r, float t) {
    return r.origin + r.dir * t;
}

/// Inserts c into xs, sorted by t, of which n (at most max) are held: when full, the farthest
/// gives way. The shapes that gather a ray's crossings before pairing them keep the nearest.
template <class C> SHEAF_HD_INLINE void insert_nearest(C* xs, int& n, int max, const C& c) {
    int at;
    if (n < max)
        at = n++;
    else if (c.t < xs[n - 1].t)
        at = n - 1;
    else
        return;
    for (; at > 0 && xs[at - 1].t > c.t; --at) xs[at] = xs[at - 1];
    xs[at] = c;
}

/// Where oz + dz t lies in the slab 0 <= z <= 1: [t0, t1] (all of t when the ray runs along
/// the slab inside it), with the outward normals of the faces it enters and leaves by; false
/// when it never does. Shared by the shapes with caps at z = 0 and 1.
SHEAF_HD_INLINE bool unit_slab(double oz, double dz, double& t0, double& t1, Vec3& n0, Vec3& n1) {
    t0 = -DBL_MAX, t1 = DBL_MAX;
    n0 = Vec3(0, 0, -1), n1 = Vec3(0, 0, 1);
    if (fabs(dz) < 1e-30) return !(oz < 0 || oz > 1);
    t0 = -oz / dz, t1 = (1 - oz) / dz;
    if (t0 > t1) {
        const double t = t0;
        t0 = t1, t1 = t;
        n0 = Vec3(0, 0, 1), n1 = Vec3(0, 0, -1);
    }
    return true;
}

} // namespace sheaf

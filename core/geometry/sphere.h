// Bounding spheres: the unions of paper 000 (eqs. 7, 8) and their n-ary form.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"
#include "core/math/vec3.h"

#include <cfloat>

namespace sheaf {

struct Sphere {
    Vec3 center;
    float radius = 0;
};

/// Relative padding that keeps float-rounded bounds conservative.
constexpr float kBoundPad = 1e-5f;

SHEAF_HD_INLINE float pad_radius(float r, Vec3 center) {
    // Absolute part scales with the magnitude of the coordinates, so that rounding of
    // positions far from the origin cannot escape the bound.
    return r * (1.0f + kBoundPad) +
           kBoundPad * (fabsf(center.x) + fabsf(center.y) + fabsf(center.z)) * 1e-2f + 1e-7f;
}

SHEAF_HD_INLINE bool sphere_contains(const Sphere& s, Vec3 p) {
    return length(p - s.center) <= s.radius;
}

/// Whether the ray from `origin` along unit `dir` (t >= 0) can meet sphere `s`: it passes
/// within the radius of the centre, not wholly behind the origin. Always for an unbounded one.
SHEAF_HD_INLINE bool ray_meets_sphere(const Sphere& s, Vec3 origin, Vec3 dir) {
    if (!(fabsf(s.radius) <= FLT_MAX)) return true;
    const Vec3 oc = s.center - origin;
    const float along = dot(oc, dir);
    return !(length_squared(oc) - along * along > s.radius * s.radius ||
             (along < -s.radius && length(oc) > s.radius));
}

/// Whether the line of ray r (a direction of any length) passes within sphere s, never false
/// where it does: the centre's distance from the line as |oc x d| / |d|, whose components are
/// off by at most a few units in the last place of |oc| |d| (err bounds that, with room).
/// Always for an unbounded sphere. ray_meets_sphere also drops spheres behind the origin, but
/// takes a unit direction and no rounding margin.
SHEAF_HD_INLINE bool line_meets_sphere(const Sphere& s, const Ray& r) {
    if (!(fabsf(s.radius) <= 1e30f)) return true;
    const Vec3 oc = s.center - r.origin, d = r.dir;
    const Vec3 cr = cross(oc, d);
    const float err = 1e-6f * (fabsf(oc.x) + fabsf(oc.y) + fabsf(oc.z)) *
                      (fabsf(d.x) + fabsf(d.y) + fabsf(d.z));
    const float reach = fabsf(s.radius) * sqrtf(dot(d, d)) * 1.0001f + 2.0f * err;
    return dot(cr, cr) <= reach * reach;
}

/// Union of two spheres as written in paper 000 (eqs. 7 and 8): centre halfway between the
/// centres, radius half their distance plus the larger radius. Conservative, not minimal.
SHEAF_HD_INLINE Sphere sphere_union_paper(const Sphere& a, const Sphere& b) {
    Sphere s;
    s.center = (a.center + b.center) * 0.5f;
    s.radius = pad_radius(length(b.center - a.center) * 0.5f + hdm::fmaxf(a.radius, b.radius), s.center);
    return s;
}

/// Union of n spheres (n >= 1): centre at the mean of the centres, radius the farthest
/// child surface from it. Every point of every child lies inside the result.
SHEAF_HD_INLINE Sphere sphere_union(const Sphere* s, int n) {
    Vec3 c(0.0f);
    for (int i = 0; i < n; ++i) c += s[i].center;
    c = c * (1.0f / float(n));
    float r = 0;
    for (int i = 0; i < n; ++i) r = hdm::fmaxf(r, length(s[i].center - c) + s[i].radius);
    return {c, pad_radius(r, c)};
}

} // namespace sheaf

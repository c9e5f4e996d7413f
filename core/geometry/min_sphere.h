// Minimal enclosing spheres: of a triangle (exact, host and device) and of a point set
// (Welzl's algorithm with Gaertner's move-to-front order).
#pragma once

#include "core/geometry/sphere.h"
#include "core/math/hd_math.h"

#include <span>

namespace sheaf {

/// The minimal sphere of three points: the midpoint of the longest edge when the triangle is
/// right or obtuse, else the circumcentre. The radius is then raised to the largest vertex
/// distance, so all three vertices are inside whatever the rounding.
SHEAF_HD_INLINE Sphere triangle_sphere(Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 ab = b - a, ac = c - a, bc = c - b;
    const float dab = dot(ab, ab), dac = dot(ac, ac), dbc = dot(bc, bc);
    Vec3 center;
    if (dab >= dac + dbc)
        center = (a + b) * 0.5f;
    else if (dac >= dab + dbc)
        center = (a + c) * 0.5f;
    else if (dbc >= dab + dac)
        center = (b + c) * 0.5f;
    else {
        const Vec3 n = cross(ab, ac);
        const float nn = dot(n, n);
        if (nn <= 0)
            center = (a + b + c) * (1.0f / 3.0f);
        else
            center = a + (cross(n, ab) * dac + cross(ac, n) * dab) * (0.5f / nn);
    }
    float r = hdm::fmaxf(length(a - center), hdm::fmaxf(length(b - center), length(c - center)));
    return {center, pad_radius(r, center)};
}

/// Minimal enclosing sphere of a point set (empty set: radius 0 at the origin). Computed in
/// double precision, then padded so every input point lies inside in float arithmetic.
Sphere min_sphere(std::span<const Vec3> points);

} // namespace sheaf

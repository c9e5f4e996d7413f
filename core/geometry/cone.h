// Direction cones: apex-free sets of unit directions within `angle` of `axis`.
#pragma once

#include "core/math/hd_math.h"
#include "core/math/vec3.h"

namespace sheaf {

struct Cone {
    Vec3 axis;       // unit length
    float angle = 0; // half-angle in radians, in [0, pi]
};

constexpr float kAnglePad = 2e-6f;

SHEAF_HD_INLINE bool cone_contains(const Cone& c, Vec3 dir) {
    return angle_between(c.axis, normalize(dir)) <= c.angle;
}

/// Union of two cones (paper 000 eqs. 5 and 6, with the extraction slip of eq. 6 fixed:
/// the half-angle is angle(x1, x2) / 2 + max(phi1, phi2), an angle, not a cosine).
SHEAF_HD_INLINE Cone cone_union_paper(const Cone& a, const Cone& b) {
    Vec3 s = a.axis + b.axis;
    float l = length(s);
    Cone c;
    if (l < 1e-6f) { // opposite axes: everything
        c.axis = a.axis;
        c.angle = kPi;
        return c;
    }
    c.axis = s / l;
    // In exact arithmetic the axis bisects a and b, so each child reaches angle(a, b) / 2 plus
    // its own angle. In floats, for nearly opposite axes the short sum's rounding (and the axes'
    // own length error) tilts the axis by up to ~1e-7 / l: measure the reach from the axis used.
    const float reach =
        hdm::fmaxf(angle_between(c.axis, a.axis) + a.angle, angle_between(c.axis, b.axis) + b.angle);
    c.angle =
        hdm::fminf(kPi, hdm::fmaxf(angle_between(a.axis, b.axis) * 0.5f + hdm::fmaxf(a.angle, b.angle), reach) +
                       kAnglePad);
    return c;
}

/// Union of n cones (n >= 1): axis along the normalised sum of the axes, half-angle the
/// largest child reach from it. Every direction of every child lies inside the result.
SHEAF_HD_INLINE Cone cone_union(const Cone* c, int n) {
    Vec3 s(0.0f);
    for (int i = 0; i < n; ++i) s += c[i].axis;
    float l = length(s);
    Vec3 axis = l > 1e-6f ? s / l : c[0].axis;
    float a = 0;
    for (int i = 0; i < n; ++i) a = hdm::fmaxf(a, angle_between(axis, c[i].axis) + c[i].angle);
    return {axis, hdm::fminf(kPi, a + kAnglePad)};
}

} // namespace sheaf

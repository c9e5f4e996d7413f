// An axis-aligned box in world space (infinite: unbounded): an analytic object's bound for
// the BVH (core/scene/analytic.h csg_box).
#pragma once

#include "core/math/vec3.h"

#include <cmath>

namespace sheaf {

struct WorldBox {
    Vec3 lo{-INFINITY, -INFINITY, -INFINITY}, hi{INFINITY, INFINITY, INFINITY};
};

/// Narrows [t0, t1] to where the line from `o` along `d` lies inside box b, side by side on
/// each axis; false where it lies outside a slab of zero direction.
SHEAF_HD_INLINE bool clip_to_box(const WorldBox& b, Vec3 o, Vec3 d, float& t0, float& t1) {
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] < b.lo[a] || o[a] > b.hi[a]) return false;
            continue;
        }
        const float inv = 1.0f / d[a];
        float ta = (b.lo[a] - o[a]) * inv, tb = (b.hi[a] - o[a]) * inv;
        if (ta > tb) {
            const float s = ta;
            ta = tb, tb = s;
        }
        if (ta > t0) t0 = ta; // NaN (an infinite side from its plane) leaves it as it was
        if (tb < t1) t1 = tb;
    }
    return true;
}

/// Whether the ray from `o` along `d` (t >= 0) meets box b, never false where it does (room
/// for rounding); t_enter: where it enters (0 from inside), a lower bound on its hits in b.
SHEAF_HD_INLINE bool ray_enters_box(const WorldBox& b, Vec3 o, Vec3 d, float& t_enter) {
    float t0 = 0, t1 = INFINITY;
    if (!clip_to_box(b, o, d, t0, t1)) return false;
    const float room = 1e-5f * (fabsf(t0) + (t1 < INFINITY ? fabsf(t1) : 0.0f)) + 1e-30f;
    if (t0 > t1 + room) return false;
    t_enter = t0 - room;
    return true;
}

/// Whether the whole line through `o` along `d` (t of any sign) meets box b, never false where
/// it does (room for rounding). An unbounded box meets every line.
SHEAF_HD_INLINE bool line_meets_box(const WorldBox& b, Vec3 o, Vec3 d) {
    float t0 = -INFINITY, t1 = INFINITY;
    if (!clip_to_box(b, o, d, t0, t1)) return false;
    return !(t0 > t1) || t0 - t1 <= 1e-5f * (fabsf(t0) + fabsf(t1)) + 1e-30f;
}

} // namespace sheaf

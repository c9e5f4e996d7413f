// The exact ray-triangle test (Moeller-Trumbore).
#pragma once

#include "core/geometry/ray.h"

namespace sheaf {

struct TriangleHit {
    float t;
    float u, v; // barycentrics of vertices 1 and 2
};

/// True when the ray meets the triangle (a, b, c) at t strictly inside (tmin, tmax).
/// Deterministic: the same inputs give the same t on every accel mode and backend.
SHEAF_HD_HOT bool intersect_triangle(const Ray& r, Vec3 a, Vec3 b, Vec3 c, TriangleHit& hit) {
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 p = cross(r.dir, e2);
    const float det = dot(e1, p);
    // Parallel ray or degenerate triangle. The bound scales with the edges: for an exactly
    // collinear triangle the rounding of p leaves |det| up to ~4e-7 |e1| |e2|, far above any
    // fixed threshold, and u, v would then be ratios of rounding noise (spurious hits); a fixed
    // threshold would also reject every triangle with edges under ~1e-6. L1 norms: no sqrt.
    const float l1 = fabsf(e1.x) + fabsf(e1.y) + fabsf(e1.z),
                l2 = fabsf(e2.x) + fabsf(e2.y) + fabsf(e2.z);
    if (!(fabsf(det) > 1e-6f * l1 * l2)) return false;
    const float inv = 1.0f / det;
    const Vec3 s = r.origin - a;
    const float u = dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const Vec3 q = cross(s, e1);
    const float v = dot(r.dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    const float t = dot(e2, q) * inv;
    if (!(t > r.tmin && t < r.tmax)) return false;
    hit = {t, u, v};
    return true;
}

} // namespace sheaf

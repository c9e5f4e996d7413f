// The exact test of any primitive: a triangle (Moeller-Trumbore) or an analytic object.
#pragma once

#include "core/geometry/ray_triangle.h"
#include "core/scene/analytic.h"

namespace sheaf {

/// Distance of the first hit of `ray` with primitive `prim` inside (tmin, tmax).
SHEAF_HD_INLINE bool intersect_prim(const SceneView& scene, uint32_t prim, const Ray& ray,
                                    float& t) {
    if (scene.is_triangle(prim)) {
        const TriangleVerts& tv = scene.tris[prim];
        TriangleHit h;
        if (!intersect_triangle(ray, tv.a, tv.b, tv.c, h)) return false;
        t = h.t;
        return true;
    }
    AnalyticHit h;
    if (!analytic_first_hit(scene, prim - scene.tri_count, ray, h)) return false;
    t = h.t;
    return true;
}

} // namespace sheaf

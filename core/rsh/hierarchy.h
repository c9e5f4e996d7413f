// The ray-space hierarchy (paper 000 section 3.3.6): leaves are rays in their sorted order;
// each node unites `arity` consecutive children with a sphere over their origins and a cone
// over their directions; `depth` levels of nodes in all. Conservative by construction: every
// ray of a node lies inside its sphere and cone.
#pragma once

#include "core/geometry/cone_sphere.h"
#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <vector>

namespace sheaf {

/// Children [first, last) of node i of a level over `below` entries (rays for level 1).
SHEAF_HD_INLINE size_t node_last_child(size_t i, int arity, size_t below) {
    const size_t e = (i + 1) * size_t(arity);
    return e < below ? e : below;
}

/// Node i of a level: over rays [first, last) of `rays` (level 1, `children` null) or over
/// nodes [first, last) of `children`. At most 64 children (hierarchy.arity).
SHEAF_HD_INLINE RayNode build_ray_node(const Ray* rays, const RayNode* children, size_t first,
                                       size_t last, bool bound_reach) {
    Sphere s[64];
    Cone c[64];
    float reach[64];
    int n = 0;
    for (size_t j = first; j < last; ++j, ++n) {
        if (!children) {
            // A leaf: a sphere of radius 0 at the origin, a cone of angle 0 along the ray.
            s[n] = {rays[j].origin, 0.0f};
            c[n] = {rays[j].dir, 0.0f};
            reach[n] = bound_reach && rays[j].tmax < 1e30f ? rays[j].tmax : INFINITY;
        } else {
            const RayNode& child = children[j];
            s[n] = {child.center, child.radius};
            c[n] = {child.axis, child.angle};
            reach[n] = child.reach;
        }
    }
    RayNode node = make_ray_node(sphere_union(s, n), cone_union(c, n));
    // Every ray point of a child lies within its reach of the child's centre.
    float r = 0;
    for (int k = 0; k < n && r < INFINITY; ++k)
        r = hdm::fmaxf(r, length(s[k].center - node.center) + reach[k]);
    node.reach = r * (1.0f + 1e-6f);
    return node;
}

} // namespace sheaf

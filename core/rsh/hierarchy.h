// The ray-space hierarchy (paper 000 section 3.3.6): leaves are rays in their sorted order;
// each node unites `arity` consecutive children with a sphere over their origins and a cone
// over their directions; `depth` levels of nodes in all. Conservative by construction: every
// ray of a node lies inside its sphere and cone.
#pragma once

#include "core/base/memory.h"
#include "core/geometry/cone_sphere.h"
#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <vector>

namespace sheaf {

struct RayHierarchy {
    int depth = 0, arity = 0;
    size_t ray_count = 0;
    // levels[k - 1] holds the nodes of level k: level 1 sits on the rays, level `depth` is the top.
    std::vector<TrackedVector<RayNode>> levels;

    size_t node_count(int level) const {
        return level == 0 ? ray_count : levels[size_t(level) - 1].size();
    }
    /// The children of node i of `level` are [first, last) of level - 1 (rays when level is 1).
    size_t first_child(size_t i) const { return i * size_t(arity); }
    size_t last_child(int level, size_t i) const {
        const size_t e = (i + 1) * size_t(arity), n = node_count(level - 1);
        return e < n ? e : n;
    }
};

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

/// `bound_reach`: nodes also bound how far their rays go (RayNode::reach; setting
/// cull.distance), so primitives beyond every ray's end are culled.
RayHierarchy build_hierarchy(const TrackedVector<Ray>& rays, int depth, int arity,
                             MemoryTracker& memory, bool bound_reach = false);

} // namespace sheaf

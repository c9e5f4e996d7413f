#include "core/rsh/hierarchy.h"

#include "core/base/parallel.h"

namespace sheaf {

RayHierarchy build_hierarchy(const TrackedVector<Ray>& rays, int depth, int arity,
                             MemoryTracker& memory, bool bound_reach) {
    RayHierarchy h;
    h.depth = depth;
    h.arity = arity;
    h.ray_count = rays.size();
    for (int level = 1; level <= depth; ++level) {
        const size_t below = h.node_count(level - 1);
        const size_t count = (below + size_t(arity) - 1) / size_t(arity);
        TrackedVector<RayNode> nodes = tracked_vector<RayNode>(memory, count);
        parallel_for(
            "rsh.build", count,
            [&](size_t i) {
                Sphere s[64];
                Cone c[64];
                float reach[64];
                const size_t first = h.first_child(i), last = h.last_child(level, i);
                int n = 0;
                for (size_t j = first; j < last; ++j, ++n) {
                    if (level == 1) {
                        // A leaf: a sphere of radius 0 at the origin, a cone of angle 0 along the
                        // ray.
                        s[n] = {rays[j].origin, 0.0f};
                        c[n] = {rays[j].dir, 0.0f};
                        reach[n] = bound_reach && rays[j].tmax < 1e30f ? rays[j].tmax : INFINITY;
                    } else {
                        const RayNode& child = h.levels[size_t(level) - 2][j];
                        s[n] = {child.center, child.radius};
                        c[n] = {child.axis, child.angle};
                        reach[n] = child.reach;
                    }
                }
                RayNode node = make_ray_node(sphere_union(s, n), cone_union(c, n));
                // Every ray point of a child lies within its reach of the child's centre.
                float r = 0;
                for (int k = 0; k < n && r < INFINITY; ++k)
                    r = fmaxf(r, length(s[k].center - node.center) + reach[k]);
                node.reach = r * (1.0f + 1e-6f);
                nodes[i] = node;
            },
            64);
        h.levels.push_back(std::move(nodes));
    }
    return h;
}

} // namespace sheaf

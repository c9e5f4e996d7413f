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
                const RayNode* children = level == 1 ? nullptr : h.levels[size_t(level) - 2].data();
                nodes[i] = build_ray_node(rays.data(), children, h.first_child(i),
                                          h.last_child(level, i), bound_reach);
            },
            64);
        h.levels.push_back(std::move(nodes));
    }
    return h;
}

} // namespace sheaf

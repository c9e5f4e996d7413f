// The ray-space hierarchy (paper 000 section 3.3.6): leaves are rays in their sorted order;
// each node unites `arity` consecutive children with a sphere over their origins and a cone
// over their directions; `depth` levels of nodes in all. Conservative by construction: every
// ray of a node lies inside its sphere and cone.
#pragma once

#include "core/base/memory.h"
#include "core/geometry/cone_sphere.h"
#include "core/geometry/ray.h"

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

/// `bound_reach`: nodes also bound how far their rays go (RayNode::reach; setting
/// cull.distance), so primitives beyond every ray's end are culled.
RayHierarchy build_hierarchy(const TrackedVector<Ray>& rays, int depth, int arity,
                             MemoryTracker& memory, bool bound_reach = false);

} // namespace sheaf

// The CPU's top-down traversal of a batch's ray hierarchy (the tracer's stage on host memory,
// core/frame/wavefront_tracer.h): top nodes against object and unit spheres, then against
// the spheres of the surviving units' primitives, then level by level down to the exact
// tests, with candidate (node, primitive) pairs compacted through per-thread lists instead
// of a count, scan and fill per level. The same tests, counts and hits as the wavefront
// traversal.
#pragma once

#include "core/base/memory.h"
#include "core/rsh/cull_units.h"
#include "core/rsh/hierarchy.h"
#include "core/rsh/test_count.h"
#include "core/rsh/trace_kernels.h"
#include "core/scene/prepared_scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sheaf {

/// A batch's ray hierarchy as the tracer built it: nodes[k - 1] holds count[k] nodes of level
/// k (k = 1 .. depth), count[0] is the rays.
struct LevelsView {
    int depth = 0, arity = 0;
    const RayNode* const* nodes = nullptr;
    const size_t* count = nullptr;

    size_t node_count(int level) const { return count[level]; }
    /// The children of node i of `level` are [first, last) of level - 1 (rays at level 1).
    size_t first_child(size_t i) const { return i * size_t(arity); }
    size_t last_child(int level, size_t i) const {
        return node_last_child(i, arity, count[level - 1]);
    }
};

/// What one traversal counted: tests and hits against object and unit spheres, per level
/// (index k: level k), the rays' own box tests (crsh-bvh, rah-bvh), and exact tests; the
/// exact tests' time apart.
struct TraversalCounts {
    TestCount objects, final, nodes;
    std::vector<TestCount> levels;
    double final_ms = 0;
};

/// Traverses hierarchy `h` over `sorted` rays (sorted[j] is ray perm[j] of the batch) against
/// the scene: results go to `sinks` by batch index, each level-1 node's candidate count to
/// leaf_pairs[node] (zeroed by the caller). When `units` carry a BVH (crsh-bvh, rah-bvh) the
/// top nodes descend it instead of testing the object and unit spheres, and the rays of each
/// level-1 node continue on their own into what their node kept (core/rsh/bvh_top.h), each
/// ray's exact tests added to ray_tests[its batch index] (zeroed by the caller), leaf_pairs
/// unused. `cull`: cull.objects (with no BVH); `batch`: the candidate pairs
/// a level holds at once (traversal.batch); `skip`: primitive flags that are no candidates.
void traverse_on_cpu(const PreparedScene& scene, const CullUnits& units, const LevelsView& h,
                     const Ray* sorted, const uint32_t* perm, bool any, bool shadow, uint8_t skip,
                     size_t batch, bool cull, MemoryTracker& memory, const HitSinks& sinks,
                     uint32_t* leaf_pairs, uint32_t* ray_tests, TraversalCounts& counts);

} // namespace sheaf

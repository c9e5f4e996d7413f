// The object-space hierarchy of accel=bvh: a bounding volume hierarchy of eight-wide nodes over
// every bounded primitive of a prepared scene (triangles, analytic shapes, CSG roots), built
// top-down with the surface-area heuristic over binned centroids, and the primitives without
// finite bounds (planes, unclipped polys) kept aside for every ray to test. Built once per
// scene on the host (bvh_for caches it beside the culling units) and traversed by the same
// per-ray function on both backends (core/accel/bvh_trace.h).
#pragma once

#include "core/base/device.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sheaf {

struct PreparedScene;

constexpr int kBvhWidth = 8;
/// Bits of a child's slot in a reference to it (node << kBvhSlotBits | slot).
constexpr int kBvhSlotBits = 3;
constexpr uint32_t kBvhSlotMask = (1u << kBvhSlotBits) - 1;
static_assert(1 << kBvhSlotBits == kBvhWidth, "a slot names one of a node's children");
constexpr uint32_t kBvhNoChild = 0xFFFFFFFFu;
/// Levels of nodes below the root at which the builder stops weighing surface areas and
/// splits at the median, so that a traversal's stack is bounded (kBvhStack). Twelve levels of
/// eight-wide nodes are 36 of a binary tree's.
constexpr int kBvhSahDepth = 12;
/// Entries of a traversal's stack: at most seven siblings wait per level, and below
/// kBvhSahDepth a node's children are its range cut at the median into eight (the child with
/// the most primitives cut first), so each level divides the primitives by eight (2^32 of them:
/// 10 levels to leaves of 8).
constexpr int kBvhStack = (kBvhWidth - 1) * (kBvhSahDepth + 10) + 1;

/// Eight children's bounds as a structure of arrays (lo[axis][child]), so that the eight slab
/// tests are one vector operation (two on SSE). Child i is the node child[i] when count[i] is
/// 0, the leaf of primitives prims[child[i], child[i] + count[i]) otherwise, and no child at
/// all when child[i] is kBvhNoChild (its bounds then empty). 256 bytes: four cache lines.
struct BvhNode {
    float lo[3][kBvhWidth];
    float hi[3][kBvhWidth];
    uint32_t child[kBvhWidth];
    uint32_t count[kBvhWidth];
};
static_assert(sizeof(BvhNode) == 256, "a BVH node is four cache lines");

/// The hierarchy as the per-ray traversal reads it (host or device pointers). The root is node
/// 0 when there are nodes.
struct BvhView {
    const BvhNode* nodes = nullptr;
    const uint32_t* prims = nullptr;     // leaves' primitives, leaf by leaf
    const uint32_t* unbounded = nullptr; // primitives every ray tests
    uint32_t node_count = 0, prim_count = 0, unbounded_count = 0;
};

struct Bvh {
    std::vector<BvhNode> nodes;
    std::vector<uint32_t> prims;
    std::vector<uint32_t> unbounded;
    int depth = 0; // levels of nodes, the root's counted

    BvhView view() const {
        return {nodes.data(),           prims.data(),           unbounded.data(),
                uint32_t(nodes.size()), uint32_t(prims.size()), uint32_t(unbounded.size())};
    }
    /// Bytes of hierarchy (nodes and leaf lists) beside the scene's own arrays.
    size_t bytes() const {
        return nodes.size() * sizeof(BvhNode) + (prims.size() + unbounded.size()) * 4;
    }
};

/// The BVH of every primitive of `scene`: each primitive with finite bounds in exactly one
/// leaf, the others in `unbounded`. Multithreaded (oneTBB); the same tree for the same scene.
/// `chunk` > 0: every range of at most `chunk` triangles a leaf and every larger range split,
/// the heuristic choosing only where (the top level of accel=strips, core/accel/strips.h);
/// ranges with analytic shapes, and every range when `chunk` is 0: leaves of at most 8, where
/// the heuristic finds them cheaper than a split.
Bvh build_bvh(const PreparedScene& scene, uint32_t chunk = 0);

/// A BVH over the primitives `prims` of `scene` only (ids into the scene's primitives, which
/// its leaves and `unbounded` list), as build_bvh builds it.
Bvh build_bvh_over(const PreparedScene& scene, const std::vector<uint32_t>& prims);

/// A BVH over every primitive of `scene` whose ranges are split at their middle in the
/// primitives' order (each object's triangles are in Morton order: prepare_scene), with no
/// heuristic: several times faster to build than build_bvh and slower to traverse, for
/// structures that serve a few rays (the POV reader's trace(), io/pov/probe.cpp). The same
/// tree for the same scene; the stack bound holds (each level halves the ranges).
Bvh build_bvh_in_order(const PreparedScene& scene);

/// The scene's BVH, built on first use and kept with the scene (PreparedScene's cache) for
/// every later frame, comparison and sweep.
std::shared_ptr<const Bvh> bvh_for(const PreparedScene& scene);

} // namespace sheaf

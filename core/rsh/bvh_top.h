// The ray hierarchy over the BVH (accel=crsh-bvh, rah-bvh): a top node's sphere and cone
// descend the scene's BVH (core/accel/bvh.h) while they meet a child's bounds and the child is
// much wider than the node where it lies (node_stops_at); where it is not (or at a leaf) the
// descent stops and the (node, reference) pair goes down the ray levels, each child node
// keeping the references whose bounds it meets; finally each ray of a level-1 node continues
// into the references its node kept, on its own, as accel=bvh's rays do from the root
// (bvh_trace_from). The upper BVH levels are then tested once per top node instead of once
// per ray. Host-and-device: the CPU traversal and the wavefront's launches run the same
// functions.
#pragma once

#include "core/accel/bvh_trace.h"
#include "core/geometry/cone_sphere.h"
#include "core/rsh/test_count.h"
#include "core/scene/scene_view.h"

#include <cstdint>

namespace sheaf {

/// The most BVH nodes and primitives the ray hierarchy over the BVH can name in its references
/// (bvh_slot_ref, kBvhPrim) and a ray's traversal in its entries (kBvhLeaf).
constexpr uint32_t kBvhTopMaxNodes = 1u << 27;
constexpr uint32_t kBvhTopMaxPrims = 1u << 30;

/// The sphere through the corners of child i's box (a present child), padded for rounding:
/// what a ray node's sphere and cone are tested against (node_hits_sphere), a conservative
/// stand-in for the box.
SHEAF_HD_INLINE Sphere bvh_child_sphere(const BvhNode& n, int i) {
    const Vec3 lo(n.lo[0][i], n.lo[1][i], n.lo[2][i]);
    const Vec3 hi(n.hi[0][i], n.hi[1][i], n.hi[2][i]);
    const Vec3 half = (hi - lo) * 0.5f;
    return {lo + half, length(half) * (1.0f + 1e-5f) + 1e-30f};
}

/// What a pair of the ray hierarchy over the BVH names: a child slot of a BVH node (node * 8
/// + slot), or a primitive without bounds (kBvhPrim | primitive).
SHEAF_HD_INLINE uint32_t bvh_slot_ref(uint32_t node, int slot) {
    return node << kBvhSlotBits | uint32_t(slot);
}

/// The bounds of a reference: its slot's box sphere, or the primitive's sphere.
SHEAF_HD_INLINE Sphere bvh_ref_sphere(const BvhView& bvh, const SceneView& scene, uint32_t ref) {
    if (ref & kBvhPrim) return scene.prim_sphere[ref & ~kBvhPrim];
    return bvh_child_sphere(bvh.nodes[ref >> kBvhSlotBits], int(ref & kBvhSlotMask));
}

/// Where a ray's traversal of a reference starts (an entry of bvh_trace_from).
SHEAF_HD_INLINE uint32_t bvh_ref_entry(const BvhView& bvh, uint32_t ref) {
    if (ref & kBvhPrim) return ref;
    return bvh_child_entry(bvh.nodes[ref >> kBvhSlotBits], ref >> kBvhSlotBits,
                           int(ref & kBvhSlotMask));
}

/// How much wider than a ray node a BVH child may be for the node's descent to stop there:
/// the rays then continue into it on their own. Measured on the generated terrain scenes
/// (docs/performance.md): the more the rays take on their own, the faster, up to about 16;
/// 1/4 tripled the box tests a ray.
constexpr float kBvhFrontier = 16.0f;

/// Whether the BVH descent of a ray node stops at a child of bounding sphere `s`: when the
/// node, its own radius and the spread of its cone at the sphere's distance along the axis,
/// is at least 1/kBvhFrontier of the sphere's radius. A wide cone (from 1.5 rad) stops at
/// once.
SHEAF_HD_INLINE bool node_stops_at(const RayNode& node, const Sphere& s) {
    if (node.angle >= 1.5f) return true;
    const float along = dot(s.center - node.center, node.axis);
    return (node.radius + (along > 0 ? along : 0.0f) * node.tan_angle) * kBvhFrontier >= s.radius;
}

/// Top node `node` through `bvh`: emit(ref) for every reference where its descent stops (the
/// primitives without bounds first, except those with the `skip` flags; then child slots,
/// depth first). Its tests against child spheres add to `tests`.
template <class Emit>
SHEAF_HD_INLINE void bvh_top_node(const BvhView& bvh, const SceneView& scene, const RayNode& node,
                                  uint8_t skip, TestCount& tests, Emit&& emit) {
    for (uint32_t k = 0; k < bvh.unbounded_count; ++k) {
        const uint32_t p = bvh.unbounded[k];
        if (!(skip && scene.prim_flag(p, skip))) emit(kBvhPrim | p);
    }
    if (bvh.node_count == 0) return;
    // Each node visited pushes at most eight children and takes one: seven wait per level.
    uint32_t stack[kBvhStack];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const uint32_t at = stack[--top];
        const BvhNode& n = bvh.nodes[at];
        for (int i = kBvhWidth - 1; i >= 0; --i) {
            if (n.child[i] == kBvhNoChild) continue;
            ++tests.tests;
            const Sphere s = bvh_child_sphere(n, i);
            if (!node_hits_sphere(node, s)) continue;
            ++tests.hits;
            if (n.count[i] > 0 || node_stops_at(node, s))
                emit(bvh_slot_ref(at, i));
            else
                stack[top++] = n.child[i];
        }
    }
}

/// The last step of a (level-1 node, reference) pair: each ray [first, last) of the node (in
/// sorted order; perm gives its place in the batch) through the reference on its own
/// (bvh_trace_from), its exact tests added to ray_tests[its place]. Returns the box and exact
/// tests of them all.
SHEAF_HD_INLINE BvhCounts bvh_ref_rays(const BvhView& bvh, const SceneView& scene, const Ray* rays,
                                       const uint32_t* perm, size_t first, size_t last,
                                       uint32_t ref, bool any, bool shadow, uint8_t skip,
                                       const HitSinks& out, uint32_t* ray_tests) {
    BvhCounts sum;
    const uint32_t e = bvh_ref_entry(bvh, ref);
    for (size_t j = first; j < last; ++j) {
        const BvhCounts c = any ? bvh_trace_from<true>(bvh, scene, rays[j], perm[j], e, false, true,
                                                       shadow, skip, out)
                                : bvh_trace_from<false>(bvh, scene, rays[j], perm[j], e, false,
                                                        true, shadow, skip, out);
        sum.nodes.tests += c.nodes.tests, sum.nodes.hits += c.nodes.hits;
        sum.prims.tests += c.prims.tests, sum.prims.hits += c.prims.hits;
        atomic_add_u32(&ray_tests[perm[j]], uint32_t(c.prims.tests));
    }
    return sum;
}

} // namespace sheaf

// The walk of one ray through a BVH (core/accel/bvh.h), host-and-device: the slab tests of a
// node's children and the order in which its leaves are met. The tracer's traversal
// (bvh_trace.h) and the media's walk over their solid objects (core/shading/media.h) share it.
#pragma once

#include "core/accel/bvh.h"
#include "core/geometry/ray.h"
#include "core/rsh/test_count.h"

#include <cstring>

#if !defined(__CUDA_ARCH__) && defined(__SSE2__)
#include <emmintrin.h>
#endif
// The host's eight-wide slab test on x86-64 processors with AVX2, chosen at run time
// (core/accel/bvh_trace.h, bvh_avx2).
#if !defined(__CUDA_ARCH__) && !defined(__CUDACC__) && defined(__x86_64__) && defined(__GNUC__)
#define SHEAF_BVH_AVX2 1
#include <immintrin.h>
#else
#define SHEAF_BVH_AVX2 0
#endif

namespace sheaf {

/// What one ray's traversal counted: box tests against children, and exact tests.
struct BvhCounts {
    TestCount nodes, prims;
};

/// A ray's slab planes in a node: for each axis, which of a child's two bounds the ray meets
/// first (lo when the direction's component is positive), as offsets into the node's bounds
/// (BvhNode::lo and hi are one array of 24 floats). Taken once per ray; the entry and exit
/// distances then need no minimum or maximum, and an empty child (lo above hi) is missed.
struct BvhPlanes {
    int near[3], far[3];
};

SHEAF_HD_INLINE BvhPlanes bvh_planes(const Vec3& inv) {
    BvhPlanes p;
    for (int a = 0; a < 3; ++a) {
        const bool up = inv[a] >= 0;
        p.near[a] = (up ? 0 : 3 * kBvhWidth) + a * kBvhWidth;
        p.far[a] = (up ? 3 * kBvhWidth : 0) + a * kBvhWidth;
    }
    return p;
}

/// The slab test of a ray against the eight children of a node, conservative under rounding
/// (the far distance grown by a few units in the last place, the boxes padded when built):
/// bit i of the result set when child i is present and meets the ray within [t0, t1], its
/// entry distance in near[i]; the children present added to `tested`. For a positive inverse
/// direction, (lo - o) * inv <= (hi - o) * inv in floating point as in reals (rounding is
/// monotonic), so taking the planes in the ray's order gives what the minimum and maximum of
/// the two would. On SSE the eight are two vectors of four; bvh_children_hit_avx2 is one.
SHEAF_HD_HOT uint32_t bvh_children_hit(const BvhNode& n, const BvhPlanes& pl, const Vec3& o,
                                       const Vec3& inv, float t0, float t1, float near[kBvhWidth],
                                       uint64_t& tested) {
    const float* b = &n.lo[0][0];
#if !defined(__CUDA_ARCH__) && defined(__SSE2__)
    uint32_t mask = 0;
    for (int h = 0; h < kBvhWidth; h += 4) {
        const auto dist = [&](int off, int axis) {
            return _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(b + off + h), _mm_set1_ps(o[axis])),
                              _mm_set1_ps(inv[axis]));
        };
        const __m128 tn = _mm_max_ps(
            _mm_max_ps(_mm_max_ps(dist(pl.near[0], 0), dist(pl.near[1], 1)), dist(pl.near[2], 2)),
            _mm_set1_ps(t0));
        __m128 tf =
            _mm_min_ps(_mm_min_ps(dist(pl.far[0], 0), dist(pl.far[1], 1)), dist(pl.far[2], 2));
        const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), tf);
        tf = _mm_add_ps(tf, _mm_mul_ps(magnitude, _mm_set1_ps(4e-7f)));
        tf = _mm_min_ps(tf, _mm_set1_ps(t1));
        _mm_storeu_ps(near + h, tn);
        const __m128i none = _mm_cmpeq_epi32(
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(n.child + h)), _mm_set1_epi32(-1));
        const uint32_t present = uint32_t(~_mm_movemask_ps(_mm_castsi128_ps(none))) & 0xFu;
        tested += (0x4332322132212110ull >> (4 * present)) & 0xFu; // bits set in 4 (no popcnt)
        mask |= (uint32_t(_mm_movemask_ps(_mm_cmple_ps(tn, tf))) & present) << h;
    }
    return mask;
#else
    uint32_t mask = 0;
    for (int i = 0; i < kBvhWidth; ++i) {
        float tn = t0, tf = 3.402823466e+38f;
        for (int a = 0; a < 3; ++a) {
            const float n0 = (b[pl.near[a] + i] - o[a]) * inv[a];
            const float f0 = (b[pl.far[a] + i] - o[a]) * inv[a];
            tn = n0 > tn ? n0 : tn;
            tf = f0 < tf ? f0 : tf;
        }
        tf += (tf < 0 ? -tf : tf) * 4e-7f;
        tf = tf < t1 ? tf : t1;
        near[i] = tn;
        if (n.child[i] == kBvhNoChild) continue;
        ++tested;
        if (tn <= tf) mask |= 1u << i;
    }
    return mask;
#endif
}

#if SHEAF_BVH_AVX2
/// bvh_children_hit as one eight-wide AVX2 operation, bit for bit the same (the same
/// operations on each lane; no fused multiply-add). Only inlined into code compiled for AVX2
/// (core/accel/bvh_trace_avx2.cpp), which runs where the processor has it (bvh_avx2).
__attribute__((target("avx2,popcnt"))) inline uint32_t
bvh_children_hit_avx2(const BvhNode& n, const BvhPlanes& pl, const Vec3& o, const Vec3& inv,
                      float t0, float t1, float near[kBvhWidth], uint64_t& tested) {
    const float* b = &n.lo[0][0];
#define SHEAF_BVH_DIST(off, axis)                                                                  \
    _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(b + (off)), _mm256_set1_ps(o[axis])),              \
                  _mm256_set1_ps(inv[axis]))
    const __m256 tn = _mm256_max_ps(
        _mm256_max_ps(_mm256_max_ps(SHEAF_BVH_DIST(pl.near[0], 0), SHEAF_BVH_DIST(pl.near[1], 1)),
                      SHEAF_BVH_DIST(pl.near[2], 2)),
        _mm256_set1_ps(t0));
    __m256 tf =
        _mm256_min_ps(_mm256_min_ps(SHEAF_BVH_DIST(pl.far[0], 0), SHEAF_BVH_DIST(pl.far[1], 1)),
                      SHEAF_BVH_DIST(pl.far[2], 2));
#undef SHEAF_BVH_DIST
    const __m256 magnitude = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), tf);
    tf = _mm256_add_ps(tf, _mm256_mul_ps(magnitude, _mm256_set1_ps(4e-7f)));
    tf = _mm256_min_ps(tf, _mm256_set1_ps(t1));
    _mm256_storeu_ps(near, tn);
    const __m256i none = _mm256_cmpeq_epi32(
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(n.child)), _mm256_set1_epi32(-1));
    const uint32_t present = uint32_t(~_mm256_movemask_ps(_mm256_castsi256_ps(none))) & 0xFFu;
    tested += uint64_t(__builtin_popcount(present));
    return uint32_t(_mm256_movemask_ps(_mm256_cmp_ps(tn, tf, _CMP_LE_OQ))) & present;
}
#endif

/// The reciprocal of a direction, with zero components replaced by a tiny one of their sign:
/// every slab distance is then a number or an infinity, never 0 * inf.
SHEAF_HD_INLINE Vec3 bvh_inverse(const Vec3& d) {
    const auto f = [](float v) {
        const float tiny = 1e-30f;
        return 1.0f / ((v < 0 ? -v : v) > tiny ? v : (v < 0 ? -tiny : tiny));
    };
    return {f(d.x), f(d.y), f(d.z)};
}

/// The index of the lowest set bit of a non-zero mask.
SHEAF_HD_INLINE int lowest_bit(uint32_t mask) {
#ifdef __CUDA_ARCH__
    return __ffs(int(mask)) - 1;
#else
    return __builtin_ctz(mask);
#endif
}

/// The float just above a finite x.
SHEAF_HD_INLINE float bvh_next_up(float x) {
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    u = x >= 0 ? (x == 0 ? 1u : u + 1) : u - 1;
    memcpy(&x, &u, sizeof x);
    return x;
}

/// Entries of a traversal: an inner node (its index), a leaf (kBvhLeaf | node * 8 + slot:
/// child `slot` of `node`), or one primitive (kBvhPrim | primitive). Inner node indices are
/// below kBvhPrim, leaf nodes below 2^28.
constexpr uint32_t kBvhLeaf = 0x80000000u;
constexpr uint32_t kBvhPrim = 0x40000000u;

/// The entry for child `slot` of node `node`: the child node, or the leaf.
SHEAF_HD_INLINE uint32_t bvh_child_entry(const BvhNode& n, uint32_t node, int slot) {
    return n.count[slot] > 0 ? kBvhLeaf | (node << kBvhSlotBits | uint32_t(slot)) : n.child[slot];
}

/// The part of the BVH under entry `e` that a ray meets, nearest child first: each leaf met
/// handed to leaf(first, count) (entries [first, first + count) of bvh.prims), which returns
/// false to end the walk. A closest-hit ray (Any false) skips what lies beyond `far`, read
/// anew at each step; box tests are counted in c.nodes. Avx2: the slab tests are
/// bvh_children_hit_avx2's (only in code compiled for AVX2).
template <bool Any, bool Avx2 = false, class Leaf>
SHEAF_HD_HOT void bvh_walk(const BvhView& bvh, const Ray& r, const Vec3& inv,
                           const BvhPlanes& planes, uint32_t e, const float& far, BvhCounts& c,
                           Leaf&& leaf) {
    // With each waiting entry its entry distance, so that a closest-hit ray drops what its
    // best hit has passed. The entry in hand (e) is not on the stack: of a node's children
    // met, the nearest is taken next and the others pushed, farthest first (any-hit rays: in
    // order; the first opaque hit anywhere ends them).
    uint32_t stack[kBvhStack];
    float stack_t[kBvhStack];
    int sp = 0;
    for (;;) {
        if (e & kBvhLeaf) {
            const BvhNode& n = bvh.nodes[(e & ~kBvhLeaf) >> kBvhSlotBits];
            const uint32_t slot = e & kBvhSlotMask;
            if (!leaf(n.child[slot], n.count[slot])) return;
        } else {
            const BvhNode& n = bvh.nodes[e];
            float near[kBvhWidth];
            uint32_t mask;
#if SHEAF_BVH_AVX2
            if constexpr (Avx2)
                mask = bvh_children_hit_avx2(n, planes, r.origin, inv, r.tmin, far, near,
                                             c.nodes.tests);
            else
#endif
                mask = bvh_children_hit(n, planes, r.origin, inv, r.tmin, far, near, c.nodes.tests);
            if (mask) {
                int order[kBvhWidth], hits = 0;
                for (; mask; mask &= mask - 1) {
                    const int k = lowest_bit(mask);
                    int at = hits++;
                    if constexpr (!Any)
                        while (at > 0 && near[order[at - 1]] < near[k])
                            order[at] = order[at - 1], --at;
                    order[at] = k;
                }
                c.nodes.hits += uint64_t(hits);
                for (int h = 0; h + 1 < hits; ++h) {
                    const int k = order[h];
                    stack[sp] = bvh_child_entry(n, e, k);
                    if constexpr (!Any) stack_t[sp] = near[k];
                    ++sp;
                }
                e = bvh_child_entry(n, e, order[hits - 1]);
                continue;
            }
        }
        // The next waiting entry that a closest-hit ray's best hit has not passed.
        while (sp > 0 && (!Any && stack_t[sp - 1] > far)) --sp;
        if (sp == 0) return;
        e = stack[--sp];
    }
}

} // namespace sheaf

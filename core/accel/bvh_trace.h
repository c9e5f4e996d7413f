// One ray through the BVH (core/accel/bvh.h), host-and-device: the tracer's bvh launch runs it
// per ray on both backends. The primitives without bounds first, then the nodes from the
// root, nearest child first; a closest-hit ray skips what lies beyond its best hit, an any-hit
// ray stops at its first opaque hit. The exact tests and what they record are brute force's
// (core/rsh/trace_kernels.h), so the hits are brute's: the same nearest hit, ties to the lower
// primitive.
#pragma once

#include "core/accel/bvh.h"
#include "core/rsh/trace_kernels.h"

#if !defined(__CUDA_ARCH__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sheaf {

/// What one ray's traversal counted: box tests against children, and exact tests.
struct BvhCounts {
    TestCount nodes, prims;
};

/// The slab test of a ray against the four children of a node, conservative under rounding
/// (the far distance grown by a few units in the last place, the boxes padded when built):
/// bit i of the result set when child i is present and meets the ray within [t0, t1], its
/// entry distance in near[i].
SHEAF_HD_INLINE uint32_t bvh_children_hit(const BvhNode& n, const Vec3& o, const Vec3& inv,
                                          float t0, float t1, float near[kBvhWidth]) {
#if !defined(__CUDA_ARCH__) && defined(__SSE2__)
    // The four children at once (the same operations as below, lane by lane: SSE's min and
    // max are the comparisons written there).
    const auto slab = [&](int axis, float origin, float rcp, __m128& lo, __m128& hi) {
        const __m128 org = _mm_set1_ps(origin), r = _mm_set1_ps(rcp);
        const __m128 a = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.lo[axis]), org), r);
        const __m128 b = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.hi[axis]), org), r);
        lo = _mm_min_ps(a, b), hi = _mm_max_ps(a, b);
    };
    __m128 nx, fx, ny, fy, nz, fz;
    slab(0, o.x, inv.x, nx, fx);
    slab(1, o.y, inv.y, ny, fy);
    slab(2, o.z, inv.z, nz, fz);
    const __m128 tn = _mm_max_ps(_mm_max_ps(_mm_max_ps(nx, ny), nz), _mm_set1_ps(t0));
    __m128 tf = _mm_min_ps(_mm_min_ps(fx, fy), fz);
    const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), tf);
    tf = _mm_add_ps(tf, _mm_mul_ps(magnitude, _mm_set1_ps(4e-7f)));
    tf = _mm_min_ps(tf, _mm_set1_ps(t1));
    _mm_storeu_ps(near, tn);
    const __m128i none = _mm_cmpeq_epi32(
        _mm_loadu_si128(reinterpret_cast<const __m128i*>(n.child)), _mm_set1_epi32(-1));
    return uint32_t(_mm_movemask_ps(_mm_cmple_ps(tn, tf)) & ~_mm_movemask_ps(_mm_castsi128_ps(none)));
#else
    uint32_t mask = 0;
    for (int i = 0; i < kBvhWidth; ++i) {
        const float ax = (n.lo[0][i] - o.x) * inv.x, bx = (n.hi[0][i] - o.x) * inv.x;
        const float ay = (n.lo[1][i] - o.y) * inv.y, by = (n.hi[1][i] - o.y) * inv.y;
        const float az = (n.lo[2][i] - o.z) * inv.z, bz = (n.hi[2][i] - o.z) * inv.z;
        const float nx = ax < bx ? ax : bx, fx = ax > bx ? ax : bx;
        const float ny = ay < by ? ay : by, fy = ay > by ? ay : by;
        const float nz = az < bz ? az : bz, fz = az > bz ? az : bz;
        float tn = nx > ny ? nx : ny;
        tn = tn > nz ? tn : nz;
        tn = tn > t0 ? tn : t0;
        float tf = fx < fy ? fx : fy;
        tf = tf < fz ? tf : fz;
        tf += (tf < 0 ? -tf : tf) * 4e-7f;
        tf = tf < t1 ? tf : t1;
        near[i] = tn;
        if (tn <= tf && n.child[i] != kBvhNoChild) mask |= 1u << i;
    }
    return mask;
#endif
}

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

/// Ray i of a batch (r) through the BVH against `scene`: writes closest[i] for closest-hit
/// queries, occluded[i] and the pass log for any-hit ones, as brute_trace_ray does. `skip`:
/// primitive flags that are no candidates for this ray type.
SHEAF_HD_INLINE BvhCounts bvh_trace_ray(const BvhView& bvh, const SceneView& scene, const Ray& r,
                                        uint32_t i, bool any, bool shadow, uint8_t skip,
                                        const HitSinks& out) {
    BvhCounts c;
    uint64_t best = kNoHit;
    bool done = false;
    // The ray the triangles are tested with: a triangle's distance does not depend on tmax, so
    // the best hit bounds their tests (equal distances still pass: the lower primitive wins
    // the tie). Analytic shapes take the ray as given.
    Ray bounded = r;
    // One primitive's exact test: false when the ray is finished (an opaque any hit).
    const auto test = [&](uint32_t p) {
        if (skip && scene.prim_flag(p, skip)) return true;
        ++c.prims.tests;
        float t;
        if (scene.is_triangle(p)) {
            const TriangleVerts& tri = scene.tris[p];
            TriangleHit h;
            if (!intersect_triangle(bounded, tri.a, tri.b, tri.c, h)) return true;
            t = h.t;
        } else if (!intersect_prim(scene, p, r, t)) {
            return true;
        }
        ++c.prims.hits;
        if (any && passes(scene, shadow, p)) return record_pass(scene, out, i, r, t, p);
        if (any) {
            out.occluded[i] = 1;
            return false;
        }
        const uint64_t h = pack_hit(t, p);
        if (h < best) {
            best = h;
            bounded.tmax = t < r.tmax ? bvh_next_up(t) : r.tmax;
        }
        return true;
    };
    for (uint32_t k = 0; k < bvh.unbounded_count && !done; ++k) done = !test(bvh.unbounded[k]);
    if (bvh.node_count > 0 && !done) {
        const Vec3 inv = bvh_inverse(r.dir);
        // Entries: a node (its index), or a leaf (kLeaf | node * 4 + slot); with the entry
        // distance, so that a closest-hit ray drops what its best hit has passed.
        constexpr uint32_t kLeaf = 0x80000000u;
        uint32_t stack[kBvhStack];
        float stack_t[kBvhStack];
        int sp = 0;
        stack[sp] = 0, stack_t[sp] = r.tmin, ++sp;
        while (sp > 0 && !done) {
            --sp;
            const uint32_t e = stack[sp];
            const float far = any || best == kNoHit ? r.tmax : hit_t(best);
            if (stack_t[sp] > far) continue;
            if (e & kLeaf) {
                const BvhNode& n = bvh.nodes[(e & ~kLeaf) >> 2];
                const uint32_t slot = e & 3u, first = n.child[slot];
                for (uint32_t k = first; k < first + n.count[slot] && !done; ++k)
                    done = !test(bvh.prims[k]);
                continue;
            }
            const BvhNode& n = bvh.nodes[e];
            float near[kBvhWidth];
            uint32_t mask = bvh_children_hit(n, r.origin, inv, r.tmin, far, near);
            for (int k = 0; k < kBvhWidth; ++k) c.nodes.tests += n.child[k] != kBvhNoChild ? 1 : 0;
            // Pushed farthest first, so the nearest is taken next (any-hit rays: in order,
            // the first opaque hit anywhere ends them).
            int order[kBvhWidth], hits = 0;
            for (; mask; mask &= mask - 1) {
                const int k = lowest_bit(mask);
                int at = hits++;
                while (!any && at > 0 && near[order[at - 1]] < near[k])
                    order[at] = order[at - 1], --at;
                order[at] = k;
            }
            c.nodes.hits += uint64_t(hits);
            for (int h = 0; h < hits; ++h) {
                const int k = order[h];
                stack[sp] = n.count[k] > 0 ? kLeaf | (e << 2 | uint32_t(k)) : n.child[k];
                stack_t[sp] = near[k];
                ++sp;
            }
        }
    }
    if (!any) out.closest[i] = best;
    return c;
}

} // namespace sheaf

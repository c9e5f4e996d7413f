// One ray through the BVH (core/accel/bvh.h), host-and-device: the tracer's bvh launch runs it
// per ray on both backends. The primitives without bounds first, then the nodes from the
// root, nearest child first; a closest-hit ray skips what lies beyond its best hit, an any-hit
// ray stops at its first opaque hit. The exact tests and what they record are brute force's
// (core/rsh/trace_kernels.h), so the hits are brute's: the same nearest hit, ties to the lower
// primitive.
#pragma once

#include "core/accel/bvh_walk.h"
#include "core/rsh/trace_kernels.h"

namespace sheaf {

/// One ray's exact tests and what they record, as brute_trace_ray does (closest hits for
/// closest-hit queries, Any false; occluded[i] and the pass log for any-hit ones), shared by
/// the traversals of accel=bvh and accel=strips. `far`: what a closest-hit ray still looks for,
/// up to its best hit.
template <bool Any> struct BvhHitTest {
    const SceneView& scene;
    const Ray& r;
    uint32_t i;
    bool shadow;
    uint8_t skip;
    const HitSinks& out;
    BvhCounts& c;
    uint64_t best = kNoHit;
    // The ray the triangles are tested with: a triangle's distance does not depend on tmax, so
    // the best hit bounds their tests (equal distances still pass: the lower primitive wins
    // the tie). Analytic shapes take the ray as given.
    Ray bounded;
    float far;

    SHEAF_HD_INLINE BvhHitTest(const SceneView& scene_, const Ray& r_, uint32_t i_, bool shadow_,
                               uint8_t skip_, const HitSinks& out_, BvhCounts& c_)
        : scene(scene_), r(r_), i(i_), shadow(shadow_), skip(skip_), out(out_), c(c_), bounded(r_),
          far(r_.tmax) {}

    /// Whether primitive p is no candidate for this ray type.
    SHEAF_HD_INLINE bool skipped(uint32_t p) const { return skip && scene.prim_flag(p, skip); }

    /// Primitive p's exact test, counted: false when the ray is finished (an opaque any hit).
    SHEAF_HD_INLINE bool operator()(uint32_t p) {
        if (skipped(p)) return true;
        if (scene.is_triangle(p)) {
            ++c.prims.tests;
            return triangle(p);
        }
        // An analytic shape's exact test costs many triangles': its bounding sphere first
        // (the leaf's box is the sphere's cube, which the ray may cross beside it).
        ++c.nodes.tests;
        if (!line_meets_sphere(scene.prim_sphere[p], r)) return true;
        ++c.nodes.hits;
        ++c.prims.tests;
        float t;
        if (!intersect_prim(scene, p, r, t)) return true;
        return hit(p, t);
    }

    /// Triangle p's exact test, neither counted nor checked against `skip`.
    SHEAF_HD_INLINE bool triangle(uint32_t p) {
        const TriangleVerts& tri = scene.tris[p];
        TriangleHit h;
        if (!intersect_triangle(bounded, tri.a, tri.b, tri.c, h)) return true;
        return hit(p, h.t);
    }

    SHEAF_HD_INLINE bool hit(uint32_t p, float t) {
        ++c.prims.hits;
        if constexpr (Any) {
            if (passes(scene, shadow, p)) return record_pass(scene, out, i, r, t, p);
            store_flag(&out.occluded[i]);
            return false;
        } else {
            const uint64_t h = pack_hit(t, p);
            if (h < best) {
                best = h;
                bounded.tmax = t < r.tmax ? bvh_next_up(t) : r.tmax;
                far = hit_t(best);
            }
            return true;
        }
    }

    /// Writes a closest-hit ray's best hit (`shared`: an atomic minimum with other traversals
    /// of the same ray).
    SHEAF_HD_INLINE void finish(bool shared) {
        if constexpr (!Any) {
            if (!shared)
                out.closest[i] = best;
            else if (best != kNoHit)
                atomic_min_u64(&out.closest[i], best);
        }
    }
};

/// The body of bvh_trace_from, inlined into it and, on x86-64 hosts, into
/// bvh_trace_from_avx2 (Avx2: the eight-wide slab tests).
template <bool Any, bool Avx2>
SHEAF_HD_HOT BvhCounts bvh_trace_body(const BvhView& bvh, const SceneView& scene, const Ray& r,
                                      uint32_t i, uint32_t start, bool unbounded, bool shared,
                                      bool shadow, uint8_t skip, const HitSinks& out) {
    BvhCounts c;
    BvhHitTest<Any> test(scene, r, i, shadow, skip, out, c);
    bool done = false;
    if (unbounded)
        for (uint32_t k = 0; k < bvh.unbounded_count && !done; ++k) done = !test(bvh.unbounded[k]);
    if (start & kBvhPrim && !(start & kBvhLeaf)) {
        test(start & ~kBvhPrim);
    } else if (bvh.node_count > 0 && !done) {
        const Vec3 inv = bvh_inverse(r.dir);
        bvh_walk<Any, Avx2>(bvh, r, inv, bvh_planes(inv), start, test.far, c,
                            [&](uint32_t first, uint32_t count) {
                                for (uint32_t k = first; k < first + count; ++k)
                                    if (!test(bvh.prims[k])) return false;
                                return true;
                            });
    }
    test.finish(shared);
    return c;
}

#if SHEAF_BVH_AVX2
/// Whether this host's traversals take the AVX2 slab tests: the processor has AVX2, and
/// neither SHEAF_SIMD=sse in the environment nor bvh_set_avx2(false) turned them off.
bool bvh_avx2();
/// Turns the AVX2 slab tests off (or back on, where the processor has them): the tests
/// compare both paths.
void bvh_set_avx2(bool on);
/// bvh_trace_from compiled for AVX2 (core/accel/bvh_trace_avx2.cpp).
BvhCounts bvh_trace_from_avx2(bool any, const BvhView& bvh, const SceneView& scene, const Ray& r,
                              uint32_t i, uint32_t start, bool unbounded, bool shared, bool shadow,
                              uint8_t skip, const HitSinks& out);
#endif

/// Ray i of a batch (r) through the part of the BVH under `start` (an entry; the root is 0),
/// against `scene`, after the primitives without bounds when `unbounded`: records its hits as
/// brute_trace_ray does (BvhHitTest). `shared`: other traversals record hits of the same ray
/// (the ray hierarchy's entries, core/rsh/bvh_top.h), so a closest hit is an atomic minimum;
/// each traversal prunes by its own best hit only, so its counts do not depend on the
/// others'. (A flag, not a template parameter, and not inlined on the device: each copy is
/// another copy of the exact tests in the CUDA module, which ptxas takes minutes over; the bvh
/// launch and the ray hierarchy's over the BVH call the same two.) `skip`: primitive flags
/// that are no candidates for this ray type. On an x86-64 host with AVX2 the walk is
/// bvh_trace_from_avx2's, the same hits and counts.
template <bool Any>
SHEAF_HD_NOINLINE BvhCounts bvh_trace_from(const BvhView& bvh, const SceneView& scene, const Ray& r,
                                           uint32_t i, uint32_t start, bool unbounded, bool shared,
                                           bool shadow, uint8_t skip, const HitSinks& out) {
#if SHEAF_BVH_AVX2
    if (bvh_avx2())
        return bvh_trace_from_avx2(Any, bvh, scene, r, i, start, unbounded, shared, shadow, skip,
                                   out);
#endif
    return bvh_trace_body<Any, false>(bvh, scene, r, i, start, unbounded, shared, shadow, skip,
                                      out);
}

/// Ray i of a batch (r) through the whole BVH against `scene`: writes closest[i] for
/// closest-hit queries (Any false), occluded[i] and the pass log for any-hit ones, as
/// brute_trace_ray does.
template <bool Any>
SHEAF_HD_INLINE BvhCounts bvh_trace_ray_as(const BvhView& bvh, const SceneView& scene, const Ray& r,
                                           uint32_t i, bool shadow, uint8_t skip,
                                           const HitSinks& out) {
    return bvh_trace_from<Any>(bvh, scene, r, i, 0, true, false, shadow, skip, out);
}

/// bvh_trace_ray_as for a query chosen at run time.
SHEAF_HD_INLINE BvhCounts bvh_trace_ray(const BvhView& bvh, const SceneView& scene, const Ray& r,
                                        uint32_t i, bool any, bool shadow, uint8_t skip,
                                        const HitSinks& out) {
    return any ? bvh_trace_ray_as<true>(bvh, scene, r, i, shadow, skip, out)
               : bvh_trace_ray_as<false>(bvh, scene, r, i, shadow, skip, out);
}

} // namespace sheaf

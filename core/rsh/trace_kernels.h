// The per-element steps of tracing a batch, host-and-device: recording a hit (closest hits as
// an atomic minimum of pack_hit, any hits as a flag, transparent crossings of shadow rays as
// fixed-point log sums), one ray against every primitive (brute), and the final tests of one
// (level-1 node, primitive) pair. The CPU tracer and the wavefront pipeline share them, so
// they count and find the same hits.
#pragma once

#include "core/base/atomics.h"
#include "core/rsh/trace.h"
#include "core/scene/prim_intersect.h"
#include "core/shading/shadow_pass.h"

namespace sheaf {

/// Where a batch's results go (indexed by the ray's place in its batch).
struct HitSinks {
    uint64_t* closest = nullptr; // closest-hit rays: pack_hit minimum, kNoHit when none
    uint8_t* occluded = nullptr; // any-hit rays: 1 when something opaque is in the way
    uint64_t* pass_log = nullptr; // shadow rays through transparent surfaces, 3 per ray; or null
};

SHEAF_HD_INLINE void record_hit(const HitSinks& out, bool any, uint32_t ray, float t,
                                uint32_t prim) {
    if (any) {
        store_flag(&out.occluded[ray]);
        return;
    }
    atomic_min_u64(&out.closest[ray], pack_hit(t, prim));
}

/// A shadow ray's hit on a primitive that may let light through: what it keeps multiplies in
/// (as a sum of logs, in any order); an opaque crossing occludes. False when it occluded.
SHEAF_HD_INLINE bool record_pass(const SceneView& scene, const HitSinks& out, uint32_t ray,
                                 const Ray& r, float t, uint32_t prim) {
    const Vec3 pass = shadow_pass(scene, prim, r, t);
    if (max_component(pass) <= 0.0f) {
        store_flag(&out.occluded[ray]);
        return false;
    }
    for (int c = 0; c < 3; ++c)
        if (const uint64_t q = pass_to_log(pass[c])) atomic_add_u64(&out.pass_log[3 * size_t(ray) + c], q);
    return true;
}

/// Shadow rays pass transparent primitives; every other any-hit query stops at them.
SHEAF_HD_INLINE bool passes(const SceneView& scene, bool shadow, uint32_t prim) {
    return shadow && scene.prim_flag(prim, kPrimMayPass);
}

/// Objects without shadows let shadow and AO rays pass; objects without reflections are not
/// seen by reflection rays, objects without an image not by camera rays, objects photons pass
/// not by photons: the object flags a batch of this type skips.
SHEAF_HD_INLINE uint8_t skip_flags(RayType type) {
    return any_hit_query(type)           ? uint8_t(kNoShadow)
           : type == RayType::Reflection ? uint8_t(kNoReflection)
           : type == RayType::Camera     ? uint8_t(kNoImage)
           : type == RayType::Photon     ? uint8_t(kPassPhotons)
                                         : uint8_t(0);
}

/// brute: ray i against every primitive; any-hit queries stop at the first opaque hit.
/// Writes closest[i] for closest-hit queries.
SHEAF_HD_INLINE TestCount brute_trace_ray(const SceneView& scene, const Ray& r, uint32_t i,
                                          bool any, bool shadow, uint8_t skip,
                                          const HitSinks& out) {
    TestCount c;
    const uint32_t prims = scene.prim_count();
    uint64_t best = kNoHit;
    for (uint32_t p = 0; p < prims; ++p) {
        if (skip && scene.prim_flag(p, skip)) continue;
        ++c.tests;
        float t;
        if (!intersect_prim(scene, p, r, t)) continue;
        ++c.hits;
        if (any && passes(scene, shadow, p)) {
            if (!record_pass(scene, out, i, r, t, p)) break;
            continue;
        }
        if (any) {
            out.occluded[i] = 1;
            break;
        }
        const uint64_t h = pack_hit(t, p);
        best = h < best ? h : best;
    }
    if (!any) out.closest[i] = best;
    return c;
}

/// Whether final_tests of this primitive is the plain triangle test (final_triangle_tests):
/// a triangle that this query does not pass through (no surface to shade).
SHEAF_HD_INLINE bool plain_final(const SceneView& scene, uint32_t prim, bool any, bool shadow) {
    return scene.is_triangle(prim) && !(any && passes(scene, shadow, prim));
}

/// final_tests of a primitive for which plain_final holds: intersection and the hit recorded,
/// nothing else, so a kernel of these alone needs few registers (on the GPU, a kernel that
/// can also reach the analytic shapes or a shadow pass's texture takes all 255 and runs at an
/// eighth of the occupancy).
SHEAF_HD_INLINE uint64_t final_triangle_tests(const SceneView& scene, const Ray* rays,
                                              const uint32_t* perm, size_t first, size_t last,
                                              uint32_t prim, bool any, const HitSinks& out) {
    uint64_t hits = 0;
    const TriangleVerts& tri = scene.tris[prim];
    for (size_t j = first; j < last; ++j) {
        TriangleHit hit;
        if (!intersect_triangle(rays[j], tri.a, tri.b, tri.c, hit)) continue;
        ++hits;
        record_hit(out, any, perm[j], hit.t, prim);
    }
    return hits;
}

/// The final tests of one (level-1 node, primitive) pair: every ray [first, last) of the
/// node (in sorted order; perm gives each one's place in the batch) against the primitive.
/// Returns the hits.
SHEAF_HD_INLINE uint64_t final_tests(const SceneView& scene, const Ray* rays, const uint32_t* perm,
                                     size_t first, size_t last, uint32_t prim, bool any,
                                     bool shadow, const HitSinks& out) {
    if (plain_final(scene, prim, any, shadow))
        return final_triangle_tests(scene, rays, perm, first, last, prim, any, out);
    uint64_t hits = 0;
    if (scene.is_triangle(prim)) { // passed through: what the surface lets through
        const TriangleVerts& tri = scene.tris[prim];
        for (size_t j = first; j < last; ++j) {
            TriangleHit hit;
            if (!intersect_triangle(rays[j], tri.a, tri.b, tri.c, hit)) continue;
            ++hits;
            record_pass(scene, out, perm[j], rays[j], hit.t, prim);
        }
    } else {
        const bool pass = any && passes(scene, shadow, prim);
        for (size_t j = first; j < last; ++j) {
            float th;
            if (!intersect_prim(scene, prim, rays[j], th)) continue;
            ++hits;
            if (pass)
                record_pass(scene, out, perm[j], rays[j], th, prim);
            else
                record_hit(out, any, perm[j], th, prim);
        }
    }
    return hits;
}

} // namespace sheaf

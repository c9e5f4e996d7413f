// Shadows through transparent surfaces, as POV-Ray casts them: a shadow ray that crosses a
// surface keeps albedo * filter + transmit of the light there (no refraction), times POV-Ray's
// fake caustics where the material has them, and stops at an opaque one. The per-ray product
// is kept as a fixed-point sum of -log2 of each factor, added atomically, so it is exactly the
// same whatever the order of the tests.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"
#include "core/scene/analytic.h"
#include "core/scene/scene_view.h"
#include "core/shading/shade.h"
#include "core/shading/surface_hit.h"

#include <cstdint>

namespace sheaf {

namespace shadow_detail {

// POV-Ray's fake caustics: a shadow ray crossing a surface of material mt along dir, where
// the shading normal is n, carries 1 + |n.dir|^caustics times the light (1 without them), so
// light meeting glass head-on comes through brighter than it went in.
SHEAF_HD_INLINE float caustic_gain(const Material& mt, Vec3 n, Vec3 dir) {
    if (!(mt.caustics > 0)) return 1.0f;
    return 1.0f + hdm::powf(fabsf(dot(n, dir)), mt.caustics);
}

// albedo * filter + transmit of material `material` at world point p, times its caustic gain,
// where the surface's normal facing the shadow ray (direction dir) is n.
SHEAF_HD_INLINE Vec3 surface_pass(const SceneView& scene, uint32_t material, Vec3 p, float s,
                                  float t, Vec3 n, Vec3 dir) {
    const uint32_t m = resolve_material(scene, material, p, n, s, t);
    const Material& mt = scene.materials[m];
    Vec3 pass = mt.color * mt.transmission;
    if (mt.pigment >= 0) {
        const SurfaceColor c = evaluate_pigment(scene, uint32_t(mt.pigment), p, s, t, n);
        pass = c.rgb * c.filter + Vec3(c.transmit);
    }
    if (mt.caustics > 0) {
        // The caustics follow the normal the material's normal pattern tilts, as POV-Ray's.
        const Vec3 shading = mt.normal >= 0 ? perturb_normal(scene, uint32_t(mt.normal), p, n) : n;
        pass = pass * caustic_gain(mt, shading, dir);
    }
    return pass;
}

// The interior fade over the stretch of `span` inside the ray's (tmin, tmax): its entering
// surface's interior (a span of an `inverse` solid may start or end at no surface, marked
// 0xFFFFFFFF).
SHEAF_HD_INLINE Vec3 span_fade(const SceneView& scene, const CsgSpan& span, const Ray& ray) {
    const uint32_t leaf = span.a.leaf != 0xFFFFFFFFu ? span.a.leaf : span.b.leaf;
    const float inside = hdm::fminf(span.b.t, ray.tmax) - hdm::fmaxf(span.a.t, ray.tmin);
    if (!(inside > 0) || leaf == 0xFFFFFFFFu) return Vec3(1.0f);
    return interior_fade(scene.materials[scene.shape_material[leaf]], inside, true);
}

} // namespace shadow_detail

/// Light a shadow ray keeps (per channel) crossing primitive `prim`, whose exact test found
/// it at distance t: the product over every surface of the primitive it crosses inside the
/// ray's (tmin, tmax), and for analytic solids the interior fade over the stretch inside.
/// Zero where a crossed surface is opaque.
SHEAF_HD_NOINLINE Vec3 shadow_pass(const SceneView& scene, uint32_t prim, const Ray& ray, float t) {
    if (scene.is_triangle(prim)) {
        const SurfaceHit h = make_surface_hit(scene, ray, prim, t);
        return (h.albedo * h.filter + Vec3(h.transmit)) *
               shadow_detail::caustic_gain(scene.materials[h.material], h.normal, ray.dir);
    }
    // Every boundary of the primitive's spans inside the ray is a surface it crosses.
    const uint32_t index = prim - scene.tri_count;
    const SpanList spans = csg_spans(scene, scene.analytic_root[index], ray);
    Vec3 pass(1.0f);
    for (int i = 0; i < spans.n; ++i) {
        const CsgSpan& span = spans.s[i];
        const CsgEnd* ends[2] = {&span.a, &span.b};
        for (const CsgEnd* e : ends) {
            if (!(e->t > ray.tmin && e->t < ray.tmax) || e->leaf == 0xFFFFFFFFu) continue;
            const Vec3 p = ray_at(ray, e->t);
            Vec3 n = normal_to_world(scene.shapes[e->leaf], e->n_local);
            if (dot(n, ray.dir) > 0) n = -n; // facing the shadow ray, as POV-Ray's
            pass = pass * shadow_detail::surface_pass(scene, scene.shape_material[e->leaf], p, p.x,
                                                      p.y, n, ray.dir);
            if (max_component(pass) <= 0.0f) return Vec3(0.0f);
        }
        // The stretch inside the solid fades as its interior does (the entering surface's; a
        // span of an `inverse` solid may start or end at no surface, marked 0xFFFFFFFF).
        pass = pass * shadow_detail::span_fade(scene, span, ray);
    }
    // A clipped object's surfaces are spans of zero length: its interior fades over the
    // stretches inside it, as POV-Ray's inside test has them (advanced/wineglass.pov's base, a
    // clipped cone of glass, darkens the floor under it).
    if (scene.prim_flag(prim, kPrimOpen)) {
        const SpanList solid = csg_spans(scene, scene.analytic_root[index], ray, true);
        for (int i = 0; i < solid.n; ++i)
            pass = pass * shadow_detail::span_fade(scene, solid.s[i], ray);
    }
    return pass;
}

/// Fixed point for the products: -log2(factor) * 2^16, as a two's-complement sum (a caustic
/// gain above 1 adds a negative term); sums at or above 256 * 2^16 (factors at or below 2^-256)
/// count as 0.
constexpr uint64_t kPassLogOne = 1u << 16;
constexpr uint64_t kPassLogZero = 256 * kPassLogOne;

SHEAF_HD_INLINE uint64_t pass_to_log(float pass) {
    if (!(pass > 0.0f)) return kPassLogZero;
    if (pass == 1.0f) return 0;
    const double q = -hdm::log2(double(hdm::fminf(pass, 65536.0f))) * double(kPassLogOne);
    return q >= double(kPassLogZero) ? kPassLogZero : uint64_t(int64_t(q < 0 ? q - 0.5 : q + 0.5));
}

SHEAF_HD_INLINE float log_to_pass(uint64_t q) {
    const int64_t s = int64_t(q);
    return s >= int64_t(kPassLogZero) ? 0.0f : float(hdm::exp2(-double(s) / double(kPassLogOne)));
}

/// The light a shadow ray keeps per channel from its three fixed-point log sums.
SHEAF_HD_INLINE Vec3 pass_from_logs(const uint64_t* logs) {
    return Vec3(log_to_pass(logs[0]), log_to_pass(logs[1]), log_to_pass(logs[2]));
}

} // namespace sheaf

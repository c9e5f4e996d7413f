#include "core/render/shadow_pass.h"

#include "core/render/shade.h"
#include "core/render/surface_texture.h"
#include "core/scene/analytic.h"

namespace sheaf {

namespace {

// albedo * filter + transmit of material `material` at world point p.
Vec3 surface_pass(const PreparedScene& scene, uint32_t material, Vec3 p, float s, float t) {
    const uint32_t m = resolve_material(scene, material, p);
    const Material& mt = scene.materials[m];
    if (mt.pigment >= 0) {
        const SurfaceColor c = evaluate_pigment(scene, uint32_t(mt.pigment), p, s, t);
        return c.rgb * c.filter + Vec3(c.transmit);
    }
    return mt.color * mt.transmission;
}

} // namespace

Vec3 shadow_pass(const PreparedScene& scene, uint32_t prim, const Ray& ray, float t) {
    if (scene.is_triangle(prim)) {
        const SurfaceHit h = make_surface_hit(scene, ray, prim, t);
        return h.albedo * h.filter + Vec3(h.transmit);
    }
    // Every boundary of the primitive's spans inside the ray is a surface it crosses.
    const uint32_t index = prim - uint32_t(scene.tris.size());
    const SpanList spans = csg_spans(scene, scene.analytic_root[index], ray);
    Vec3 pass(1.0f);
    for (int i = 0; i < spans.n; ++i) {
        const CsgSpan& span = spans.s[i];
        for (const CsgEnd* e : {&span.a, &span.b}) {
            if (!(e->t > ray.tmin && e->t < ray.tmax) || e->leaf == 0xFFFFFFFFu) continue;
            const Vec3 p = ray_at(ray, e->t);
            pass = pass * surface_pass(scene, scene.shape_material[e->leaf], p, p.x, p.y);
            if (max_component(pass) <= 0.0f) return Vec3(0.0f);
        }
        // The stretch inside the solid fades as its interior does (the entering surface's).
        const float inside = fminf(span.b.t, ray.tmax) - fmaxf(span.a.t, ray.tmin);
        if (inside > 0)
            pass = pass * interior_fade(scene.materials[scene.shape_material[span.a.leaf]], inside);
    }
    return pass;
}

} // namespace sheaf

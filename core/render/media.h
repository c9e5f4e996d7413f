// Interior media (POV-Ray's `media` in an object's interior): light given off and taken away
// along the parts of a ray inside the analytic objects that hold media (their containers),
// whatever the ray met on the way in. Deterministic: each part is cut into as many equal steps
// as its media ask for, each evaluated at its middle, so the CPU and the device give the same
// bits and a frame has no noise.
#pragma once

#include "core/math/hd_math.h"
#include "core/render/surface_texture.h"
#include "core/scene/analytic.h"
#include "core/scene/scene_view.h"

namespace sheaf {

/// The media of material `m` over the d units of a ray from `from` along unit `dir`: `keep`
/// is the share of light from the far end that arrives at `from` (exp of minus the absorption
/// integrated), `add` the light the media give off on the way that arrives there (each step's
/// emission, faded by the absorption between it and `from`). Densities multiply the
/// emission and the absorption channel by channel.
SHEAF_HD_INLINE void through_media(const SceneView& scene, const Material& m, Vec3 from, Vec3 dir,
                                   float d, Vec3& keep, Vec3& add) {
    keep = Vec3(1.0f);
    add = Vec3(0.0f);
    if (m.media_count == 0 || !(d > 0) || !(d <= 1e30f)) return;
    uint32_t steps = 1;
    for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k)
        steps = scene.media[k].samples > steps ? scene.media[k].samples : steps;
    const float step = d / float(steps);
    for (uint32_t i = 0; i < steps; ++i) {
        const Vec3 p = from + dir * ((float(i) + 0.5f) * step);
        Vec3 emission(0.0f), absorption(0.0f);
        for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k) {
            const Medium& md = scene.media[k];
            Vec3 density(1.0f);
            for (uint32_t j = md.density_first; j < md.density_first + md.density_count; ++j)
                density = density * evaluate_pigment(scene, scene.medium_densities[j], p, 0, 0).rgb;
            emission += md.emission * density;
            absorption += md.absorption * density;
        }
        // Huge emissions times huge densities overflow: keep both finite (NaN: none), so that
        // a step that absorbs everything adds nothing rather than 0 x infinity.
        for (int c = 0; c < 3; ++c) {
            const float e = emission[c] == emission[c] ? emission[c] : 0.0f;
            const float a = absorption[c] == absorption[c] ? absorption[c] : 0.0f;
            emission[c] = hdm::fminf(hdm::fmaxf(e, -1e30f), 1e30f);
            absorption[c] = hdm::fminf(hdm::fmaxf(a, 0.0f), 1e30f);
        }
        // Half the step's absorption lies between its middle and its near end.
        const Vec3 half(hdm::expf(-0.5f * absorption.x * step),
                        hdm::expf(-0.5f * absorption.y * step),
                        hdm::expf(-0.5f * absorption.z * step));
        add += keep * half * emission * step;
        keep = keep * half * half;
    }
}

/// The media of every container along the ray from `origin` along unit `dir` up to t_end
/// (infinite for rays that leave the scene): what arrives at `origin` of light from t_end
/// (`keep`) and the light the media give off on the way (`add`). Parts of different
/// containers are taken in the order of the containers, each part in ray order.
SHEAF_HD_INLINE void media_along(const SceneView& scene, Vec3 origin, Vec3 dir, float t_end,
                                 Vec3& keep, Vec3& add) {
    keep = Vec3(1.0f);
    add = Vec3(0.0f);
    for (uint32_t c = 0; c < scene.media_container_count; ++c) {
        const uint32_t a = scene.media_containers[c];
        if (!ray_meets_sphere(scene.prim_sphere[scene.tri_count + a], origin, dir)) continue;
        Ray ray;
        ray.origin = origin, ray.dir = dir, ray.tmin = 0.0f, ray.tmax = FLT_MAX;
        SpanList spans = csg_spans(scene, scene.analytic_root[a], ray);
        // Solid objects inside are left out (POV-Ray fills only hollow ones).
        for (uint32_t s = 0; s < scene.media_solid_count && spans.n > 0; ++s) {
            const uint32_t b = scene.media_solids[s];
            if (b == a || !ray_meets_sphere(scene.prim_sphere[scene.tri_count + b], origin, dir))
                continue;
            spans = span_difference(spans, csg_spans(scene, scene.analytic_root[b], ray));
        }
        for (int i = 0; i < spans.n; ++i) {
            const float t0 = spans.s[i].a.t > 0 ? spans.s[i].a.t : 0.0f;
            const float t1 = spans.s[i].b.t < t_end ? spans.s[i].b.t : t_end;
            if (!(t1 > t0) || !(t1 - t0 <= 1e30f)) continue; // empty, or unbounded
            // The media of the shape the span enters by (a union's members have their own).
            const uint32_t leaf =
                spans.s[i].a.leaf != 0xFFFFFFFFu ? spans.s[i].a.leaf : spans.s[i].b.leaf;
            if (leaf == 0xFFFFFFFFu) continue;
            const Material& m = scene.materials[resolve_material(
                scene, scene.shape_material[leaf], origin + dir * (0.5f * (t0 + t1)))];
            if (m.media_count == 0) continue;
            Vec3 k, e;
            through_media(scene, m, origin + dir * t0, dir, t1 - t0, k, e);
            add += keep * e;
            keep = keep * k;
        }
    }
}

} // namespace sheaf

// Interior media (POV-Ray's `media` in an object's interior): light given off and taken away
// along the parts of a ray inside the analytic objects that hold media (their containers),
// whatever the ray met on the way in. Deterministic: each part is cut into as many equal steps
// as its media ask for, each evaluated at its middle, so the CPU and the device give the same
// bits and a frame has no noise.
#pragma once

#include "core/accel/bvh_walk.h"
#include "core/math/hd_math.h"
#include "core/scene/analytic.h"
#include "core/scene/scene_view.h"
#include "core/shading/shade.h"
#include "core/shading/surface_texture.h"
#include "core/texture/lattice_hash.h"

namespace sheaf {

/// POV-Ray's phase function of medium md at cosine c of the angle between the way to the light
/// and the way the ray goes (c = 1: the light lies straight ahead, behind the medium).
SHEAF_HD_INLINE float scatter_phase(const Medium& md, float c) {
    switch (md.scatter_type) {
    case ScatterType::MieHazy:
        return 0.576655375f * (1.0f + 9.0f * hdm::powf(0.5f * (1.0f + c), 8.0f));
    case ScatterType::MieMurky:
        return 0.495714547f * (1.0f + 50.0f * hdm::powf(0.5f * (1.0f + c), 32.0f));
    case ScatterType::Rayleigh:
        return 0.799372013f * (1.0f + c * c);
    case ScatterType::HenyeyGreenstein: {
        const float g = md.eccentricity, d = 1.0f + g * g - 2.0f * g * c;
        return d > 0 ? (1.0f - g * g) / (d * sqrtf(d)) : 0.0f;
    }
    case ScatterType::Isotropic:
        break;
    }
    return 1.0f;
}

/// The phase of material m's media, averaged over them as POV-Ray averages it (their summed
/// scattering multiplies it).
SHEAF_HD_INLINE float media_phase(const SceneView& scene, const Material& m, float c) {
    float k = 0;
    for (uint32_t i = m.media_first; i < m.media_first + m.media_count; ++i)
        k += scatter_phase(scene.media[i], c);
    return m.media_count > 0 ? k / float(m.media_count) : 0.0f;
}

/// Whether light l scatters in the media of material m: it interacts with media and lights the
/// material's light group.
SHEAF_HD_INLINE bool light_scatters_in(const Light& l, const Material& m) {
    return l.media_interaction && light_reaches_group(l, m.light_group);
}

/// The light of the shadowless lights that material m's media scatter at p back along unit
/// `dir` (towards where the ray comes from), per unit of scattering: they need no shadow ray.
SHEAF_HD_INLINE Vec3 shadowless_scatter(const SceneView& scene, const Material& m, Vec3 p,
                                        Vec3 dir) {
    Vec3 c(0.0f);
    for (uint32_t li = 0; li < scene.light_count; ++li) {
        const Light& l = scene.lights[li];
        if (!l.shadowless || !light_scatters_in(l, m)) continue;
        const LightSample ls = sample_light(l, p, 1.0f);
        c += ls.radiance * media_phase(scene, m, dot(ls.to_light, dir));
    }
    return c;
}

/// The product of medium md's densities' colours at p (1 without densities).
SHEAF_HD_INLINE Vec3 medium_density(const SceneView& scene, const Medium& md, Vec3 p) {
    Vec3 density(1.0f);
    for (uint32_t j = md.density_first; j < md.density_first + md.density_count; ++j)
        density = density * evaluate_pigment(scene, scene.medium_densities[j], p, 0, 0).rgb;
    return density;
}

/// x kept finite: NaN as 0, clamped to [lo, 1e30]. Huge emissions times huge densities
/// overflow, and a step that absorbs everything must add nothing rather than 0 x infinity.
SHEAF_HD_INLINE float media_finite(float x, float lo) {
    return x == x ? hdm::fminf(hdm::fmaxf(x, lo), 1e30f) : 0.0f;
}

/// Where in its steps a ray of sample `pixel` takes its media's values (through_media's u): a
/// hash of the sample in [0, 1), so that neighbouring samples step at different places and a
/// thin feature the steps straddle (a narrow light beam) shows as grain that anti-aliasing
/// averages, not as bands. Deterministic: the same on every backend.
SHEAF_HD_INLINE float media_jitter(uint32_t pixel) {
    return hash_unit(lattice_hash(int(pixel), 0, 0, 0x6d656469u));
}

/// Visits nothing: media walks that only integrate.
struct NoScatterVisit {
    SHEAF_HD void operator()(const Material&, Vec3, Vec3) const {}
};

/// The media of material `m` over the d units of a ray from `from` along unit `dir`: `keep`
/// is the share of light from the far end that arrives at `from` (exp of minus the extinction
/// integrated: absorption plus `extinction` times scattering), `add` the light the media give
/// off on the way that arrives there (each step's emission and the shadowless lights it
/// scatters, faded by the extinction between it and `from`). Densities multiply the emission,
/// absorption and scattering channel by channel. Each step takes the media's values at the
/// fraction u of its length (0.5: its middle; media_jitter). At each step that scatters,
/// `visit(m, p, w)` is called with that point p and w, the share of light scattered there
/// (phase 1) that arrives at `from`: the lights that cast shadows reach p through shadow rays
/// (core/shading/media_light.h).
template <class Visit>
SHEAF_HD_INLINE void through_media(const SceneView& scene, const Material& m, Vec3 from, Vec3 dir,
                                   float d, Vec3& keep, Vec3& add, const Visit& visit,
                                   float u = 0.5f) {
    keep = Vec3(1.0f);
    add = Vec3(0.0f);
    if (m.media_count == 0 || !(d > 0) || !(d <= 1e30f)) return;
    uint32_t steps = 1;
    for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k)
        steps = scene.media[k].samples > steps ? scene.media[k].samples : steps;
    const float step = d / float(steps);
    for (uint32_t i = 0; i < steps; ++i) {
        const Vec3 p = from + dir * ((float(i) + u) * step);
        Vec3 emission(0.0f), absorption(0.0f), scattering(0.0f);
        for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k) {
            const Medium& md = scene.media[k];
            const Vec3 density = medium_density(scene, md, p);
            emission += md.emission * density;
            absorption += md.attenuation() * density;
            scattering += md.scattering * density;
        }
        for (int c = 0; c < 3; ++c) {
            emission[c] = media_finite(emission[c], -1e30f);
            absorption[c] = media_finite(absorption[c], 0.0f);
            scattering[c] = media_finite(scattering[c], 0.0f);
        }
        // The fraction u of the step's extinction lies between p and the step's near end.
        const Vec3 near(hdm::expf(-u * absorption.x * step), hdm::expf(-u * absorption.y * step),
                        hdm::expf(-u * absorption.z * step));
        const Vec3 far(hdm::expf(-(1.0f - u) * absorption.x * step),
                       hdm::expf(-(1.0f - u) * absorption.y * step),
                       hdm::expf(-(1.0f - u) * absorption.z * step));
        if (max_component(scattering) > 0) {
            const Vec3 w = keep * near * scattering * step;
            emission += scattering * shadowless_scatter(scene, m, p, dir);
            visit(m, p, w);
        }
        add += keep * near * emission * step;
        keep = keep * near * far;
    }
}

SHEAF_HD_INLINE void through_media(const SceneView& scene, const Material& m, Vec3 from, Vec3 dir,
                                   float d, Vec3& keep, Vec3& add) {
    through_media(scene, m, from, dir, d, keep, add, NoScatterVisit());
}

/// Takes the parts inside solid objects (kSolid, all but analytic object `self`) out of
/// `spans`, the ray's parts in some media: POV-Ray's media fill only hollow objects. The
/// solids are found through their BVH (PreparedScene::media_solid_bvh), the ones on the ray's
/// way only; the parts behind its origin do not matter.
SHEAF_HD_INLINE void leave_solids(const SceneView& scene, const Ray& ray, uint32_t self,
                                  SpanList& spans) {
    auto leave = [&](uint32_t b) {
        if (b == self ||
            !ray_meets_sphere(scene.prim_sphere[scene.tri_count + b], ray.origin, ray.dir))
            return;
        spans = span_difference(spans, csg_spans(scene, scene.analytic_root[b], ray));
    };
    const BvhView& tree = scene.media_solid_bvh;
    for (uint32_t u = 0; u < tree.unbounded_count && spans.n > 0; ++u)
        leave(tree.unbounded[u] - scene.tri_count);
    if (tree.node_count == 0 || spans.n == 0) return;
    const Vec3 inv = bvh_inverse(ray.dir);
    const float far = FLT_MAX;
    BvhCounts counts;
    bvh_walk<true>(tree, ray, inv, bvh_planes(inv), 0, far, counts,
                   [&](uint32_t first, uint32_t count) {
                       for (uint32_t k = first; k < first + count && spans.n > 0; ++k)
                           leave(tree.prims[k] - scene.tri_count);
                       return spans.n > 0;
                   });
}

/// Calls f(m, t0, t1) for every part [t0, t1] of the ray from `origin` along unit `dir` up to
/// t_end (infinite for rays that leave the scene) that lies in a container's media of material
/// m: the containers in their order, each one's parts in ray order; then, with `atmosphere`,
/// the parts outside solid objects in the atmosphere's (Scene::atmosphere), up to
/// kAtmosphereFar. One loop serves both, so that f is inlined once (the device's stack).
template <class F>
SHEAF_HD_INLINE void for_media_parts(const SceneView& scene, Vec3 origin, Vec3 dir, float t_end,
                                     bool atmosphere, const F& f) {
    Ray ray;
    ray.origin = origin, ray.dir = dir, ray.tmin = 0.0f, ray.tmax = FLT_MAX;
    const uint32_t containers = scene.media_container_count;
    const uint32_t parts = containers + (atmosphere && scene.atmosphere >= 0 ? 1u : 0u);
    for (uint32_t c = 0; c < parts; ++c) {
        const bool air = c == containers; // the atmosphere comes last
        const uint32_t a = air ? 0xFFFFFFFFu : scene.media_containers[c];
        const float end = air && kAtmosphereFar < t_end ? kAtmosphereFar : t_end;
        SpanList spans;
        if (air) {
            spans.push({CsgEnd{0.0f, 0xFFFFFFFFu, Vec3(0, 0, 1), false},
                        CsgEnd{end, 0xFFFFFFFFu, Vec3(0, 0, 1), false}});
        } else {
            if (!ray_meets_sphere(scene.prim_sphere[scene.tri_count + a], origin, dir)) continue;
            spans = csg_spans(scene, scene.analytic_root[a], ray);
        }
        // The media of the shape each of the container's spans enters by (a union's members
        // have their own), kept for the pieces the solid objects inside leave of it: a piece
        // that starts where the ray leaves a solid still holds the container's media.
        uint32_t owner_leaf[kMaxCsgSpans];
        float owner_end[kMaxCsgSpans];
        const int owners = spans.n;
        for (int i = 0; i < owners; ++i) {
            owner_leaf[i] =
                spans.s[i].a.leaf != 0xFFFFFFFFu ? spans.s[i].a.leaf : spans.s[i].b.leaf;
            owner_end[i] = spans.s[i].b.t;
        }
        leave_solids(scene, ray, a, spans);
        int o = 0;
        for (int i = 0; i < spans.n; ++i) {
            const float t0 = spans.s[i].a.t > 0 ? spans.s[i].a.t : 0.0f;
            const float t1 = spans.s[i].b.t < end ? spans.s[i].b.t : end;
            if (!(t1 > t0) || !(t1 - t0 <= 1e30f)) continue; // empty, or unbounded
            const float mid = 0.5f * (t0 + t1);
            while (o + 1 < owners && mid > owner_end[o]) ++o; // pieces come in ray order
            const uint32_t leaf = owner_leaf[o];
            if (!air && leaf == 0xFFFFFFFFu) continue;
            const Material& m =
                scene.materials[air ? uint32_t(scene.atmosphere)
                                    : resolve_material(scene, scene.shape_material[leaf],
                                                       origin + dir * mid)];
            if (m.media_count > 0) f(m, t0, t1);
        }
    }
}

/// The media of every container and of the atmosphere along the ray from `origin` along unit
/// `dir` up to t_end (infinite for rays that leave the scene): what arrives at `origin` of
/// light from t_end (`keep`) and the light the media give off on the way (`add`). Parts of
/// different containers are taken in the order of the containers, then the atmosphere's, each
/// part in ray order, each step taking the media at its fraction u (through_media). `visit`
/// sees every step that scatters, its share w already faded by the containers before it.
template <class Visit>
SHEAF_HD_INLINE void media_along(const SceneView& scene, Vec3 origin, Vec3 dir, float t_end,
                                 Vec3& keep, Vec3& add, const Visit& visit, float u = 0.5f) {
    keep = Vec3(1.0f);
    add = Vec3(0.0f);
    for_media_parts(scene, origin, dir, t_end, true, [&](const Material& m, float t0, float t1) {
        Vec3 k, e;
        const Vec3 before = keep;
        through_media(
            scene, m, origin + dir * t0, dir, t1 - t0, k, e,
            [&](const Material& mm, Vec3 p, Vec3 w) { visit(mm, p, before * w); }, u);
        add += keep * e;
        keep = keep * k;
    });
}

SHEAF_HD_INLINE void media_along(const SceneView& scene, Vec3 origin, Vec3 dir, float t_end,
                                 Vec3& keep, Vec3& add, float u = 0.5f) {
    media_along(scene, origin, dir, t_end, keep, add, NoScatterVisit(), u);
}

/// The share of light that crosses the media between `from` and from + dir * d: exp of minus
/// the extinction integrated, as POV-Ray fades the light a shadow ray carries through the
/// interiors it crosses, and through the atmosphere with `atmosphere` (a light's
/// media_attenuation). Media without densities are constant: exact in one step; the others
/// take their light_samples steps (POV-Ray samples shadow rays without refining).
SHEAF_HD_INLINE Vec3 media_transmittance(const SceneView& scene, Vec3 from, Vec3 dir, float d,
                                         bool atmosphere) {
    Vec3 optical(0.0f);
    if (scene.media_container_count == 0 && !(atmosphere && scene.atmosphere >= 0))
        return Vec3(1.0f);
    for_media_parts(scene, from, dir, d, atmosphere, [&](const Material& m, float t0, float t1) {
        uint32_t steps = 1;
        for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k)
            if (scene.media[k].density_count > 0 && scene.media[k].light_samples > steps)
                steps = scene.media[k].light_samples;
        const float step = (t1 - t0) / float(steps);
        for (uint32_t i = 0; i < steps; ++i) {
            const Vec3 p = from + dir * (t0 + (float(i) + 0.5f) * step);
            Vec3 a(0.0f);
            for (uint32_t k = m.media_first; k < m.media_first + m.media_count; ++k) {
                const Medium& md = scene.media[k];
                a += md.attenuation() * medium_density(scene, md, p);
            }
            for (int c = 0; c < 3; ++c) optical[c] += media_finite(a[c], 0.0f) * step;
        }
    });
    return Vec3(hdm::expf(-optical.x), hdm::expf(-optical.y), hdm::expf(-optical.z));
}

/// The share of a light's light the fogs leave between `from` and from + dir * d, for a
/// light with media_attenuation (as POV-Ray's shadow rays, which take the fogs' attenuation
/// and not their colour): over the parts outside solid objects, which fog does not fill.
SHEAF_HD_INLINE Vec3 fog_transmittance(const SceneView& scene, Vec3 from, Vec3 dir, float d) {
    if (!scene.fog.any()) return Vec3(1.0f);
    Ray ray;
    ray.origin = from, ray.dir = dir, ray.tmin = 0.0f, ray.tmax = FLT_MAX;
    SpanList spans;
    spans.push({CsgEnd{0.0f, 0xFFFFFFFFu, Vec3(0, 0, 1), false},
                CsgEnd{d, 0xFFFFFFFFu, Vec3(0, 0, 1), false}});
    leave_solids(scene, ray, 0xFFFFFFFFu, spans);
    Vec3 through(1.0f);
    for (int i = 0; i < spans.n; ++i) {
        const float t0 = spans.s[i].a.t > 0 ? spans.s[i].a.t : 0.0f;
        const float t1 = spans.s[i].b.t < d ? spans.s[i].b.t : d;
        if (!(t1 > t0)) continue;
        Vec3 keep, add;
        fog_over(scene.fog, from + dir * t0, dir, t1 - t0, keep, add);
        through = through * keep;
    }
    return through;
}

} // namespace sheaf

// Light that media scatter towards the viewer from lights that cast shadows. Every ray that
// brings light to a sample (camera, reflection, refraction) leaves a segment: where it starts,
// its direction, where it stops and what it carries. Each step of a scattering medium along a
// segment (core/shading/media.h) sends a shadow ray to each light whose light arrives there
// (to at most kMediaLights of them, a different share at each step, when more do), carrying the
// light that arrives if nothing is in the way. The rays go through the ray hierarchy like the
// surfaces' shadow rays; both backends count, scan and fill them
// with the functions here, in the same order.
#pragma once

#include "core/math/hd_math.h"
#include "core/rays/ray_gen.h"
#include "core/scene/scene_view.h"
#include "core/shading/media.h"

#include <cstdint>

namespace sheaf {

/// A ray's way through the scene, for the light its media scatter. weight 0: no segment.
struct MediaSegment {
    Vec3 origin, dir;
    float t_end = 0; // INFINITY for a ray that leaves the scene
    Vec3 weight;     // the ray's throughput times the fog's share over the whole way
    uint32_t pixel = 0;
};

/// The segment of a ray from `origin` along unit `dir` to t_end carrying w to sample `pixel`:
/// the fog over the way fades what its media add, as through_fog and leave_scene fade it
/// (`no_fog`: a way inside a solid object, which the fog does not fill).
SHEAF_HD_INLINE MediaSegment media_segment(const SceneView& scene, Vec3 origin, Vec3 dir,
                                           float t_end, Vec3 w, uint32_t pixel,
                                           bool no_fog = false) {
    Vec3 keep(1.0f), add(0.0f);
    if (!no_fog) fog_over(scene.fog, origin, dir, t_end, keep, add);
    MediaSegment s;
    s.origin = origin, s.dir = dir, s.t_end = t_end, s.weight = w * keep, s.pixel = pixel;
    return s;
}

/// A scattering step sends shadow rays to this many lights at most.
constexpr uint32_t kMediaLights = 4;

/// Whether light l lights the scattering step at `at` in material m's media through a shadow
/// ray: it casts shadows, scatters in the media and its light arrives there (a spotlight's
/// cone holds the point); `ls` receives its sample.
SHEAF_HD_INLINE bool media_light_reaches(const Light& l, const Material& m, Vec3 at,
                                         const RayGenParams& p, LightSample& ls) {
    if (l.shadowless || !light_scatters_in(l, m)) return false; // shadowless: media.h adds it
    ls = sample_light(l, at, p.far);
    return max_component(ls.radiance) > 0;
}

/// Calls emit(ray, weight, light) for the shadow ray of every (scattering step, light) pair of
/// segment s: the ray runs from the light to the step's middle, and weight is the light that
/// arrives at the segment's start when nothing is in the way. Only the lights whose light
/// arrives at the step count (media_light_reaches: narrow spotlights reach few steps). With
/// more than kMediaLights of them, step k takes lights o + j * stride of them
/// (j < kMediaLights), o drawn per step from a hash of the sample and k, each carrying stride
/// times its light. `fade`: weights include the media between the step and the light
/// (media_transmittance); counting needs no weights.
template <class Emit>
SHEAF_HD_INLINE void media_light_rays(const SceneView& scene, const MediaSegment& s,
                                      const RayGenParams& p, bool fade, const Emit& emit) {
    if (!(max_component(s.weight) > 0) || scene.light_count == 0) return;
    uint32_t step = 0;
    Vec3 keep, add;
    media_along(
        scene, s.origin, s.dir, s.t_end, keep, add,
        [&](const Material& m, Vec3 at, Vec3 w) {
            const uint32_t tag = step++;
            if (!(max_component(s.weight * w) > 0)) return;
            // With no more lights than a step takes, all that reach it are taken: no need to
            // count them first (each count samples every light).
            uint32_t reach = scene.light_count;
            LightSample ls;
            if (reach > kMediaLights) {
                reach = 0;
                for (uint32_t li = 0; li < scene.light_count; ++li)
                    reach += media_light_reaches(scene.lights[li], m, at, p, ls) ? 1u : 0u;
            }
            const uint32_t stride = light_share_stride(reach, kMediaLights);
            const uint32_t o = light_share_offset(s.pixel, tag, stride);
            for (uint32_t li = 0, k = 0; li < scene.light_count; ++li) {
                const Light& l = scene.lights[li];
                if (!media_light_reaches(l, m, at, p, ls)) continue;
                const uint32_t c = k++; // its place among the lights that reach the step
                if (c < o || (c - o) % stride != 0) continue;
                if ((c - o) / stride >= kMediaLights) break;
                Vec3 weight = s.weight * w * ls.radiance *
                              (media_phase(scene, m, dot(ls.to_light, s.dir)) * float(stride));
                if (!(max_component(weight) > 0)) continue;
                // The media on the way to the light fade it: the containers', and the
                // atmosphere's for lights with media_attenuation (counting needs no weights).
                if (fade)
                    weight = weight * media_transmittance(scene, at, ls.to_light, ls.distance,
                                                          l.media_attenuation);
                Ray r;
                r.origin = ls.origin;
                r.dir = -ls.to_light;
                r.tmin = 0.0f;
                r.tmax = ls.distance;
                emit(r, weight, li);
            }
        },
        media_jitter(s.pixel));
}

/// How many shadow rays segment s sends (media_light_rays).
SHEAF_HD_INLINE uint32_t media_light_count(const SceneView& scene, const MediaSegment& s,
                                           const RayGenParams& p) {
    uint32_t n = 0;
    media_light_rays(scene, s, p, false, [&](const Ray&, Vec3, uint32_t) { ++n; });
    return n;
}

/// Writes segment s's shadow rays from `slot` on.
SHEAF_HD_INLINE void media_light_fill(const SceneView& scene, const MediaSegment& s, uint32_t slot,
                                      const RayGenParams& p, const RaySlots& out) {
    media_light_rays(scene, s, p, true, [&](const Ray& r, Vec3 w, uint32_t li) {
        out.rays[slot] = r;
        out.pixel[slot] = s.pixel;
        out.weight[slot] = w;
        out.light[slot] = li;
        ++slot;
    });
}

/// How many segments go into one batch of media shadow rays: about 4M rays at the most steps
/// a medium of the scene takes and kMediaLights lights, at least 256.
inline size_t media_segments_per_batch(const PreparedScene& scene) {
    uint32_t steps = 1;
    for (const Medium& md : scene.media) steps = md.samples > steps ? md.samples : steps;
    const size_t n = (size_t(1) << 22) / (size_t(steps) * kMediaLights);
    return n > 256 ? n : 256;
}

} // namespace sheaf

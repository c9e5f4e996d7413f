// Secondary ray generation from a wave of surface hits: shadow rays (one per light per lit
// point, origin moved to the light as in paper 000 section 3.3.2), ambient-occlusion rays
// (cosine-weighted, Halton, paper 003) and reflection/refraction rays (Fresnel, Snell).
// The frame pipeline (core/frame/frame_pipeline.h) counts, scans and fills with these
// host-and-device per-element functions, so the ray order is the same on every run and every
// backend.
#pragma once

#include "core/math/hd_math.h"
#include "core/rays/ray_batch.h"
#include "core/scene/scene_view.h"
#include "core/shading/media.h"
#include "core/shading/shade.h"
#include "core/shading/surface.h"

#include <cfloat>
#include <vector>

namespace sheaf {

/// Offsets from surfaces, relative to the coordinates' size (float rounding is about 1e-7 of
/// it, so a hundred times that).
constexpr float kRelativeOffset = 1e-5f;

struct RayGenParams {
    // Rays that leave a surface start this far off it (surface_offset), at least: a hit's
    // rounding grows with its distance from the origin and the camera's, so the offset is
    // kRelativeOffset times the larger (`epsilon` holds the camera's part).
    float epsilon = 1e-4f;
    // Where shadow rays end above surfaces, at least: they start at the lights, so the
    // rounding of their end grows with the lights' distance too.
    float shadow_epsilon = 1e-4f;
    float far = 1e4f; // beyond the scene: where parallel lights' shadow rays start
    int ao_samples = 0;
    float ao_distance = 1.0f;
    float min_weight = 1e-3f; // reflection/refraction rays carrying less are not traced
    // Gather rays carrying less are not traced. Fixed: a gathered path's weight is split
    // among its rays, so the reflection bailout (POV-Ray's adc_bailout) would cut its bounces.
    float gather_min_weight = 1e-3f;
    int radiosity_samples = 0; // gather rays per camera-path point (0: no radiosity)
    int radiosity_depth = 2;   // diffuse bounces of a gathered path
    float radiosity_brightness = 1.0f;
};

/// How far off a surface at `pos` the rays leaving it start: the camera's part of the offset
/// or kRelativeOffset of the point's largest coordinate, whichever is more. A large object far
/// away (a sky sphere) does not push the rays of small ones near the origin off their surfaces.
SHEAF_HD_INLINE float surface_offset(const RayGenParams& p, Vec3 pos) {
    const float m = hdm::fmaxf(fabsf(pos.x), hdm::fmaxf(fabsf(pos.y), fabsf(pos.z)));
    return hdm::fmaxf(p.epsilon, kRelativeOffset * m);
}

/// Where generated rays go: structure-of-arrays slots (light only for shadow rays).
struct RaySlots {
    Ray* rays = nullptr;
    uint32_t* pixel = nullptr;
    Vec3* weight = nullptr;
    uint32_t* light = nullptr;
};

/// Radical inverse in base b of index i (the Halton sequence's coordinate).
SHEAF_HD_INLINE float radical_inverse(uint32_t i, uint32_t base) {
    const float inv = 1.0f / float(base);
    float f = inv, r = 0;
    while (i > 0) {
        r += f * float(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

/// True when light l lights hit h at all (the hit is in its light group, faces it, and a
/// spot reaches it).
SHEAF_HD_INLINE bool lights_point(const Light& l, const SurfaceHit& h, const RayGenParams& p) {
    if (!light_reaches_group(l, h.light_group)) return false;
    const LightSample s = sample_light(l, h.position, p.far);
    return dot(h.geo_normal, s.to_light) > 0 && dot(h.normal, s.to_light) > 0 &&
           max_component(s.radiance) > 0;
}

namespace raygen_detail {

// A frame around unit n.
SHEAF_HD_INLINE void basis(Vec3 n, Vec3& t, Vec3& b) {
    const float s = n.z >= 0 ? 1.0f : -1.0f;
    const float a = -1.0f / (s + n.z);
    const float c = n.x * n.y * a;
    t = Vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = Vec3(c, s + n.y * n.y * a, -n.y);
}

/// Points on a gathered (radiosity) path are lit by this many of the scene's lights at most,
/// a different share at each point (an area light is many lights: its 81 shadow rays at
/// every gathered point would cost far more than the gathering).
constexpr uint32_t kGatherLights = 4;

/// The cosine-weighted direction about unit n (with t and b around it) of Halton point
/// `index` in bases b1 and b2.
SHEAF_HD_INLINE Vec3 cosine_direction(Vec3 n, Vec3 t, Vec3 b, uint32_t index, uint32_t b1,
                                      uint32_t b2) {
    const float u1 = radical_inverse(index, b1), u2 = radical_inverse(index, b2);
    const float r = sqrtf(u1), phi = 2.0f * kPi * u2;
    const Vec3 d = t * (r * hdm::cosf(phi)) + b * (r * hdm::sinf(phi)) +
                   n * sqrtf(hdm::fmaxf(0.0f, 1.0f - u1));
    return normalize(d);
}

} // namespace raygen_detail

/// A point that takes `per` of `lights` lights takes every stride-th one, stride =
/// ceil(lights / per), so each light has chance 1 / stride and carries stride times its light.
SHEAF_HD_INLINE uint32_t light_share_stride(uint32_t lights, uint32_t per) {
    return lights <= per ? 1u : (lights + per - 1) / per;
}

/// Which of the stride shares a point takes: a hash of its sample and tag (its path, or its
/// step along a ray), so neighbouring points take different lights.
SHEAF_HD_INLINE uint32_t light_share_offset(uint32_t pixel, uint32_t tag, uint32_t stride) {
    if (stride <= 1) return 0;
    uint32_t x = pixel * 0x9E3779B9u ^ (tag * 0x85EBCA6Bu);
    x ^= x >> 16, x *= 0x7FEB352Du, x ^= x >> 15, x *= 0x846CA68Bu, x ^= x >> 16;
    return x % stride;
}

/// Which (hit, light) pairs a wave's shadow rays come from. The wave's first `camera` hits
/// (camera, reflection and refraction paths) take every light, light-major: element k <
/// camera * lights is light k / camera at hit k % camera, so rays that leave the same light
/// towards neighbouring pixels sit side by side even unsorted (rah). The rest are points on
/// gathered radiosity paths (a wave lists them last), hit-major, kGatherLights elements each:
/// element j of such a hit is light offset + j * stride, stride = ceil(lights /
/// kGatherLights), offset drawn per hit from a hash of its sample and path, so each light has
/// chance 1 / stride and its rays carry stride times its light.
struct ShadowLayout {
    size_t hits = 0, camera = 0;
    uint32_t lights = 0;

    SHEAF_HD size_t elements() const {
        if (lights == 0) return 0;
        return camera * lights + (hits - camera) * raygen_detail::kGatherLights;
    }
    SHEAF_HD uint32_t stride() const {
        return light_share_stride(lights, raygen_detail::kGatherLights);
    }
    /// Element e's hit and light, and the factor on its light; false when it has none.
    SHEAF_HD bool pair(const SurfaceHit* h, size_t e, size_t& hit, uint32_t& light,
                       float& scale) const {
        const size_t lit = camera * lights;
        if (e < lit) {
            hit = e % camera, light = uint32_t(e / camera), scale = 1.0f;
            return true;
        }
        const size_t g = e - lit;
        hit = camera + g / raygen_detail::kGatherLights;
        const uint32_t j = uint32_t(g % raygen_detail::kGatherLights), s = stride();
        light = light_share_offset(h[hit].pixel, h[hit].gather, s) + j * s;
        scale = float(s);
        return light < lights;
    }
};

SHEAF_HD_INLINE uint32_t shadow_ray_count(const SceneView& scene, const SurfaceHit* hits,
                                          const ShadowLayout& layout, size_t e,
                                          const RayGenParams& p) {
    size_t hit;
    uint32_t li;
    float scale;
    if (!layout.pair(hits, e, hit, li, scale)) return 0;
    const Light& l = scene.lights[li];
    return !l.shadowless && lights_point(l, hits[hit], p) ? 1u : 0u;
}

/// Writes the shadow ray of element e, which shadow_ray_count gave 1.
SHEAF_HD_INLINE void shadow_ray_write(const SceneView& scene, const SurfaceHit* hits,
                                      const ShadowLayout& layout, size_t e, uint32_t slot,
                                      const RayGenParams& p, const RaySlots& out) {
    size_t hit;
    uint32_t li;
    float scale;
    layout.pair(hits, e, hit, li, scale);
    const SurfaceHit& h = hits[hit];
    const Light& l = scene.lights[li];
    // The ray starts at the light and ends just above the surface.
    const Vec3 target =
        h.position + h.geo_normal * hdm::fmaxf(p.shadow_epsilon, surface_offset(p, h.position));
    const LightSample ls = sample_light(l, target, p.far);
    Ray r;
    r.origin = ls.origin;
    r.dir = -ls.to_light;
    r.tmin = 0.0f;
    r.tmax = ls.distance;
    out.rays[slot] = r;
    out.pixel[slot] = h.pixel;
    // The media on the way fade the light (their extinction), as POV-Ray's shadow rays do;
    // the atmosphere's and the fog's only for lights with media_attenuation.
    Vec3 through =
        media_transmittance(scene, target, ls.to_light, ls.distance, l.media_attenuation);
    if (l.media_attenuation && l.media_interaction)
        through = through * fog_transmittance(scene, target, ls.to_light, ls.distance);
    out.weight[slot] = h.throughput * direct_light(scene.materials[h.material], h, ls.to_light,
                                                   ls.radiance * through * scale, l.highlights);
    out.light[slot] = li;
}

SHEAF_HD_INLINE void shadow_ray_fill(const SceneView& scene, const SurfaceHit* hits,
                                     const ShadowLayout& layout, size_t e, uint32_t slot,
                                     const RayGenParams& p, const RaySlots& out) {
    if (shadow_ray_count(scene, hits, layout, e, p))
        shadow_ray_write(scene, hits, layout, e, slot, p, out);
}

/// The `ao_samples` rays of hit h from `slot` on; its Halton points start at its pixel index
/// times the count.
SHEAF_HD_INLINE void ao_ray_fill(const SceneView& scene, const SurfaceHit& h, uint32_t slot,
                                 const RayGenParams& p, const RaySlots& out) {
    const uint32_t n = uint32_t(p.ao_samples);
    const Material& m = scene.materials[h.material];
    const Vec3 w = h.throughput * ambient_light(m, h) * (1.0f / float(n));
    Vec3 t, b;
    raygen_detail::basis(h.geo_normal, t, b);
    for (uint32_t s = 0; s < n; ++s) {
        // Cosine-weighted hemisphere from the Halton points (bases 2 and 3).
        Ray ray;
        ray.origin = h.position + h.geo_normal * surface_offset(p, h.position);
        ray.dir = raygen_detail::cosine_direction(h.geo_normal, t, b, h.pixel * n + s + 1, 2, 3);
        ray.tmin = 0.0f;
        ray.tmax = p.ao_distance;
        out.rays[slot + s] = ray;
        out.pixel[slot + s] = h.pixel;
        out.weight[slot + s] = w;
    }
}

/// The mirror direction at hit h: about the shading normal, or about the geometric one where
/// the shading normal would send it below the surface.
SHEAF_HD_INLINE Vec3 mirror_direction(const SurfaceHit& h) {
    const Vec3 d = reflect(h.incoming, h.normal);
    return dot(d, h.geo_normal) > 0 ? d : reflect(h.incoming, h.geo_normal);
}

/// A ray leaving hit h along `dir` from just off the surface on the side it leaves (`side`
/// +1 above, -1 below), unbounded.
SHEAF_HD_INLINE Ray bounce_ray(const SurfaceHit& h, Vec3 dir, float side, const RayGenParams& p) {
    Ray r;
    r.origin = h.position + h.geo_normal * (side * surface_offset(p, h.position));
    r.dir = dir;
    r.tmin = 0.0f;
    r.tmax = FLT_MAX;
    return r;
}

/// How a hit splits what arrives into a reflection and a refraction ray.
struct BounceSplit {
    Vec3 reflect_weight, refract_weight;
    Vec3 reflect_dir, refract_dir;
};

SHEAF_HD_INLINE BounceSplit bounce_split(const SceneView& scene, const SurfaceHit& h) {
    const Material& m = scene.materials[h.material];
    BounceSplit s{};
    // Points on a gathered (radiosity) path send no mirror rays: they bring their light,
    // not their reflections (see diffuse_ray_count).
    if (h.gather != 0) return s;
    // Light passing through: tinted by the colour (filter) or not (transmit).
    const Vec3 pass = h.albedo * h.filter + Vec3(h.transmit);
    const Vec3 mirror = mirror_weight(m, h);
    s.reflect_dir = mirror_direction(h);
    // Iridescence tints what the mirror reflects, not what refraction turns back.
    Vec3 reflect_w = m.irid > 0 ? mirror * irid_factor(m, h, s.reflect_dir) : mirror;
    if (max_component(pass) > 0) {
        // Entering from outside the object: n_outside / n_inside; leaving: the inverse.
        const float eta = h.front ? 1.0f / m.ior : m.ior;
        float kr = 0.0f;
        if (m.fresnel_split) {
            const float cos_i = hdm::fminf(1.0f, hdm::fmaxf(0.0f, -dot(h.normal, h.incoming)));
            kr = fresnel_dielectric(cos_i, eta);
        }
        if (kr < 1.0f && refract(h.incoming, h.normal, eta, s.refract_dir)) {
            Vec3 keep(1.0f - kr);
            // conserve_energy: what passes loses what the mirror takes, per channel (POV-Ray's
            // filter colour times 1 - reflection, clipped).
            if (m.conserve_energy)
                for (int c = 0; c < 3; ++c) keep[c] *= hdm::fmaxf(0.0f, 1.0f - mirror[c]);
            s.refract_weight = h.throughput * pass * keep;
        } else {
            kr = 1.0f; // total internal reflection: what would pass is reflected
            // POV-Ray then reflects all of it, unfiltered, and leaves out the finish's own
            // reflection about the same normal (interior/caustic2.pov's ceiling, seen from
            // inside).
            if (!m.fresnel_split) {
                s.reflect_weight = h.throughput;
                return s;
            }
        }
        reflect_w += pass * kr;
    }
    s.reflect_weight = h.throughput * reflect_w;
    return s;
}

SHEAF_HD_INLINE uint32_t reflect_ray_count(const BounceSplit& s, const RayGenParams& p) {
    return max_component(s.reflect_weight) > p.min_weight ? 1u : 0u;
}
SHEAF_HD_INLINE uint32_t refract_ray_count(const BounceSplit& s, const RayGenParams& p) {
    return max_component(s.refract_weight) > p.min_weight ? 1u : 0u;
}

/// A bounce ray from hit `h`: offset to the side it leaves on (`side` +1 above the surface,
/// -1 below), unbounded; written only when its weight is worth tracing.
SHEAF_HD_INLINE void bounce_ray_fill(const SurfaceHit& h, Vec3 dir, Vec3 weight, float side,
                                     uint32_t slot, const RayGenParams& p, const RaySlots& out) {
    if (max_component(weight) <= p.min_weight) return;
    out.rays[slot] = bounce_ray(h, dir, side, p);
    out.pixel[slot] = h.pixel;
    out.weight[slot] = weight;
}

SHEAF_HD_INLINE void reflect_ray_fill(const SurfaceHit& h, const BounceSplit& s, uint32_t slot,
                                      const RayGenParams& p, const RaySlots& out) {
    bounce_ray_fill(h, s.reflect_dir, s.reflect_weight, 1.0f, slot, p, out);
}

SHEAF_HD_INLINE void refract_ray_fill(const SurfaceHit& h, const BounceSplit& s, uint32_t slot,
                                      const RayGenParams& p, const RaySlots& out) {
    bounce_ray_fill(h, s.refract_dir, s.refract_weight, -1.0f, slot, p, out);
}

namespace raygen_detail {

/// The gather weight of hit h per ray when it sends `n`: what the surface's diffuse reflects
/// of the light arriving, averaged over the cosine-weighted rays (POV-Ray's radiosity adds
/// colour x diffuse x the mean radiance gathered, times brightness).
SHEAF_HD_INLINE Vec3 gather_weight(const SceneView& scene, const SurfaceHit& h, uint32_t n,
                                   const RayGenParams& p) {
    const Material& m = scene.materials[h.material];
    return h.throughput * h.albedo * (m.diffuse * opacity(h) * p.radiosity_brightness / float(n));
}

/// The Halton bases of the gather directions at diffuse depth d (a pair per depth, after AO's
/// 2 and 3, so the dimensions of a path are not correlated).
SHEAF_HD_INLINE void gather_bases(uint32_t d, uint32_t& b1, uint32_t& b2) {
    constexpr uint32_t primes[18] = {5,  7,  11, 13, 17, 19, 23, 29, 31,
                                     37, 41, 43, 47, 53, 59, 61, 67, 71};
    const uint32_t i = d < 9 ? d : 8;
    b1 = primes[2 * i], b2 = primes[2 * i + 1];
}

} // namespace raygen_detail

/// Radiosity's gather rays from hit h: `radiosity_samples` on a camera, reflection or
/// refraction path (gather 0), one to continue a gathered path until `radiosity_depth`
/// diffuse bounces; none from surfaces without diffuse or when the weight is too small.
SHEAF_HD_INLINE uint32_t diffuse_ray_count(const SceneView& scene, const SurfaceHit& h,
                                           const RayGenParams& p) {
    if (p.radiosity_samples <= 0) return 0;
    const uint32_t depth = h.gather & 0xFFu;
    if (depth >= uint32_t(p.radiosity_depth)) return 0;
    const uint32_t n = depth == 0 ? uint32_t(p.radiosity_samples) : 1u;
    if (!(max_component(raygen_detail::gather_weight(scene, h, 1, p)) > p.gather_min_weight))
        return 0;
    return n;
}

/// The gather rays of hit h from `slot` on (`n` of them, diffuse_ray_count's), cosine-weighted
/// about the geometric normal from Halton points: on a camera path sample s of pixel i takes
/// index i * n + s + 1; a gathered path goes on with the index it began with, in the next
/// pair of bases. Each ray's tag is the path's: one more bounce, the same sample.
SHEAF_HD_INLINE void diffuse_ray_fill(const SceneView& scene, const SurfaceHit& h, uint32_t n,
                                      uint32_t slot, const RayGenParams& p, const RaySlots& out) {
    if (n == 0) return;
    const uint32_t depth = h.gather & 0xFFu;
    const Vec3 w = raygen_detail::gather_weight(scene, h, n, p);
    uint32_t b1, b2;
    raygen_detail::gather_bases(depth, b1, b2);
    Vec3 t, b;
    raygen_detail::basis(h.geo_normal, t, b);
    for (uint32_t s = 0; s < n; ++s) {
        const uint32_t sample = depth == 0 ? s : h.gather >> 8;
        const uint32_t index = h.pixel * uint32_t(p.radiosity_samples) + sample + 1;
        Ray ray;
        ray.origin = h.position + h.geo_normal * surface_offset(p, h.position);
        ray.dir = raygen_detail::cosine_direction(h.geo_normal, t, b, index, b1, b2);
        ray.tmin = 0.0f;
        ray.tmax = FLT_MAX;
        out.rays[slot + s] = ray;
        out.pixel[slot + s] = h.pixel;
        out.weight[slot + s] = w;
        out.light[slot + s] = (sample << 8) | (depth + 1);
    }
}

/// Rays of a batch are indexed with 32 bits: a batch that could hold more than 4,294,967,295
/// rays (`most`, an upper bound known before any is made) is refused with OutOfMemory naming
/// the ray type, before its counts would wrap.
void check_batch_bound(uint64_t most, RayType type);

} // namespace sheaf

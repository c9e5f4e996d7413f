// Secondary ray generation from a wave of surface hits: shadow rays (one per light per lit
// point, origin moved to the light as in paper 000 section 3.3.2), ambient-occlusion rays
// (cosine-weighted, Halton, paper 003) and reflection/refraction rays (Fresnel, Snell).
// Every generator counts, scans and fills, so the ray order is the same on every run.
// The per-element count and fill functions are host-and-device: the CPU renderer and the
// wavefront pipeline emit the same rays in the same order.
#pragma once

#include "core/math/hd_math.h"
#include "core/rays/ray_batch.h"
#include "core/render/shade.h"
#include "core/render/surface.h"
#include "core/scene/scene_view.h"

#include <cfloat>
#include <vector>

namespace sheaf {

struct RayGenParams {
    float epsilon = 1e-4f; // offset from surfaces, in scene units
    float far = 1e4f;      // beyond the scene: where parallel lights' shadow rays start
    int ao_samples = 0;
    float ao_distance = 1.0f;
    float min_weight = 1e-3f; // reflection/refraction rays carrying less are not traced
};

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

/// True when light l lights hit h at all (the surface faces it, a spot reaches it).
SHEAF_HD_INLINE bool lights_point(const Light& l, const SurfaceHit& h, const RayGenParams& p) {
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

} // namespace raygen_detail

// Shadow rays, light-major: element k of n * lights is light k / n at hit k % n. All rays of
// light 0 in hit order, then light 1, ...: rays that leave the same light towards
// neighbouring pixels sit side by side even unsorted (rah).

SHEAF_HD_INLINE uint32_t shadow_ray_count(const SceneView& scene, const SurfaceHit* hits, size_t n,
                                          size_t k, const RayGenParams& p) {
    const Light& l = scene.lights[k / n];
    return !l.shadowless && lights_point(l, hits[k % n], p) ? 1u : 0u;
}

SHEAF_HD_INLINE void shadow_ray_fill(const SceneView& scene, const SurfaceHit* hits, size_t n,
                                     size_t k, uint32_t slot, const RayGenParams& p,
                                     const RaySlots& out) {
    const SurfaceHit& h = hits[k % n];
    const uint32_t li = uint32_t(k / n);
    const Light& l = scene.lights[li];
    if (l.shadowless || !lights_point(l, h, p)) return;
    // The ray starts at the light and ends just above the surface.
    const Vec3 target = h.position + h.geo_normal * p.epsilon;
    const LightSample ls = sample_light(l, target, p.far);
    Ray r;
    r.origin = ls.origin;
    r.dir = -ls.to_light;
    r.tmin = 0.0f;
    r.tmax = ls.distance;
    out.rays[slot] = r;
    out.pixel[slot] = h.pixel;
    out.weight[slot] =
        h.throughput * direct_light(scene.materials[h.material], h, ls.to_light, ls.radiance);
    out.light[slot] = li;
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
        const uint32_t index = h.pixel * n + s + 1;
        const float u1 = radical_inverse(index, 2), u2 = radical_inverse(index, 3);
        const float r = sqrtf(u1), phi = 2.0f * kPi * u2;
        const Vec3 d = t * (r * hdm::cosf(phi)) + b * (r * hdm::sinf(phi)) +
                       h.geo_normal * sqrtf(hdm::fmaxf(0.0f, 1.0f - u1));
        Ray ray;
        ray.origin = h.position + h.geo_normal * p.epsilon;
        ray.dir = normalize(d);
        ray.tmin = 0.0f;
        ray.tmax = p.ao_distance;
        out.rays[slot + s] = ray;
        out.pixel[slot + s] = h.pixel;
        out.weight[slot + s] = w;
    }
}

/// How a hit splits what arrives into a reflection and a refraction ray.
struct BounceSplit {
    Vec3 reflect_weight, refract_weight;
    Vec3 reflect_dir, refract_dir;
};

SHEAF_HD_INLINE BounceSplit bounce_split(const SceneView& scene, const SurfaceHit& h) {
    const Material& m = scene.materials[h.material];
    BounceSplit s{};
    // Light passing through: tinted by the colour (filter) or not (transmit).
    const Vec3 pass = h.albedo * h.filter + Vec3(h.transmit);
    const Vec3 mirror = mirror_weight(m, h);
    Vec3 reflect_w = mirror;
    if (max_component(pass) > 0) {
        // Entering from outside the object: n_outside / n_inside; leaving: the inverse.
        const float eta = h.front ? 1.0f / m.ior : m.ior;
        float kr = 0.0f;
        if (m.fresnel_split) {
            const float cos_i = hdm::fminf(1.0f, hdm::fmaxf(0.0f, -dot(h.normal, h.incoming)));
            kr = fresnel_dielectric(cos_i, eta);
        }
        if (kr < 1.0f && refract(h.incoming, h.normal, eta, s.refract_dir)) {
            float keep = 1.0f - kr;
            if (m.conserve_energy) keep *= hdm::fmaxf(0.0f, 1.0f - max_component(mirror));
            s.refract_weight = h.throughput * pass * keep;
        } else {
            kr = 1.0f; // total internal reflection: what would pass is reflected
        }
        reflect_w += pass * kr;
    }
    s.reflect_weight = h.throughput * reflect_w;
    s.reflect_dir = reflect(h.incoming, h.normal);
    // A shading normal can send a reflection below the surface; the geometric one cannot.
    if (dot(s.reflect_dir, h.geo_normal) <= 0) s.reflect_dir = reflect(h.incoming, h.geo_normal);
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
    Ray r;
    r.origin = h.position + h.geo_normal * (side * p.epsilon);
    r.dir = dir;
    r.tmin = 0.0f;
    r.tmax = FLT_MAX;
    out.rays[slot] = r;
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

/// Shadow rays for every lit (hit, light) pair of the lights that cast shadows.
void generate_shadow_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& out);
/// `ao_samples` rays per hit; each hit's Halton points start at its pixel index times the count.
void generate_ao_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                      const RayGenParams& p, RayBatch& out);
/// Reflection rays go to `refl`, refraction rays to `refr`.
void generate_bounce_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& refl, RayBatch& refr);

} // namespace sheaf

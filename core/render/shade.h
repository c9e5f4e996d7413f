// Per-element shading: surface reconstruction at a hit, local lighting, Fresnel and Snell.
// Host-and-device functions; the CPU and CUDA backends share them.
#pragma once

#include "core/geometry/ray.h"
#include "core/render/surface.h"
#include "core/scene/prepared_scene.h"

namespace sheaf {

/// Rebuilds the surface at the intersection of `ray` with primitive `prim` at distance t.
/// Barycentrics come from the triangle's plane, clamped inside it, so a pixel whose centre
/// grazes an edge still gets a normal from the triangle.
SurfaceHit make_surface_hit(const PreparedScene& scene, const Ray& ray, uint32_t prim, float t);

/// Diffuse and Phong light from one point light arriving along unit `to_light`.
SHEAF_HD_INLINE Vec3 direct_light(const Material& m, Vec3 n, Vec3 incoming, Vec3 to_light,
                                  Vec3 light_color) {
    const float ndl = fmaxf(dot(n, to_light), 0.0f);
    Vec3 c = m.color * (m.diffuse * ndl * (1.0f - m.transmission));
    if (m.specular > 0) {
        const Vec3 r = reflect(-to_light, n);
        const float s = fmaxf(dot(r, -incoming), 0.0f);
        c += Vec3(m.specular * powf(s, m.phong_exponent));
    }
    return c * light_color;
}

/// Ambient term (scaled by ambient occlusion where it is traced).
SHEAF_HD_INLINE Vec3 ambient_light(const Material& m) {
    return m.color * (m.ambient * (1.0f - m.transmission));
}

/// Fresnel reflectance of a dielectric for unpolarised light; eta = n_incident / n_transmitted.
SHEAF_HD_INLINE float fresnel_dielectric(float cos_i, float eta) {
    const float sin_t2 = eta * eta * fmaxf(0.0f, 1.0f - cos_i * cos_i);
    if (sin_t2 >= 1.0f) return 1.0f; // total internal reflection
    const float cos_t = sqrtf(1.0f - sin_t2);
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

/// Snell refraction of unit d through unit n (facing d's origin side); false on total
/// internal reflection.
SHEAF_HD_INLINE bool refract(Vec3 d, Vec3 n, float eta, Vec3& out) {
    const float cos_i = -dot(n, d);
    const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f) return false;
    out = normalize(d * eta + n * (eta * cos_i - sqrtf(k)));
    return true;
}

} // namespace sheaf

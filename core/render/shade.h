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
/// `albedo` is the material's colour at the point (textured or not).
SHEAF_HD_INLINE Vec3 direct_light(const Material& m, Vec3 albedo, Vec3 n, Vec3 incoming,
                                  Vec3 to_light, Vec3 light_color) {
    const float ndl = fmaxf(dot(n, to_light), 0.0f);
    Vec3 c = albedo * (m.diffuse * ndl * (1.0f - m.transmission));
    if (m.specular > 0) {
        const Vec3 r = reflect(-to_light, n);
        const float s = fmaxf(dot(r, -incoming), 0.0f);
        c += Vec3(m.specular * powf(s, m.phong_exponent));
    }
    return c * light_color;
}

/// What a light brings to point p: the unit direction towards it, the distance, the radiance
/// arriving (colour, spot cone, fade) and where its shadow ray starts (paper 000 moves shadow
/// origins to the light; a parallel light's rays start `far` away, against its direction).
struct LightSample {
    Vec3 to_light;
    float distance = 0;
    Vec3 radiance;
    Vec3 origin;
};

/// Spot-light factor in POV-Ray's manner: full inside `radius`, smoothly to zero at `falloff`,
/// times cos(angle)^tightness.
SHEAF_HD_INLINE float spot_factor(const Light& l, Vec3 light_to_point) {
    const float angle = angle_between(normalize(l.direction), light_to_point) * (180.0f / kPi);
    if (angle >= l.spot_falloff) return 0.0f;
    float f = 1.0f;
    if (angle > l.spot_radius) {
        const float u = (l.spot_falloff - angle) / fmaxf(l.spot_falloff - l.spot_radius, 1e-6f);
        f = u * u * (3.0f - 2.0f * u);
    }
    if (l.spot_tightness > 0) f *= powf(fmaxf(cosf(angle * kPi / 180.0f), 0.0f), l.spot_tightness);
    return f;
}

SHEAF_HD_INLINE LightSample sample_light(const Light& l, Vec3 p, float far) {
    LightSample s;
    if (l.type == LightType::Parallel) {
        s.to_light = -normalize(l.direction);
        s.distance = far;
        s.origin = p + s.to_light * far;
        s.radiance = l.color;
        return s;
    }
    const Vec3 d = l.position - p;
    s.distance = length(d);
    s.to_light = s.distance > 0 ? d / s.distance : Vec3(0, 0, 1);
    s.origin = l.position;
    float k = 1.0f;
    if (l.type == LightType::Spot) k *= spot_factor(l, -s.to_light);
    if (l.fade_distance > 0 && l.fade_power > 0)
        k *= 2.0f / (1.0f + powf(s.distance / l.fade_distance, l.fade_power));
    s.radiance = l.color * k;
    return s;
}

/// Ambient term (scaled by ambient occlusion where it is traced).
SHEAF_HD_INLINE Vec3 ambient_light(const Material& m, Vec3 albedo) {
    return albedo * (m.ambient * (1.0f - m.transmission));
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

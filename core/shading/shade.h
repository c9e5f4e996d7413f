// Per-element shading: local lighting, Fresnel and Snell (surface reconstruction at a hit is
// surface_hit.h).
// Host-and-device functions; the CPU and CUDA backends share them.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"
#include "core/scene/prepared_scene.h"
#include "core/shading/surface.h"
#include "core/shading/surface_hit.h"
#include "core/texture/pov_noise.h"

namespace sheaf {

/// The share of a surface that is opaque: what filter and transmit do not let through. Not
/// clamped, as in POV-Ray: scenes use filter + transmit > 1 to amplify what is behind.
SHEAF_HD_INLINE float opacity(const SurfaceHit& h) {
    return 1.0f - h.filter - h.transmit;
}

/// Fresnel reflectance of a dielectric for unpolarised light; eta = n_incident / n_transmitted.
SHEAF_HD_INLINE float fresnel_dielectric(float cos_i, float eta) {
    const float sin_t2 = eta * eta * hdm::fmaxf(0.0f, 1.0f - cos_i * cos_i);
    if (sin_t2 >= 1.0f) return 1.0f; // total internal reflection
    const float cos_t = sqrtf(1.0f - sin_t2);
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

/// The mirror reflection of the surface at h (per channel): constant, or varying with the angle
/// of view (POV-Ray's reflection { min max falloff } and fresnel), tinted when metallic as
/// POV-Ray tints it: towards the surface colour by 1 - F, F its empirical Fresnel term of the
/// angle of view (0 head-on, rising to 1 at grazing angles).
SHEAF_HD_INLINE Vec3 mirror_weight(const Material& m, const SurfaceHit& h) {
    float r = m.mirror;
    if (m.mirror_min >= 0.0f || m.mirror_fresnel) {
        const float lo = hdm::fmaxf(m.mirror_min, 0.0f), hi = m.mirror;
        const float cos_i = hdm::fminf(1.0f, hdm::fmaxf(0.0f, -dot(h.normal, h.incoming)));
        const float f = m.mirror_fresnel ? fresnel_dielectric(cos_i, h.front ? 1.0f / m.ior : m.ior)
                                         : hdm::powf(1.0f - cos_i, m.mirror_falloff);
        r = lo + (hi - lo) * f;
    }
    Vec3 w = m.mirror_color * r;
    if (m.mirror_metallic) {
        const float cos_i = hdm::fminf(1.0f, hdm::fmaxf(-1.0f, -dot(h.normal, h.incoming)));
        const float x = fabsf(hdm::acosf(cos_i)) / (0.5f * kPi);
        const float f = hdm::fminf(
            1.0f, hdm::fmaxf(0.0f, 0.014567225f / ((x - 1.12f) * (x - 1.12f)) - 0.011612903f));
        w = w * (Vec3(1.0f) + (h.albedo - Vec3(1.0f)) * (1.0f - f));
    }
    return w;
}

/// Iridescence (POV-Ray's thin film): the factor per channel for light leaving the surface at
/// h towards the viewer after arriving along unit `to_light` (a light, or the mirror
/// direction). The film's thickness varies with POV-Ray's turbulence (5 octaves, omega 0.5,
/// lambda 2, the default noise generator) at the point in POV-Ray's world (Sheaf's, z mirrored).
SHEAF_HD_INLINE Vec3 irid_factor(const Material& m, const SurfaceHit& h, Vec3 to_light) {
    float film = m.irid_thickness;
    if (m.irid_turbulence != 0.0f) {
        const DVec3 at(h.position.x, h.position.y, -h.position.z);
        const double noise = pov_turbulence(at, 5, 0.5, 2.0, kPovDefaultNoiseGenerator);
        film *= float(1.0 + (2.0 * noise - 1.0) * double(m.irid_turbulence));
    }
    const float phase =
        2.0f * kPi * film * (fabsf(dot(h.normal, to_light)) + fabsf(dot(h.normal, h.incoming)));
    return Vec3(1.0f + m.irid * hdm::cosf(phase / m.irid_wavelength.x),
                1.0f + m.irid * hdm::cosf(phase / m.irid_wavelength.y),
                1.0f + m.irid * hdm::cosf(phase / m.irid_wavelength.z));
}

/// Diffuse and highlights from one light arriving along unit `to_light` with `light_color`:
/// diffuse cos^brilliance on the opaque share (less the reflected share with conserve_energy),
/// Phong (reflection vector) and Blinn (half vector) highlights, tinted when metallic; no
/// highlights when `highlights` is false (the light's: POV-Ray's shadowless lights give none).
SHEAF_HD_INLINE Vec3 direct_light(const Material& m, const SurfaceHit& h, Vec3 to_light,
                                  Vec3 light_color, bool highlights = true) {
    const Vec3 n = h.normal;
    const float ndl = hdm::fmaxf(dot(n, to_light), 0.0f);
    float kd = m.diffuse * (m.brilliance == 1.0f ? ndl : hdm::powf(ndl, m.brilliance)) * opacity(h);
    if (m.conserve_energy && m.conserve_diffuse)
        kd *= hdm::fmaxf(0.0f, 1.0f - max_component(mirror_weight(m, h)));
    Vec3 c = h.albedo * kd;
    float highlight = 0.0f;
    if (highlights && m.specular > 0) {
        const Vec3 r = reflect(-to_light, n);
        highlight +=
            m.specular * hdm::powf(hdm::fmaxf(dot(r, -h.incoming), 0.0f), m.phong_exponent);
    }
    if (highlights && m.blinn > 0) {
        const Vec3 half = normalize(to_light - h.incoming);
        highlight += m.blinn * hdm::powf(hdm::fmaxf(dot(n, half), 0.0f), m.blinn_exponent);
    }
    if (highlight > 0) {
        const Vec3 tint = Vec3(1.0f - m.metallic) + h.albedo * m.metallic;
        c += tint * highlight;
    }
    if (m.irid > 0) c = c * irid_factor(m, h, to_light);
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

/// Spot-light factor as POV-Ray computes it, from the cosine c of the angle to the axis:
/// nothing behind the light's plane (c <= 0), else c^tightness; inside a cone (radius under 90
/// degrees) also full within `radius`, nothing beyond `falloff`, and between them a cubic
/// (3 - 2t) t^2 of t running from 0 at cos(falloff) to 1 at cos(radius).
SHEAF_HD_INLINE float spot_factor(const Light& l, Vec3 light_to_point) {
    const float c = dot(normalize(l.direction), light_to_point);
    if (!(c > 0.0f)) return 0.0f;
    float f = l.spot_tightness > 0 ? hdm::powf(c, l.spot_tightness) : 1.0f;
    if (l.spot_radius < 90.0f) {
        const float cr = hdm::cosf(l.spot_radius * (kPi / 180.0f));
        const float cf = hdm::cosf(l.spot_falloff * (kPi / 180.0f));
        if (c < cf) return 0.0f;
        if (c < cr) {
            const float t = (c - cf) / (cr - cf);
            f *= (3.0f - 2.0f * t) * t * t;
        }
    }
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
    // An area light's sample takes its cone and fade from the area light's centre.
    Vec3 from_light = -s.to_light;
    float reach = s.distance;
    if (l.centred) {
        const Vec3 c = p - l.centre;
        reach = length(c);
        from_light = reach > 0 ? c / reach : from_light;
    }
    float k = 1.0f;
    if (l.type == LightType::Spot) k *= spot_factor(l, from_light);
    if (l.fade_distance > 0 && l.fade_power > 0)
        k *= 2.0f / (1.0f + hdm::powf(reach / l.fade_distance, l.fade_power));
    s.radiance = l.color * k;
    return s;
}

/// Ambient term on the opaque share (scaled by ambient occlusion where it is traced).
SHEAF_HD_INLINE Vec3 ambient_light(const Material& m, const SurfaceHit& h) {
    return h.albedo * (m.ambient * opacity(h));
}

/// What light keeps after travelling d inside a material that fades it (POV-Ray's interior
/// fade_distance, fade_power, fade_color): fade_color + (1 - fade_color) / (1 + (d /
/// fade_distance)^fade_power). A fade_power of 1000 or more is POV-Ray's exponential absorption
/// instead: exp(-(1 - fade_color) d / fade_distance) per channel. As in POV-Ray, a fade_power
/// of 0 halves what a refracted ray carries, and leaves shadow rays (`shadow`) as they are.
SHEAF_HD_INLINE Vec3 interior_fade(const Material& m, float d, bool shadow = false) {
    if (!(m.fade_distance > 0) || !(m.fade_power > 0 || (!shadow && m.fade_power == 0)))
        return Vec3(1.0f);
    if (m.fade_power >= 1000.0f) {
        const float k = d / m.fade_distance;
        return Vec3(hdm::expf(-(1.0f - m.fade_color.x) * k),
                    hdm::expf(-(1.0f - m.fade_color.y) * k),
                    hdm::expf(-(1.0f - m.fade_color.z) * k));
    }
    const float a = 1.0f / (1.0f + hdm::powf(d / m.fade_distance, m.fade_power));
    return Vec3(a) + m.fade_color * (1.0f - a);
}

/// The length of a finite way of d from `origin` along unit `dir` as fog `f`'s turbulence
/// makes it (Fog::turb): shorter by exp(-d / distance) times the turbulence at its middle.
SHEAF_HD_INLINE double fog_turbulence(const Fog& f, Vec3 origin, Vec3 dir, float d) {
    if (f.turb.x == 0 && f.turb.y == 0 && f.turb.z == 0) return double(d);
    const Vec3 mid = origin + dir * (0.5f * d);
    const DVec3 p(double(mid.x) * f.turb.x, double(mid.y) * f.turb.y, double(mid.z) * f.turb.z);
    const double k = hdm::exp(-double(d) / f.distance);
    const double t = pov_turbulence(p, f.octaves, f.omega, f.lambda, f.noise_generator);
    const double s = t * f.turb_depth;
    return double(d) * (1.0 - k * (s < 1.0 ? s : 1.0));
}

/// The fog's optical depth (length times density over distance) along the ray from `origin`
/// along unit `dir` for length d (infinite for rays that leave the scene). Constant fog:
/// d / distance. Ground fog as POV-Ray integrates it: the mean density between the end
/// heights Y1, Y2 (in units of alt over the offset) is the integral of 1 (below 0) and
/// 1 / (1 + Y^2) (above: atan) over their difference. A finite way's length is the one
/// fog_turbulence gives.
SHEAF_HD_INLINE double fog_depth(const Fog& f, Vec3 origin, Vec3 dir, float d) {
    if (!(f.alt > 0))
        return d < 3.0e38f ? fog_turbulence(f, origin, dir, d) / f.distance : INFINITY;
    const double y1 = (double(dot(origin, f.up)) - f.offset) / f.alt;
    const double dy = double(dot(dir, f.up)) / f.alt; // change of Y per unit of length
    // The integral of the density over Y from 0 (or below) up to y, for y >= 0.
    auto above = [](double y) { return hdm::atan(y); };
    if (!(d < 3.0e38f)) { // to infinity: finite only when climbing out of the fog
        if (!(dy > 1e-12)) return INFINITY;
        const double below = y1 < 0 ? -y1 : 0.0;
        return (below + 1.5707963267948966 - above(y1 > 0 ? y1 : 0.0)) / dy / f.distance;
    }
    const double y2 = y1 + dy * d;
    double mean;
    if (y1 <= 0 && y2 <= 0)
        mean = 1;
    else if (y1 <= 0)
        mean = (above(y2) - y1) / (y2 - y1);
    else if (y2 <= 0)
        mean = (above(y1) - y2) / (y1 - y2);
    else if (fabs(y1 - y2) > 1e-10)
        mean = (above(y1) - above(y2)) / (y1 - y2);
    else
        mean = 1 / (y1 * y1 + 1);
    return fog_turbulence(f, origin, dir, d) * mean / f.distance;
}

/// How far a ray that leaves the scene crosses the atmosphere's media and a rainbow's fog:
/// POV-Ray's distance (measured with povray: an emission of 1e-11 per unit gives such a ray
/// 0.2, and a rainbow of distance 1e10 keeps exp(-2) of the background).
constexpr float kAtmosphereFar = 2e10f;

/// The share a of what lies d behind that fog `f` lets through along a way (from `origin`
/// along unit `dir`, length d, infinite for rays that leave the scene): max(exp(-depth),
/// transmit), as POV-Ray.
SHEAF_HD_INLINE float fog_pass(const Fog& f, Vec3 origin, Vec3 dir, float d) {
    const double depth = fog_depth(f, origin, dir, d);
    const float a = depth < 1e30 ? float(hdm::exp(-depth)) : 0.0f;
    return hdm::fmaxf(a, f.transmit);
}

/// Fogs along a ray segment (from `origin` along unit `dir`, length d, infinite for rays that
/// leave the scene): the far colour keeps `keep` of itself and the fogs add `add`. As
/// POV-Ray: each fog keeps its fog_pass a, tinted by its filter, and adds its colour times
/// 1 - a.
SHEAF_HD_INLINE void fog_over(const Fogs& fs, Vec3 origin, Vec3 dir, float d, Vec3& keep,
                              Vec3& add) {
    keep = Vec3(1.0f), add = Vec3(0.0f);
    for (uint32_t i = 0; i < fs.count; ++i) {
        const Fog& f = fs.layer[i];
        if (!(f.distance > 0)) continue;
        const float a = fog_pass(f, origin, dir, d);
        keep = keep * ((Vec3(1.0f - f.filter) + f.color * f.filter) * a);
        add += f.color * (1.0f - a);
    }
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

// POV-Ray's rainbow (Rainbow in core/scene/pattern.h): a fog-like band of colour around the
// antisolar direction, as POV-Ray 3.7 computes it for every ray, host and device alike.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/scene_view.h"
#include "core/shading/shade.h"
#include "core/shading/surface_texture.h"
#include "core/texture/lattice_hash.h"

namespace sheaf {

/// What the scene's rainbows do to the colour C a ray along unit `dir` brings from `depth`
/// away (kAtmosphereFar for rays that leave the scene): C becomes C * mul + add. Each rainbow
/// the ray falls in takes the colour Cr of its band and keeps k = exp(-depth / distance) of
/// C, k at least Cr's transmit (and, in the fading part of the arc, rising towards 1), C
/// filtered by Cr as far as Cr's filter times 1 - k says, and adds (1 - k) Cr; several
/// rainbows average. `pixel` picks the jitter.
SHEAF_HD_INLINE void rainbow_over(const SceneView& scene, Vec3 dir, float depth, uint32_t pixel,
                                  Vec3& mul, Vec3& add) {
    mul = Vec3(1.0f);
    add = Vec3(0.0f);
    Vec3 m(0.0f), a(0.0f);
    uint32_t n = 0;
    for (uint32_t i = 0; i < scene.rainbow_count; ++i) {
        const Rainbow& r = scene.rainbows[i];
        // The angle around the antisolar direction, from up.
        const float x = dot(dir, r.right), y = dot(dir, r.up), l = sqrtf(x * x + y * y);
        const float around = hdm::acosf(hdm::fminf(hdm::fmaxf(l > 0 ? y / l : y, -1.0f), 1.0f));
        if (around > r.arc) continue;
        const float c = dot(dir, r.antisolar);
        if (c < 0) continue;
        float index = (hdm::acosf(hdm::fminf(c, 1.0f)) - r.start) / r.width;
        if (r.jitter > 0)
            index += (2.0f * hash_unit(lattice_hash(int(pixel), int(i), 0, 0x7261696eu)) - 1.0f) *
                     r.jitter;
        if (!(index >= 0.0f && index <= 1.0f - 1e-6f)) continue;
        const SurfaceColor cr = evaluate_pigment(scene, r.colors, Vec3(index, 0.0f, 0.0f), 0, 0);
        float fade = 0.0f;
        if (r.arc > r.falloff && around > r.falloff) {
            fade = (around - r.falloff) / (r.arc - r.falloff);
            fade = (3.0f - 2.0f * fade) * fade * fade;
        }
        float k = hdm::expf(-depth / r.distance);
        k = hdm::fmaxf(k, fade * (1.0f - cr.transmit) + cr.transmit);
        const float ki = 1.0f - k, f = cr.filter * ki;
        m += Vec3(k * ((1.0f - f) + f * cr.rgb.x), k * ((1.0f - f) + f * cr.rgb.y),
                  k * ((1.0f - f) + f * cr.rgb.z));
        a += cr.rgb * ki;
        ++n;
    }
    if (n > 0) mul = m / float(n), add = a / float(n);
}

} // namespace sheaf

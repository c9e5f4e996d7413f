// Shadows through transparent surfaces, as POV-Ray casts them: a shadow ray that crosses a
// surface keeps albedo * filter + transmit of the light there (no refraction, no caustics),
// and stops at an opaque one. The per-ray product is kept as a fixed-point sum of -log2 of
// each factor, added atomically, so it is exactly the same whatever the order of the tests.
#pragma once

#include "core/geometry/ray.h"
#include "core/scene/prepared_scene.h"

#include <cstdint>

namespace sheaf {

/// Light a shadow ray keeps (per channel) crossing primitive `prim`, whose exact test found
/// it at distance t: the product over every surface of the primitive it crosses inside the
/// ray's (tmin, tmax), and for analytic solids the interior fade over the stretch inside.
/// Zero where a crossed surface is opaque.
Vec3 shadow_pass(const PreparedScene& scene, uint32_t prim, const Ray& ray, float t);

/// Fixed point for the products: -log2(factor) * 2^16; factors at or below 2^-256 count as 0.
constexpr uint64_t kPassLogOne = 1u << 16;
constexpr uint64_t kPassLogZero = 256 * kPassLogOne;

SHEAF_HD_INLINE uint64_t pass_to_log(float pass) {
    if (!(pass > 0.0f)) return kPassLogZero;
    if (pass >= 1.0f) return 0;
    const double q = -log2(double(pass)) * double(kPassLogOne);
    return q >= double(kPassLogZero) ? kPassLogZero : uint64_t(q + 0.5);
}

SHEAF_HD_INLINE float log_to_pass(uint64_t q) {
    return q >= kPassLogZero ? 0.0f : float(exp2(-double(q) / double(kPassLogOne)));
}

} // namespace sheaf

// Lattice noise for procedural patterns: gradient noise (Perlin's improved noise with hashed
// gradients, no tables, so host and device share it), its vector form, fractal sums and
// cellular (Worley) distances. Deterministic: the same point gives the same value everywhere.
#pragma once

#include "core/math/hd_math.h"
#include "core/math/vec3.h"

#include <cstdint>

namespace sheaf {

/// A well-mixed 32-bit hash of a lattice point and a salt.
SHEAF_HD_INLINE uint32_t lattice_hash(int x, int y, int z, uint32_t salt = 0) {
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^
                 uint32_t(z) * 0xcb1ab31fu ^ salt * 0x9e3779b9u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

/// A value in [0, 1) from a hash.
SHEAF_HD_INLINE float hash_unit(uint32_t h) {
    return float(h >> 8) * (1.0f / 16777216.0f);
}

namespace noise_detail {

SHEAF_HD_INLINE float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
SHEAF_HD_INLINE float lerp(float a, float b, float t) {
    return a + t * (b - a);
}
// Perlin's twelve edge directions (and four repeated) picked by the hash.
SHEAF_HD_INLINE float grad(uint32_t h, float x, float y, float z) {
    const uint32_t k = h & 15u;
    const float u = k < 8 ? x : y;
    const float v = k < 4 ? y : (k == 12 || k == 14 ? x : z);
    return ((k & 1u) ? -u : u) + ((k & 2u) ? -v : v);
}

} // namespace noise_detail

/// Gradient noise in about [-1, 1], zero on the lattice points, smooth (C2) everywhere.
SHEAF_HD_INLINE float gradient_noise(Vec3 p, uint32_t salt = 0) {
    using namespace noise_detail;
    const float fx = floorf(p.x), fy = floorf(p.y), fz = floorf(p.z);
    const int ix = hdm::floor_int(p.x), iy = hdm::floor_int(p.y), iz = hdm::floor_int(p.z);
    const float x = p.x - fx, y = p.y - fy, z = p.z - fz;
    const float u = fade(x), v = fade(y), w = fade(z);
    auto g = [&](int dx, int dy, int dz) {
        return grad(lattice_hash(ix + dx, iy + dy, iz + dz, salt), x - float(dx), y - float(dy),
                    z - float(dz));
    };
    return lerp(lerp(lerp(g(0, 0, 0), g(1, 0, 0), u), lerp(g(0, 1, 0), g(1, 1, 0), u), v),
                lerp(lerp(g(0, 0, 1), g(1, 0, 1), u), lerp(g(0, 1, 1), g(1, 1, 1), u), v), w);
}

/// Patterns sample the noise at this scale: features about as large as POV-Ray's.
constexpr float kPatternNoiseScale = 0.625f;

/// Noise in [0, 1] (POV-Ray's bozo, spotted and bumps look).
SHEAF_HD_INLINE float noise01(Vec3 p) {
    const float n = 0.5f + 0.5f * gradient_noise(p * kPatternNoiseScale);
    return hdm::fminf(1.0f, hdm::fmaxf(0.0f, n));
}

/// Three independent noises in about [-1, 1].
SHEAF_HD_INLINE Vec3 vector_noise(Vec3 p) {
    p = p * kPatternNoiseScale;
    return {gradient_noise(p, 1), gradient_noise(p, 2), gradient_noise(p, 3)};
}

/// Fractal sum of |noise|: sum of omega^i |n(p lambda^i)| over `octaves` terms.
SHEAF_HD_INLINE float turbulence(Vec3 p, int octaves, float omega, float lambda) {
    float sum = 0, amp = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += amp * fabsf(gradient_noise(p * kPatternNoiseScale));
        amp *= omega;
        p = p * lambda;
    }
    return sum;
}

/// The vector form: the displacement POV-Ray's `turbulence` applies to a point.
SHEAF_HD_INLINE Vec3 vector_turbulence(Vec3 p, int octaves, float omega, float lambda) {
    Vec3 sum(0.0f);
    float amp = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += vector_noise(p) * amp;
        amp *= omega;
        p = p * lambda;
    }
    return sum;
}

/// The random point of unit cell (cx, cy, cz), and in `h` the cell's hash.
SHEAF_HD_INLINE Vec3 cell_point(int cx, int cy, int cz, uint32_t& h) {
    h = lattice_hash(cx, cy, cz, 7);
    return {float(cx) + hash_unit(h), float(cy) + hash_unit(h * 0x2545f491u + 1),
            float(cz) + hash_unit(h * 0x9e3779b9u + 2)};
}

/// Distances to the nearest and second nearest of one random point per unit cell (Worley).
/// `id` receives a hash of the nearest point's cell; `nearest` (when given) that point.
SHEAF_HD_INLINE void cell_distances(Vec3 p, float& f1, float& f2, uint32_t& id,
                                    Vec3* nearest = nullptr) {
    const int ix = hdm::floor_int(p.x), iy = hdm::floor_int(p.y), iz = hdm::floor_int(p.z);
    f1 = f2 = 1e30f;
    id = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                uint32_t h;
                const Vec3 q = cell_point(ix + dx, iy + dy, iz + dz, h);
                const float d = length(q - p);
                if (d < f1) {
                    f2 = f1;
                    f1 = d;
                    id = h;
                    if (nearest) *nearest = q;
                } else if (d < f2) {
                    f2 = d;
                }
            }
}

} // namespace sheaf

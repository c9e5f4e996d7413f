// Ray hash keys (hash.mode). Keys are arrays of 32-bit words, word 0 least significant:
// one word for crsh and hash32, six for hash192.
//  - crsh (paper 000 section 3.3.2): shadow rays, whose origin is moved to the light, key on
//    the light index (high bits) and the spherical direction (below, theta and phi in Morton
//    order); reflection, refraction and ambient-occlusion rays key on origin and direction,
//    interleaved (5-D Morton order).
//  - hash32 and hash192: paper 003, Algorithm 1, with its TRANSLATE slip fixed
//    ((point - aabb_min) / (aabb_max - aabb_min)).
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <cstdint>

namespace sheaf {

struct Aabb {
    Vec3 lo, hi;
};

/// TRANSLATE of Algorithm 1 (fixed): the point in [0, 1]^3 of the box.
SHEAF_HD_INLINE Vec3 translate_to_unit(const Aabb& box, Vec3 p) {
    const Vec3 ext = box.hi - box.lo;
    auto f = [](float v, float lo, float e) {
        return e > 0 ? hdm::fminf(hdm::fmaxf((v - lo) / e, 0.0f), 1.0f) : 0.0f;
    };
    return {f(p.x, box.lo.x, ext.x), f(p.y, box.lo.y, ext.y), f(p.z, box.lo.z, ext.z)};
}

/// Quantises v in [0, 1] to an integer in [0, 2^bits - 1] (NaN to 0: converting it would be
/// undefined).
SHEAF_HD_INLINE uint32_t quantize(float v, int bits) {
    const uint32_t n = 1u << bits;
    const float q = v * float(n);
    return !(q > 0) ? 0u : (q >= float(n - 1) ? n - 1 : uint32_t(q));
}

/// Spreads the low 10 bits of x so that two zero bits separate each (3-D Morton order).
SHEAF_HD_INLINE uint32_t spread3(uint32_t x) {
    x &= 0x3FF;
    x = (x | (x << 16)) & 0x030000FF;
    x = (x | (x << 8)) & 0x0300F00F;
    x = (x | (x << 4)) & 0x030C30C3;
    x = (x | (x << 2)) & 0x09249249;
    return x;
}

SHEAF_HD_INLINE uint32_t morton3(uint32_t x, uint32_t y, uint32_t z) {
    return spread3(x) | (spread3(y) << 1) | (spread3(z) << 2);
}

/// Spreads the low 16 bits of x so that one zero bit separates each (2-D Morton order).
SHEAF_HD_INLINE uint32_t spread2(uint32_t x) {
    x &= 0xFFFF;
    x = (x | (x << 8)) & 0x00FF00FF;
    x = (x | (x << 4)) & 0x0F0F0F0F;
    x = (x | (x << 2)) & 0x33333333;
    x = (x | (x << 1)) & 0x55555555;
    return x;
}

/// Directions in Morton order of (theta, phi): nearby keys are nearby directions, which a
/// theta-major order is not (rays of one theta band would span every phi).
SHEAF_HD_INLINE uint32_t morton2(uint32_t a, uint32_t b) {
    return (spread2(a) << 1) | spread2(b);
}

/// Spherical coordinates of a unit direction mapped to [0, 1]: (phi, theta) with theta from +z.
SHEAF_HD_INLINE void spherical_unit(Vec3 d, float& u_phi, float& u_theta) {
    const float theta = hdm::acosf(hdm::fminf(hdm::fmaxf(d.z, -1.0f), 1.0f));
    const float phi = hdm::atan2f(d.y, d.x);
    u_phi = (phi + kPi) / (2.0f * kPi);
    u_theta = theta / kPi;
}

/// Bits the light index takes in a crsh shadow key.
SHEAF_HD_INLINE int light_bits(uint32_t light_count) {
    int b = 0;
    while (b < 16 && (1u << b) < light_count) ++b;
    return b;
}

/// crsh shadow key: light index in the high bits, then theta and phi in Morton order.
SHEAF_HD_INLINE uint32_t crsh_shadow_key(uint32_t light, int lbits, Vec3 dir) {
    float up, ut;
    spherical_unit(dir, up, ut);
    const int rest = 32 - lbits;
    const int b = rest / 2; // bits per angle
    const uint32_t key_dir = morton2(quantize(ut, b), quantize(up, b));
    return lbits == 0 ? key_dir : ((light << rest) | key_dir);
}

/// crsh key of reflection, refraction and ambient-occlusion rays: the origin in the batch's
/// origin box and the spherical direction, 6 bits each of x, y, z, theta and phi, interleaved
/// bit by bit (5-D Morton order), so that rays close in both origin and direction get close
/// keys. A direction-major key would put rays from opposite ends of the scene side by side.
SHEAF_HD_INLINE uint32_t crsh_secondary_key(const Aabb& box, Vec3 origin, Vec3 dir) {
    float up, ut;
    spherical_unit(dir, up, ut);
    const Vec3 o = translate_to_unit(box, origin);
    const uint32_t c[5] = {quantize(o.x, 6), quantize(o.y, 6), quantize(o.z, 6), quantize(ut, 6),
                           quantize(up, 6)};
    uint32_t key = 0;
    for (int bit = 5; bit >= 0; --bit)
        for (int d = 0; d < 5; ++d) key = (key << 1) | ((c[d] >> bit) & 1u);
    return key;
}

/// HASHKEY32 of paper 003: origin 8 bits per axis (Morton order) in the low 24 bits,
/// direction 4 bits each of phi and theta in the high 8.
SHEAF_HD_INLINE uint32_t hash32_key(const Aabb& box, Vec3 origin, Vec3 dir) {
    const Vec3 o = translate_to_unit(box, origin);
    float up, ut;
    spherical_unit(dir, up, ut);
    const uint32_t h3 = morton3(quantize(o.x, 8), quantize(o.y, 8), quantize(o.z, 8));
    const uint32_t h2 = quantize(up, 4) | (quantize(ut, 4) << 4);
    return h3 | (h2 << 24);
}

/// COLLECTBITS of paper 003: bit i of x goes to bit (idx + 6 i) of the 192-bit key.
SHEAF_HD_INLINE void collect_bits(uint32_t* hash, int idx, uint32_t x) {
    for (int i = 0; i < 32; ++i) {
        const int pos = idx + i * 6;
        hash[pos >> 5] |= ((x >> i) & 1u) << (pos & 31);
    }
}

/// HASHKEY192 of paper 003: origin 24 bits and direction 21 bits per axis, interleaved.
SHEAF_HD_INLINE void hash192_key(const Aabb& box, Vec3 origin, Vec3 dir, uint32_t* out6) {
    const Vec3 o = translate_to_unit(box, origin);
    const Vec3 d = (dir + Vec3(1.0f)) * 0.5f;
    for (int i = 0; i < 6; ++i) out6[i] = 0;
    auto q = [](float v, int bits) { return quantize(hdm::fminf(hdm::fmaxf(v, 0.0f), 1.0f), bits); };
    collect_bits(out6, 0, q(o.x, 24));
    collect_bits(out6, 1, q(o.y, 24));
    collect_bits(out6, 2, q(o.z, 24));
    collect_bits(out6, 3, q(d.x, 21));
    collect_bits(out6, 4, q(d.y, 21));
    collect_bits(out6, 5, q(d.z, 21));
}

/// Paper 003's static 3D order: 8 x 16-pixel tiles of the sample grid (grid_w wide, tiles_x
/// tiles across, `tiles` in all), one sample index (AO) or light (shadow rays) at a time.
SHEAF_HD_INLINE uint64_t static3d_key(uint64_t pixel, uint64_t sample, uint64_t grid_w,
                                      uint64_t tiles_x, uint64_t tiles) {
    const uint64_t x = pixel % grid_w, y = pixel / grid_w;
    const uint64_t tile = (y / 16) * tiles_x + x / 8;
    return ((sample * tiles + tile) << 7) | ((y % 16) * 8 + x % 8);
}

} // namespace sheaf

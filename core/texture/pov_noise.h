// POV-Ray 3.7's noise, as POV-Ray computes it, in double precision on both backends: the scalar
// noise under each `noise_generator` (1 the original, 2 the original range-corrected, 3
// Perlin's), the vector noise (DNoise), and their fractal sums `turbulence` and the
// displacement DTurbulence. The tables are pov_noise_tables.h (tests/pov/noise_tables.py made
// them: the hash and generator 3's from POV-Ray's generator, the 267 values measured from
// POV-Ray 3.7). Written from POV-Ray's documentation and the behaviour of its renders.
#pragma once

#include "core/base/device.h"
#include "core/math/vec3.h"
#include "core/texture/pov_noise_tables.h"

#include <cmath>
#include <cstdint>

namespace sheaf {

/// POV-Ray's `noise_generator`: 1 the original, 2 range-corrected (POV-Ray's default), 3 Perlin.
constexpr int kPovDefaultNoiseGenerator = 2;

/// A point in double precision, as POV-Ray's noise takes it.
struct DVec3 {
    double x = 0, y = 0, z = 0;
    DVec3() = default;
    SHEAF_HD_INLINE DVec3(double a, double b, double c) : x(a), y(b), z(c) {}
    SHEAF_HD_INLINE explicit DVec3(Vec3 v) : x(v.x), y(v.y), z(v.z) {}
    SHEAF_HD_INLINE Vec3 to_float() const { return Vec3(float(x), float(y), float(z)); }
    SHEAF_HD_INLINE DVec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    SHEAF_HD_INLINE DVec3 operator+(DVec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
};

namespace pov_noise_detail {

inline constexpr uint16_t kHashHost[4096] = {SHEAF_POV_NOISE_HASH};
inline constexpr double kValuesHost[267] = {SHEAF_POV_NOISE_VALUES};
inline constexpr uint16_t kSolidPermHost[2048] = {SHEAF_POV_NOISE_SOLID_PERM};
inline constexpr int16_t kSolidGradHost[2048 * 3] = {SHEAF_POV_NOISE_SOLID_GRAD};
inline constexpr uint32_t kRandsHost[4098] = {SHEAF_POV_PATTERN_RANDS};
#if defined(__CUDACC__)
static __device__ const uint16_t kHashDevice[4096] = {SHEAF_POV_NOISE_HASH};
static __device__ const double kValuesDevice[267] = {SHEAF_POV_NOISE_VALUES};
static __device__ const uint16_t kSolidPermDevice[2048] = {SHEAF_POV_NOISE_SOLID_PERM};
static __device__ const int16_t kSolidGradDevice[2048 * 3] = {SHEAF_POV_NOISE_SOLID_GRAD};
static __device__ const uint32_t kRandsDevice[4098] = {SHEAF_POV_PATTERN_RANDS};
#endif

#if defined(__CUDA_ARCH__)
#define SHEAF_POV_TABLE(name) name##Device
#else
#define SHEAF_POV_TABLE(name) name##Host
#endif

SHEAF_HD_INLINE int hash(int i) {
    return SHEAF_POV_TABLE(kHash)[i & 4095];
}
SHEAF_HD_INLINE double value(int k) {
    return SHEAF_POV_TABLE(kValues)[k];
}
// The slot (0..255) of the value triple a lattice corner weights: its values are j (halved:
// the corner's own value) and j + 1, j + 2, j + 3 (the slopes along x, y, z); the vector noise
// reads y from j + 4 and z from j + 8.
SHEAF_HD_INLINE int slot(int hash_xy, int iz) {
    return hash(hash_xy ^ iz) & 0xFF;
}
SHEAF_HD_INLINE int hash2(int ix, int iy) {
    return hash(hash(ix) ^ iy);
}

// A coordinate's lattice index (0..4095) and its offset within the cell. POV-Ray rounds down,
// but for negative coordinates within 1e-10 under a whole number, which count as that number.
// Coordinates are kept within +-1e9 (POV-Ray's int conversion has no meaning beyond), NaN as 0.
SHEAF_HD_INLINE void locate(double v, int& index, double& offset) {
    if (!(v > -1e9)) v = v != v ? 0.0 : -1e9;
    if (v > 1e9) v = 1e9;
    const int whole = v >= 0 ? int(v) : int(v - (1.0 - 1.0e-10));
    index = (whole + 10000) & 0xFFF;
    offset = v - whole;
}

SHEAF_HD_INLINE double scurve(double t) {
    return t * t * (3.0 - 2.0 * t);
}

// One corner's term: weight times (the corner's value + its slopes times the offsets).
SHEAF_HD_INLINE double corner(int j, double w, double x, double y, double z) {
    return w * (0.5 * value(j) + value(j + 1) * x + value(j + 2) * y + value(j + 3) * z);
}

// The unit gradient of generator 3's entry k.
SHEAF_HD_INLINE DVec3 solid_gradient(int k) {
    k &= 2047;
    const int16_t* g = SHEAF_POV_TABLE(kSolidGrad) + 3 * k;
    DVec3 v(g[0] / 2048.0, g[1] / 2048.0, g[2] / 2048.0);
    const double s = 1.0 / ::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return v * s;
}
SHEAF_HD_INLINE int solid_perm(int k) {
    return SHEAF_POV_TABLE(kSolidPerm)[k & 2047];
}
SHEAF_HD_INLINE void solid_locate(double v, int& b0, int& b1, double& r0, double& r1) {
    double t = v + 10000000.023157213;
    if (!(t > -1e9)) t = t != t ? 0.0 : -1e9;
    if (t > 1e9) t = 1e9;
    const int it = int(::floor(t));
    b0 = it & 2047;
    b1 = (b0 + 1) & 2047;
    r0 = t - it;
    r1 = r0 - 1.0;
}
SHEAF_HD_INLINE double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

// Perlin's noise (generator 3), about [-1, 1].
SHEAF_HD_INLINE double solid_noise(DVec3 p) {
    int bx0, bx1, by0, by1, bz0, bz1;
    double rx0, rx1, ry0, ry1, rz0, rz1;
    solid_locate(p.x, bx0, bx1, rx0, rx1);
    solid_locate(p.y, by0, by1, ry0, ry1);
    solid_locate(p.z, bz0, bz1, rz0, rz1);
    const int i = solid_perm(bx0), j = solid_perm(bx1);
    const int b00 = solid_perm(i + by0), b10 = solid_perm(j + by0);
    const int b01 = solid_perm(i + by1), b11 = solid_perm(j + by1);
    const double sx = scurve(rx0), sy = scurve(ry0), sz = scurve(rz0);
    auto at = [](int k, double x, double y, double z) {
        const DVec3 g = solid_gradient(k);
        return x * g.x + y * g.y + z * g.z;
    };
    double a = lerp(sx, at(b00 + bz0, rx0, ry0, rz0), at(b10 + bz0, rx1, ry0, rz0));
    double b = lerp(sx, at(b01 + bz0, rx0, ry1, rz0), at(b11 + bz0, rx1, ry1, rz0));
    const double c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + bz1, rx0, ry0, rz1), at(b10 + bz1, rx1, ry0, rz1));
    b = lerp(sx, at(b01 + bz1, rx0, ry1, rz1), at(b11 + bz1, rx1, ry1, rz1));
    const double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

SHEAF_HD_INLINE double clamp01(double v) {
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

} // namespace pov_noise_detail

namespace pov_noise_detail {

// The lattice cell around a point, as POV-Ray's noise and vector noise both set it up: the
// offsets from its low corner (0) and high corner (1) along each axis, the S-curve weights
// towards the high corners (s) and the low ones (t), and the xy hashes of its four columns.
struct Cell {
    int iz;
    double x0, y0, z0, x1, y1, z1;
    double sx, sy, sz, tx, ty, tz;
    int h00, h10, h01, h11;
    SHEAF_HD_INLINE explicit Cell(DVec3 p) {
        int ix, iy;
        locate(p.x, ix, x0);
        locate(p.y, iy, y0);
        locate(p.z, iz, z0);
        x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
        sx = scurve(x0), sy = scurve(y0), sz = scurve(z0);
        tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
        h00 = hash2(ix, iy), h10 = hash2(ix + 1, iy);
        h01 = hash2(ix, iy + 1), h11 = hash2(ix + 1, iy + 1);
    }
};

} // namespace pov_noise_detail

/// POV-Ray's scalar noise at p under `generator` (2 range-corrected, 3 Perlin, any other the
/// original), in [0, 1]: the bozo, spotted and bumps patterns' value and `f_noise3d`'s.
SHEAF_HD_INLINE double pov_noise(DVec3 p, int generator) {
    using namespace pov_noise_detail;
    if (generator == 3) return clamp01(0.5 * (1.59 * solid_noise(p) + 0.985));
    const Cell c(p);
    const double txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy, sxsy = c.sx * c.sy;
    double sum = corner(slot(c.h00, c.iz), txty * c.tz, c.x0, c.y0, c.z0);
    sum += corner(slot(c.h10, c.iz), sxty * c.tz, c.x1, c.y0, c.z0);
    sum += corner(slot(c.h01, c.iz), txsy * c.tz, c.x0, c.y1, c.z0);
    sum += corner(slot(c.h11, c.iz), sxsy * c.tz, c.x1, c.y1, c.z0);
    sum += corner(slot(c.h00, c.iz + 1), txty * c.sz, c.x0, c.y0, c.z1);
    sum += corner(slot(c.h10, c.iz + 1), sxty * c.sz, c.x1, c.y0, c.z1);
    sum += corner(slot(c.h01, c.iz + 1), txsy * c.sz, c.x0, c.y1, c.z1);
    sum += corner(slot(c.h11, c.iz + 1), sxsy * c.sz, c.x1, c.y1, c.z1);
    if (generator != 2) return clamp01(sum + 0.5);
    // Generator 2 stretches the original's range (about -1.05 .. 0.99) over [0, 1].
    return clamp01((sum + 1.05242) * 0.48985582);
}

/// POV-Ray's vector noise (DNoise) at p, each component about [-1, 1]; the same under every
/// generator.
SHEAF_HD_INLINE DVec3 pov_dnoise(DVec3 p) {
    using namespace pov_noise_detail;
    const Cell c(p);
    DVec3 r;
    auto add = [&](int j, double w, double x, double y, double z) {
        r.x += corner(j, w, x, y, z);
        r.y += corner(j + 4, w, x, y, z);
        r.z += corner(j + 8, w, x, y, z);
    };
    add(slot(c.h00, c.iz), c.tx * c.ty * c.tz, c.x0, c.y0, c.z0);
    add(slot(c.h10, c.iz), c.sx * c.ty * c.tz, c.x1, c.y0, c.z0);
    add(slot(c.h11, c.iz), c.sx * c.sy * c.tz, c.x1, c.y1, c.z0);
    add(slot(c.h01, c.iz), c.tx * c.sy * c.tz, c.x0, c.y1, c.z0);
    add(slot(c.h01, c.iz + 1), c.tx * c.sy * c.sz, c.x0, c.y1, c.z1);
    add(slot(c.h11, c.iz + 1), c.sx * c.sy * c.sz, c.x1, c.y1, c.z1);
    add(slot(c.h10, c.iz + 1), c.sx * c.ty * c.sz, c.x1, c.y0, c.z1);
    add(slot(c.h00, c.iz + 1), c.tx * c.ty * c.sz, c.x0, c.y0, c.z1);
    return r;
}

/// POV-Ray's scalar turbulence: the noise summed over `octaves`, octave i at p * lambda^i
/// weighted omega^i. Generators 2 and 3 take each octave as 2 noise - 0.5 (the first clamped
/// to [0, 1]), as POV-Ray does.
SHEAF_HD_INLINE double pov_turbulence(DVec3 p, int octaves, double omega, double lambda,
                                      int generator) {
    using namespace pov_noise_detail;
    const bool original = generator <= 1;
    double v = pov_noise(p, generator);
    if (!original) v = clamp01(2.0 * v - 0.5);
    double l = lambda, o = omega;
    for (int i = 2; i <= octaves; ++i) {
        const double n = pov_noise(p * l, generator);
        v += o * (original ? n : 2.0 * n - 0.5);
        if (i < octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return v;
}

/// POV-Ray's DTurbulence: the vector noise summed over `octaves` as pov_turbulence sums the
/// scalar one; a classic `turbulence` moves a pattern's point by it times the amount.
SHEAF_HD_INLINE DVec3 pov_dturbulence(DVec3 p, int octaves, double omega, double lambda) {
    DVec3 r = pov_dnoise(p);
    double l = lambda, o = omega;
    for (int i = 2; i <= octaves; ++i) {
        const DVec3 n = pov_dnoise(p * l);
        r = r + n * o;
        if (i < octaves) {
            l *= lambda;
            o *= omega;
        }
    }
    return r;
}

/// The centre of POV-Ray's wave i (ripples and waves): the vector noise at (i, 0, 0), made
/// unit length. At a lattice point only the low corner weighs, so the vector noise there is
/// half its three values (the same bits pov_dnoise gives, without its eight corners).
SHEAF_HD_INLINE DVec3 pov_wave_source(int i) {
    using namespace pov_noise_detail;
    const int j = slot(hash2((i + 10000) & 0xFFF, 10000 & 0xFFF), 10000 & 0xFFF);
    const DVec3 d(0.5 * value(j), 0.5 * value(j + 4), 0.5 * value(j + 8));
    const double l = ::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return l > 0 ? DVec3(d.x / l, d.y / l, d.z / l) : d;
}

/// POV-Ray's generator of wave frequencies, from its seed: each next() the relative frequency of
/// the next wave (the waves pattern), in [0.01, 1.01].
struct PovWaveFrequencies {
    uint32_t state = uint32_t(-560851967);
    SHEAF_HD double next() {
        state = state * 1812433253u + 12345u;
        return double((state >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
    }
};

/// The relative frequency of POV-Ray's wave i: the i-th draw of PovWaveFrequencies.
SHEAF_HD_INLINE double pov_wave_frequency(int i) {
    PovWaveFrequencies g;
    double f = g.next();
    for (int k = 0; k < i; ++k) f = g.next();
    return f;
}

/// POV-Ray's hash of a lattice cell (each coordinate modulo 4096), 0..4095: the cells and
/// crackle patterns' seed.
SHEAF_HD_INLINE int pov_hash3(int x, int y, int z) {
    using pov_noise_detail::hash;
    return hash(hash(hash(x & 0xFFF) ^ (y & 0xFFF)) ^ (z & 0xFFF));
}

/// POV-Ray's pattern random number `seed` (0..4097) in [0, 1].
SHEAF_HD_INLINE double pov_pattern_rand(int seed) {
    return double(SHEAF_POV_TABLE(pov_noise_detail::kRands)[seed]) / 4294967295.0;
}

/// The random point POV-Ray's crackle (and facets) place in unit cell (x, y, z).
SHEAF_HD_INLINE DVec3 pov_cell_point(int x, int y, int z) {
    const int seed = pov_hash3(x, y, z);
    return {x + pov_pattern_rand(seed), y + pov_pattern_rand(seed + 1),
            z + pov_pattern_rand(seed + 2)};
}

/// POV-Ray's number of waves unless global_settings' number_of_waves sets it (Pattern::waves).
constexpr int kPovWaves = 10;
/// The most waves a scene may ask for (more are clamped, with a warning).
constexpr int kPovMostWaves = 1000;

#undef SHEAF_POV_TABLE

} // namespace sheaf

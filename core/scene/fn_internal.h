// POV-Ray's internal functions (functions.inc's `internal(N)`) that Sheaf evaluates, on both
// backends: the shapes isosurfaces are made of and the fractal noises of terrains and water.
// Each takes x, y, z and then its parameters. The noises are POV-Ray's (pov_noise.h) under the
// generator their parameter names, and the fractals are built as POV-Ray builds them.
#pragma once

#include "core/math/hd_math.h"
#include "core/texture/pov_noise.h"

#include <cstdint>

namespace sheaf {

enum class FnInternal : uint8_t {
    Helix1 = 25,         // f_helix1(x, y, z, helices, period, minor, major, shape, section, angle)
    HeteroMf = 29,       // f_hetero_mf(x, y, z, H, lacunarity, octaves, offset, T, generator)
    Ph = 47,             // f_ph: the angle from the y axis
    R = 57,              // f_r: the distance from the origin
    Ridge = 58,          // f_ridge(x, y, z, lambda, octaves, omega, offset, ridge, generator)
    RidgedMf = 59,       // f_ridged_mf(x, y, z, H, lacunarity, octaves, offset, gain, generator)
    RoundedBox = 60,     // f_rounded_box(x, y, z, radius, half x, half y, half z)
    Sphere = 61,         // f_sphere(x, y, z, radius)
    Superellipsoid = 68, // f_superellipsoid(x, y, z, east-west, north-south)
    Th = 69,             // f_th: the angle around the y axis, from z towards x
    Torus = 70,          // f_torus(x, y, z, major, minor) around the y axis
    Noise3d = 76,        // f_noise3d: noise in [0, 1]
    NoiseGenerator = 78, // f_noise_generator(x, y, z, generator): noise in [0, 1]
};

/// The number of parameters after x, y, z; -1 when Sheaf does not evaluate internal(id).
inline int fn_internal_extra(int id) {
    switch (id) {
    case 47:
    case 57:
    case 69:
    case 76:
        return 0;
    case 61:
    case 78:
        return 1;
    case 68:
    case 70:
        return 2;
    case 60:
        return 4;
    case 29:
    case 58:
    case 59:
        return 6;
    case 25:
        return 7;
    default:
        return -1;
    }
}

/// The fractal noises stop after this many octaves (a scene's count is not trusted to end).
constexpr int kFnMaxOctaves = 64;

namespace fn_internal_detail {

SHEAF_HD_INLINE double sq(double v) {
    return v * v;
}

/// POV-Ray's noise under generator `gen` (a parameter: its whole part's last two bits, as
/// POV-Ray reads it; 0 and 1 the original).
SHEAF_HD_INLINE double noise(double x, double y, double z, int gen) {
    return pov_noise(DVec3(x, y, z), gen);
}
SHEAF_HD_INLINE int generator(double p) {
    return p > -1e9 && p < 1e9 ? int(p) & 3 : 0;
}

/// How many whole octaves of `octaves` run, within [0, kFnMaxOctaves].
SHEAF_HD_INLINE int whole_octaves(double octaves) {
    if (!(octaves > 0)) return 0;
    return octaves < double(kFnMaxOctaves) ? int(octaves) : kFnMaxOctaves;
}

/// A helix of `helices` strands around the y axis, turning once every 1 / period along y:
/// the distance from its strand of the point's position across it, in a cross-section
/// (section 1: a circle; 2: a diamond; 0: a square; between: rounded) turned by `angle`
/// degrees, minus the minor radius. `shape` stretches the strand along its way.
SHEAF_HD_INLINE double helix1(double x, double y, double z, const double* p) {
    const double helices = p[0], period = p[1], minor = p[2], major = p[3];
    const double shape = p[4], section = p[5], angle = p[6];
    const double r = sqrt(x * x + z * z);
    if (x == 0 && z == 0) x = 1e-6;
    const double two_pi = 6.283185307179586;
    double around = fmod(hdm::atan2(z, x) * helices + y * period * helices, two_pi);
    if (around < 0) around += two_pi;
    double u = r - major, v = (around - 0.5 * two_pi) / shape / (period * helices);
    double d;
    if (section == 1) {
        d = sqrt(u * u + v * v);
    } else {
        if (angle != 0) {
            const double a = angle * (3.14159265358979323846 / 180.0);
            const double c = hdm::cos(a), s = hdm::sin(a);
            const double ru = u * c - v * s;
            v = u * s + v * c;
            u = ru;
        }
        if (section != 0) {
            const double e = 2.0 / section;
            d = hdm::pow(hdm::pow(fabs(u), e) + hdm::pow(fabs(v), e), 0.5 * section);
        } else {
            d = fabs(u) > fabs(v) ? fabs(u) : fabs(v);
        }
    }
    const double outside = major + r;
    return (outside < d ? outside : d) - minor;
}

/// Heterogeneous multifractal (Musgrave): each octave's noise, offset and faded by
/// lacunarity^-H per octave, is scaled by the signal so far to the power T.
SHEAF_HD_INLINE double hetero_mf(double x, double y, double z, const double* p) {
    const double h = p[0], lacunarity = p[1], octaves = p[2], offset = p[3];
    const int power = p[4] > 0 ? (p[4] < 16 ? int(p[4]) : 16) : 0;
    const int gen = generator(p[5]);
    const double fade = hdm::pow(lacunarity, -h);
    double signal = 2 * noise(x, y, z, gen) - 1 + offset;
    double f = lacunarity, weight = fade;
    for (int i = 1; i < kFnMaxOctaves && double(i) < octaves; ++i) {
        double step = (2 * noise(x * f, y * f, z * f, gen) - 1 + offset) * weight;
        for (int k = 0; k < power; ++k) step *= signal;
        signal += step;
        f *= lacunarity;
        weight *= fade;
    }
    const double rest = octaves - double(whole_octaves(octaves));
    if (rest > 0 && rest < 1)
        signal += rest * signal * (2 * noise(x * f, y * f, z * f, gen) - 1 + offset) * weight;
    return signal;
}

/// Ridged noise: each octave is |noise - ridge| (scaled to [0, 1]) minus `offset`, octave k
/// at lambda^k times the frequency and omega^k times the weight, normalised by the weights.
SHEAF_HD_INLINE double ridge(double x, double y, double z, const double* p) {
    const double lambda = p[0], octaves = p[1], omega = p[2], offset = p[3], ridge = p[4];
    const double across = 1.0 / (ridge > 1 - ridge ? ridge : 1 - ridge);
    const double scale = 1.0 / (offset > 1 - offset ? offset : 1 - offset);
    const int gen = generator(p[5]);
    auto octave = [&](double f) { return fabs(noise(x * f, y * f, z * f, gen) - ridge) * across; };
    double value = octave(1.0) - offset, total = 1;
    double f = lambda, w = omega;
    const int whole = whole_octaves(octaves);
    for (int i = 2; i <= whole; ++i) {
        value += w * (octave(f) - offset);
        total += w;
        f *= lambda;
        w *= omega;
    }
    const double rest = octaves - double(whole);
    if (rest > 0 && rest < 1) {
        value += w * (octave(f) - offset) * rest;
        total += w * rest;
    }
    return value * scale / total;
}

/// Ridged multifractal (Musgrave): each octave is (offset - |2 noise - 1|)^2, weighted by
/// the previous octave times `gain` (clamped to [0, 1]) and by lacunarity^-H per octave.
SHEAF_HD_INLINE double ridged_mf(double x, double y, double z, const double* p) {
    const double h = p[0], lacunarity = p[1], octaves = p[2], offset = p[3], gain = p[4];
    const int gen = generator(p[5]);
    auto crest = [&](double f) {
        return sq(offset - fabs(2 * noise(x * f, y * f, z * f, gen) - 1));
    };
    double signal = crest(1.0), result = signal;
    const double fade = hdm::pow(lacunarity, -h);
    double f = 1, weight = 1;
    for (int i = 1; i < kFnMaxOctaves && double(i) < octaves; ++i) {
        f *= lacunarity;
        weight *= fade;
        double w = signal * gain;
        w = w > 1 ? 1 : (w < 0 ? 0 : w);
        signal = crest(f) * w;
        result += signal * weight;
    }
    return result;
}

/// A superellipsoid's inside-outside function: 1 at the centre, 0 on the surface.
SHEAF_HD_INLINE double superellipsoid(double x, double y, double z, const double* p) {
    const double e = p[0], n = p[1];
    const double xy = hdm::pow(hdm::pow(fabs(x), 2 / e) + hdm::pow(fabs(y), 2 / e), e / n);
    return 1 - hdm::pow(xy + hdm::pow(fabs(z), 2 / n), 0.5 * n);
}

} // namespace fn_internal_detail

/// Internal function `id` over x, y, z and its parameters p (fn_internal_extra(id) of them).
SHEAF_HD_INLINE double fn_internal(int id, double x, double y, double z, const double* p) {
    using fn_internal_detail::sq;
    switch (FnInternal(id)) {
    case FnInternal::Helix1:
        return fn_internal_detail::helix1(x, y, z, p);
    case FnInternal::HeteroMf:
        return fn_internal_detail::hetero_mf(x, y, z, p);
    case FnInternal::Ph:
        return hdm::atan2(sqrt(x * x + z * z), y);
    case FnInternal::R:
        return sqrt(x * x + y * y + z * z);
    case FnInternal::Ridge:
        return fn_internal_detail::ridge(x, y, z, p);
    case FnInternal::RidgedMf:
        return fn_internal_detail::ridged_mf(x, y, z, p);
    case FnInternal::RoundedBox: {
        const double r = p[0];
        const double dx = fabs(x) - (p[1] - r), dy = fabs(y) - (p[2] - r),
                     dz = fabs(z) - (p[3] - r);
        const double ox = dx > 0 ? dx : 0, oy = dy > 0 ? dy : 0, oz = dz > 0 ? dz : 0;
        const double inner = dx > dy ? (dx > dz ? dx : dz) : (dy > dz ? dy : dz);
        return sqrt(ox * ox + oy * oy + oz * oz) + (inner < 0 ? inner : 0) - r;
    }
    case FnInternal::Sphere:
        return sqrt(x * x + y * y + z * z) - p[0];
    case FnInternal::Superellipsoid:
        return fn_internal_detail::superellipsoid(x, y, z, p);
    case FnInternal::Th:
        return hdm::atan2(x, z);
    case FnInternal::Torus:
        return sqrt(sq(sqrt(x * x + z * z) - p[0]) + y * y) - p[1];
    case FnInternal::Noise3d: // the default generator: a scene's global one does not reach it
        return fn_internal_detail::noise(x, y, z, kPovDefaultNoiseGenerator);
    case FnInternal::NoiseGenerator:
        return fn_internal_detail::noise(x, y, z, fn_internal_detail::generator(p[0]));
    }
    return 0;
}

} // namespace sheaf

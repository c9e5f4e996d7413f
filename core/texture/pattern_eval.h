// Evaluating a Pattern (core/scene/pattern.h) at a world point: the point moves into pattern
// space, turbulence displaces it, then a continuous pattern gives a value in [0, 1] (after
// frequency, phase and the wave) and a list pattern gives the index of an entry.
// The shapes follow POV-Ray 3.7's descriptions. The noise patterns (bozo, spotted, bumps,
// granite, agate, wrinkles, dents), turbulence and the band patterns' own turbulence (marble,
// wood, agate, the spirals) are POV-Ray's, in double precision (pov_noise.h); crackle and cells
// are Sheaf's own cells (noise.h), alike but not POV-Ray's point for point.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/pattern.h"
#include "core/texture/fractal_pattern.h"
#include "core/texture/pov_noise.h"

namespace sheaf {

namespace pattern_detail {

SHEAF_HD_INLINE float frac(float v) {
    return v - floorf(v);
}
SHEAF_HD_INLINE float clamp01(float v) {
    return hdm::fminf(1.0f, hdm::fmaxf(0.0f, v));
}
using hdm::floor_int;
SHEAF_HD_INLINE int imod(int a, int n) {
    const int r = a % n;
    return r < 0 ? r + n : r;
}

// POV-Ray's sine of a fraction of a turn (its `cycloidal`), odd about 0.
SHEAF_HD_INLINE double cycloidal(double v) {
    constexpr double kTurn = 6.283185307179586476925286766559;
    if (v >= 0.0) return hdm::sin((v - ::floor(v)) * 50000.0 / 50000.0 * kTurn);
    return -hdm::sin((-(v + ::floor(-v))) * 50000.0 / 50000.0 * kTurn);
}

// POV-Ray's triangle wave: 0 at whole numbers, 1 halfway.
SHEAF_HD_INLINE double triangle_wave(double v) {
    const double offset = v >= 0.0 ? v - ::floor(v) : v + 1.0 + ::floor(fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// POV-Ray's quilted cell: the point's offset from its unit cell's centre, scaled by the cubic
// of its length with control points control0 and control1 (param[0], param[1]; the curve runs
// from 0 to 1 and is divided by sqrt(3/4), the longest offset). The pattern is the scaled
// offset's mean absolute component; the normal leans by the offset itself.
SHEAF_HD_INLINE DVec3 quilted_offset(const Pattern& pt, DVec3 p) {
    const DVec3 q(p.x - ::floor(p.x) - 0.5, p.y - ::floor(p.y) - 0.5, p.z - ::floor(p.z) - 0.5);
    const double t = ::sqrt(q.x * q.x + q.y * q.y + q.z * q.z), it = 1.0 - t;
    const double s = (t * t * t + 3.0 * t * it * it * double(pt.param[0]) +
                      3.0 * t * t * it * double(pt.param[1])) *
                     1.154700538;
    return q * s;
}

// The wave shapes a value in [0, 1], as POV-Ray's do.
SHEAF_HD_INLINE double apply_wave(const Pattern& pt, double v) {
    switch (pt.wave) {
    case Wave::Ramp:
        return v;
    case Wave::Triangle:
        return triangle_wave(v);
    case Wave::Sine:
        return (1.0 + cycloidal(v)) * 0.5;
    case Wave::Scallop:
        return fabs(cycloidal(v * 0.5));
    case Wave::Cubic:
        return v * v * (-2.0 * v + 3.0);
    case Wave::Poly:
        return hdm::pow(v, double(pt.wave_exponent));
    }
    return v;
}

// POV-Ray's ripples (the mean of the waves' sines of distance times frequency plus phase,
// from 0..1) and waves (each wave at its own frequency, weighted by its inverse).
SHEAF_HD_INLINE double pov_waves_value(DVec3 p, bool waves, double frequency, double phase,
                                       int count) {
    double sum = 0.0;
    PovWaveFrequencies freq;
    for (int i = 0; i < count; ++i) {
        const DVec3 s = pov_wave_source(i);
        const double dx = p.x - s.x, dy = p.y - s.y, dz = p.z - s.z;
        double len = ::sqrt(dx * dx + dy * dy + dz * dz);
        if (len == 0.0) len = 1.0;
        const double f = freq.next();
        if (waves)
            sum += cycloidal(len * frequency * f + phase) / f;
        else
            sum += cycloidal(len * frequency + phase);
    }
    return waves ? 0.2 * (2.5 + sum / count) : 0.5 * (1.0 + sum / count);
}

// Coordinates kept within +-1e9 (NaN as 0), where whole cell numbers still fit an int.
SHEAF_HD_INLINE DVec3 clamp_coords(DVec3 p) {
    auto c = [](double v) { return !(v > -1e9) ? (v != v ? 0.0 : -1e9) : v > 1e9 ? 1e9 : v; };
    return {c(p.x), c(p.y), c(p.z)};
}

// POV-Ray's crackle: one random point per unit cell (pov_cell_point); the distances (under
// `metric`, param[0]) to the nearest three of the points in the 81 cells around p, each raised
// by `offset` (param[1]), weighted by `form` (vector) and summed; or, `solid` (param[2]), the
// noise at the nearest point. Clamped to [0, 1].
SHEAF_HD_NOINLINE double pov_crackle(const Pattern& pt, DVec3 p) {
    p = clamp_coords(p);
    const double metric = pt.param[0];
    const bool square = metric == 2.0, unity = metric == 1.0;
    auto dist = [&](DVec3 q) {
        const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
        if (square) return dx * dx + dy * dy + dz * dz;
        if (unity) return fabs(dx) + fabs(dy) + fabs(dz);
        return hdm::pow(fabs(dx), metric) + hdm::pow(fabs(dy), metric) + hdm::pow(fabs(dz), metric);
    };
    const int fx = int(::floor(p.x - 1e-10)), fy = int(::floor(p.y - 1e-10)),
              fz = int(::floor(p.z - 1e-10));
    double m1 = 0, m2 = 0, m3 = 0;
    DVec3 nearest, first[3];
    int seen = 0;
    // The cells at most two away along each axis, and two away along one axis at most, in
    // POV-Ray's order (which settles ties).
    for (int ax = -2; ax <= 2; ++ax)
        for (int ay = -2; ay <= 2; ++ay)
            for (int az = -2; az <= 2; ++az) {
                if ((ax == 2 || ax == -2) + (ay == 2 || ay == -2) + (az == 2 || az == -2) > 1)
                    continue;
                const DVec3 q = pov_cell_point(fx + ax, fy + ay, fz + az);
                const double s = dist(q);
                if (seen < 3) { // the first three, then sorted as POV-Ray sorts them
                    first[seen] = q;
                    (seen == 0 ? m1 : seen == 1 ? m2 : m3) = s;
                    if (++seen == 3) {
                        int idx = 0;
                        double t;
                        if (m2 < m1) t = m1, m1 = m2, m2 = t, idx = 1;
                        if (m3 < m1) t = m1, m1 = m3, m3 = t, idx = 2;
                        if (m3 < m2) t = m2, m2 = m3, m3 = t;
                        nearest = first[idx];
                    }
                    continue;
                }
                if (s < m1) {
                    m3 = m2, m2 = m1, m1 = s;
                    nearest = q;
                } else if (s < m2) {
                    m3 = m2, m2 = s;
                } else if (s < m3) {
                    m3 = s;
                }
            }
    const double offset = pt.param[1];
    if (offset != 0) {
        const double o = square ? offset * offset : unity ? offset : hdm::pow(offset, metric);
        m1 += o, m2 += o, m3 += o;
    }
    double v;
    if (pt.param[2] != 0) {
        v = pov_noise(nearest, pt.noise_generator);
    } else if (square) {
        v = pt.vector.x * ::sqrt(m1) + pt.vector.y * ::sqrt(m2) + pt.vector.z * ::sqrt(m3);
    } else if (unity) {
        v = pt.vector.x * m1 + pt.vector.y * m2 + pt.vector.z * m3;
    } else {
        v = pt.vector.x * hdm::pow(m1, 1.0 / metric) + pt.vector.y * hdm::pow(m2, 1.0 / metric) +
            pt.vector.z * hdm::pow(m3, 1.0 / metric);
    }
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

// POV-Ray's scalar turbulence of the pattern (its octaves, omega, lambda and generator).
SHEAF_HD_INLINE double own_turbulence(const Pattern& pt, DVec3 p) {
    return pov_turbulence(p, pt.octaves, double(pt.omega), double(pt.lambda), pt.noise_generator);
}

// 2 noise - 0.5 clamped to [0, 1]: how generators 2 and 3 take an octave in wrinkles.
SHEAF_HD_INLINE double stretched_noise(DVec3 p, int gen) {
    return pov_noise_detail::clamp01(pov_noise(p, gen) * 2.0 - 0.5);
}

// The raw value of a continuous pattern at pattern-space point p, before frequency, phase and
// the wave, as POV-Ray's pattern gives it; some leave [0, 1] (marble, wood, spiral1 ...).
SHEAF_HD_NOINLINE double raw_value(const Pattern& pt, Vec3 p) {
    const DVec3 d(p);
    const int gen = pt.noise_generator;
    switch (pt.kind) {
    case PatternKind::Gradient: {
        const float l = length(pt.vector);
        const double r = l > 0 ? double(dot(p, pt.vector)) / double(l) : 0.0;
        return r > 1.0 ? ::fmod(r, 1.0) : r;
    }
    case PatternKind::Marble: // the band bent by the scalar turbulence
        return d.x + (pt.has_turbulence ? double(pt.turbulence.x) * own_turbulence(pt, d) : 0.0);
    case PatternKind::Wood: {
        // Rings about z, the point pushed by the vector turbulence through a sine of it.
        double x = d.x, y = d.y;
        if (pt.has_turbulence) {
            const DVec3 t = pov_dturbulence(d, pt.octaves, double(pt.omega), double(pt.lambda));
            x += cycloidal((d.x + t.x) * double(pt.turbulence.x));
            y += cycloidal((d.y + t.y) * double(pt.turbulence.y));
        }
        return ::sqrt(x * x + y * y);
    }
    case PatternKind::Onion:
        return ::fmod(::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), 1.0);
    case PatternKind::Radial: // POV-Ray's: a quarter turn on, 0.25 on the axis
        if (fabs(d.x) < 0.001 && fabs(d.z) < 0.001) return 0.25;
        return 0.25 + (::atan2(d.x, d.z) + 3.141592653589793) / 6.283185307179586;
    case PatternKind::Spherical:
        return 1.0f - clamp01(length(p));
    case PatternKind::Cylindrical:
        return 1.0f - clamp01(sqrtf(p.x * p.x + p.z * p.z));
    case PatternKind::Planar:
        return 1.0f - clamp01(fabsf(p.y));
    case PatternKind::Boxed:
        return 1.0f - clamp01(hdm::fmaxf(fabsf(p.x), hdm::fmaxf(fabsf(p.y), fabsf(p.z))));
    case PatternKind::Leopard: {
        const double s = (hdm::sin(d.x) + hdm::sin(d.y) + hdm::sin(d.z)) / 3.0;
        return s * s;
    }
    case PatternKind::Bozo:
        return pov_noise(d, gen);
    case PatternKind::Granite: { // six octaves of |1 - 2 noise| (the original: |0.5 - noise|)
        double sum = 0.0, freq = 1.0;
        const DVec3 q = d * 4.0;
        for (int i = 0; i < 6; freq *= 2.0, ++i) {
            const double n = pov_noise(q * freq, gen);
            const double t =
                gen == 1 ? fabs(0.5 - n) : (fabs(1.0 - 2.0 * n) > 0.5 ? 0.5 : fabs(1.0 - 2.0 * n));
            sum += t / freq;
        }
        return sum;
    }
    case PatternKind::Agate: { // bands along z bent by the scalar turbulence times agate_turb
        const double scale = pt.param[0] > 0 ? double(pt.param[0]) : 1.0;
        const double turb = scale * own_turbulence(pt, d);
        const double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * d.z) + 1.0);
        return v < 0.0 ? 0.0 : hdm::pow(v > 1.0 ? 1.0 : v, 0.77);
    }
    case PatternKind::Wrinkles: { // ten octaves of noise, halved
        double v = gen > 1 ? stretched_noise(d, gen) : pov_noise(d, gen);
        double lambda = 2.0, omega = 0.5;
        for (int i = 1; i < 10; ++i) {
            const DVec3 q = d * lambda;
            v += omega * (gen > 1 ? stretched_noise(q, gen) : pov_noise(q, gen));
            lambda *= 2.0;
            omega *= 0.5;
        }
        return v / 2.0;
    }
    case PatternKind::Dents: {
        const double n = pov_noise(d, gen);
        return n * n * n;
    }
    case PatternKind::Crackle:
        return pov_crackle(pt, d);
    case PatternKind::Cells: { // a random value per unit cube
        const DVec3 c = clamp_coords(d);
        const double v = pov_pattern_rand(pov_hash3(
            int(::floor(c.x + 1e-10)), int(::floor(c.y + 1e-10)), int(::floor(c.z + 1e-10))));
        return v < 1.0 ? v : 1.0;
    }
    case PatternKind::Ripples:
    case PatternKind::Waves: // POV-Ray's sources (number_of_waves); waves weigh each by its own
                             // frequency
        return pov_waves_value(d, pt.kind == PatternKind::Waves, double(pt.frequency),
                               double(pt.phase), pt.waves);
    case PatternKind::Spiral1:
    case PatternKind::Spiral2: {
        // POV-Ray's: the arms turn about z, the angle counted from -y towards +x; spiral2
        // adds rings of the distance, each triangle-waved. Turbulence bends the arms.
        const double arms = pt.param[0] != 0 ? double(pt.param[0]) : 1.0;
        const double r = ::sqrt(d.x * d.x + d.y * d.y);
        constexpr double kHalfPi = 1.5707963267948966192313216916398;
        const double phi = r == 0.0  ? 0.0
                           : d.x < 0 ? 3.0 * kHalfPi - hdm::asin(d.y / r)
                                     : kHalfPi + hdm::asin(d.y / r);
        const double a = phi / 6.283185307179586476925286766559;
        const double turb =
            pt.has_turbulence ? double(pt.turbulence.x) * own_turbulence(pt, d) : 0.0;
        const double s = d.z + r + arms * a + turb;
        if (pt.kind == PatternKind::Spiral1) return s;
        return triangle_wave(s) + triangle_wave(r);
    }
    case PatternKind::Quilted: { // the cell's offset scaled by the cushion, summed (POV-Ray)
        const DVec3 q = quilted_offset(pt, d);
        return (::fabs(q.x) + ::fabs(q.y) + ::fabs(q.z)) / 3.0;
    }
    case PatternKind::Mandel:
    case PatternKind::Julia:
        return fractal_value(pt.fractal, pt.kind == PatternKind::Julia, p);
    default:
        return 0.0;
    }
}

// As POV-Ray: with a frequency, the value times it plus the phase, modulo 1.00001 (POV-Ray's
// constant); a negative value wraps into [0, 1); then the wave. (Ripples and waves use
// frequency and phase inside too, and then again here, as in POV-Ray.)
SHEAF_HD_INLINE float shape_value(const Pattern& pt, double raw) {
    double v = raw;
    if (pt.frequency != 0.0f) v = ::fmod(v * double(pt.frequency) + double(pt.phase), 1.00001);
    if (v < 0.0) v -= ::floor(v);
    return float(apply_wave(pt, v));
}

} // namespace pattern_detail

namespace pattern_detail {

// The angle of (x, z) from +x towards +z as a fraction of a turn in [0, 1), as POV-Ray's
// warps measure it; len is the length of (x, z), above 0.
SHEAF_HD_INLINE float turn_fraction(float x, float z, float len) {
    if (z == 0.0f) return x > 0 ? 0.0f : 0.5f;
    const float a = hdm::acosf(fmaxf(-1.0f, fminf(1.0f, x / len))) / (2.0f * kPi);
    return z < 0 ? 1.0f - a : a;
}

// (x, y, z) computed along z, turned to the unit orientation o (POV-Ray's formula).
SHEAF_HD_INLINE Vec3 orient(Vec3 v, Vec3 o) {
    if (o.x == 0 && o.y == 0 && o.z == 1) return v;
    return {o.x * v.z + o.y * v.x + o.z * v.x, o.x * v.y - o.y * v.z + o.z * v.y,
            -o.x * v.x + o.y * v.y + o.z * v.z};
}

SHEAF_HD_INLINE float dist_factor(float dist, float exponent) {
    return exponent == 1.0f ? dist : exponent != 0.0f ? hdm::powf(dist, exponent) : 1.0f;
}

} // namespace pattern_detail

/// Point p moved by warp w (in the space where it was declared), before w.to_inner.
SHEAF_HD_NOINLINE Vec3 warp_point(const Warp& w, Vec3 p) {
    using namespace pattern_detail;
    switch (w.kind) {
    case WarpKind::Turbulence: {
        const DVec3 t = pov_dturbulence(DVec3(p), w.octaves, double(w.f[0]), double(w.f[1]));
        return Vec3(float(p.x + w.a.x * t.x), float(p.y + w.a.y * t.y), float(p.z + w.a.z * t.z));
    }
    case WarpKind::Repeat: {
        const float width = w.f[0];
        const float block = floorf(p[w.axis] / width);
        Vec3 r = p;
        r[w.axis] = p[w.axis] - block * width;
        if (int(block) & 1) { // odd slabs mirrored where flip says
            r = r * w.b;
            if (w.b[w.axis] < 0) r[w.axis] += width;
        }
        return r + w.a * block;
    }
    case WarpKind::Planar:
        return orient(Vec3(p.x, p.y, w.f[0]), w.b);
    case WarpKind::Cylindrical: {
        const float len = sqrtf(p.x * p.x + p.z * p.z);
        if (len == 0.0f) return p;
        const float theta = turn_fraction(p.x, p.z, len) * dist_factor(len, w.f[0]);
        return orient(Vec3(theta, p.y, len), w.b);
    }
    case WarpKind::Spherical: {
        const float dist = length(p);
        if (dist == 0.0f) return p;
        const Vec3 u = p / dist;
        const float phi = 0.5f + hdm::asinf(fmaxf(-1.0f, fminf(1.0f, u.y))) / kPi;
        const float len = sqrtf(u.x * u.x + u.z * u.z);
        const float theta = len == 0.0f ? 0.0f : turn_fraction(u.x, u.z, len);
        const float k = dist_factor(dist, w.f[0]);
        return orient(Vec3(theta * k, phi * k, dist), w.b);
    }
    case WarpKind::Toroidal: {
        const float len0 = sqrtf(p.x * p.x + p.z * p.z);
        if (len0 == 0.0f) return p;
        const float theta = turn_fraction(p.x, p.z, len0);
        const float x = len0 - w.f[1];
        const float len = sqrtf(x * x + p.y * p.y);
        float phi = len > 0 ? hdm::acosf(fmaxf(-1.0f, fminf(1.0f, -x / len))) : 0.0f;
        if (p.y > 0) phi = 2.0f * kPi - phi;
        const float k = dist_factor(len, w.f[0]);
        return orient(Vec3(theta * k, phi / (2.0f * kPi) * k, len), w.b);
    }
    case WarpKind::BlackHole: {
        Vec3 centre = w.a;
        if (w.b.x > 0 || w.b.y > 0 || w.b.z > 0) { // repeated: the copy whose block holds p
            const int bx = w.b.x > 0 ? floor_int(p.x / w.b.x) : 0;
            const int by = w.b.y > 0 ? floor_int(p.y / w.b.y) : 0;
            const int bz = w.b.z > 0 ? floor_int(p.z / w.b.z) : 0;
            // Its jitter (turbulence): POV-Ray's random numbers at the block's hash.
            const int seed = pov_hash3(bx, by, bz);
            centre += Vec3(w.c.x * float(pov_pattern_rand(seed)),
                           w.c.y * float(pov_pattern_rand(seed + 1)),
                           w.c.z * float(pov_pattern_rand(seed + 2)));
            centre += Vec3(w.b.x * float(bx), w.b.y * float(by), w.b.z * float(bz));
        }
        const Vec3 d = p - centre;
        const float len = length(d);
        if (!(len < w.f[0])) return p;
        const float s = hdm::fminf(hdm::powf((w.f[0] - len) / w.f[0], w.f[1]) * w.f[2], 1);
        return p + d * (w.axis ? -s : s);
    }
    case WarpKind::Cubic: {
        const float ax = fabsf(p.x), ay = fabsf(p.y), az = fabsf(p.z);
        const float third = 1.0f / 3.0f;
        if (p.x >= 0 && p.x >= ay && p.x >= az)
            return {0.75f - 0.125f * (p.z / p.x + 1), third + third * 0.5f * (p.y / p.x + 1), p.x};
        if (p.y >= 0 && p.y >= ax && p.y >= az)
            return {0.25f + 0.125f * (p.x / p.y + 1), 1 - third * 0.5f * (p.z / p.y + 1), p.y};
        if (p.z >= 0 && p.z >= ax && p.z >= ay)
            return {0.25f + 0.125f * (p.x / p.z + 1), third + third * 0.5f * (p.y / p.z + 1), p.z};
        if (p.x < 0 && p.x <= -ay && p.x <= -az)
            return {0.125f * (p.z / -p.x + 1), third + third * 0.5f * (p.y / -p.x + 1), -p.x};
        if (p.y < 0 && p.y <= -ax && p.y <= -az)
            return {0.25f + 0.125f * (p.x / -p.y + 1), third * 0.5f * (p.z / -p.y + 1), -p.y};
        return {1 - 0.125f * (p.x / -p.z + 1), third + third * 0.5f * (p.y / -p.z + 1), -p.z};
    }
    }
    return p;
}

/// The pattern-space point of world point `world`: through the pattern's transforms and
/// warps (`warps`: the scene's warp array, read when the pattern has any; none without it),
/// then its classic turbulence.
SHEAF_HD_NOINLINE Vec3 pattern_point(const Pattern& pt, Vec3 world, const Warp* warps) {
    Vec3 p = pt.to_pattern.point(world);
    for (uint32_t i = 0; warps && i < pt.warp_count; ++i) {
        const Warp& w = warps[pt.warp_first + i];
        p = w.to_inner.point(warp_point(w, p));
    }
    // POV-Ray's classic turbulence moves the point by DTurbulence times the amount, but for
    // marble and wood, which bend their bands by it themselves (raw_value).
    if (pt.has_turbulence && !bends_by_own_turbulence(pt.kind)) {
        const DVec3 t = pov_dturbulence(DVec3(p), pt.octaves, double(pt.omega), double(pt.lambda));
        p = Vec3(float(p.x + pt.turbulence.x * t.x), float(p.y + pt.turbulence.y * t.y),
                 float(p.z + pt.turbulence.z * t.z));
    }
    return p;
}

/// The gradient g, taken in pattern space, in the world: through the transposes of the
/// pattern's transforms (the warps' own bending aside, as POV-Ray's normals do).
SHEAF_HD_INLINE Vec3 pattern_gradient_to_world(const Pattern& pt, const Warp* warps, Vec3 g) {
    auto transpose = [](const Affine& m, Vec3 v) {
        return Vec3(m.m[0][0] * v.x + m.m[1][0] * v.y + m.m[2][0] * v.z,
                    m.m[0][1] * v.x + m.m[1][1] * v.y + m.m[2][1] * v.z,
                    m.m[0][2] * v.x + m.m[1][2] * v.y + m.m[2][2] * v.z);
    };
    for (uint32_t i = pt.warp_count; i-- > 0;) g = transpose(warps[pt.warp_first + i].to_inner, g);
    return transpose(pt.to_pattern, g);
}

/// A continuous pattern's value in [0, 1] at pattern-space point p.
SHEAF_HD_INLINE float pattern_value_at(const Pattern& pt, Vec3 p) {
    using namespace pattern_detail;
    return shape_value(pt, raw_value(pt, p));
}

/// The slope pattern's raw value (SlopeParams) at pattern-space point q of a surface at world
/// point `world` whose normal, facing the ray, is n; 0 where there is no surface (n zero).
/// In double precision, as POV-Ray computes it.
SHEAF_HD_NOINLINE float slope_raw(const Pattern& pt, Vec3 q, Vec3 world, Vec3 n) {
    if (!(length_squared(n) > 0)) return 0.0f;
    Vec3 d = pt.vector;
    if (pt.slope.point_at) { // towards a point: the direction from the surface to it
        d = pt.vector - world;
        const float l = length(d);
        d = l > 0 ? d / l : Vec3(0.0f);
    }
    double v = double(dot(n, d));
    v = v < -1.0 ? -1.0 : v > 1.0 ? 1.0 : v;
    v = (hdm::asin(v) / 3.14159265358979323846 * 2.0 + 1.0) * 0.5; // [-pi/2, pi/2] -> [0, 1]
    if (pt.param[1] != 0) v = (v - pt.param[0]) / pt.param[1];
    if (length_squared(pt.slope.altitude) > 0) {
        double a = double(dot(q, pt.slope.altitude));
        if (pt.param[3] != 0) a = (a - pt.param[2]) / pt.param[3];
        v = pt.slope.slope_weight * v + (1.0 - pt.slope.slope_weight) * a;
    }
    if (v >= 1.0 && v - 1.0 < 1e-10) return 1.0f; // a 1 (common on flat ground) stays 1
    const double f = v - trunc(v);
    return float(v < 0 ? 1.0 + f : f);
}

/// The hexagon pattern's entry (0, 1 or 2) at (x, z), laid out as POV-Ray lays it: hexagons
/// of unit side, flat sides along x, the one around the origin entry 0; the plane mirrored
/// about x = 0, and z below 0 moved up by the layout's repeat (6 blocks of sqrt(3)/2) rather
/// than mirrored. The layout repeats every 6 x 6 blocks half a side wide and sqrt(3)/2 high;
/// a block of column 0, 2, 3 or 5 lies in one hexagon, one of column 1 or 4 is cut by a
/// hexagon's slanted side. In double precision, as POV-Ray computes it.
SHEAF_HD_INLINE int hexagon_cell(double x, double z) {
    const double height = 0.866025404; // a block's height: sqrt(3)/2
    x = fabs(x);
    if (z < 0) z = 6.0 * height - fabs(z);
    double xs = x / 0.5, zs = z / height;
    xs -= floor(xs / 6.0) * 6.0;
    zs -= floor(zs / 6.0) * 6.0;
    const int col = int(floor(xs)) % 6, row = int(floor(zs)) % 6;
    // Blocks within one hexagon: the entry by row, for columns 0 and 5, and 2 and 3.
    if (col == 0 || col == 5) return (row + 1) % 6 / 2; // rows 0..5: 0 1 1 2 2 0
    if (col == 2 || col == 3) return (row + 4) % 6 / 2; // rows 0..5: 2 2 0 0 1 1
    // A block cut by a slanted side: which side of its diagonal (the blocks of odd column plus
    // row slope the other way), then the entry by row.
    double xl = xs - col;
    const double zl = zs - row;
    if ((col + row) % 2 == 1) xl = 1.0 - xl;
    if (xl == 0.0) xl = 1e-4;
    const int step = row % 3; // rows 0 and 3, 1 and 4, 2 and 5 alike
    const int below[3] = {0, 2, 1}, above[3] = {2, 1, 0};
    return zl / xl < 1.0 ? below[step] : above[step];
}

/// A list pattern's entry (0 .. entries-1) at pattern-space point p.
SHEAF_HD_NOINLINE int pattern_index_at(const Pattern& pt, Vec3 p) {
    using namespace pattern_detail;
    // 1e-4 world units along each pattern axis: keeps faces lying on the cells' planes on one
    // side (a float hit point strays from them), without moving the planes of cells scaled
    // large (a checker 32000 wide keeps its edge at 0, as in POV-Ray).
    const Affine& m = pt.to_pattern;
    auto row = [&](int r) {
        return 1e-4f * sqrtf(m.m[r][0] * m.m[r][0] + m.m[r][1] * m.m[r][1] + m.m[r][2] * m.m[r][2]);
    };
    const Vec3 e(row(0), row(1), row(2));
    switch (pt.kind) {
    case PatternKind::Checker:
        return imod(floor_int(p.x + e.x) + floor_int(p.y + e.y) + floor_int(p.z + e.z), 2);
    case PatternKind::Square:
        return imod(floor_int(p.x + e.x), 2) + 2 * imod(floor_int(p.z + e.z), 2);
    case PatternKind::Hexagon:
        return hexagon_cell(double(p.x), double(p.z));
    case PatternKind::Triangular: {
        // Axial coordinates of hexagons of unit side in the x-z plane, flat sides along x.
        const float q = (2.0f / 3.0f) * p.x;
        const float r = (-1.0f / 3.0f) * p.x + (sqrtf(3.0f) / 3.0f) * p.z;
        // Cube rounding.
        float cx = q, cz = r, cy = -q - r;
        float rx = roundf(cx), ry = roundf(cy), rz = roundf(cz);
        const float dx = fabsf(rx - cx), dy = fabsf(ry - cy), dz = fabsf(rz - cz);
        if (dx > dy && dx > dz)
            rx = -ry - rz;
        else if (dy > dz)
            ry = -rx - rz;
        else
            rz = -rx - ry;
        // Six triangles per hexagon: the sector of the point around its hexagon's centre.
        const float hx = 1.5f * rx, hz = sqrtf(3.0f) * (rz + 0.5f * rx);
        const float a = hdm::atan2f(p.z - hz, p.x - hx) / (2.0f * kPi) + 0.5f;
        return imod(floor_int(a * 6.0f), 6);
    }
    case PatternKind::Brick: {
        const Vec3 size(pt.param[0] > 0 ? pt.param[0] : 8.0f, pt.param[1] > 0 ? pt.param[1] : 3.0f,
                        pt.param[2] > 0 ? pt.param[2] : 4.5f);
        const float mortar = pt.param[3] > 0 ? pt.param[3] : 0.5f;
        // POV-Ray's layout: the point moved by the mortar's width, so each course, brick and
        // layer starts with its mortar (a joint at the low end of every cell); courses of
        // even and odd number shift their end joints by half a brick, along x and along z
        // the other way round. Nudged as checker is, so a face lying on a course boundary
        // takes one side.
        const Vec3 q = p + e + Vec3(mortar);
        if (frac(q.y / size.y) <= mortar / size.y) return 0;
        const bool odd = frac(q.y / (2.0f * size.y)) <= 0.5f;
        if (frac(q.x / size.x + (odd ? 0.0f : 0.5f)) <= mortar / size.x) return 0;
        if (frac(q.z / size.z + (odd ? 0.5f : 0.0f)) <= mortar / size.z) return 0;
        return 1;
    }
    default:
        return 0;
    }
}

} // namespace sheaf

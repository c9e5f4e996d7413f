// Evaluating a Pattern (core/scene/pattern.h) at a world point: the point moves into pattern
// space, turbulence displaces it, then a continuous pattern gives a value in [0, 1] (after
// frequency, phase and the wave) and a list pattern gives the index of an entry.
// The shapes follow POV-Ray 3.7's descriptions; the noise is Sheaf's own (noise.h), so noise
// patterns look alike but are not POV-Ray's pixel for pixel.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/pattern.h"
#include "core/texture/fractal_pattern.h"
#include "core/texture/noise.h"

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

// The ten fixed sources of ripples and waves, inside the unit cube around the origin.
SHEAF_HD_INLINE Vec3 wave_source(int k) {
    const uint32_t h = lattice_hash(k, 17, 29, 11);
    return Vec3(hash_unit(h), hash_unit(h * 0x2545f491u + 3), hash_unit(h * 0x9e3779b9u + 5)) *
               2.0f -
           Vec3(1.0f);
}

// The wave shapes a value in [0, 1].
SHEAF_HD_INLINE float apply_wave(const Pattern& pt, float v) {
    switch (pt.wave) {
    case Wave::Ramp:
        return v;
    case Wave::Triangle:
        return v < 0.5f ? 2.0f * v : 2.0f - 2.0f * v;
    case Wave::Sine:
        return 0.5f + 0.5f * hdm::sinf(2.0f * kPi * v);
    case Wave::Scallop:
        return fabsf(hdm::sinf(kPi * v));
    case Wave::Cubic:
        return v * v * (3.0f - 2.0f * v);
    case Wave::Poly:
        return hdm::powf(v, pt.wave_exponent);
    }
    return v;
}

// The raw value of a continuous pattern at pattern-space point p, before frequency, phase and
// the wave; some leave [0, 1] (gradient, onion, wood ...) and wrap.
SHEAF_HD_NOINLINE float raw_value(const Pattern& pt, Vec3 p) {
    switch (pt.kind) {
    case PatternKind::Gradient: {
        const float l = length(pt.vector);
        return l > 0 ? dot(p, pt.vector) / l : 0.0f;
    }
    case PatternKind::Marble:
        return p.x;
    case PatternKind::Wood:
        return sqrtf(p.x * p.x + p.y * p.y);
    case PatternKind::Onion:
        return length(p);
    case PatternKind::Radial:
        return hdm::atan2f(p.x, -p.z) / (2.0f * kPi) + 0.5f;
    case PatternKind::Spherical:
        return 1.0f - clamp01(length(p));
    case PatternKind::Cylindrical:
        return 1.0f - clamp01(sqrtf(p.x * p.x + p.z * p.z));
    case PatternKind::Planar:
        return 1.0f - clamp01(fabsf(p.y));
    case PatternKind::Boxed:
        return 1.0f - clamp01(hdm::fmaxf(fabsf(p.x), hdm::fmaxf(fabsf(p.y), fabsf(p.z))));
    case PatternKind::Leopard: {
        const float s = (hdm::sinf(p.x) + hdm::sinf(p.y) + hdm::sinf(p.z)) / 3.0f;
        return s * s;
    }
    case PatternKind::Bozo:
        return noise01(p);
    case PatternKind::Granite: {
        float sum = 0, f = 1;
        for (int i = 0; i < 6; ++i) {
            sum += fabsf(gradient_noise(p * (4.0f * f))) / f;
            f *= 2.0f;
        }
        return clamp01(sum * 0.9f);
    }
    case PatternKind::Agate: {
        const float turb = turbulence(p, 7, 0.5f, 2.0f) * (pt.param[0] > 0 ? pt.param[0] : 1.0f);
        const float v = 0.5f + 0.5f * hdm::cosf((p.z + 2.0f * turb) * 2.0f * kPi * 0.5f);
        return clamp01(hdm::powf(v, 0.5f));
    }
    case PatternKind::Wrinkles: {
        float sum = 0, f = 1;
        for (int i = 0; i < 10; ++i) {
            sum += gradient_noise(p * (f * kPatternNoiseScale)) / f;
            f *= 2.0f;
        }
        return clamp01(0.5f + 0.5f * sum);
    }
    case PatternKind::Dents: {
        const float n = noise01(p);
        return n * n * n;
    }
    case PatternKind::Crackle: {
        float f1, f2;
        uint32_t id;
        cell_distances(p, f1, f2, id);
        return clamp01(f2 - f1);
    }
    case PatternKind::Cells:
        return hash_unit(lattice_hash(floor_int(p.x), floor_int(p.y), floor_int(p.z), 3));
    case PatternKind::Ripples:
    case PatternKind::Waves: {
        // The mean of ten cosine waves; waves weigh near sources more.
        float sum = 0, weight = 0;
        for (int k = 0; k < 10; ++k) {
            const float d = length(p - wave_source(k));
            const float w = pt.kind == PatternKind::Waves ? 1.0f / (1.0f + d) : 1.0f;
            sum += w * hdm::cosf(2.0f * kPi * (d * pt.frequency + pt.phase));
            weight += w;
        }
        return clamp01(0.5f + 0.5f * sum / weight);
    }
    case PatternKind::Spiral1:
    case PatternKind::Spiral2: {
        // POV-Ray's: the arms turn about z, the angle counted from -y towards +x; spiral2
        // adds rings of the distance, each triangle-waved.
        const float arms = pt.param[0] != 0 ? pt.param[0] : 1.0f;
        const float r = sqrtf(p.x * p.x + p.y * p.y);
        const float a = r > 0 ? hdm::atan2f(p.x, -p.y) / (2.0f * kPi) : 0.0f;
        const float s = p.z + r + arms * a;
        if (pt.kind == PatternKind::Spiral1) return s;
        auto triangle = [](float x) {
            x = frac(x);
            return x < 0.5f ? 2.0f * x : 2.0f - 2.0f * x;
        };
        return triangle(s) + triangle(r);
    }
    case PatternKind::Quilted: {
        const Vec3 q(frac(p.x + 0.5f) - 0.5f, frac(p.y + 0.5f) - 0.5f, frac(p.z + 0.5f) - 0.5f);
        const float m = 2.0f * hdm::fmaxf(fabsf(q.x), hdm::fmaxf(fabsf(q.y), fabsf(q.z)));
        return clamp01(m * m * (3.0f - 2.0f * m));
    }
    case PatternKind::Mandel:
    case PatternKind::Julia:
        return fractal_value(pt.fractal, pt.kind == PatternKind::Julia, p);
    default:
        return 0.0f;
    }
}

// Frequency and phase, then the value wraps into [0, 1) when it left [0, 1] or was modified
// (an unmodified 1 stays 1), then the wave. Ripples and waves use frequency and phase inside.
SHEAF_HD_INLINE float shape_value(const Pattern& pt, float raw) {
    if (pt.kind == PatternKind::Ripples || pt.kind == PatternKind::Waves)
        return apply_wave(pt, raw);
    float v = raw * pt.frequency + pt.phase;
    if (v < 0.0f || v > 1.0f || pt.frequency != 1.0f || pt.phase != 0.0f) v = frac(v);
    return apply_wave(pt, v);
}

} // namespace pattern_detail

/// Classic turbulence displaces a pattern's point by its amount times the fractal vector noise
/// (POV-Ray's DTurbulence, whose length vturbulence gives), as POV-Ray displaces it, and
/// warp { turbulence } likewise. POV-Ray's marble, wood, agate and spirals instead bend their
/// bands by the scalar turbulence inside the pattern; Sheaf displaces their point by this
/// factor more, which bends them about as far.
constexpr float kBandTurbulenceScale = 4.0f;

SHEAF_HD_INLINE float turbulence_scale(PatternKind k) {
    return bends_by_own_turbulence(k) ? kBandTurbulenceScale : 1.0f;
}

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
    case WarpKind::Turbulence:
        return p + w.a * vector_turbulence(p, w.octaves, w.f[0], w.f[1]);
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
            const uint32_t h = lattice_hash(bx, by, bz, 0x6b1au);
            centre += Vec3(w.c.x * (2 * hash_unit(h) - 1),
                           w.c.y * (2 * hash_unit(lattice_hash(bx, by, bz, h)) - 1),
                           w.c.z * (2 * hash_unit(lattice_hash(bx, by, bz, h + 1)) - 1));
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
/// then its turbulence.
SHEAF_HD_NOINLINE Vec3 pattern_point(const Pattern& pt, Vec3 world, const Warp* warps) {
    Vec3 p = pt.to_pattern.point(world);
    for (uint32_t i = 0; warps && i < pt.warp_count; ++i) {
        const Warp& w = warps[pt.warp_first + i];
        p = w.to_inner.point(warp_point(w, p));
    }
    if (pt.has_turbulence)
        p += pt.turbulence * vector_turbulence(p, pt.octaves, pt.omega, pt.lambda) *
             turbulence_scale(pt.kind);
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

/// A list pattern's entry (0 .. entries-1) at pattern-space point p.
SHEAF_HD_NOINLINE int pattern_index_at(const Pattern& pt, Vec3 p) {
    using namespace pattern_detail;
    const float e = 1e-4f; // keeps faces lying on integer planes on one side
    switch (pt.kind) {
    case PatternKind::Checker:
        return imod(floor_int(p.x + e) + floor_int(p.y + e) + floor_int(p.z + e), 2);
    case PatternKind::Square:
        return imod(floor_int(p.x + e), 2) + 2 * imod(floor_int(p.z + e), 2);
    case PatternKind::Hexagon:
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
        const int hex = imod(int(rx) - int(rz), 3);
        if (pt.kind == PatternKind::Hexagon) return hex;
        // Six triangles per hexagon: the sector of the point around its hexagon's centre.
        const float hx = 1.5f * rx, hz = sqrtf(3.0f) * (rz + 0.5f * rx);
        const float a = hdm::atan2f(p.z - hz, p.x - hx) / (2.0f * kPi) + 0.5f;
        return imod(floor_int(a * 6.0f), 6);
    }
    case PatternKind::Brick: {
        const Vec3 size(pt.param[0] > 0 ? pt.param[0] : 8.0f, pt.param[1] > 0 ? pt.param[1] : 3.0f,
                        pt.param[2] > 0 ? pt.param[2] : 4.5f);
        const float mortar = pt.param[3] > 0 ? pt.param[3] : 0.5f;
        // Nudged as checker is, so a face lying on a course boundary takes one side.
        const Vec3 q = p + Vec3(e);
        const int course = floor_int(q.y / size.y);
        const float shift = (course & 1) ? 0.5f : 0.0f;
        const float fx = frac(q.x / size.x + shift) * size.x;
        const float fy = frac(q.y / size.y) * size.y;
        const float fz = frac(q.z / size.z + shift) * size.z;
        const float m = 0.5f * mortar;
        const bool in_mortar =
            fx < m || fx > size.x - m || fy < m || fy > size.y - m || fz < m || fz > size.z - m;
        return in_mortar ? 0 : 1;
    }
    default:
        return 0;
    }
}

} // namespace sheaf

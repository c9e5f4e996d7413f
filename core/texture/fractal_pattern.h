// The mandel, julia and magnet patterns (FractalParams in core/scene/pattern.h), as POV-Ray
// 3.7 computes them, in double precision.
// Checked value for value against povray renders of every interior and exterior type
// (fractal_pattern_test.cpp holds points of those renders).
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/pattern.h"

namespace sheaf {

namespace fractal_detail {

// The whole part of factor k as POV-Ray takes it for the modulo types, within 0 .. 2^32 - 2
// (a float beyond an unsigned's range has no defined conversion).
SHEAF_HD_INLINE unsigned whole(double k) {
    return k >= 1.0 ? (k < 4294967294.0 ? unsigned(k) : 4294967294u) : 0u;
}

// Types 2 to 5 of both: the real part of z = (a, b), its imaginary part, their squares.
SHEAF_HD_INLINE double part(int type, double a, double b) {
    return type == 2 ? a : type == 3 ? b : type == 4 ? a * a : b * b;
}

// The value of a point that escaped at step `step` with z = (a, b).
SHEAF_HD_INLINE double exterior(const FractalParams& f, int step, double a, double b) {
    const double k = f.exterior_factor;
    switch (f.exterior_type) {
    case 0:
        return k;
    case 1:
        return double(step) / double(f.iterations);
    case 2:
    case 3:
    case 4:
    case 5:
        return part(f.exterior_type, a, b) * k;
    case 6:
        return ::sqrt(a * a + b * b) * k;
    case 7: // the readers keep the factor at 1 or more
    case 8: { // and above 0
        const unsigned m = whole(k) + (f.exterior_type == 8 ? 1u : 0u);
        return m && k > 0 ? double(unsigned(step) % m) / k : 0.0;
    }
    }
    return 0.0;
}

// The value of a point that never escaped, z = (a, b) at the end, `least` its orbit's least
// |z|^2 (the point itself included).
SHEAF_HD_INLINE double interior(const FractalParams& f, double a, double b, double least) {
    const double k = f.interior_factor;
    switch (f.interior_type) {
    case 0:
        return k;
    case 1:
        return ::sqrt(least) * k;
    case 2:
    case 3:
    case 4:
    case 5:
        return part(f.interior_type, a, b) * k;
    case 6:
        return (a * a + b * b) * k;
    }
    return 0.0;
}

// The magnet patterns stop when |z|^2 passes this or z comes this close (squared) to 1.
constexpr double kMagnetBailout = 10000.0, kMagnetNearOne = 0.0001;

// (ar + i ai) / (br + i bi), squared, into (a, b); a zero divisor sends z far away.
SHEAF_HD_INLINE void divide_squared(double& a, double& b, double ar, double ai, double br,
                                    double bi) {
    const double d = br * br + bi * bi;
    if (!(d > 0)) { // a pole: infinitely far, which escapes
        a = 1.0e30, b = 0.0;
        return;
    }
    const double qr = (ar * br + ai * bi) / d, qi = (ai * br - ar * bi) / d;
    a = qr * qr - qi * qi;
    b = 2.0 * qr * qi;
}

// z -> ((z^2 + c - 1) / (2z + c - 2))^2
SHEAF_HD_INLINE void magnet1(double& a, double& b, double cr, double ci) {
    divide_squared(a, b, a * a - b * b + cr - 1.0, 2.0 * a * b + ci, 2.0 * a + cr - 2.0,
                   2.0 * b + ci);
}

// z -> ((z^3 + 3(c-1)z + (c-1)(c-2)) / (3z^2 + 3(c-2)z + (c-1)(c-2) + 1))^2
SHEAF_HD_INLINE void magnet2(double& a, double& b, double cr, double ci) {
    const double z2r = a * a - b * b, z2i = 2.0 * a * b;
    const double z3r = z2r * a - z2i * b, z3i = z2r * b + z2i * a;
    const double c1r = cr - 1.0, c2r = cr - 2.0; // c - 1, c - 2 (same imaginary ci)
    const double pr = c1r * c2r - ci * ci, pi = c1r * ci + ci * c2r; // (c-1)(c-2)
    const double nr = z3r + 3.0 * (c1r * a - ci * b) + pr;
    const double ni = z3i + 3.0 * (c1r * b + ci * a) + pi;
    const double dr = 3.0 * z2r + 3.0 * (c2r * a - ci * b) + pr + 1.0;
    const double di = 3.0 * z2i + 3.0 * (c2r * b + ci * a) + pi;
    divide_squared(a, b, nr, ni, dr, di);
}

// Within float's range, NaN as -1e30: the value wraps into [0, 1] afterwards.
SHEAF_HD_INLINE float to_float(double v) {
    if (!(v >= -1.0e30)) return -1.0e30f; // NaN too
    return v > 1.0e30 ? 1.0e30f : float(v);
}

} // namespace fractal_detail

/// The raw value of a mandel (julia: `julia` true) pattern at pattern-space point p, before
/// frequency, phase and the wave; exterior and interior types 2..8 leave [0, 1] and wrap.
SHEAF_HD_INLINE float fractal_value(const FractalParams& f, bool julia, Vec3 p) {
    using namespace fractal_detail;
    const double x = p.x, y = p.y;
    const double cr = julia ? double(f.c[0]) : x, ci = julia ? double(f.c[1]) : y;
    const bool magnet = f.magnet != 0;
    double a = x, b = y;
    // The orbit's least |z|^2 counts the start, except a magnet mandel's (which starts at 0).
    double least = a * a + b * b;
    if (magnet && !julia) a = b = 0, least = kMagnetBailout;
    const int n = f.iterations, power = f.exponent < 2 ? 2 : f.exponent;
    for (int step = 0; step < n; ++step) {
        if (f.magnet == 1) {
            magnet1(a, b, cr, ci);
        } else if (f.magnet == 2) {
            magnet2(a, b, cr, ci);
        } else {
            // z^power by repeated products (POV-Ray expands the binomial; both round alike
            // to well under a colour step).
            double zr = a, zi = b;
            for (int k = 1; k < power; ++k) {
                const double t = zr * a - zi * b;
                zi = zr * b + zi * a;
                zr = t;
            }
            a = zr + cr;
            b = zi + ci;
        }
        const double d2 = a * a + b * b;
        if (d2 < least) least = d2;
        // Written so that a NaN (an overflow far away) escapes too.
        const bool escaped =
            magnet ? !(d2 <= kMagnetBailout) || (a - 1.0) * (a - 1.0) + b * b < kMagnetNearOne
                   : !(d2 <= 4.0);
        if (escaped) return to_float(exterior(f, step, a, b));
    }
    return to_float(interior(f, a, b, least));
}

} // namespace sheaf

// Transcendental functions that give the same bits on the CPU and on the GPU. The C library's
// sinf, powf, atan2f … and CUDA's are each accurate to an ulp or so, but not correctly
// rounded, so they differ in the last bit on some inputs; a frame that must match bit for
// bit between backends (images and every count: ray hash keys come from acos and atan2)
// cannot call them from shared code. These are built from IEEE double operations only
// (+ - * /, sqrt, floor, fmod, frexp, ldexp: exact or correctly rounded on both sides, with
// nvcc's --fmad=false and no FMA contraction on the host), range reduction and truncated
// series that are accurate to about 1e-16 relative in double; the float versions round that
// result once. Accuracy: within an ulp of the C library (tested in hd_math_test.cpp).
#pragma once

#include "core/base/device.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace sheaf::hdm {

/// Minimum and maximum of floats by comparison, the same bits on the host and the device:
/// std::fminf/fmaxf may return either zero for +0 and -0 (glibc and the GPU's min and max
/// instructions need not agree). A NaN argument gives the other one, as fminf/fmaxf do.
SHEAF_HD_INLINE float fminf(float a, float b) {
    return (b < a || a != a) ? b : a;
}
SHEAF_HD_INLINE float fmaxf(float a, float b) {
    return (a < b || a != a) ? b : a;
}

/// floor(v) as an int, defined everywhere: a float to int conversion out of range is undefined
/// in C++ (x86 gives INT_MIN, the GPU saturates, and NaN gives 0 there), so NaN and values
/// beyond 2^30 give 0 on both sides, with room left for the lattice offsets callers add.
SHEAF_HD_INLINE int floor_int(float v) {
    const float f = ::floorf(v);
    return f >= -1073741824.0f && f <= 1073741824.0f ? int(f) : 0;
}

namespace detail {

constexpr double kPiO2Hi = 1.5707963267341256;    // pi/2, first 33 bits
constexpr double kPiO2Lo = 6.077100506506192e-11; // pi/2 - kPiO2Hi
constexpr double kTwoOverPi = 0.6366197723675814;
constexpr double kTwoPi = 6.283185307179586;
constexpr double kPi = 3.141592653589793;
constexpr double kPiO2 = 1.5707963267948966;
constexpr double kPiO6 = 0.5235987755982988;
constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kLn2Hi = 0.6931471803691238; // ln 2, first 32 bits
constexpr double kLn2Lo = 1.9082149292705877e-10;
constexpr double kLog2E = 1.4426950408889634;
constexpr double kLn2 = 0.6931471805599453;

SHEAF_HD_INLINE double nan_value() {
    return std::numeric_limits<double>::quiet_NaN();
}
SHEAF_HD_INLINE double inf_value() {
    return std::numeric_limits<double>::infinity();
}
SHEAF_HD_INLINE bool negative_sign(double x) {
    return x < 0 || (x == 0 && 1.0 / x < 0);
}

/// ldexp(p, k) for p in [0.5, 2): on the host, where the result is a normal number, p times
/// 2^k made from its bits (exact, so ldexp's result), without the library call.
SHEAF_HD_INLINE double ldexp_unit(double p, int k) {
#ifndef __CUDA_ARCH__
    if (k >= -1021 && k <= 1022) {
        const unsigned long long bits = static_cast<unsigned long long>(k + 1023) << 52;
        double scale;
        std::memcpy(&scale, &bits, sizeof scale);
        return p * scale;
    }
#endif
    return ::ldexp(p, k);
}

/// frexp(x, &e) for positive finite x: on the host, for a normal x, from its bits.
SHEAF_HD_INLINE double frexp_positive(double x, int* e) {
#ifndef __CUDA_ARCH__
    unsigned long long bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int field = int(bits >> 52) & 0x7FF;
    if (field != 0) {
        *e = field - 1022;
        bits = (bits & 0x800FFFFFFFFFFFFFull) | (1022ull << 52);
        double m;
        std::memcpy(&m, &bits, sizeof m);
        return m;
    }
#endif
    return ::frexp(x, e);
}

/// sin r and cos r for |r| <= pi/4 (Taylor series to r^17 and r^18: error below 1e-16).
SHEAF_HD_INLINE double sin_kernel(double r) {
    const double z = r * r;
    return r + r * z *
                   (-0.16666666666666666 +
                    z * (0.008333333333333333 +
                         z * (-0.0001984126984126984 +
                              z * (2.7557319223985893e-06 +
                                   z * (-2.505210838544172e-08 +
                                        z * (1.6059043836821613e-10 +
                                             z * (-7.647163731819816e-13 +
                                                  z * 2.8114572543455206e-15)))))));
}
SHEAF_HD_INLINE double cos_kernel(double r) {
    const double z = r * r;
    return 1.0 + z * (-0.5 + z * (0.041666666666666664 +
                                  z * (-0.001388888888888889 +
                                       z * (2.48015873015873e-05 +
                                            z * (-2.755731922398589e-07 +
                                                 z * (2.08767569878681e-09 +
                                                      z * (-1.1470745597729725e-11 +
                                                           z * (4.779477332387385e-14 +
                                                                z * -1.5619206968586225e-16))))))));
}

/// x = k pi/2 + r with |r| <= about pi/4; returns r, *quadrant = k mod 4.
/// Below 10^6, k < 2^20 and k * kPiO2Hi is exact; above, fmod (exact) brings x down first.
SHEAF_HD_INLINE double reduce_half_pi(double x, int* quadrant) {
    if (!(::fabs(x) < 1e6)) x = ::fmod(x, kTwoPi); // infinities become NaN
    if (x != x) {
        *quadrant = 0;
        return x;
    }
    const double k = ::floor(x * kTwoOverPi + 0.5);
    *quadrant = int(static_cast<long long>(k) & 3);
    return (x - k * kPiO2Hi) - k * kPiO2Lo;
}

/// atan t for 0 <= t <= 1.
SHEAF_HD_INLINE double atan_unit(double t) {
    double base = 0.0;
    if (t > 0.2679491924311227) { // tan(pi/12): atan t = pi/6 + atan((t sqrt3 - 1) / (t + sqrt3))
        t = (t * kSqrt3 - 1.0) / (t + kSqrt3);
        base = kPiO6;
    }
    const double z = t * t; // |t| <= 0.268: terms beyond t^31 are below 1e-18
    const double s =
        t +
        t * z *
            (-0.3333333333333333 +
             z * (0.2 +
                  z * (-0.14285714285714285 +
                       z * (0.1111111111111111 +
                            z * (-0.09090909090909091 +
                                 z * (0.07692307692307693 +
                                      z * (-0.06666666666666667 +
                                           z * (0.058823529411764705 +
                                                z * (-0.05263157894736842 +
                                                     z * (0.047619047619047616 +
                                                          z * (-0.043478260869565216 +
                                                               z * (0.04 +
                                                                    z * (-0.037037037037037035 +
                                                                         z * (0.034482758620689655 +
                                                                              z * -0.03225806451612903))))))))))))));
    return base + s;
}

} // namespace detail

SHEAF_HD_INLINE double sin(double x) {
    int q;
    const double r = detail::reduce_half_pi(x, &q);
    switch (q) {
    case 0:
        return detail::sin_kernel(r);
    case 1:
        return detail::cos_kernel(r);
    case 2:
        return -detail::sin_kernel(r);
    default:
        return -detail::cos_kernel(r);
    }
}

SHEAF_HD_INLINE double cos(double x) {
    int q;
    const double r = detail::reduce_half_pi(x, &q);
    switch (q) {
    case 0:
        return detail::cos_kernel(r);
    case 1:
        return -detail::sin_kernel(r);
    case 2:
        return -detail::cos_kernel(r);
    default:
        return detail::sin_kernel(r);
    }
}

SHEAF_HD_INLINE double tan(double x) {
    int q;
    const double r = detail::reduce_half_pi(x, &q);
    const double s = detail::sin_kernel(r), c = detail::cos_kernel(r);
    return (q & 1) ? -c / s : s / c;
}

/// atan2 with the C library's special cases (signed zeros, infinities, NaN).
SHEAF_HD_INLINE double atan2(double y, double x) {
    if (x != x || y != y) return detail::nan_value();
    const double ax = ::fabs(x), ay = ::fabs(y);
    double r;
    if (ay == 0.0)
        r = 0.0;
    else if (ax == detail::inf_value() && ay == detail::inf_value())
        r = 0.25 * detail::kPi;
    else if (ay <= ax)
        r = detail::atan_unit(ay / ax);
    else
        r = detail::kPiO2 - detail::atan_unit(ax / ay);
    if (detail::negative_sign(x)) r = detail::kPi - r;
    return detail::negative_sign(y) ? -r : r;
}

SHEAF_HD_INLINE double atan(double t) {
    return atan2(t, 1.0);
}

/// asin and acos through atan2 of the sine and cosine sides; NaN outside [-1, 1].
SHEAF_HD_INLINE double asin(double x) {
    return atan2(x, ::sqrt((1.0 - x) * (1.0 + x)));
}
SHEAF_HD_INLINE double acos(double x) {
    return atan2(::sqrt((1.0 - x) * (1.0 + x)), x);
}

SHEAF_HD_INLINE double exp(double x) {
    if (x != x) return x;
    if (x > 709.8) return detail::inf_value();
    if (x < -745.2) return 0.0;
    const double k = ::floor(x * detail::kLog2E + 0.5);
    const double r = (x - k * detail::kLn2Hi) - k * detail::kLn2Lo; // |r| <= 0.35
    const double p =
        1.0 +
        r * (1.0 +
             r * (0.5 +
                  r * (0.16666666666666666 +
                       r * (0.041666666666666664 +
                            r * (0.008333333333333333 +
                                 r * (0.001388888888888889 +
                                      r * (0.0001984126984126984 +
                                           r * (2.48015873015873e-05 +
                                                r * (2.7557319223985893e-06 +
                                                     r * (2.755731922398589e-07 +
                                                          r * (2.505210838544172e-08 +
                                                               r * (2.08767569878681e-09 +
                                                                    r * (1.6059043836821613e-10 +
                                                                         r * 1.1470745597729725e-11)))))))))))));
    return detail::ldexp_unit(p, int(k));
}

SHEAF_HD_INLINE double log(double x) {
    if (x != x || x < 0) return detail::nan_value();
    if (x == 0) return -detail::inf_value();
    if (x == detail::inf_value()) return x;
    int e;
    double m = detail::frexp_positive(x, &e); // [0.5, 1)
    if (m < 0.7071067811865476) m *= 2.0, e -= 1;
    const double s = (m - 1.0) / (m + 1.0); // |s| <= 0.1716
    const double z = s * s;
    const double series =
        2.0 * s *
        (1.0 +
         z * (0.3333333333333333 +
              z * (0.2 +
                   z * (0.14285714285714285 +
                        z * (0.1111111111111111 +
                             z * (0.09090909090909091 +
                                  z * (0.07692307692307693 +
                                       z * (0.06666666666666667 +
                                            z * (0.058823529411764705 +
                                                 z * (0.05263157894736842 +
                                                      z * (0.047619047619047616 +
                                                           z * 0.043478260869565216)))))))))));
    return double(e) * detail::kLn2Hi + (double(e) * detail::kLn2Lo + series);
}

SHEAF_HD_INLINE double log2(double x) {
    return log(x) * detail::kLog2E;
}
SHEAF_HD_INLINE double exp2(double x) {
    if (!(::fabs(x) < 2000.0)) return x != x ? x : x > 0 ? detail::inf_value() : 0.0;
    const double k = ::floor(x + 0.5); // x = k + f exactly, |f| <= 1/2
    return detail::ldexp_unit(exp((x - k) * detail::kLn2), int(k));
}

/// x^y with the C library's special cases for y = 0, x = 1, zero, negative and infinite x
/// (the sign of a zero x is not kept). Not recursive: these functions are force-inlined.
SHEAF_HD_INLINE double pow(double x, double y) {
    if (y == 0.0 || x == 1.0) return 1.0;
    if (x != x || y != y) return detail::nan_value();
    const double ay = ::fabs(y);
    bool negate = false;
    if (x < 0) {
        if (::floor(y) != y) return detail::nan_value(); // a non-integer power of a negative
        negate = ay < 9007199254740992.0 && ::fmod(ay, 2.0) == 1.0;
        x = -x;
    }
    double r;
    if (x == 0)
        r = y > 0 ? 0.0 : detail::inf_value();
    else if (x == detail::inf_value())
        r = y > 0 ? x : 0.0;
    else if (x == 1.0)
        r = 1.0;
    else if (ay == detail::inf_value())
        r = (x > 1.0) == (y > 0) ? detail::inf_value() : 0.0;
    else
        r = exp(y * log(x));
    return negate ? -r : r;
}

// Float versions: the double result rounded once.
SHEAF_HD_INLINE float sinf(float x) {
    return float(sin(double(x)));
}
SHEAF_HD_INLINE float cosf(float x) {
    return float(cos(double(x)));
}
SHEAF_HD_INLINE float tanf(float x) {
    return float(tan(double(x)));
}
SHEAF_HD_INLINE float atan2f(float y, float x) {
    return float(atan2(double(y), double(x)));
}
SHEAF_HD_INLINE float asinf(float x) {
    return float(asin(double(x)));
}
SHEAF_HD_INLINE float acosf(float x) {
    return float(acos(double(x)));
}
SHEAF_HD_INLINE float expf(float x) {
    return float(exp(double(x)));
}
SHEAF_HD_INLINE float powf(float x, float y) {
    return float(pow(double(x), double(y)));
}

} // namespace sheaf::hdm

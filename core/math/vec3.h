// Three-component float vectors, usable on host and device.
#pragma once

#include "core/base/device.h"
#include "core/math/hd_math.h"

#include <cmath>

namespace sheaf {

struct Vec3 {
    float x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    SHEAF_HD constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    SHEAF_HD constexpr explicit Vec3(float s) : x(s), y(s), z(s) {}

    SHEAF_HD constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    SHEAF_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

SHEAF_HD_INLINE Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
SHEAF_HD_INLINE Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
SHEAF_HD_INLINE Vec3 operator-(Vec3 a) {
    return {-a.x, -a.y, -a.z};
}
SHEAF_HD_INLINE Vec3 operator*(Vec3 a, Vec3 b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
SHEAF_HD_INLINE Vec3 operator*(Vec3 a, float s) {
    return {a.x * s, a.y * s, a.z * s};
}
SHEAF_HD_INLINE Vec3 operator*(float s, Vec3 a) {
    return {a.x * s, a.y * s, a.z * s};
}
SHEAF_HD_INLINE Vec3 operator/(Vec3 a, float s) {
    return a * (1.0f / s);
}
SHEAF_HD_INLINE Vec3& operator+=(Vec3& a, Vec3 b) {
    return a = a + b;
}
SHEAF_HD_INLINE Vec3& operator-=(Vec3& a, Vec3 b) {
    return a = a - b;
}
SHEAF_HD_INLINE Vec3& operator*=(Vec3& a, float s) {
    return a = a * s;
}
SHEAF_HD_INLINE bool operator==(Vec3 a, Vec3 b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

SHEAF_HD_INLINE float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
SHEAF_HD_INLINE Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
SHEAF_HD_INLINE float length_squared(Vec3 a) {
    return dot(a, a);
}
SHEAF_HD_INLINE float length(Vec3 a) {
    return sqrtf(dot(a, a));
}
SHEAF_HD_INLINE Vec3 normalize(Vec3 a) {
    float l = length(a);
    return l > 0 ? a / l : Vec3(0, 0, 0);
}
SHEAF_HD_INLINE Vec3 vmin(Vec3 a, Vec3 b) {
    return {hdm::fminf(a.x, b.x), hdm::fminf(a.y, b.y), hdm::fminf(a.z, b.z)};
}
SHEAF_HD_INLINE Vec3 vmax(Vec3 a, Vec3 b) {
    return {hdm::fmaxf(a.x, b.x), hdm::fmaxf(a.y, b.y), hdm::fmaxf(a.z, b.z)};
}
SHEAF_HD_INLINE Vec3 vabs(Vec3 a) {
    return Vec3(::fabsf(a.x), ::fabsf(a.y), ::fabsf(a.z));
}
SHEAF_HD_INLINE float max_component(Vec3 a) {
    return hdm::fmaxf(a.x, hdm::fmaxf(a.y, a.z));
}
SHEAF_HD_INLINE bool is_finite(Vec3 a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// Mirror reflection of incoming direction d about normal n (both unit).
SHEAF_HD_INLINE Vec3 reflect(Vec3 d, Vec3 n) {
    return d - n * (2.0f * dot(d, n));
}

/// Angle between two unit vectors, robust near 0 and pi.
SHEAF_HD_INLINE float angle_between(Vec3 a, Vec3 b) {
    // atan2 of |a x b| and a.b is accurate everywhere, unlike acos of the dot product.
    return hdm::atan2f(length(cross(a, b)), dot(a, b));
}

constexpr float kPi = 3.14159265358979323846f;

} // namespace sheaf

// Double-precision vectors for the computations that need the headroom (minimal spheres) and
// for the tests' reference implementations.
#pragma once

#include "core/math/vec3.h"

#include <cmath>

namespace sheaf {

struct Vec3d {
    double x = 0, y = 0, z = 0;
};

inline Vec3d to_double(Vec3 v) {
    return {v.x, v.y, v.z};
}
inline Vec3d operator+(Vec3d a, Vec3d b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3d operator-(Vec3d a, Vec3d b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3d operator*(Vec3d a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline double dot(Vec3d a, Vec3d b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3d cross(Vec3d a, Vec3d b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3d a) {
    return std::sqrt(dot(a, a));
}
inline double distance(Vec3d a, Vec3d b) {
    return length(a - b);
}

} // namespace sheaf

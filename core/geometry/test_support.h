// Random inputs shared by the geometry tests (test code only).
#pragma once

#include "core/math/vec3d.h"

#include <random>

namespace sheaf::test {

/// A uniformly distributed unit vector (normalised in double precision).
inline Vec3 random_unit(std::mt19937& g) {
    std::normal_distribution<double> n;
    for (;;) {
        const Vec3d v{n(g), n(g), n(g)};
        const double l = length(v);
        if (l > 1e-3) return Vec3(float(v.x / l), float(v.y / l), float(v.z / l));
    }
}

/// A point uniformly distributed in the cube [-extent, extent]^3.
inline Vec3 random_point(std::mt19937& g, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    return Vec3(u(g), u(g), u(g));
}

/// A unit direction at angle `theta` from `axis`, random azimuth, computed in double.
inline Vec3 direction_at(Vec3 axis, double theta, std::mt19937& g) {
    const Vec3d a = to_double(axis) * (1.0 / length(to_double(axis)));
    Vec3d t{0, 0, 0};
    (std::fabs(a.x) < 0.6 ? t.x : (std::fabs(a.y) < 0.6 ? t.y : t.z)) = 1;
    Vec3d u = t - a * dot(t, a);
    u = u * (1.0 / length(u));
    const Vec3d w = cross(a, u);
    const double psi = std::uniform_real_distribution<double>(0, 2 * M_PI)(g);
    const Vec3d o = a * std::cos(theta) + (u * std::cos(psi) + w * std::sin(psi)) * std::sin(theta);
    return Vec3(float(o.x), float(o.y), float(o.z));
}

} // namespace sheaf::test

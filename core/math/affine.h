// Affine transforms (3x4, row-major): the placement of an object in the world.
#pragma once

#include "core/math/vec3.h"

namespace sheaf {

struct Affine {
    // Rows of the 3x4 matrix [R | t]; a point p maps to R p + t.
    float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    static Affine identity() { return {}; }
    static Affine translate(Vec3 t) {
        Affine a;
        a.m[0][3] = t.x, a.m[1][3] = t.y, a.m[2][3] = t.z;
        return a;
    }
    static Affine scale(Vec3 s) {
        Affine a;
        a.m[0][0] = s.x, a.m[1][1] = s.y, a.m[2][2] = s.z;
        return a;
    }
    /// Rotation about a unit axis by an angle in radians (right-handed).
    static Affine rotate(Vec3 axis, float radians) {
        const Vec3 u = normalize(axis);
        const float c = cosf(radians), s = sinf(radians), k = 1 - c;
        Affine a;
        a.m[0][0] = c + u.x * u.x * k, a.m[0][1] = u.x * u.y * k - u.z * s,
        a.m[0][2] = u.x * u.z * k + u.y * s;
        a.m[1][0] = u.y * u.x * k + u.z * s, a.m[1][1] = c + u.y * u.y * k,
        a.m[1][2] = u.y * u.z * k - u.x * s;
        a.m[2][0] = u.z * u.x * k - u.y * s, a.m[2][1] = u.z * u.y * k + u.x * s,
        a.m[2][2] = c + u.z * u.z * k;
        return a;
    }

    SHEAF_HD Vec3 point(Vec3 p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    SHEAF_HD Vec3 vector(Vec3 v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// Normals transform by the inverse transpose of the linear part.
    Vec3 normal(Vec3 n) const;
    float determinant() const;
    /// Whether every entry is a finite number (no NaN or infinity).
    bool finite() const;
    /// The inverse transform (the matrix must not be singular).
    Affine inverse() const;
    /// The inverse transpose of the linear part, as an Affine with no translation: what
    /// normals transform by (not normalised).
    Affine normal_matrix() const;
    /// The largest factor by which the transform stretches a length (its largest singular value).
    float max_scale() const;
};

/// a * b: first b, then a.
Affine operator*(const Affine& a, const Affine& b);

} // namespace sheaf

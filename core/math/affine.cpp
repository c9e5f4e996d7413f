#include "core/math/affine.h"

namespace sheaf {

float Affine::determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Vec3 Affine::normal(Vec3 n) const {
    // Cofactor matrix = det * inverse transpose; the scale does not matter for a direction.
    const Vec3 r0(m[0][0], m[0][1], m[0][2]), r1(m[1][0], m[1][1], m[1][2]),
        r2(m[2][0], m[2][1], m[2][2]);
    const Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    // The inverse has columns c0, c1, c2 (over det), so its transpose has them as rows.
    Vec3 out(dot(c0, n), dot(c1, n), dot(c2, n));
    if (determinant() < 0) out = -out;
    return normalize(out);
}

Affine operator*(const Affine& a, const Affine& b) {
    Affine r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            float s = (j == 3) ? a.m[i][3] : 0.0f;
            for (int k = 0; k < 3; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    }
    return r;
}

} // namespace sheaf

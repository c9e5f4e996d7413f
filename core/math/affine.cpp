#include "core/math/affine.h"

#include <algorithm>
#include <cmath>

namespace sheaf {

float Affine::determinant() const {
    // In double: with float products, entries above about 1e13 overflow to infinity and
    // 0 * infinity makes the determinant NaN, so a large but regular transform looked singular.
    const auto e = [this](int i, int j) { return double(m[i][j]); };
    return float(e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1)) -
                 e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0)) +
                 e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0)));
}

bool Affine::finite() const {
    for (const auto& row : m)
        for (float v : row)
            if (!std::isfinite(v)) return false;
    return true;
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

Affine Affine::inverse() const {
    // Rows of the inverse of the linear part are the cofactor columns over the determinant.
    const Vec3 r0(m[0][0], m[0][1], m[0][2]), r1(m[1][0], m[1][1], m[1][2]),
        r2(m[2][0], m[2][1], m[2][2]);
    const Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    const float inv_det = 1.0f / dot(r0, c0);
    Affine out;
    for (int j = 0; j < 3; ++j) {
        out.m[j][0] = c0[j] * inv_det;
        out.m[j][1] = c1[j] * inv_det;
        out.m[j][2] = c2[j] * inv_det;
    }
    const Vec3 t(m[0][3], m[1][3], m[2][3]);
    const Vec3 it = out.vector(t);
    out.m[0][3] = -it.x, out.m[1][3] = -it.y, out.m[2][3] = -it.z;
    return out;
}

Affine Affine::normal_matrix() const {
    const Affine inv = inverse();
    Affine out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out.m[i][j] = inv.m[j][i];
    out.m[0][3] = out.m[1][3] = out.m[2][3] = 0;
    return out;
}

float Affine::max_scale() const {
    // Largest eigenvalue of the symmetric M^T M by Jacobi rotations, in double precision.
    double a[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) s += double(m[k][i]) * m[k][j];
            a[i][j] = s;
        }
    // Gershgorin's bound (no eigenvalue exceeds a row's diagonal plus its other entries'
    // magnitudes) where it is as tight as the answer needs: a rotation and a uniform scale
    // leave only rounding off the diagonal. That is most objects' transform, and Jacobi's
    // rotations (an atan2, a sine and a cosine each) were a tenth of reading a scene of many
    // rotated objects (advanced/abyss.pov).
    double diag = 0, bound = 0;
    for (int i = 0; i < 3; ++i) {
        double row = a[i][i];
        for (int j = 0; j < 3; ++j)
            if (j != i) row += std::fabs(a[i][j]);
        diag = std::max(diag, a[i][i]);
        bound = std::max(bound, row);
    }
    if (bound - diag <= 1e-9 * diag) return float(std::sqrt(bound) * (1 + 1e-6));
    for (int sweep = 0; sweep < 32; ++sweep) {
        double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
        if (off < 1e-300) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::fabs(a[p][q]) < 1e-300) continue;
                const double theta = 0.5 * std::atan2(2 * a[p][q], a[q][q] - a[p][p]);
                const double c = std::cos(theta), s = std::sin(theta);
                for (int k = 0; k < 3; ++k) { // columns
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) { // rows
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
                }
            }
    }
    const double e = std::max({a[0][0], a[1][1], a[2][2], 0.0});
    return float(std::sqrt(e) * (1 + 1e-6));
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

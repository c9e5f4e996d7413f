// Affine transforms: points, vectors and normals against double-precision references.
#include "core/geometry/test_support.h"
#include "core/math/affine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sheaf {
namespace {

using test::direction_at;
using test::random_point;
using test::random_unit;

void expect_vec_near(Vec3 a, Vec3 b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// A random product of rotations, scales (non-uniform, sometimes mirroring) and translations.
Affine random_affine(std::mt19937& g) {
    std::uniform_real_distribution<float> u(0, 1);
    Affine a;
    const int steps = 1 + int(g() % 4);
    for (int i = 0; i < steps; ++i) {
        switch (g() % 3) {
        case 0:
            a = Affine::rotate(random_unit(g), u(g) * 7 - 3.5f) * a;
            break;
        case 1: {
            Vec3 s(0.1f + 4 * u(g), 0.1f + 4 * u(g), 0.1f + 4 * u(g));
            if (g() % 4 == 0) s.y = -s.y; // mirror
            a = Affine::scale(s) * a;
            break;
        }
        default:
            a = Affine::translate(random_point(g, 10)) * a;
        }
    }
    return a;
}

// Reference linear part and inverse transpose, in double.
struct Mat3d {
    double m[3][3];
};
Mat3d linear(const Affine& a) {
    Mat3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j];
    return r;
}
Mat3d inverse_transpose(const Mat3d& a) {
    const auto& m = a.m;
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3d inv; // inverse = adjugate / det; its transpose is the cofactor matrix / det
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            inv.m[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
        }
    return inv;
}
Vec3 apply(const Mat3d& a, Vec3 v) {
    double o[3];
    for (int i = 0; i < 3; ++i) o[i] = a.m[i][0] * v.x + a.m[i][1] * v.y + a.m[i][2] * v.z;
    return Vec3(float(o[0]), float(o[1]), float(o[2]));
}

TEST(Affine, Identity) {
    const Affine a = Affine::identity();
    const Vec3 p(1, -2, 3);
    EXPECT_EQ(a.point(p), p);
    EXPECT_EQ(a.vector(p), p);
    expect_vec_near(a.normal(Vec3(0, 0, 2)), Vec3(0, 0, 1), 0);
    EXPECT_EQ(a.determinant(), 1.0f);
}

TEST(Affine, Translate) {
    const Affine t = Affine::translate(Vec3(1, 2, 3));
    EXPECT_EQ(t.point(Vec3(1, 1, 1)), Vec3(2, 3, 4));
    EXPECT_EQ(t.vector(Vec3(1, 1, 1)), Vec3(1, 1, 1)); // directions do not move
    expect_vec_near(t.normal(Vec3(0, 1, 0)), Vec3(0, 1, 0), 1e-7f);
    EXPECT_EQ(t.determinant(), 1.0f);
}

// Entries near float's range: the determinant is large (infinite past float's range), never
// NaN, so a large regular transform is not taken for a singular one.
TEST(Affine, DeterminantOfLargeScalesIsNotNaN) {
    EXPECT_FLOAT_EQ(Affine::scale(Vec3(1e12f)).determinant(), 1e36f);
    const float big = Affine::scale(Vec3(1e20f)).determinant();
    EXPECT_FALSE(std::isnan(big));
    EXPECT_GT(big, 1.0f);
    EXPECT_LT(Affine::scale(Vec3(-1e20f, 1e20f, 1e20f)).determinant(), -1.0f);
}

TEST(Affine, Scale) {
    const Affine s = Affine::scale(Vec3(2, 3, 4));
    EXPECT_EQ(s.point(Vec3(1, 1, 1)), Vec3(2, 3, 4));
    EXPECT_EQ(s.vector(Vec3(1, -1, 0.5f)), Vec3(2, -3, 2));
    EXPECT_FLOAT_EQ(s.determinant(), 24.0f);
    // Normals scale by the inverse: (1, 1, 0) becomes (1/2, 1/3, 0), normalised.
    const Vec3 n = s.normal(normalize(Vec3(1, 1, 0)));
    expect_vec_near(n, normalize(Vec3(0.5f, 1.0f / 3, 0)), 1e-6f);
    // A mirror keeps the normal on the same side of the (mirrored) surface.
    const Affine m = Affine::scale(Vec3(-1, 1, 1));
    expect_vec_near(m.normal(Vec3(1, 0, 0)), Vec3(-1, 0, 0), 1e-7f);
    expect_vec_near(m.normal(Vec3(0, 1, 0)), Vec3(0, 1, 0), 1e-7f);
    EXPECT_FLOAT_EQ(m.determinant(), -1.0f);
}

TEST(Affine, Rotate) {
    const Affine r = Affine::rotate(Vec3(0, 0, 1), float(M_PI / 2));
    expect_vec_near(r.point(Vec3(1, 0, 0)), Vec3(0, 1, 0), 1e-6f); // right-handed
    expect_vec_near(r.point(Vec3(0, 1, 0)), Vec3(-1, 0, 0), 1e-6f);
    expect_vec_near(r.point(Vec3(0, 0, 5)), Vec3(0, 0, 5), 1e-6f);
    expect_vec_near(r.normal(Vec3(1, 0, 0)), Vec3(0, 1, 0), 1e-6f);
    EXPECT_NEAR(r.determinant(), 1.0f, 1e-6f);
    // The axis need not be unit length.
    const Affine rx = Affine::rotate(Vec3(3, 0, 0), float(M_PI / 2));
    expect_vec_near(rx.point(Vec3(0, 1, 0)), Vec3(0, 0, 1), 1e-6f);

    std::mt19937 g(601);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 axis = random_unit(g);
        const float angle = std::uniform_real_distribution<float>(-7, 7)(g);
        const Affine a = Affine::rotate(axis, angle);
        const Vec3 p = random_point(g, 5), q = random_point(g, 5);
        // Lengths, dot products and the axis are preserved; det 1; normals rotate like vectors.
        EXPECT_NEAR(length(a.point(p)), length(p), 1e-4f);
        EXPECT_NEAR(dot(a.vector(p), a.vector(q)), dot(p, q), 1e-3f);
        expect_vec_near(a.vector(axis), axis, 1e-5f);
        EXPECT_NEAR(a.determinant(), 1.0f, 1e-5f);
        expect_vec_near(a.normal(normalize(p)), normalize(a.vector(p)), 1e-5f);
        // Rotating back undoes it.
        expect_vec_near((Affine::rotate(axis, -angle) * a).point(p), p, 1e-4f);
        // The angle between p's projection off the axis and its image is |angle| mod 2 pi.
        const Vec3 pp = p - axis * dot(p, axis);
        if (length(pp) > 0.1f) {
            const float turned = angle_between(normalize(pp), normalize(a.vector(pp)));
            const float expected = std::fabs(std::remainder(angle, float(2 * M_PI)));
            EXPECT_NEAR(turned, expected, 1e-3f);
            // Right-handed: the turn is counter-clockwise seen from the axis' tip.
            if (expected > 0.05f && expected < 3.09f) {
                EXPECT_GT(dot(cross(pp, a.vector(pp)), axis) *
                              std::remainder(angle, float(2 * M_PI)),
                          0.0f);
            }
        }
    }
}

// a * b applies b first, then a; the product matches applying both, for points, vectors,
// normals and the determinant.
TEST(Affine, Products) {
    const Affine t = Affine::translate(Vec3(1, 0, 0)), s = Affine::scale(Vec3(2, 2, 2));
    EXPECT_EQ((t * s).point(Vec3(1, 1, 1)), Vec3(3, 2, 2)); // scale, then translate
    EXPECT_EQ((s * t).point(Vec3(1, 1, 1)), Vec3(4, 2, 2)); // translate, then scale

    std::mt19937 g(602);
    for (int k = 0; k < 2000; ++k) {
        const Affine a = random_affine(g), b = random_affine(g), c = random_affine(g);
        const Affine ab = a * b;
        const Vec3 p = random_point(g, 5), v = random_point(g, 1);
        const float tol = 1e-4f * (1 + length(a.point(b.point(p))));
        expect_vec_near(ab.point(p), a.point(b.point(p)), tol);
        expect_vec_near(ab.vector(v), a.vector(b.vector(v)),
                        1e-4f * (1 + length(a.vector(b.vector(v)))));
        const Vec3 n = random_unit(g);
        expect_vec_near(ab.normal(n), a.normal(b.normal(n)), 2e-3f);
        EXPECT_NEAR(ab.determinant(), a.determinant() * b.determinant(),
                    1e-4f * (1 + std::fabs(a.determinant() * b.determinant())));
        // Associative.
        expect_vec_near(((a * b) * c).point(p), (a * (b * c)).point(p), tol * 10 + 1e-3f);
    }
}

// The normal stays perpendicular to every transformed tangent, also under non-uniform scale
// and mirrors, and it is the inverse transpose, pointing to the same side as before:
// n' . (M v) has the sign of n . v for every v.
TEST(Affine, NormalsStayPerpendicular) {
    std::mt19937 g(603);
    for (int k = 0; k < 5000; ++k) {
        const Affine a = random_affine(g);
        const Vec3 n = random_unit(g);
        Vec3 t1 = normalize(cross(n, random_unit(g)));
        const Vec3 t2 = cross(n, t1);
        const Vec3 nn = a.normal(n);
        ASSERT_NEAR(length(nn), 1.0f, 1e-5f);
        for (Vec3 t : {t1, t2, normalize(t1 + t2 * 0.3f)}) {
            const Vec3 tt = normalize(a.vector(t));
            EXPECT_NEAR(dot(nn, tt), 0.0f, 1e-3f);
        }
        // Matches the double-precision inverse transpose.
        expect_vec_near(nn, normalize(apply(inverse_transpose(linear(a)), n)), 1e-3f);
        // Same side.
        const Vec3 v = random_unit(g);
        if (std::fabs(dot(n, v)) > 0.05f) {
            EXPECT_GT(dot(nn, a.vector(v)) * dot(n, v), 0.0f);
        }
        // The normal does not depend on the translation.
        const Affine moved = Affine::translate(random_point(g, 100)) * a;
        expect_vec_near(moved.normal(n), nn, 1e-5f);
    }
    // A concrete case: the plane x + y = 0 squashed by x * 4.
    const Affine s = Affine::scale(Vec3(4, 1, 1));
    const Vec3 n = s.normal(normalize(Vec3(1, 1, 0)));
    const Vec3 t = s.vector(Vec3(1, -1, 0));
    EXPECT_NEAR(dot(n, t), 0.0f, 1e-6f);
    EXPECT_GT(n.y, n.x);
}

// max_scale bounds how far the transform stretches any vector, and is no looser than its
// padding: on random products (Jacobi's path) and on rotations with a uniform scale
// (Gershgorin's bound, exact there but for rounding).
TEST(Affine, MaxScaleBoundsTheStretchTightly) {
    std::mt19937 g(604);
    std::uniform_real_distribution<float> u(0, 1);
    for (int k = 0; k < 4000; ++k) {
        const bool uniform = k % 2 == 1;
        Affine a = random_affine(g);
        if (uniform)
            a = Affine::scale(Vec3(0.01f + 50 * u(g))) *
                Affine::rotate(random_unit(g), u(g) * 7 - 3.5f) *
                Affine::rotate(random_unit(g), u(g) * 7 - 3.5f);
        const float bound = a.max_scale();
        double most = 0; // the stretch of many directions, in double
        for (int d = 0; d < 200; ++d) {
            const Vec3 v = random_unit(g);
            double o[3];
            for (int i = 0; i < 3; ++i)
                o[i] = double(a.m[i][0]) * v.x + double(a.m[i][1]) * v.y + double(a.m[i][2]) * v.z;
            const double len = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) /
                               std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
            ASSERT_LE(len, double(bound)) << k;
            most = std::max(most, len);
        }
        // Sampled directions fall short of the largest stretch; for a uniform scale every
        // direction is the largest.
        if (uniform)
            EXPECT_LE(double(bound), most * (1 + 4e-6)) << k;
        else
            EXPECT_LE(double(bound), most * 1.1) << k;
    }
}

} // namespace
} // namespace sheaf

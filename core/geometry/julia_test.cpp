// Julia fractals against sets whose shape is known: with c = 0 the quaternion square and cube
// keep exactly the unit 4-ball, whose slices are a unit sphere (w = 0) or an ellipsoid (a
// tilted slice); for other parameters every crossing found separates points inside the set
// from points outside it, and the march's answers do not depend on how far the ray is taken.
#include "core/geometry/julia.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sheaf {
namespace {

struct Pieces {
    int n = 0;
    double t0[4], t1[4];
    Vec3 n0[4], n1[4];
};

Pieces pieces(const JuliaFractal& j, Vec3 o, Vec3 d, float tmin = 0, float tmax = 1e30f) {
    Ray r;
    r.origin = o, r.dir = d, r.tmin = tmin, r.tmax = tmax;
    Pieces p;
    p.n = julia_pieces(j, r, p.t0, p.t1, p.n0, p.n1, 4);
    return p;
}

JuliaFractal ball(JuliaAlgebra a) {
    JuliaFractal j;
    j.c[0] = 0;
    j.algebra = a;
    return j;
}

TEST(Julia, WithCZeroTheSquareAndTheCubeKeepTheUnitBall) {
    for (JuliaAlgebra a : {JuliaAlgebra::QuaternionSqr, JuliaAlgebra::QuaternionCube}) {
        const JuliaFractal j = ball(a);
        // Along x at height 0.2, 0.1: the chord of the unit sphere, |x| < sqrt(0.95).
        const Pieces p = pieces(j, Vec3(-3, 0.2f, 0.1f), Vec3(1, 0, 0));
        ASSERT_EQ(p.n, 1);
        EXPECT_NEAR(p.t0[0], 3 - std::sqrt(0.95), 1e-6);
        EXPECT_NEAR(p.t1[0], 3 + std::sqrt(0.95), 1e-6);
        // The normals point out, along the radius.
        const Vec3 at0 = normalize(Vec3(float(-std::sqrt(0.95)), 0.2f, 0.1f));
        EXPECT_GT(dot(p.n0[0], at0), 0.9999f);
        EXPECT_GT(dot(p.n1[0], Vec3(-at0.x, at0.y, at0.z)), 0.9999f);
        EXPECT_TRUE(julia_inside(j, Vec3(0.5f, 0.5f, 0.5f)));
        EXPECT_FALSE(julia_inside(j, Vec3(0.6f, 0.6f, 0.6f)));
        // A ray whose direction is not unit: t stays the ray's own parameter.
        const Pieces q = pieces(j, Vec3(-3, 0, 0), Vec3(2, 0, 0));
        ASSERT_EQ(q.n, 1);
        EXPECT_NEAR(q.t0[0], 1.0, 1e-6);
        EXPECT_NEAR(q.t1[0], 2.0, 1e-6);
    }
}

TEST(Julia, ATiltedSliceCutsAnEllipsoid) {
    // The slice z + w = 0: w = -z, so the unit 4-ball leaves x^2 + y^2 + 2 z^2 <= 1.
    JuliaFractal j = ball(JuliaAlgebra::QuaternionSqr);
    j.slice[2] = j.slice[3] = std::sqrt(0.5);
    Pieces p = pieces(j, Vec3(0, 0, -3), Vec3(0, 0, 1));
    ASSERT_EQ(p.n, 1);
    EXPECT_NEAR(p.t0[0], 3 - std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(p.t1[0], 3 + std::sqrt(0.5), 1e-6);
    p = pieces(j, Vec3(-3, 0, 0), Vec3(1, 0, 0));
    ASSERT_EQ(p.n, 1);
    EXPECT_NEAR(p.t0[0], 2, 1e-6);
    // The slice's distance moves the cut: w = (0.6 - z sqrt(0.5)) / sqrt(0.5) at z = 0 is
    // 0.6 sqrt(2), so the x chord at the origin is sqrt(1 - 0.72).
    j.slice_dist = 0.6;
    p = pieces(j, Vec3(-3, 0, 0), Vec3(1, 0, 0));
    ASSERT_EQ(p.n, 1);
    EXPECT_NEAR(p.t0[0], 3 - std::sqrt(1 - 0.72), 1e-6);
}

TEST(Julia, EveryCrossingSeparatesInsideFromOutside) {
    // POV-Ray's sample parameters (objects/fractal1.pov, fractal4.pov).
    JuliaFractal sqr, cube, hyper;
    const double c1[4] = {-0.083, 0.0, -0.83, -0.025}, c2[4] = {-0.745, 0, 0.113, 0.05};
    for (int i = 0; i < 4; ++i) sqr.c[i] = cube.c[i] = c1[i], hyper.c[i] = c2[i];
    sqr.iterations = cube.iterations = 8, hyper.iterations = 9;
    cube.algebra = JuliaAlgebra::QuaternionCube;
    hyper.algebra = JuliaAlgebra::HypercomplexSqr;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    for (const JuliaFractal& j : {sqr, cube, hyper}) {
        int crossings = 0;
        for (int k = 0; k < 200; ++k) {
            const Vec3 o = normalize(Vec3(u(rng), u(rng), u(rng))) * 5.0f;
            const Vec3 d = normalize(Vec3(u(rng), u(rng), u(rng)) * 0.5f - o);
            const Pieces p = pieces(j, o, d);
            for (int i = 0; i < p.n; ++i) {
                ASSERT_LT(p.t0[i], p.t1[i]);
                if (i > 0) ASSERT_LT(p.t1[i - 1], p.t0[i]);
                for (const auto& [t, normal, sign] :
                     {std::tuple{p.t0[i], p.n0[i], 1.0}, std::tuple{p.t1[i], p.n1[i], -1.0}}) {
                    const double e = 1e-6 * sign;
                    EXPECT_TRUE(julia_inside(j, o + d * float(t + e)));
                    EXPECT_FALSE(julia_inside(j, o + d * float(t - 20 * e)));
                    EXPECT_NEAR(length(normal), 1.0f, 1e-4f);
                    ++crossings;
                }
            }
            // Asked only up to the first piece's end, the march finds that same piece.
            if (p.n > 0) {
                const Pieces q = pieces(j, o, d, 0, float(p.t1[0]) + 1e-3f);
                ASSERT_GE(q.n, 1);
                EXPECT_EQ(q.t0[0], p.t0[0]);
                EXPECT_EQ(q.t1[0], p.t1[0]);
            }
        }
        EXPECT_GT(crossings, 50); // the rays aim at the set
    }
}

TEST(Julia, ARayStartingInsideBeginsItsFirstPieceBeforeTheSearch) {
    const JuliaFractal j = ball(JuliaAlgebra::QuaternionSqr);
    const Pieces p = pieces(j, Vec3(0, 0, 0), Vec3(1, 0, 0), 1e-4f);
    ASSERT_EQ(p.n, 1);
    EXPECT_EQ(p.t0[0], -FLT_MAX);
    EXPECT_NEAR(p.t1[0], 1, 1e-6);
    // One iteration keeps the whole bounding ball: its piece starts at the sphere, not before
    // the search.
    JuliaFractal one = j;
    one.iterations = 1;
    const Pieces q = pieces(one, Vec3(-3, 0, 0), Vec3(1, 0, 0));
    ASSERT_EQ(q.n, 1);
    EXPECT_NEAR(q.t0[0], 2, 1e-6);
    EXPECT_GT(dot(q.n0[0], Vec3(-1, 0, 0)), 0.9999f);
    // Nothing is found beyond the bounding sphere, nor behind the ray.
    EXPECT_EQ(pieces(j, Vec3(-3, 2.5f, 0), Vec3(1, 0, 0)).n, 0);
    EXPECT_EQ(pieces(j, Vec3(3, 0, 0), Vec3(1, 0, 0)).n, 0);
}

} // namespace
} // namespace sheaf

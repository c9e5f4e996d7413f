// Brute-force checks of the cone unions (paper 000 eqs. 5, 6 and the n-ary form).
#include "core/geometry/cone.h"
#include "core/geometry/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace sheaf {
namespace {

using test::direction_at;
using test::random_point;
using test::random_unit;

float random_angle(std::mt19937& g, int kind) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    switch (kind % 5) {
    case 0:
        return 0.0f; // a single direction
    case 1:
        return 0.05f * u(g); // narrow
    case 2:
        return 1.5f * u(g); // up to 86 degrees
    case 3:
        return float(M_PI / 2) + 1.5f * u(g); // wider than 90 degrees
    default:
        return float(M_PI) * (0.9f + 0.1f * u(g)); // nearly everything
    }
}

// Random children; some pairs have nearly opposite (or identical) axes.
std::vector<Cone> random_cones(std::mt19937& g, int n, int trial) {
    std::vector<Cone> c(n);
    for (int i = 0; i < n; ++i) {
        c[i].angle = random_angle(g, int(g() % 5));
        if (i > 0 && trial % 3 == 1) {
            // Nearly opposite to the previous axis, by 1e-7 .. 1e-2.
            const float eps = std::pow(10.0f, -7.0f + 5.0f * float(g() % 1000) / 1000.0f);
            c[i].axis = normalize(-c[i - 1].axis + random_unit(g) * eps);
        } else if (i > 0 && trial % 3 == 2 && g() % 2) {
            c[i].axis = c[i - 1].axis; // identical axes
        } else {
            c[i].axis = random_unit(g);
        }
    }
    if (trial % 7 == 0) c[0].angle = random_angle(g, 0); // keep some narrow-only sets
    return c;
}

void expect_union_holds_children(const Cone& u, const std::vector<Cone>& children, std::mt19937& g,
                                 const char* what) {
    ASSERT_GE(u.angle, 0.0f) << what;
    ASSERT_LE(u.angle, kPi) << what;
    ASSERT_NEAR(length(u.axis), 1.0f, 1e-5f) << what;
    std::uniform_real_distribution<double> unit(0, 1);
    for (const Cone& c : children) {
        ASSERT_TRUE(cone_contains(u, c.axis)) << what;
        ASSERT_GE(u.angle, c.angle) << what;
        for (int k = 0; k < 24; ++k) {
            // Half on the child's boundary, half inside.
            const double theta = (k % 2 == 0) ? c.angle : c.angle * unit(g);
            const Vec3 d = direction_at(c.axis, theta, g);
            ASSERT_TRUE(cone_contains(u, d))
                << what << ": direction " << angle_between(u.axis, normalize(d))
                << " rad from the axis, union angle " << u.angle << ", child angle " << c.angle;
        }
    }
}

TEST(ConeUnion, NaryContainsEveryChildDirection) {
    std::mt19937 g(201);
    for (int trial = 0; trial < 1500; ++trial) {
        const int n = 1 + trial % 12;
        const auto c = random_cones(g, n, trial);
        expect_union_holds_children(cone_union(c.data(), n), c, g, "cone_union");
    }
}

TEST(ConeUnion, PaperPairAndFoldContainEveryChildDirection) {
    std::mt19937 g(202);
    for (int trial = 0; trial < 1500; ++trial) {
        const int n = 2 + trial % 11;
        const auto c = random_cones(g, n, trial);
        expect_union_holds_children(cone_union_paper(c[0], c[1]), {c[0], c[1]}, g,
                                    "cone_union_paper");
        Cone f = c[0];
        for (int i = 1; i < n; ++i) f = cone_union_paper(f, c[i]);
        expect_union_holds_children(f, c, g, "folded cone_union_paper");
    }
}

// Two zero-angle cones with axes 1e-7 .. 1e-2 from opposite: the short sum of the axes is
// dominated by rounding, so the union must measure its reach from the axis it really uses.
TEST(ConeUnion, NearlyOppositeAxesStayConservative) {
    std::mt19937 g(203);
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 a = random_unit(g);
        const float eps = std::pow(10.0f, -7.0f + 5.0f * float(trial % 1000) / 1000.0f);
        const Vec3 b = normalize(-a + random_unit(g) * eps);
        const Cone ca{a, 0.0f}, cb{b, trial % 2 ? 0.0f : 1e-3f};
        const Cone p = cone_union_paper(ca, cb);
        ASSERT_TRUE(cone_contains(p, a) && cone_contains(p, b))
            << "paper union misses a child axis, eps " << eps << ": reach "
            << std::max(angle_between(p.axis, a), angle_between(p.axis, b)) << " > " << p.angle;
        const Cone both[2] = {ca, cb};
        const Cone n = cone_union(both, 2);
        ASSERT_TRUE(cone_contains(n, a) && cone_contains(n, b)) << "eps " << eps;
        ASSERT_LE(p.angle, kPi);
        ASSERT_LE(n.angle, kPi);
    }
}

TEST(ConeUnion, ExactlyOppositeAxesGiveEverything) {
    const Cone a{Vec3(0, 0, 1), 0.1f}, b{Vec3(0, 0, -1), 0.2f};
    const Cone p = cone_union_paper(a, b);
    EXPECT_FLOAT_EQ(p.angle, kPi);
    const Cone both[2] = {a, b};
    const Cone n = cone_union(both, 2);
    EXPECT_LE(n.angle, kPi);
    std::mt19937 g(204);
    for (int k = 0; k < 200; ++k) {
        const Vec3 d = random_unit(g);
        EXPECT_TRUE(cone_contains(p, d));
    }
    // Axes pointing along the coordinate axes in six directions cancel too.
    const Cone six[6] = {{Vec3(1, 0, 0), 0},  {Vec3(-1, 0, 0), 0}, {Vec3(0, 1, 0), 0},
                         {Vec3(0, -1, 0), 0}, {Vec3(0, 0, 1), 0},  {Vec3(0, 0, -1), 0}};
    const Cone u = cone_union(six, 6);
    for (const Cone& c : six) EXPECT_TRUE(cone_contains(u, c.axis));
    EXPECT_LE(u.angle, kPi);
}

TEST(ConeUnion, ExactForSimpleCases) {
    // Identical cones: the union is the cone itself (plus the pad).
    const Cone a{Vec3(0, 1, 0), 0.3f};
    const Cone same[3] = {a, a, a};
    const Cone n = cone_union(same, 3);
    EXPECT_NEAR(n.angle, 0.3f, 1e-5f);
    EXPECT_NEAR(cone_union_paper(a, a).angle, 0.3f, 1e-5f);
    // Two axes 90 degrees apart: half-angle 45 degrees plus the larger child angle.
    const Cone x{Vec3(1, 0, 0), 0.1f}, y{Vec3(0, 1, 0), 0.2f};
    const Cone p = cone_union_paper(x, y);
    EXPECT_NEAR(p.angle, float(M_PI / 4) + 0.2f, 1e-5f);
    EXPECT_NEAR(p.axis.x, float(M_SQRT1_2), 1e-6f);
    EXPECT_NEAR(p.axis.y, float(M_SQRT1_2), 1e-6f);
    const Cone xy[2] = {x, y};
    EXPECT_NEAR(cone_union(xy, 2).angle, p.angle, 1e-5f);
    // A direction just outside is rejected.
    std::mt19937 g(206);
    for (int k = 0; k < 50; ++k)
        EXPECT_FALSE(cone_contains(p, direction_at(p.axis, p.angle + 1e-3, g)));
}

TEST(ConeUnion, AngleNeverExceedsPi) {
    std::mt19937 g(205);
    for (int trial = 0; trial < 2000; ++trial) {
        Cone c[4];
        for (Cone& x : c) x = {random_unit(g), float(M_PI) * (0.8f + 0.2f * float(g() % 100) / 99)};
        EXPECT_LE(cone_union(c, 4).angle, kPi);
        EXPECT_LE(cone_union_paper(c[0], c[1]).angle, kPi);
    }
}

} // namespace
} // namespace sheaf

// Brute-force checks of the sphere unions (paper 000 eqs. 7, 8 and the n-ary form).
#include "core/geometry/sphere.h"
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

// A point inside s: on its surface when `surface`, else uniform in its ball.
Vec3 point_in(const Sphere& s, std::mt19937& g, bool surface) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float r = surface ? s.radius : s.radius * std::cbrt(u(g));
    return s.center + random_unit(g) * r;
}

std::vector<Sphere> random_spheres(std::mt19937& g, int n, float offset, float spread, float rmax) {
    std::uniform_real_distribution<float> c(-spread, spread), r(0.0f, rmax);
    std::vector<Sphere> s(n);
    for (Sphere& x : s) {
        x.center = Vec3(offset) + Vec3(c(g), c(g), c(g));
        x.radius = (g() % 8 == 0) ? 0.0f : r(g); // some radius-0 children (ray origins)
    }
    return s;
}

Sphere fold_paper(const std::vector<Sphere>& s) {
    Sphere f = s[0];
    for (size_t i = 1; i < s.size(); ++i) f = sphere_union_paper(f, s[i]);
    return f;
}

// Every sampled point of every child (inside and on the surface) is inside the union.
void expect_union_holds_children(const Sphere& u, const std::vector<Sphere>& s, std::mt19937& g,
                                 const char* what) {
    for (const Sphere& c : s) {
        ASSERT_TRUE(sphere_contains(u, c.center)) << what;
        for (int k = 0; k < 24; ++k) {
            const Vec3 p = point_in(c, g, k % 2 == 0);
            ASSERT_TRUE(sphere_contains(u, p)) << what << ": point at distance "
                                               << length(p - u.center) << " > radius " << u.radius;
        }
    }
}

TEST(SphereUnion, NaryContainsEveryChildPoint) {
    std::mt19937 g(101);
    for (int trial = 0; trial < 400; ++trial) {
        const int n = 1 + trial % 16;
        const float offset = (trial % 4 == 3) ? 1000.0f : 0.0f; // far from the origin too
        const auto s = random_spheres(g, n, offset, 10.0f, 3.0f);
        expect_union_holds_children(sphere_union(s.data(), n), s, g, "sphere_union");
    }
}

TEST(SphereUnion, PaperPairwiseContainsEveryChildPoint) {
    std::mt19937 g(102);
    for (int trial = 0; trial < 400; ++trial) {
        const int n = 2 + trial % 15;
        const float offset = (trial % 4 == 3) ? -5000.0f : 0.0f;
        const auto s = random_spheres(g, n, offset, 10.0f, 3.0f);
        const Sphere pair = sphere_union_paper(s[0], s[1]);
        expect_union_holds_children(pair, {s[0], s[1]}, g, "sphere_union_paper");
        expect_union_holds_children(fold_paper(s), s, g, "folded sphere_union_paper");
    }
}

TEST(SphereUnion, NestedAndIdenticalChildren) {
    std::mt19937 g(103);
    // A child inside another, identical children, and all radii 0 at one point.
    std::vector<Sphere> nested = {{Vec3(1, 2, 3), 5.0f}, {Vec3(1.5f, 2, 3), 0.5f}};
    Sphere u = sphere_union(nested.data(), 2);
    expect_union_holds_children(u, nested, g, "nested");
    expect_union_holds_children(sphere_union_paper(nested[0], nested[1]), nested, g, "nested");

    std::vector<Sphere> same(5, Sphere{Vec3(-3, 4, 7), 2.0f});
    u = sphere_union(same.data(), 5);
    EXPECT_NEAR(u.radius, 2.0f, 1e-3f);
    expect_union_holds_children(u, same, g, "identical");

    std::vector<Sphere> points(4, Sphere{Vec3(10, 10, 10), 0.0f});
    u = sphere_union(points.data(), 4);
    EXPECT_TRUE(sphere_contains(u, Vec3(10, 10, 10)));
    EXPECT_LT(u.radius, 1e-4f);
}

TEST(SphereUnion, SingleChildAndPairMatchThePaper) {
    std::mt19937 g(104);
    for (int trial = 0; trial < 200; ++trial) {
        const auto s = random_spheres(g, 2, 0.0f, 10.0f, 3.0f);
        const Sphere one = sphere_union(s.data(), 1);
        EXPECT_LE(length(one.center - s[0].center), 1e-5f);
        EXPECT_GE(one.radius, s[0].radius);
        EXPECT_LE(one.radius, s[0].radius * 1.001f + 1e-3f);
        // For two children both forms are the same sphere: midpoint, half distance + max radius.
        const Sphere a = sphere_union(s.data(), 2), b = sphere_union_paper(s[0], s[1]);
        EXPECT_LE(length(a.center - b.center), 1e-4f);
        EXPECT_NEAR(a.radius, b.radius, 1e-4f * b.radius + 1e-5f);
    }
}

// Any sphere (c', R') holding every child bounds the n-ary radius: |c_i - mean| + r_i
// <= (R' - r_i) + max_j (R' - r_j) + r_i, so below 2 R'. The n-ary union is therefore never more
// than twice the folded paper union; on random children it is smaller on average and at most
// about 1.3 times larger (a lopsided cluster pulls the mean away from the middle).
TEST(SphereUnion, NaryRadiusAgainstPaperFold) {
    std::mt19937 g(105);
    double sum_ratio = 0, worst = 0;
    int count = 0, smaller = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = 2 + trial % 15;
        const auto s = random_spheres(g, n, 0.0f, 10.0f, 3.0f);
        const Sphere nary = sphere_union(s.data(), n), fold = fold_paper(s);
        // Lower bound for any enclosing sphere: the widest pair of children.
        float lower = 0;
        for (int i = 0; i < n; ++i)
            for (int j = i; j < n; ++j)
                lower = std::max(
                    lower, 0.5f * (length(s[i].center - s[j].center) + s[i].radius + s[j].radius));
        ASSERT_GE(nary.radius, lower * (1 - 1e-5f));
        ASSERT_GE(fold.radius, lower * (1 - 1e-5f));
        const double ratio = double(nary.radius) / fold.radius;
        ASSERT_LE(ratio, 2.0);
        worst = std::max(worst, ratio);
        sum_ratio += ratio;
        smaller += nary.radius <= fold.radius;
        ++count;
    }
    EXPECT_LT(sum_ratio / count, 0.9) << "n-ary union should be tighter than folding on average";
    EXPECT_GT(smaller, count * 3 / 4);
    EXPECT_LT(worst, 1.5);

    // The adversarial case: n - 1 children at one point, one opposite. The mean sits near the
    // cluster, so the n-ary radius approaches twice the minimal one (the fold is minimal here).
    std::vector<Sphere> lopsided(16, Sphere{Vec3(1, 0, 0), 0.0f});
    lopsided.back().center = Vec3(-1, 0, 0);
    const Sphere nary = sphere_union(lopsided.data(), 16), fold = fold_paper(lopsided);
    EXPECT_NEAR(fold.radius, 1.0f, 1e-3f);
    EXPECT_GT(nary.radius, 1.8f);
    EXPECT_LE(nary.radius, 2.0f * fold.radius);
}

} // namespace
} // namespace sheaf

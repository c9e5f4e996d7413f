// Minimal enclosing spheres against brute force: the triangle's exact sphere and Welzl's
// algorithm for point sets.
#include "core/geometry/min_sphere.h"
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

struct Ball {
    Vec3d c{0, 0, 0};
    double r = -1; // invalid
};

// The smallest sphere through three points (their circumcircle's sphere); invalid when they
// are collinear.
Ball circum3(Vec3d a, Vec3d b, Vec3d c) {
    const Vec3d ab = b - a, ac = c - a, n = cross(ab, ac);
    const double nn = dot(n, n);
    if (nn <= 1e-24 * dot(ab, ab) * dot(ac, ac)) return {};
    const Vec3d center = a + (cross(n, ab) * dot(ac, ac) + cross(ac, n) * dot(ab, ab)) * (0.5 / nn);
    return {center, distance(center, a)};
}

// The sphere through four points, by Cramer's rule on 2 (p_i - a) . x = |p_i - a|^2; invalid
// when they are coplanar.
Ball circum4(Vec3d a, Vec3d b, Vec3d c, Vec3d d) {
    const Vec3d u = b - a, v = c - a, w = d - a;
    const double det = dot(u, cross(v, w));
    const double scale = std::sqrt(dot(u, u) * dot(v, v) * dot(w, w));
    if (std::fabs(det) <= 1e-9 * scale) return {};
    const Vec3d x =
        (cross(v, w) * dot(u, u) + cross(w, u) * dot(v, v) + cross(u, v) * dot(w, w)) * (0.5 / det);
    return {a + x, std::sqrt(dot(x, x))};
}

bool holds_all(const Ball& b, const std::vector<Vec3d>& p) {
    if (b.r < 0) return false;
    for (Vec3d q : p)
        if (distance(q, b.c) > b.r * (1 + 1e-9) + 1e-12) return false;
    return true;
}

void keep_smaller(Ball& best, const Ball& cand, const std::vector<Vec3d>& p) {
    if (holds_all(cand, p) && (best.r < 0 || cand.r < best.r)) best = cand;
}

// Brute force: the minimal enclosing sphere is determined by at most four points on its
// boundary; try every pair (midpoint), triple (circumcircle) and quadruple (circumsphere).
Ball brute_min_sphere(const std::vector<Vec3d>& p) {
    const size_t n = p.size();
    Ball best;
    if (n == 1) return {p[0], 0.0};
    keep_smaller(best, {p[0], 0.0}, p); // all points equal
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const Vec3d m = (p[i] + p[j]) * 0.5;
            keep_smaller(best, {m, distance(m, p[i])}, p);
            for (size_t k = j + 1; k < n; ++k) {
                keep_smaller(best, circum3(p[i], p[j], p[k]), p);
                for (size_t l = k + 1; l < n; ++l)
                    keep_smaller(best, circum4(p[i], p[j], p[k], p[l]), p);
            }
        }
    return best;
}

std::vector<Vec3d> to_double(const std::vector<Vec3>& v) {
    std::vector<Vec3d> out;
    for (Vec3 x : v) out.push_back(to_double(x));
    return out;
}

void expect_holds_all(const Sphere& s, const std::vector<Vec3>& p, const char* what) {
    for (Vec3 q : p)
        ASSERT_TRUE(sphere_contains(s, q))
            << what << ": point at " << length(q - s.center) << " > radius " << s.radius;
}

void expect_matches_brute(const Sphere& s, const std::vector<Vec3>& p, double rel,
                          const char* what) {
    const Ball b = brute_min_sphere(to_double(p));
    ASSERT_GE(b.r, 0) << what;
    // Relative to the radius, plus what float positions far from the origin allow: their
    // rounding, and the padding pad_radius adds for it (1e-7 of the centre's L1 norm).
    const double far = 2e-7 * (std::fabs(b.c.x) + std::fabs(b.c.y) + std::fabs(b.c.z));
    const double tol = rel * b.r + far + 1e-6;
    EXPECT_NEAR(s.radius, b.r, tol) << what << " (" << p.size() << " points)";
    EXPECT_LE(distance(to_double(s.center), b.c), tol) << what << " (" << p.size() << " points)";
    EXPECT_GE(s.radius, b.r * (1 - 1e-6)) << what << ": smaller than the minimal sphere";
}

// ---------------------------------------------------------------------------------------------

TEST(TriangleSphere, MatchesBruteForce) {
    std::mt19937 g(501);
    std::uniform_real_distribution<float> u(0, 1);
    for (int trial = 0; trial < 20000; ++trial) {
        const float extent = (trial % 3 == 0) ? 100.0f : 1.0f;
        const Vec3 off = (trial % 5 == 0) ? Vec3(1000.0f, -500.0f, 250.0f) : Vec3(0.0f);
        Vec3 a = off + random_point(g, extent), b = off + random_point(g, extent),
             c = off + random_point(g, extent);
        if (trial % 4 == 1)
            c = a + (b - a) * (0.5f + 0.1f * u(g)) + random_unit(g) * (0.5f * extent); // near right
        if (trial % 4 == 2)
            c = a + (b - a) * u(g) + random_unit(g) * (0.01f * extent); // obtuse sliver
        const Sphere s = triangle_sphere(a, b, c);
        expect_holds_all(s, {a, b, c}, "triangle_sphere");
        expect_matches_brute(s, {a, b, c}, 1e-4, "triangle_sphere");
    }
}

TEST(TriangleSphere, RightAndEquilateralAndDegenerate) {
    // Right triangle: the hypotenuse's midpoint.
    Sphere s = triangle_sphere(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
    EXPECT_NEAR(s.center.x, 1.0f, 1e-6f);
    EXPECT_NEAR(s.center.y, 1.0f, 1e-6f);
    EXPECT_NEAR(s.radius, std::sqrt(2.0f), 1e-4f);
    // Equilateral: the circumcentre.
    const float h = std::sqrt(3.0f);
    s = triangle_sphere(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, h, 0));
    EXPECT_NEAR(s.center.y, h / 3, 1e-6f);
    EXPECT_NEAR(s.radius, 2 * h / 3, 1e-4f);
    // Degenerate: a point, two equal vertices, collinear points.
    s = triangle_sphere(Vec3(3, 4, 5), Vec3(3, 4, 5), Vec3(3, 4, 5));
    EXPECT_TRUE(sphere_contains(s, Vec3(3, 4, 5)));
    EXPECT_LT(s.radius, 1e-4f);
    for (auto tri :
         std::vector<std::vector<Vec3>>{{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(4, 0, 0)},
                                        {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(3, 3, 3)},
                                        {Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(3, 3, 3)},
                                        {Vec3(-1, 2, 0), Vec3(5, 2, 0), Vec3(2, 2, 0)}}) {
        s = triangle_sphere(tri[0], tri[1], tri[2]);
        expect_holds_all(s, tri, "degenerate triangle");
        expect_matches_brute(s, tri, 1e-4, "degenerate triangle");
    }
}

TEST(MinSphere, MatchesBruteForceOnSmallSets) {
    std::mt19937 g(502);
    std::uniform_real_distribution<float> u(0, 1);
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = 1 + trial % 12;
        std::vector<Vec3> p(n);
        const float extent = (trial % 7 == 0) ? 1000.0f : 1.0f;
        for (Vec3& q : p) q = random_point(g, extent);
        if (trial % 5 == 1) // points on a sphere: many on the boundary
            for (Vec3& q : p) q = Vec3(2, -1, 3) + random_unit(g) * 5.0f;
        if (trial % 5 == 3) // a small integer grid: exact coplanar and cospherical subsets
            for (Vec3& q : p) q = Vec3(float(g() % 5), float(g() % 5), float(g() % 3));
        if (trial % 5 == 2) // squashed: nearly coplanar
            for (Vec3& q : p) q.z *= 1e-3f;
        const Sphere s = min_sphere(p);
        expect_holds_all(s, p, "min_sphere");
        expect_matches_brute(s, p, 1e-3, "min_sphere");
    }
}

TEST(MinSphere, DegenerateInputs) {
    std::mt19937 g(503);
    std::uniform_real_distribution<float> u(0, 1);
    // Empty and single point.
    EXPECT_EQ(min_sphere({}).radius, 0.0f);
    std::vector<Vec3> one = {Vec3(7, -8, 9)};
    Sphere s = min_sphere(one);
    EXPECT_EQ(s.center, Vec3(7, -8, 9));
    EXPECT_LT(s.radius, 1e-4f);
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 2 + trial % 30;
        std::vector<Vec3> p(n);
        const Vec3 base = random_point(g, 10), dir = random_unit(g), dir2 = random_unit(g);
        switch (trial % 4) {
        case 0: // all equal
            for (Vec3& q : p) q = base;
            break;
        case 1: // collinear
            for (Vec3& q : p) q = base + dir * (u(g) * 10 - 5);
            break;
        case 2: // coplanar
            for (Vec3& q : p) q = base + dir * (u(g) * 10 - 5) + dir2 * (u(g) * 10 - 5);
            break;
        default: // duplicated points, shuffled
            for (int i = 0; i < n; ++i) p[i] = i < 4 ? random_point(g, 5) : p[g() % 4];
            std::shuffle(p.begin(), p.end(), g);
        }
        s = min_sphere(p);
        expect_holds_all(s, p, "degenerate min_sphere");
        if (trial % 4 == 0) {
            EXPECT_LT(length(s.center - base), 1e-4f);
            EXPECT_LT(s.radius, 1e-3f);
        } else if (n <= 12) {
            expect_matches_brute(s, p, 1e-3, "degenerate min_sphere");
        }
        if (trial % 4 == 1) { // the farthest pair's midpoint
            float lo = 1e30f, hi = -1e30f;
            for (Vec3 q : p)
                lo = std::min(lo, dot(q - base, dir)), hi = std::max(hi, dot(q - base, dir));
            EXPECT_NEAR(s.radius, 0.5f * (hi - lo), 1e-3f * std::max(1.0f, hi - lo));
        }
    }
}

TEST(MinSphere, ManyPoints) {
    std::mt19937 g(504);
    for (int shape = 0; shape < 3; ++shape) {
        std::vector<Vec3> p(100000);
        for (Vec3& q : p) {
            if (shape == 0)
                q = random_point(g, 1) * Vec3(3, 1, 0.5f) + Vec3(0, 5, 0);
            else if (shape == 1)
                q = Vec3(10, 0, -3) + random_unit(g) * 2.0f; // on a sphere
            else
                q = random_point(g, 1) * Vec3(4, 1, 0.1f); // a thin slab
        }
        const Sphere s = min_sphere(p);
        expect_holds_all(s, p, "min_sphere of 100k points");
        Vec3 lo(1e30f), hi(-1e30f);
        for (Vec3 q : p) lo = vmin(lo, q), hi = vmax(hi, q);
        EXPECT_LE(s.radius, 0.5f * length(hi - lo) * 1.0001f);
        // No smaller than half the widest extent along an axis.
        EXPECT_GE(s.radius * 1.0001f, 0.5f * max_component(hi - lo));
        if (shape == 1) {
            EXPECT_NEAR(s.radius, 2.0f, 1e-3f);
        }
    }
}

} // namespace
} // namespace sheaf

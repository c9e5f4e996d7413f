// Moeller-Trumbore against an independent double-precision reference: the plane
// intersection, then barycentrics from sub-areas.
#include "core/geometry/ray_triangle.h"
#include "core/geometry/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace sheaf {
namespace {

using test::direction_at;
using test::random_point;
using test::random_unit;

struct Reference {
    bool parallel = true;
    double t = 0, u = 0, v = 0; // u, v: barycentrics of b and c
    double cos_incidence = 0;   // |cos| of the angle between ray and normal
    // |det| / (|e1| |e2|): the conditioning of Moeller-Trumbore's division, small for grazing
    // rays and thin triangles, where float loses relative accuracy in t.
    double kappa = 0;
};

Reference reference(const Ray& r, Vec3 a, Vec3 b, Vec3 c) {
    Reference ref;
    const Vec3d A = to_double(a), e1 = to_double(b) - A, e2 = to_double(c) - A,
                o = to_double(r.origin), d = to_double(r.dir);
    const Vec3d n = cross(e1, e2);
    const double nn = dot(n, n), dn = dot(d, n);
    if (nn == 0 || dn == 0) return ref;
    ref.parallel = false;
    ref.cos_incidence = std::fabs(dn) / std::sqrt(nn * dot(d, d));
    ref.kappa = std::fabs(dn) / std::sqrt(dot(e1, e1) * dot(e2, e2) * dot(d, d));
    ref.t = dot(n, A - o) / dn;
    const Vec3d p = o + d * ref.t - A;
    // p = u e1 + v e2: the sub-areas against the full area.
    ref.u = dot(cross(p, e2), n) / nn;
    ref.v = dot(cross(e1, p), n) / nn;
    return ref;
}

TEST(IntersectTriangle, AgreesWithDoubleReference) {
    std::mt19937 g(401);
    std::uniform_real_distribution<float> u01(0, 1);
    int hits = 0, misses = 0, well = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const float scale = (trial % 3 == 0) ? 100.0f : 1.0f;
        const Vec3 a = random_point(g, scale), b = random_point(g, scale),
                   c = random_point(g, scale);
        Ray r;
        r.origin = random_point(g, 3 * scale);
        // Aim at a point near the triangle (barycentrics in -0.3 .. 1.3) most of the time.
        if (trial % 4 != 0) {
            const float s = u01(g) * 1.6f - 0.3f, t = u01(g) * 1.6f - 0.3f;
            const Vec3 target = a + (b - a) * s + (c - a) * t;
            if (length(target - r.origin) < 1e-3f * scale) continue;
            r.dir = normalize(target - r.origin);
        } else {
            r.dir = random_unit(g);
        }
        switch (trial % 5) {
        case 0:
            r.tmin = 0, r.tmax = std::numeric_limits<float>::infinity();
            break;
        case 1:
            r.tmin = 1e-4f, r.tmax = 1e30f;
            break;
        default:
            r.tmin = u01(g) * 3 * scale;
            r.tmax = r.tmin + u01(g) * 6 * scale;
        }
        const Reference ref = reference(r, a, b, c);
        TriangleHit hit{-1, -1, -1};
        const bool got = intersect_triangle(r, a, b, c, hit);
        // Grazing rays on thin triangles: float has no reliable answer there.
        if (ref.parallel || ref.kappa < 1e-3) continue;
        // The margin: 1e-4 where the problem is well conditioned, else float rounding of order
        // 1e-5 / kappa (origin up to a few triangle sizes away).
        const double tol = std::max(1e-4, 1e-5 / ref.kappa);
        const double w = 1 - ref.u - ref.v;
        const double edge = std::min({ref.u, ref.v, w});
        const double tm = tol * std::max(1.0, std::fabs(ref.t));
        const bool t_inside = ref.t > r.tmin + tm && ref.t < double(r.tmax) - tm;
        const bool t_outside = ref.t < r.tmin - tm || ref.t > double(r.tmax) + tm;
        if (edge > tol && t_inside) {
            ++hits;
            well += tol == 1e-4;
            ASSERT_TRUE(got) << "reference hits at t " << ref.t << " (u " << ref.u << ", v "
                             << ref.v << "), intersect_triangle misses; trial " << trial;
            EXPECT_NEAR(hit.t, ref.t, tm) << "kappa " << ref.kappa;
            EXPECT_NEAR(hit.u, ref.u, tol) << "kappa " << ref.kappa;
            EXPECT_NEAR(hit.v, ref.v, tol) << "kappa " << ref.kappa;
            EXPECT_GT(hit.t, r.tmin);
            EXPECT_LT(hit.t, r.tmax);
        } else if (edge < -tol || t_outside) {
            ++misses;
            ASSERT_FALSE(got) << "reference misses (edge " << edge << ", t " << ref.t << " in ("
                              << r.tmin << ", " << r.tmax << ")), intersect_triangle hits at t "
                              << hit.t << "; trial " << trial;
        }
    }
    EXPECT_GT(hits, 15000);
    EXPECT_GT(well, hits * 3 / 4); // most hits are checked at the full 1e-4
    EXPECT_GT(misses, 20000);
}

TEST(IntersectTriangle, BothWindingsHit) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    TriangleHit h1{}, h2{};
    for (float z : {-2.0f, 2.0f}) {
        const Ray r{Vec3(0.25f, 0.25f, z), 0.0f, Vec3(0, 0, z < 0 ? 1.0f : -1.0f), 100.0f};
        ASSERT_TRUE(intersect_triangle(r, a, b, c, h1));
        ASSERT_TRUE(intersect_triangle(r, a, c, b, h2));
        EXPECT_FLOAT_EQ(h1.t, 2.0f);
        EXPECT_FLOAT_EQ(h2.t, 2.0f);
        EXPECT_FLOAT_EQ(h1.u, 0.25f);
        EXPECT_FLOAT_EQ(h1.v, 0.25f);
        EXPECT_FLOAT_EQ(h2.u, 0.25f); // vertices swapped: u and v swap, here both 0.25
    }
    // A point behind the origin is no hit when tmin = 0.
    const Ray away{Vec3(0.25f, 0.25f, 2.0f), 0.0f, Vec3(0, 0, 1), 100.0f};
    EXPECT_FALSE(intersect_triangle(away, a, b, c, h1));
}

// The interval is open at both ends: a hit exactly at tmin or tmax is no hit, one ulp
// inside is.
TEST(IntersectTriangle, RespectsTheOpenInterval) {
    std::mt19937 g(402);
    std::uniform_real_distribution<float> u01(0, 1);
    int checked = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 a = random_point(g, 1), b = random_point(g, 1), c = random_point(g, 1);
        const float s = 0.1f + 0.4f * u01(g), t = 0.1f + 0.4f * u01(g);
        Ray r;
        r.origin = random_point(g, 3);
        r.dir = normalize(a + (b - a) * s + (c - a) * t - r.origin);
        r.tmin = -1e30f, r.tmax = 1e30f;
        TriangleHit hit{};
        if (!intersect_triangle(r, a, b, c, hit)) continue;
        const float th = hit.t;
        ++checked;
        TriangleHit h{};
        Ray q = r;
        q.tmin = th;
        EXPECT_FALSE(intersect_triangle(q, a, b, c, h));
        q = r;
        q.tmax = th;
        EXPECT_FALSE(intersect_triangle(q, a, b, c, h));
        q.tmin = std::nextafter(th, -1e30f);
        q.tmax = std::nextafter(th, 1e30f);
        ASSERT_TRUE(intersect_triangle(q, a, b, c, h));
        EXPECT_EQ(h.t, th);                          // deterministic
        q.tmin = th + std::fabs(th) * 1e-3f + 1e-3f; // interval wholly after the hit
        q.tmax = q.tmin + 10;
        EXPECT_FALSE(intersect_triangle(q, a, b, c, h));
        q.tmin = th - 10; // interval wholly before it
        q.tmax = th - std::fabs(th) * 1e-3f - 1e-3f;
        EXPECT_FALSE(intersect_triangle(q, a, b, c, h));
    }
    EXPECT_GT(checked, 15000);
}

TEST(IntersectTriangle, DegenerateTrianglesNeverHit) {
    std::mt19937 g(403);
    std::uniform_int_distribution<int> small(-8, 8);
    int rays = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Integer coordinates keep collinearity exact in float.
        const Vec3 a(small(g), small(g), small(g));
        const Vec3 e(small(g), small(g), small(g));
        Vec3 b, c;
        switch (trial % 4) {
        case 0:
            b = a, c = a;
            break; // a point
        case 1:
            b = a + e, c = a;
            break; // two equal vertices
        case 2:
            b = a + e, c = a + e * 2.0f;
            break; // collinear
        default:
            b = a + e * -1.0f, c = a + e * 3.0f; // collinear, a in the middle
        }
        Ray r;
        // Aim at the segment, so a robust miss is really needed.
        const float s = std::uniform_real_distribution<float>(0, 1)(g);
        r.origin = random_point(g, 10);
        const Vec3 target = a + (c - a) * s;
        if (length(target - r.origin) < 1e-3f) continue;
        r.dir = normalize(target - r.origin);
        r.tmin = 0, r.tmax = 1e30f;
        TriangleHit hit{};
        ++rays;
        ASSERT_FALSE(intersect_triangle(r, a, b, c, hit))
            << "degenerate triangle (case " << trial % 4 << ") hit at t " << hit.t;
    }
    EXPECT_GT(rays, 19000);
}

// The degenerate-triangle bound is relative to the edges: tiny and huge triangles still hit.
TEST(IntersectTriangle, ScaleIndependent) {
    std::mt19937 g(404);
    for (float scale : {1e-7f, 1e-5f, 1e-3f, 1.0f, 1e3f, 1e6f}) {
        int hits = 0;
        for (int k = 0; k < 200; ++k) {
            const Vec3 a = random_point(g, 1) * scale, b = random_point(g, 1) * scale,
                       c = random_point(g, 1) * scale;
            Ray r;
            r.origin = random_point(g, 3) * scale;
            const Vec3 target = (a + b + c) * (1.0f / 3.0f);
            r.dir = normalize(target - r.origin);
            r.tmin = 0, r.tmax = 1e30f;
            const Reference ref = reference(r, a, b, c);
            if (ref.parallel || ref.kappa < 1e-2) continue;
            TriangleHit hit{};
            ASSERT_TRUE(intersect_triangle(r, a, b, c, hit)) << "scale " << scale;
            EXPECT_NEAR(hit.t, ref.t, 1e-4 * ref.t) << "scale " << scale;
            ++hits;
        }
        EXPECT_GT(hits, 150) << "scale " << scale;
    }
}

TEST(IntersectTriangle, ParallelRayMisses) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    TriangleHit hit{};
    const Ray in_plane{Vec3(-1, 0.25f, 0), 0.0f, Vec3(1, 0, 0), 100.0f};
    EXPECT_FALSE(intersect_triangle(in_plane, a, b, c, hit));
    const Ray above{Vec3(-1, 0.25f, 1), 0.0f, Vec3(1, 0, 0), 100.0f};
    EXPECT_FALSE(intersect_triangle(above, a, b, c, hit));
}

} // namespace
} // namespace sheaf

// Polynomial surfaces: roots of known polynomials, and poly shapes against the shapes they
// describe (a sphere, a torus as a quartic) and against their own sign along random rays.
#include "core/geometry/poly.h"
#include "core/geometry/shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace sheaf {
namespace {

// Coefficients (ascending) of prod (t - r) over `rs`, times `lead`.
std::vector<double> from_roots(std::vector<double> rs, double lead = 1) {
    std::vector<double> q{lead};
    for (double r : rs) {
        std::vector<double> next(q.size() + 1, 0.0);
        for (size_t m = 0; m < q.size(); ++m) next[m + 1] += q[m], next[m] -= r * q[m];
        q = next;
    }
    return q;
}

std::vector<double> roots_of(const std::vector<double>& q) {
    double r[kPolyMaxDegree];
    const int n = poly_roots(q.data(), int(q.size()) - 1, r);
    return std::vector<double>(r, r + n);
}

TEST(Poly, RootsOfKnownPolynomials) {
    auto expect = [](std::vector<double> want, std::vector<double> got, double tol) {
        ASSERT_EQ(got.size(), want.size());
        std::sort(want.begin(), want.end());
        for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << i;
    };
    expect({1, 2, 3, 4}, roots_of(from_roots({4, 2, 1, 3})), 1e-12);
    expect({-7, 0.5, 1e3}, roots_of(from_roots({1e3, -7, 0.5}, -2)), 1e-9);
    // Close roots are still told apart: the derivative's root lies between them.
    expect({1, 1 + 1e-6, -2, 5}, roots_of(from_roots({1, 1 + 1e-6, -2, 5})), 1e-9);
    // A double root only touches (no sign change): not a crossing.
    expect({-1, 3}, roots_of(from_roots({1, 1, 3, -1})), 1e-9);
    expect({}, roots_of({1, 0, 0, 0, 1}), 0);           // t^4 + 1
    expect({-1, 1}, roots_of({-1, 0, 0, 0, 1}), 1e-12); // t^4 - 1
    expect({2}, roots_of({-8, 0, 0, 1}), 1e-12);        // t^3 - 8
    expect({0.25}, roots_of({-1, 4}), 0);
}

PolyCoeffs poly(std::initializer_list<std::pair<std::array<int, 3>, double>> terms) {
    PolyCoeffs p;
    for (const auto& [e, c] : terms) {
        const int t = poly_term(e[0], e[1], e[2]);
        EXPECT_GE(t, 0);
        p.c[t] += c;
    }
    return p;
}

TEST(Poly, TermOrderIsPovRays) {
    // POV-Ray's quartic: x^4, x^3 y, x^3 z, x^3, x^2 y^2, ... z, 1.
    EXPECT_EQ(poly_term(4, 0, 0), 0);
    EXPECT_EQ(poly_term(3, 1, 0), 1);
    EXPECT_EQ(poly_term(3, 0, 1), 2);
    EXPECT_EQ(poly_term(3, 0, 0), 3);
    EXPECT_EQ(poly_term(2, 2, 0), 4);
    EXPECT_EQ(poly_term(1, 0, 0), 19);
    EXPECT_EQ(poly_term(0, 4, 0), 20);
    EXPECT_EQ(poly_term(0, 0, 4), 30);
    EXPECT_EQ(poly_term(0, 0, 0), 34);
    EXPECT_EQ(poly_term(2, 2, 2), -1);
}

TEST(Poly, PovOrderOfEveryDegreeLandsInTheQuarticLayout) {
    EXPECT_EQ(poly_coefficient_count(2), 10u);
    EXPECT_EQ(poly_coefficient_count(3), 20u);
    EXPECT_EQ(poly_coefficient_count(4), 35u);
    // Cubic: x^3, x^2 y, x^2 z, x^2, x y^2, ... z, 1.
    double c[20];
    for (int i = 0; i < 20; ++i) c[i] = i + 1;
    const PolyCoeffs p = poly_from_pov_order(3, c);
    EXPECT_EQ(p.c[poly_term(3, 0, 0)], 1);
    EXPECT_EQ(p.c[poly_term(2, 1, 0)], 2);
    EXPECT_EQ(p.c[poly_term(2, 0, 0)], 4);
    EXPECT_EQ(p.c[poly_term(0, 3, 0)], 11);
    EXPECT_EQ(p.c[poly_term(0, 0, 0)], 20);
    EXPECT_EQ(p.c[poly_term(4, 0, 0)], 0);
    EXPECT_FALSE(poly_is_zero(p));
    EXPECT_TRUE(poly_is_zero(PolyCoeffs{}));
}

// The torus of shape.h (major radius 1, minor r) as a quartic:
// (x^2 + y^2 + z^2 + 1 - r^2)^2 - 4 (x^2 + y^2).
PolyCoeffs torus_quartic(double r) {
    const double k = 1 - r * r;
    return poly({{{4, 0, 0}, 1},
                 {{0, 4, 0}, 1},
                 {{0, 0, 4}, 1},
                 {{2, 2, 0}, 2},
                 {{2, 0, 2}, 2},
                 {{0, 2, 2}, 2},
                 {{2, 0, 0}, 2 * k - 4},
                 {{0, 2, 0}, 2 * k - 4},
                 {{0, 0, 2}, 2 * k},
                 {{0, 0, 0}, k * k}});
}

Ray random_ray(std::mt19937& g) {
    std::uniform_real_distribution<float> u(-1, 1);
    Ray r;
    r.origin = Vec3(u(g), u(g), u(g)) * 3.0f;
    r.dir = (Vec3(u(g), u(g), u(g)) * 0.9f - r.origin) * (0.5f + 0.5f * (u(g) + 1));
    r.tmin = -1e30f, r.tmax = 1e30f;
    return r;
}

TEST(Poly, SameSpansAsTheShapesTheyDescribe) {
    const PolyCoeffs polys[2] = {
        poly({{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -1}}), // unit sphere
        torus_quartic(0.3)};
    const Shape same[2] = {{ShapeKind::Sphere}, {ShapeKind::Torus, 0.3f}};
    std::mt19937 g(11);
    for (int which = 0; which < 2; ++which) {
        Shape s{ShapeKind::Poly};
        s.index = uint32_t(which);
        int hits = 0;
        for (int k = 0; k < 2000; ++k) {
            const Ray r = random_ray(g);
            Span a[kMaxShapeSpans], b[kMaxShapeSpans];
            const int na = shape_spans(s, r, a, {polys}), nb = shape_spans(same[which], r, b);
            ASSERT_EQ(na, nb) << "shape " << which << " ray " << k;
            hits += na > 0;
            for (int i = 0; i < na; ++i) {
                EXPECT_NEAR(a[i].t0, b[i].t0, 1e-4f);
                EXPECT_NEAR(a[i].t1, b[i].t1, 1e-4f);
                EXPECT_GT(dot(normalize(a[i].n0), normalize(b[i].n0)), 0.999f);
                EXPECT_GT(dot(normalize(a[i].n1), normalize(b[i].n1)), 0.999f);
            }
        }
        EXPECT_GT(hits, 200) << which;
    }
}

TEST(Poly, SpansFollowTheSignOfUnboundedSurfaces) {
    const PolyCoeffs polys[] = {
        poly({{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 0}, -1}}),                     // cylinder
        poly({{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, -1}, {{0, 0, 0}, -0.25}}), // hyperboloid
        poly({{{3, 0, 0}, 1}, {{1, 0, 0}, -1}, {{0, 1, 0}, -1}}),                    // cubic
        poly({{{2, 2, 0}, 1}, {{0, 2, 2}, 1}, {{2, 0, 2}, 1}, {{1, 1, 1}, 1}}),      // Steiner-like
        poly({{{4, 0, 0}, 1}, {{0, 4, 0}, -1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -0.5}}),
    };
    std::mt19937 g(12);
    for (uint32_t which = 0; which < std::size(polys); ++which) {
        Shape s{ShapeKind::Poly};
        s.index = which;
        for (int k = 0; k < 300; ++k) {
            const Ray r = random_ray(g);
            Span sp[kMaxShapeSpans];
            const int n = shape_spans(s, r, sp, {polys});
            for (int i = 0; i + 1 < n; ++i) EXPECT_LT(sp[i].t1, sp[i + 1].t0);
            for (float t = -4.0f; t <= 4.0f; t += 0.01f) {
                const Vec3 p = ray_at(r, t);
                const double f = poly_value(polys[which], p.x, p.y, p.z);
                const Vec3 grad = poly_gradient(polys[which], p.x, p.y, p.z);
                if (std::fabs(f) < 1e-3 * (1 + length(grad) * length(r.dir))) continue;
                bool in = false;
                for (int i = 0; i < n; ++i) in |= t >= sp[i].t0 && t <= sp[i].t1;
                ASSERT_EQ(in, f < 0) << "poly " << which << " ray " << k << " t " << t;
            }
            for (int i = 0; i < n; ++i)
                for (const float t : {sp[i].t0, sp[i].t1}) {
                    if (std::fabs(t) >= 1e30f) continue;
                    const Vec3 p = ray_at(r, t);
                    const Vec3 grad = poly_gradient(polys[which], p.x, p.y, p.z);
                    EXPECT_NEAR(poly_value(polys[which], p.x, p.y, p.z), 0.0,
                                1e-4 * (1 + length(grad) * length(r.dir)));
                }
        }
    }
}

TEST(Poly, RaysAlongAnInfiniteCylinder) {
    const PolyCoeffs cyl = poly({{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 0}, -1}});
    Shape s{ShapeKind::Poly};
    Span sp[kMaxShapeSpans];
    Ray inside{Vec3(0.2f, 0.1f, -5), 0, Vec3(0, 0, 1), 1e30f};
    ASSERT_EQ(shape_spans(s, inside, sp, {&cyl}), 1); // inside all along
    EXPECT_EQ(sp[0].t0, -FLT_MAX);
    EXPECT_EQ(sp[0].t1, FLT_MAX);
    Ray outside{Vec3(2, 0, -5), 0, Vec3(0, 0, 1), 1e30f};
    EXPECT_EQ(shape_spans(s, outside, sp, {&cyl}), 0);
    Ray across{Vec3(-3, 0, 7), 0, Vec3(1, 0, 0), 1e30f};
    ASSERT_EQ(shape_spans(s, across, sp, {&cyl}), 1);
    EXPECT_NEAR(sp[0].t0, 2.0f, 1e-6f);
    EXPECT_NEAR(sp[0].t1, 4.0f, 1e-6f);
    EXPECT_GT(dot(normalize(sp[0].n0), Vec3(-1, 0, 0)), 0.9999f);
    // Nearly along the axis: the far crossings are found, not lost to rounding.
    Ray slant{Vec3(0, 0, 0), 0, normalize(Vec3(1e-4f, 0, 1)), 1e30f};
    ASSERT_EQ(shape_spans(s, slant, sp, {&cyl}), 1);
    EXPECT_NEAR(sp[0].t1, 1e4f, 1.0f);
    // Without coefficients a poly shape is never hit.
    EXPECT_EQ(shape_spans(s, across, sp), 0);
}

} // namespace
} // namespace sheaf

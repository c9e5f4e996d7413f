// Analytic shapes against their implicit definitions: along random rays, a point is inside a
// span exactly when the shape's inside test says so (away from the boundary), and span ends
// carry the outward normal.
#include "core/geometry/shape.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

// Signed "inside" of each canonical solid: negative inside.
double implicit(const Shape& s, Vec3 p) {
    const double x = p.x, y = p.y, z = p.z;
    switch (s.kind) {
    case ShapeKind::Sphere:
        return x * x + y * y + z * z - 1;
    case ShapeKind::Box:
        return std::max({std::fabs(x), std::fabs(y), std::fabs(z)}) - 1;
    case ShapeKind::Cylinder:
        return std::max(std::sqrt(x * x + y * y) - 1, std::max(-z, z - 1));
    case ShapeKind::Cone: {
        const double r = s.a + (double(s.b) - s.a) * z;
        return std::max(std::sqrt(x * x + y * y) - r, std::max(-z, z - 1));
    }
    case ShapeKind::Plane:
        return z;
    case ShapeKind::Torus: {
        const double q = std::sqrt(x * x + y * y) - 1;
        return std::sqrt(q * q + z * z) - s.a;
    }
    case ShapeKind::Superellipsoid: {
        const double e = s.a, n = s.b;
        if (std::max({std::fabs(x), std::fabs(y), std::fabs(z)}) > 1 + 1e-5) return 1;
        return std::pow(std::pow(std::fabs(x), 2 / e) + std::pow(std::fabs(y), 2 / e), e / n) +
               std::pow(std::fabs(z), 2 / n) - 1;
    }
    case ShapeKind::Disc:
    case ShapeKind::Poly: // poly_test.cpp
        return 1;
    }
    return 1;
}

// Near an edge of a box, cylinder or cone the normal is not defined by one face.
bool near_edge(const Shape& s, Vec3 p) {
    const float e = 0.01f;
    if (s.kind == ShapeKind::Box)
        return (std::fabs(p.x) > 1 - e) + (std::fabs(p.y) > 1 - e) + (std::fabs(p.z) > 1 - e) >= 2;
    if (s.kind == ShapeKind::Cylinder || s.kind == ShapeKind::Cone) {
        const float r = s.kind == ShapeKind::Cylinder ? 1.0f : s.a + (s.b - s.a) * p.z;
        return std::fabs(std::sqrt(p.x * p.x + p.y * p.y) - r) < e && (p.z < e || p.z > 1 - e);
    }
    if (s.kind == ShapeKind::Superellipsoid) // creases on the coordinate planes when pinched
        return std::min({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) < 0.02f;
    return false;
}

Vec3 gradient(const Shape& s, Vec3 p) {
    const float h = 1e-3f;
    return normalize(Vec3(float(implicit(s, p + Vec3(h, 0, 0)) - implicit(s, p - Vec3(h, 0, 0))),
                          float(implicit(s, p + Vec3(0, h, 0)) - implicit(s, p - Vec3(0, h, 0))),
                          float(implicit(s, p + Vec3(0, 0, h)) - implicit(s, p - Vec3(0, 0, h)))));
}

void check_solid(const Shape& s, uint32_t seed) {
    std::mt19937 g(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int k = 0; k < 400; ++k) {
        Ray r;
        r.origin = Vec3(u(g), u(g), u(g)) * 3.0f + Vec3(0, 0, 0.5f);
        const Vec3 target = Vec3(u(g), u(g), u(g) * 0.6f + 0.5f) * 0.9f;
        r.dir = (target - r.origin) * (0.5f + 0.5f * (u(g) + 1)); // not unit: like a local ray
        r.tmin = -1e30f, r.tmax = 1e30f;
        Span spans[kMaxShapeSpans];
        const int n = shape_spans(s, r, spans);
        hits += n > 0;
        for (int i = 0; i + 1 < n; ++i) EXPECT_LE(spans[i].t1, spans[i + 1].t0);
        for (float t = -1.0f; t <= 4.0f; t += 0.01f) {
            const Vec3 p = ray_at(r, t);
            const double f = implicit(s, p);
            if (std::fabs(f) < 2e-3) continue; // too close to the surface to judge
            bool in = false;
            for (int i = 0; i < n; ++i) in |= t >= spans[i].t0 && t <= spans[i].t1;
            ASSERT_EQ(in, f < 0) << "kind " << int(s.kind) << " a " << s.a << " b " << s.b
                                 << " ray " << k << " t " << t << " f " << f;
        }
        for (int i = 0; i < n; ++i)
            for (const auto& [t, nl] :
                 {std::pair{spans[i].t0, spans[i].n0}, std::pair{spans[i].t1, spans[i].n1}}) {
                if (std::fabs(t) > 1e20f) continue;
                const Vec3 p = ray_at(r, t);
                EXPECT_NEAR(implicit(s, p), 0.0, 1e-3)
                    << "span end off the surface, kind " << int(s.kind);
                const Vec3 gr = gradient(s, p);
                // Edges and corners have no single normal; elsewhere it must match the gradient.
                if (!near_edge(s, p)) {
                    EXPECT_GT(dot(normalize(nl), gr), 0.99f) << "normal, kind " << int(s.kind);
                }
            }
    }
    EXPECT_GT(hits, 40) << "kind " << int(s.kind);
}

TEST(Shapes, SolidsMatchTheirImplicitForms) {
    check_solid({ShapeKind::Sphere}, 1);
    check_solid({ShapeKind::Box}, 2);
    check_solid({ShapeKind::Cylinder}, 3);
    check_solid({ShapeKind::Cone, 1.0f, 0.3f}, 4);
    check_solid({ShapeKind::Cone, 0.0f, 1.0f}, 5);
    check_solid({ShapeKind::Plane}, 6);
    check_solid({ShapeKind::Torus, 0.3f}, 7);
    check_solid({ShapeKind::Superellipsoid, 1.0f, 1.0f}, 8);  // a ball
    check_solid({ShapeKind::Superellipsoid, 0.25f, 0.5f}, 9); // a rounded box
    check_solid({ShapeKind::Superellipsoid, 2.0f, 2.0f}, 10); // an octahedron
    check_solid({ShapeKind::Superellipsoid, 3.0f, 1.0f}, 11); // pinched around z: not convex
    check_solid({ShapeKind::Superellipsoid, 1.0f, 2.5f}, 12); // pinched along z
}

TEST(Shapes, SurfacesAreHitOnTheirSurface) {
    std::mt19937 g(8);
    std::uniform_real_distribution<float> u(-1, 1);
    int disc_hits = 0, tube_hits = 0;
    for (int k = 0; k < 500; ++k) {
        Ray r;
        r.origin = Vec3(u(g), u(g), u(g)) * 3.0f;
        r.dir = normalize(Vec3(u(g), u(g), u(g) * 0.5f + 0.5f) * 0.8f - r.origin);
        r.tmin = 0, r.tmax = 1e30f;
        Span s[kMaxShapeSpans];
        const int nd = shape_spans({ShapeKind::Disc, 0.25f}, r, s);
        for (int i = 0; i < nd; ++i) {
            const Vec3 p = ray_at(r, s[i].t0);
            EXPECT_NEAR(p.z, 0.0f, 1e-4f);
            const float rr = std::sqrt(p.x * p.x + p.y * p.y);
            EXPECT_LE(rr, 1.0f + 1e-5f);
            EXPECT_GE(rr, 0.25f - 1e-5f);
            EXPECT_EQ(s[i].t0, s[i].t1);
            ++disc_hits;
        }
        const int nt = shape_spans({ShapeKind::Cylinder, 0, 0, true}, r, s);
        for (int i = 0; i < nt; ++i) {
            const Vec3 p = ray_at(r, s[i].t0);
            EXPECT_NEAR(p.x * p.x + p.y * p.y, 1.0f, 1e-3f);
            EXPECT_GE(p.z, -1e-4f);
            EXPECT_LE(p.z, 1.0f + 1e-4f);
            ++tube_hits;
        }
    }
    EXPECT_GT(disc_hits, 20);
    EXPECT_GT(tube_hits, 20);
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// A sphere far larger than the scene around it, centred far from the rays' origins (a planet
// of radius 50,000 under a camera 1 unit above it, advanced/mediasky.pov): its hits lie on its
// surface to well within the offset of the rays that leave them, so a mirror ray from its
// surface does not find it again.
TEST(Shapes, AHugeSpheresHitsLieOnItsSurface) {
    const double R = 50000;
    PlacedShape ps;
    ps.shape = {ShapeKind::Sphere};
    // world -> local: (p + R y) / R
    ps.to_local = Affine::scale(Vec3(float(1 / R))) * Affine::translate(Vec3(0, float(R), 0));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    double lo = 1e30, hi = -1e30;
    for (int i = 0; i < 200; ++i) {
        Ray r;
        r.origin = Vec3(-5 + u(rng), 1 + 0.5f * u(rng), -25 + u(rng));
        r.dir = normalize(Vec3(u(rng), -0.2f - 0.7f * (u(rng) + 1) / 2, 1));
        r.tmax = 1e30f;
        Span sp[kMaxShapeSpans];
        ASSERT_GE(shape_spans(ps.shape, to_local_ray(ps, r), sp), 1);
        const Vec3 p = r.origin + r.dir * sp[0].t0;
        const double y = double(p.y) + R;
        const double off = std::sqrt(double(p.x) * p.x + y * y + double(p.z) * p.z) - R;
        lo = std::min(lo, off), hi = std::max(hi, off);
    }
    // The sphere's float scale rounds its radius (the same for every ray); around that, float
    // positions here are good to about 4e-6. A float local origin scattered the hits over
    // about 4e-3, ten times the offset of the rays leaving them.
    EXPECT_LT(hi - lo, 1e-4) << lo << " .. " << hi;
    EXPECT_LT(std::fabs(lo), 2e-3);
}

} // namespace
} // namespace sheaf

// Brute-force checks of the cone-sphere test (paper 000 eq. 9, node sphere folded into the
// primitive sphere): it must be conservative, and not trivially true.
#include "core/geometry/cone_sphere.h"
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

struct Node {
    RayNode node;
    Sphere sphere;
    Cone cone;
};

// A node built the way the hierarchy builds it: the union of radius-0 spheres at the ray
// origins and of angle-0 cones along the ray directions.
Node make_node(std::mt19937& g, Vec3 center, float spread, Vec3 axis, float half_angle, int rays) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Sphere> origins(rays);
    std::vector<Cone> dirs(rays);
    for (int i = 0; i < rays; ++i) {
        origins[i] = {center + random_unit(g) * float(spread * std::cbrt(u(g))), 0.0f};
        // Half the rays on the boundary of the generating cone.
        const double theta = (i % 2 == 0) ? half_angle : half_angle * std::sqrt(u(g));
        dirs[i] = {normalize(direction_at(axis, theta, g)), 0.0f};
    }
    Node n;
    n.sphere = sphere_union(origins.data(), rays);
    n.cone = cone_union(dirs.data(), rays);
    n.node = make_ray_node(n.sphere, n.cone);
    return n;
}

// A ray of the node: origin in its sphere (often on the surface), direction in its cone (often
// on the boundary), shrunk by a hair so that rounding cannot carry it outside the node.
void sample_ray(const Node& n, std::mt19937& g, Vec3& o, Vec3& d) {
    std::uniform_real_distribution<double> u(0, 1);
    const double r = n.sphere.radius * (1 - 1e-5) * (g() % 2 ? 1.0 : std::cbrt(u(g)));
    o = n.sphere.center + random_unit(g) * float(r);
    const double a = std::max(0.0, n.cone.angle - 1e-5);
    const double theta = g() % 2 ? a : a * std::sqrt(u(g));
    d = direction_at(n.cone.axis, theta, g);
}

// Analytic ray-sphere test in double: does {o + t d, t >= 0} meet the ball (c, r)? `margin`
// shrinks the ball, so only clear hits count.
bool ray_hits(Vec3 o, Vec3 d, const Sphere& s, double margin) {
    const Vec3d dd = to_double(d);
    const double dl = std::sqrt(dot(dd, dd));
    const Vec3d dn{dd.x / dl, dd.y / dl, dd.z / dl};
    const Vec3d w{double(s.center.x) - o.x, double(s.center.y) - o.y, double(s.center.z) - o.z};
    const double t = std::max(0.0, dot(w, dn));
    const Vec3d q{w.x - t * dn.x, w.y - t * dn.y, w.z - t * dn.z};
    const double r = s.radius - margin;
    return r >= 0 && dot(q, q) <= r * r;
}

float angle_for(int kind, std::mt19937& g) {
    std::uniform_real_distribution<float> u(0, 1);
    switch (kind % 6) {
    case 0:
        return 0.002f + 0.02f * u(g); // narrow
    case 1:
        return 0.3f * u(g); // moderate
    case 2:
        return 0.5f + 0.9f * u(g); // wide, under 86 degrees
    case 3:
        return 1.4f + 0.15f * u(g); // around the 1.5 rad switch
    case 4:
        return 1.6f + 0.4f * u(g); // above 90 degrees
    default:
        return 2.0f + 1.1f * u(g); // nearly everything
    }
}

// Many random nodes and primitive spheres; every sampled ray that clearly hits a primitive
// must have been let through. Returns the number of (node, primitive) pairs the test passed
// with no sampled ray hitting, and the number it rejected.
void check_random(std::mt19937& g, int kind, int nodes, int& pairs, int& passed, int& hits,
                  int& rejected) {
    std::uniform_real_distribution<float> u(0, 1);
    for (int k = 0; k < nodes; ++k) {
        const Vec3 c = Vec3(u(g), u(g), u(g)) * 20.0f - Vec3(10.0f);
        const float spread = (k % 4 == 0) ? 0.0f : 0.05f + 0.5f * u(g);
        const Node n = make_node(g, c, spread, random_unit(g), angle_for(kind, g), 8 + k % 9);
        for (int p = 0; p < 24; ++p) {
            Sphere prim;
            const float dist = 0.5f + 15.0f * u(g);
            // Near the cone boundary half the time, anywhere otherwise; some behind the node.
            Vec3 dir;
            if (p % 4 == 0)
                dir = direction_at(n.cone.axis, n.cone.angle + (u(g) - 0.5f) * 0.4f, g);
            else if (p % 4 == 1)
                dir = -n.cone.axis;
            else
                dir = random_unit(g);
            prim.center = n.sphere.center + dir * dist;
            prim.radius = (p % 3 == 0) ? 0.02f + 0.2f * u(g) : 0.1f + 3.0f * u(g);
            const bool test = node_hits_sphere(n.node, prim);
            bool any = false;
            for (int r = 0; r < 64 && !any; ++r) {
                Vec3 o, d;
                sample_ray(n, g, o, d);
                if (ray_hits(o, d, prim, 1e-5 * (1 + dist))) {
                    any = true;
                    ASSERT_TRUE(test)
                        << "a ray of the node hits the primitive, the test says no: "
                        << "node angle " << n.cone.angle << ", radius " << n.sphere.radius
                        << ", primitive at " << dist << " radius " << prim.radius;
                }
            }
            ++pairs;
            hits += any;
            passed += test && !any;
            rejected += !test;
        }
    }
}

TEST(NodeHitsSphere, ConservativeOnRandomNodes) {
    std::mt19937 g(301);
    for (int kind = 0; kind < 6; ++kind) {
        int pairs = 0, passed = 0, hits = 0, rejected = 0;
        check_random(g, kind, 60, pairs, passed, hits, rejected);
        // Not trivially true: for each kind of cone some pairs are culled, and hits do occur.
        EXPECT_GT(hits, 0) << "kind " << kind;
        EXPECT_GT(rejected, 0) << "kind " << kind;
        // False positives (passed, yet no sampled ray hit) are below 100% of the non-hits.
        EXPECT_LT(passed, pairs - hits) << "kind " << kind;
    }
}

// Adversarial: pick a ray of the node (origin on the node sphere's surface, direction on the
// cone's boundary), a point X on it, and a primitive sphere holding X close to its surface.
// Some ray of the node then reaches the primitive, so the test must pass it.
TEST(NodeHitsSphere, ConservativeForSpheresTouchingANodeRay) {
    std::mt19937 g(302);
    std::uniform_real_distribution<float> u(0, 1);
    for (int kind = 0; kind < 6; ++kind) {
        for (int k = 0; k < 300; ++k) {
            const Vec3 c = Vec3(u(g), u(g), u(g)) * 200.0f - Vec3(100.0f);
            const float spread = (k % 3 == 0) ? 0.0f : 0.01f + u(g);
            const Node n = make_node(g, c, spread, random_unit(g), angle_for(kind, g), 8);
            for (int p = 0; p < 20; ++p) {
                Vec3 o, d;
                sample_ray(n, g, o, d);
                const float t = (p % 5 == 0) ? 0.0f : 50.0f * u(g) * u(g);
                const Vec3 x = o + d * t;
                Sphere prim;
                prim.radius = (p % 2 == 0) ? 1e-3f + 0.05f * u(g) : 0.05f + 5.0f * u(g);
                // X lies inside the primitive, at 0.999 of its radius or less.
                prim.center = x + random_unit(g) * (prim.radius * (p % 3 == 0 ? 0.999f : u(g)));
                if (!ray_hits(o, d, prim, 0.0)) continue; // float rounding of the construction
                ASSERT_TRUE(node_hits_sphere(n.node, prim))
                    << "kind " << kind << ", node angle " << n.cone.angle << ", radius "
                    << n.sphere.radius << ", t " << t << ", primitive radius " << prim.radius;
            }
        }
    }
}

TEST(NodeHitsSphere, NodeCentreInsidePrimitive) {
    std::mt19937 g(303);
    for (int k = 0; k < 500; ++k) {
        const Node n = make_node(g, Vec3(1, 2, 3), 0.3f, random_unit(g), angle_for(k, g), 8);
        Sphere prim{n.sphere.center + random_unit(g) * 0.5f, 0.6f};
        EXPECT_TRUE(node_hits_sphere(n.node, prim));
        // A primitive behind the node that still reaches into its origin sphere.
        prim = {n.sphere.center - n.cone.axis * (n.sphere.radius + 0.5f), 0.6f};
        EXPECT_TRUE(node_hits_sphere(n.node, prim));
    }
}

TEST(NodeHitsSphere, RejectsClearlySeparatedSpheres) {
    const Vec3 z(0, 0, 1);
    const std::vector<float> narrow = {0.0f, 0.01f, 0.1f, 0.5f, 1.0f, 1.45f, 1.5f, 1.55f};
    for (float a : narrow) {
        const RayNode n = make_ray_node({Vec3(0, 0, 0), 0.5f}, {z, a});
        // Far behind a forward cone.
        EXPECT_FALSE(node_hits_sphere(n, {Vec3(0, 0, -100), 1.0f})) << a;
        EXPECT_FALSE(node_hits_sphere(n, {Vec3(3, -2, -50), 5.0f})) << a;
        // Ahead, on the axis: always reachable.
        EXPECT_TRUE(node_hits_sphere(n, {Vec3(0, 0, 100), 1.0f})) << a;
    }
    // Far to the side of narrow cones.
    for (float a : {0.0f, 0.01f, 0.1f, 0.3f}) {
        const RayNode n = make_ray_node({Vec3(0, 0, 0), 0.5f}, {z, a});
        EXPECT_FALSE(node_hits_sphere(n, {Vec3(100, 0, 0), 1.0f})) << a;
        EXPECT_FALSE(node_hits_sphere(n, {Vec3(50, 0, 20), 1.0f})) << a;
    }
    // A wide cone (115 degrees) reaches sideways and slightly back, but not straight back.
    const RayNode wide = make_ray_node({Vec3(0, 0, 0), 0.5f}, {z, 2.0f});
    EXPECT_TRUE(node_hits_sphere(wide, {Vec3(100, 0, 0), 1.0f}));
    EXPECT_TRUE(node_hits_sphere(wide, {Vec3(100, 0, -20), 1.0f}));
    EXPECT_FALSE(node_hits_sphere(wide, {Vec3(0, 0, -100), 1.0f}));
    EXPECT_FALSE(node_hits_sphere(wide, {Vec3(10, 0, -100), 1.0f}));
    // The full sphere of directions reaches everything.
    const RayNode all = make_ray_node({Vec3(0, 0, 0), 0.0f}, {z, kPi});
    EXPECT_TRUE(node_hits_sphere(all, {Vec3(0, 0, -100), 0.0f}));
}

// A sphere just off a narrow cone's boundary: eq. (9) must resolve it both ways.
TEST(NodeHitsSphere, TightNearTheBoundary) {
    std::mt19937 g(304);
    for (float a : {0.05f, 0.4f, 1.0f, 1.45f, 1.6f, 2.2f}) {
        const RayNode n = make_ray_node({Vec3(0, 0, 0), 0.0f}, {Vec3(0, 0, 1), a});
        for (int k = 0; k < 200; ++k) {
            const float dist = 10.0f, r = 0.5f;
            const double reach = std::asin(r / dist);
            // Centre at angle a + reach - 0.01 from the axis: the boundary ray passes inside.
            Sphere in{direction_at(Vec3(0, 0, 1), a + reach - 0.01, g) * dist, r};
            EXPECT_TRUE(node_hits_sphere(n, in)) << a;
            // At a + reach + 0.01 every ray of the cone misses; only the conservative slack of
            // eq. (9) behind the apex could let it pass, and here the sphere is ahead or wide.
            Sphere out{direction_at(Vec3(0, 0, 1), a + reach + 0.01, g) * dist, r};
            if (a + reach + 0.01 < M_PI / 2 || a >= 1.5f) {
                EXPECT_FALSE(node_hits_sphere(n, out)) << a;
            }
        }
    }
}

} // namespace
} // namespace sheaf

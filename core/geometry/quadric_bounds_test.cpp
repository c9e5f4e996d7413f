// Boxes of quadrics cut by boxes: every point of the solid inside the box stays inside the
// narrowed box, and shapes.inc's unbounded quadrics cut by planes get finite boxes.
#include "core/geometry/quadric_bounds.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

// POV-Ray's quadric { <a, b, c>, <d, e, f>, <g, h, i>, j }: a x^2 + b y^2 + c z^2 + d xy +
// e xz + f yz + g x + h y + i z + j, in the polynomial's 35 terms.
PolyCoeffs quadric(double a, double b, double c, double d, double e, double f, double g,
                   double h, double i, double j) {
    PolyCoeffs p;
    poly_detail::for_each_term([&](int term, int x, int y, int z) {
        const int key = x * 100 + y * 10 + z;
        double v = 0;
        switch (key) {
        case 200: v = a; break;
        case 20: v = b; break;
        case 2: v = c; break;
        case 110: v = d; break;
        case 101: v = e; break;
        case 11: v = f; break;
        case 100: v = g; break;
        case 10: v = h; break;
        case 1: v = i; break;
        case 0: v = j; break;
        }
        p.c[term] = v;
    });
    return p;
}

double eval(const PolyCoeffs& p, Vec3 u) {
    double s = 0;
    poly_detail::for_each_term([&](int term, int x, int y, int z) {
        s += p.c[term] * std::pow(double(u.x), x) * std::pow(double(u.y), y) * std::pow(double(u.z), z);
    });
    return s;
}

TEST(QuadricBounds, HyperboloidBetweenTwoPlanesIsBoundedAcross) {
    // Hyperboloid_Y (x^2 - y^2 + z^2 - 1) scaled by <0.5, 1, 0.5> and cut to 2.5 <= y <= 5.5.
    const PolyCoeffs h = quadric(1, -1, 1, 0, 0, 0, 0, 0, 0, -1);
    const Affine to_local = Affine::scale(Vec3(0.5f, 1, 0.5f)).inverse();
    WorldQuadric w;
    ASSERT_TRUE(world_quadric(h, to_local, w));
    WorldBox b;
    b.lo.y = 2.5f, b.hi.y = 5.5f;
    narrow_by_quadric(w, b);
    // |x| <= 0.5 sqrt(1 + 5.5^2) = 2.795 and likewise z.
    EXPECT_NEAR(b.hi.x, 0.5 * std::sqrt(1 + 5.5 * 5.5), 1e-4);
    EXPECT_NEAR(b.lo.x, -0.5 * std::sqrt(1 + 5.5 * 5.5), 1e-4);
    EXPECT_NEAR(b.hi.z, 0.5 * std::sqrt(1 + 5.5 * 5.5), 1e-4);
    EXPECT_EQ(b.lo.y, 2.5f);
    EXPECT_EQ(b.hi.y, 5.5f);
}

TEST(QuadricBounds, NotAQuadricIsLeftAlone) {
    PolyCoeffs p;
    p.c[0] = 1; // x^4
    WorldQuadric w;
    EXPECT_FALSE(world_quadric(p, Affine(), w));
}

TEST(QuadricBounds, EveryPointOfTheSolidInTheBoxStaysInside) {
    std::mt19937 g(9);
    std::uniform_real_distribution<double> u(-1, 1);
    int narrowed = 0;
    for (int k = 0; k < 300; ++k) {
        // A random quadric (cross terms and all), placed by a random rotation, scale and move.
        const PolyCoeffs p = quadric(u(g), u(g), u(g), u(g), u(g), u(g), u(g), u(g), u(g), u(g));
        const Affine to_world = Affine::translate(Vec3(float(u(g)), float(u(g)), float(u(g)))) *
                                Affine::rotate(normalize(Vec3(float(u(g)), float(u(g)), 0.3f)),
                                               float(u(g) * 3)) *
                                Affine::scale(Vec3(float(1.5 + u(g)), float(1.5 + u(g)), 1.0f));
        const Affine to_local = to_world.inverse();
        WorldQuadric w;
        ASSERT_TRUE(world_quadric(p, to_local, w));
        // A box bounded on one to three axes (planes cut it), the others infinite.
        WorldBox box;
        for (int a = 0; a < 3; ++a)
            if (k % 3 >= a) box.lo[a] = float(-2 + u(g)), box.hi[a] = float(2 + u(g));
        WorldBox n = box;
        narrow_by_quadric(w, n);
        for (int a = 0; a < 3; ++a) narrowed += n.lo[a] > box.lo[a] || n.hi[a] < box.hi[a];
        for (int s = 0; s < 3000; ++s) {
            Vec3 pt;
            for (int a = 0; a < 3; ++a) {
                const double lo = std::isfinite(box.lo[a]) ? box.lo[a] : -40,
                             hi = std::isfinite(box.hi[a]) ? box.hi[a] : 40;
                pt[a] = float(lo + (hi - lo) * (0.5 + 0.5 * u(g)));
            }
            if (!(eval(p, to_local.point(pt)) < 0)) continue;
            for (int a = 0; a < 3; ++a)
                ASSERT_TRUE(pt[a] >= n.lo[a] && pt[a] <= n.hi[a])
                    << "quadric " << k << " axis " << a << ": " << pt[a] << " outside ["
                    << n.lo[a] << ", " << n.hi[a] << "]";
        }
    }
    EXPECT_GT(narrowed, 40); // where the quadric and the box allow it (58 sides of 900 here)
}

} // namespace
} // namespace sheaf

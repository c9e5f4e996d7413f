#include "core/geometry/min_sphere.h"
#include "core/math/vec3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sheaf {
namespace {

struct Ball {
    Vec3d c{0, 0, 0};
    double r2 = -1; // empty
};

bool inside(const Ball& b, Vec3d p, double tol) {
    return b.r2 >= 0 && dot(p - b.c, p - b.c) <= b.r2 * (1 + tol) + tol * 1e-12;
}

Ball ball2(Vec3d a, Vec3d b) {
    Ball r;
    r.c = (a + b) * 0.5;
    r.r2 = dot(a - r.c, a - r.c);
    return r;
}

// Smallest ball with a, b, c on its boundary (the circumscribed circle's ball); falls back to
// the widest pair when the points are collinear.
Ball ball3(Vec3d a, Vec3d b, Vec3d c) {
    const Vec3d ab = b - a, ac = c - a;
    const Vec3d n = cross(ab, ac);
    const double nn = dot(n, n);
    if (nn <= 1e-30 * dot(ab, ab) * dot(ac, ac)) {
        Ball best = ball2(a, b);
        for (const Ball& cand : {ball2(a, c), ball2(b, c)})
            if (cand.r2 > best.r2) best = cand;
        return best;
    }
    Ball r;
    r.c = a + (cross(n, ab) * dot(ac, ac) + cross(ac, n) * dot(ab, ab)) * (0.5 / nn);
    r.r2 = dot(a - r.c, a - r.c);
    return r;
}

// Ball with a, b, c, d on its boundary; coplanar sets fall back to the smallest of the
// three-point balls that hold all four.
Ball ball4(Vec3d a, Vec3d b, Vec3d c, Vec3d d) {
    const Vec3d ab = b - a, ac = c - a, ad = d - a;
    const double det = dot(ab, cross(ac, ad));
    const double scale = std::sqrt(dot(ab, ab) * dot(ac, ac) * dot(ad, ad));
    if (std::fabs(det) <= 1e-12 * scale) {
        std::array<Vec3d, 4> p{a, b, c, d};
        Ball best;
        for (int skip = 0; skip < 4; ++skip) {
            std::array<Vec3d, 3> q;
            for (int i = 0, k = 0; i < 4; ++i)
                if (i != skip) q[k++] = p[i];
            Ball cand = ball3(q[0], q[1], q[2]);
            if (inside(cand, p[skip], 1e-9) && (best.r2 < 0 || cand.r2 < best.r2)) best = cand;
        }
        return best.r2 >= 0 ? best : ball3(a, b, c);
    }
    const Vec3d num =
        cross(ac, ad) * dot(ab, ab) + cross(ad, ab) * dot(ac, ac) + cross(ab, ac) * dot(ad, ad);
    Ball r;
    r.c = a + num * (0.5 / det);
    r.r2 = dot(a - r.c, a - r.c);
    return r;
}

constexpr double kTol = 1e-10;

// Welzl's recursion unrolled by the number of boundary points, with move-to-front: a point
// found outside moves to the front so that later passes meet it early (Gaertner).
Ball with3(std::vector<Vec3d>& p, size_t end, Vec3d q1, Vec3d q2, Vec3d q3) {
    Ball b = ball3(q1, q2, q3);
    for (size_t i = 0; i < end; ++i)
        if (!inside(b, p[i], kTol)) b = ball4(q1, q2, q3, p[i]);
    return b;
}

Ball with2(std::vector<Vec3d>& p, size_t end, Vec3d q1, Vec3d q2) {
    Ball b = ball2(q1, q2);
    for (size_t i = 0; i < end; ++i)
        if (!inside(b, p[i], kTol)) {
            b = with3(p, i, q1, q2, p[i]);
            std::rotate(p.begin(), p.begin() + i, p.begin() + i + 1);
        }
    return b;
}

Ball with1(std::vector<Vec3d>& p, size_t end, Vec3d q) {
    Ball b;
    b.c = q;
    b.r2 = 0;
    for (size_t i = 0; i < end; ++i)
        if (!inside(b, p[i], kTol)) {
            b = with2(p, i, q, p[i]);
            std::rotate(p.begin(), p.begin() + i, p.begin() + i + 1);
        }
    return b;
}

} // namespace

Sphere min_sphere(std::span<const Vec3> points) {
    if (points.empty()) return {Vec3(0.0f), 0.0f};
    std::vector<Vec3d> p;
    p.reserve(points.size());
    for (Vec3 v : points) p.push_back({v.x, v.y, v.z});
    // A fixed pseudo-random order gives Welzl's expected linear time deterministically.
    uint64_t state = 0x9E3779B97F4A7C15ull;
    for (size_t i = p.size(); i > 1; --i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        std::swap(p[i - 1], p[(state >> 33) % i]);
    }
    Ball b;
    b.c = p[0];
    b.r2 = 0;
    for (size_t i = 1; i < p.size(); ++i)
        if (!inside(b, p[i], kTol)) b = with1(p, i, p[i]);

    Sphere s;
    s.center = Vec3(float(b.c.x), float(b.c.y), float(b.c.z));
    // Whatever the rounding, every input point ends up inside the float sphere.
    float r = 0;
    for (Vec3 v : points) r = std::max(r, length(v - s.center));
    s.radius = pad_radius(r, s.center);
    return s;
}

} // namespace sheaf

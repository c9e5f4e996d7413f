// The ray hierarchy is conservative: every ray lies in its node's sphere and cone, and every
// node in its parent's. Levels are built here node by node with build_ray_node, as the tracer
// (core/frame/wavefront_tracer.h) builds them with one launch a level.
#include "core/rsh/hierarchy.h"

#include "core/base/memory.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

struct RayHierarchy {
    int depth = 0, arity = 0;
    size_t ray_count = 0;
    // levels[k - 1] holds the nodes of level k: level 1 sits on the rays, level `depth` is the top.
    std::vector<TrackedVector<RayNode>> levels;

    size_t node_count(int level) const {
        return level == 0 ? ray_count : levels[size_t(level) - 1].size();
    }
    /// The children of node i of `level` are [first, last) of level - 1 (rays when level is 1).
    size_t first_child(size_t i) const { return i * size_t(arity); }
    size_t last_child(int level, size_t i) const {
        const size_t e = (i + 1) * size_t(arity), n = node_count(level - 1);
        return e < n ? e : n;
    }
};

RayHierarchy build_hierarchy(const TrackedVector<Ray>& rays, int depth, int arity,
                             MemoryTracker& memory, bool bound_reach = false) {
    RayHierarchy h;
    h.depth = depth, h.arity = arity, h.ray_count = rays.size();
    for (int level = 1; level <= depth; ++level) {
        const size_t below = h.node_count(level - 1);
        TrackedVector<RayNode> nodes =
            tracked_vector<RayNode>(memory, (below + size_t(arity) - 1) / size_t(arity));
        const RayNode* children = level == 1 ? nullptr : h.levels[size_t(level) - 2].data();
        for (size_t i = 0; i < nodes.size(); ++i)
            nodes[i] = build_ray_node(rays.data(), children, h.first_child(i),
                                      h.last_child(level, i), bound_reach);
        h.levels.push_back(std::move(nodes));
    }
    return h;
}

TrackedVector<Ray> random_rays(MemoryTracker& m, size_t n, uint32_t seed) {
    std::mt19937 g(seed);
    std::normal_distribution<float> nd;
    std::uniform_real_distribution<float> u(-5, 5);
    TrackedVector<Ray> rays = tracked_vector<Ray>(m, n);
    Vec3 o(u(g), u(g), u(g)), d = normalize(Vec3(nd(g), nd(g), nd(g)));
    for (size_t i = 0; i < n; ++i) {
        // Locally coherent runs with jumps, like sorted rays.
        if (i % 13 == 0) o = Vec3(u(g), u(g), u(g)), d = normalize(Vec3(nd(g), nd(g), nd(g)));
        rays[i].origin = o + Vec3(nd(g), nd(g), nd(g)) * 0.1f;
        rays[i].dir = normalize(d + Vec3(nd(g), nd(g), nd(g)) * (i % 3 == 0 ? 1.5f : 0.05f));
        rays[i].tmax = 1e30f;
    }
    return rays;
}

TEST(Hierarchy, LevelSizesFollowDepthAndArity) {
    MemoryTracker m;
    const auto rays = random_rays(m, 1000, 1);
    const RayHierarchy h = build_hierarchy(rays, 3, 8, m);
    EXPECT_EQ(h.node_count(0), 1000u);
    EXPECT_EQ(h.node_count(1), 125u);
    EXPECT_EQ(h.node_count(2), 16u);
    EXPECT_EQ(h.node_count(3), 2u);
    EXPECT_EQ(h.last_child(3, 1), 16u);
    EXPECT_GT(m.peak(), 0);
}

TEST(Hierarchy, EveryRayLiesInsideEveryAncestor) {
    MemoryTracker m;
    for (int arity : {2, 3, 8, 16})
        for (int depth : {1, 2, 4}) {
            const auto rays = random_rays(m, 2001, uint32_t(arity * 10 + depth));
            const RayHierarchy h = build_hierarchy(rays, depth, arity, m);
            for (size_t r = 0; r < rays.size(); ++r) {
                size_t idx = r;
                for (int level = 1; level <= depth; ++level) {
                    idx /= size_t(arity);
                    const RayNode& n = h.levels[size_t(level) - 1][idx];
                    ASSERT_LE(length(rays[r].origin - n.center), n.radius) << "level " << level;
                    ASSERT_LE(angle_between(n.axis, rays[r].dir), n.angle + 1e-6f)
                        << "level " << level;
                }
            }
            // Children inside parents.
            for (int level = 2; level <= depth; ++level)
                for (size_t i = 0; i < h.node_count(level); ++i) {
                    const RayNode& p = h.levels[size_t(level) - 1][i];
                    for (size_t c = h.first_child(i); c < h.last_child(level, i); ++c) {
                        const RayNode& ch = h.levels[size_t(level) - 2][c];
                        ASSERT_LE(length(ch.center - p.center) + ch.radius, p.radius * (1 + 1e-6f));
                        if (p.angle >= kPi) continue; // the parent holds every direction
                        ASSERT_LE(angle_between(ch.axis, p.axis) + ch.angle, p.angle + 1e-5f);
                    }
                }
        }
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// A node's reach holds every point of its rays: origin + t dir for t up to tmax.
TEST(Hierarchy, ReachBoundsEveryRayPoint) {
    std::mt19937 g(21);
    std::uniform_real_distribution<float> u(-5, 5), len(0.1f, 3.0f);
    TrackedVector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
        Ray r;
        r.origin = Vec3(u(g), u(g), u(g));
        r.dir = normalize(Vec3(u(g), u(g), u(g)));
        r.tmax = len(g);
        rays.push_back(r);
    }
    MemoryTracker m;
    const RayHierarchy h = build_hierarchy(rays, 3, 4, m, true);
    for (int level = 1; level <= 3; ++level)
        for (size_t i = 0; i < h.node_count(level); ++i) {
            const RayNode& n = h.levels[size_t(level) - 1][i];
            ASSERT_LT(n.reach, INFINITY);
            // The rays under node i of this level.
            size_t first = i, last = i + 1;
            for (int l = level; l >= 1; --l) first *= 4, last = std::min(last * 4, h.node_count(l - 1));
            for (size_t j = first; j < last; ++j)
                for (float t : {0.0f, rays[j].tmax * 0.5f, rays[j].tmax})
                    ASSERT_LE(length(rays[j].origin + rays[j].dir * t - n.center), n.reach);
        }
    // Rays without an end, or reach not bounded: infinite.
    EXPECT_EQ(build_hierarchy(rays, 2, 4, m, false).levels[1][0].reach, INFINITY);
}

} // namespace
} // namespace sheaf

// The BVH is valid (every bounded primitive in exactly one leaf, every box inside its parent's
// and around its primitives, the stack bound kept), and frames under accel=bvh are the frames
// of brute force and crsh, on both traversal paths of the pipeline.
#include "core/accel/bvh.h"

#include "core/frame/render_frame.h"
#include "core/rsh/cull_units.h"
#include "tests/support/accel_scenes.h"
#include "tests/support/same_image.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

struct Box3 {
    Vec3 lo, hi;
};

bool inside(const Vec3& p, const Box3& b) {
    return p.x >= b.lo.x && p.y >= b.lo.y && p.z >= b.lo.z && p.x <= b.hi.x && p.y <= b.hi.y &&
           p.z <= b.hi.z;
}

Box3 child_box(const BvhNode& n, int i) {
    return {{n.lo[0][i], n.lo[1][i], n.lo[2][i]}, {n.hi[0][i], n.hi[1][i], n.hi[2][i]}};
}

// Walks the tree from the root: each primitive's leaf count, boxes nested, primitives inside.
void expect_valid(const PreparedScene& scene, const Bvh& bvh, const std::string& what) {
    std::vector<int> seen(scene.prim_count(), 0);
    for (uint32_t p : bvh.unbounded) ++seen[p];
    ASSERT_EQ(bvh.prims.size() + bvh.unbounded.size(), scene.prim_count()) << what;
    if (bvh.nodes.empty()) {
        EXPECT_TRUE(bvh.prims.empty()) << what;
        return;
    }
    EXPECT_LE((kBvhWidth - 1) * bvh.depth + 1, kBvhStack) << what;
    struct Item {
        uint32_t node;
        Box3 box;
        int depth;
    };
    const float big = 3e38f;
    std::vector<Item> work{{0, {Vec3(-big), Vec3(big)}, 1}};
    int deepest = 0;
    size_t visited = 0;
    while (!work.empty()) {
        const Item it = work.back();
        work.pop_back();
        ASSERT_LT(it.node, bvh.nodes.size()) << what;
        ++visited;
        deepest = std::max(deepest, it.depth);
        const BvhNode& n = bvh.nodes[it.node];
        int children = 0;
        for (int i = 0; i < kBvhWidth; ++i) {
            if (n.child[i] == kBvhNoChild) continue;
            ++children;
            const Box3 b = child_box(n, i);
            EXPECT_TRUE(inside(b.lo, it.box) && inside(b.hi, it.box)) << what << ": nesting";
            if (n.count[i] == 0) {
                work.push_back({n.child[i], b, it.depth + 1});
                continue;
            }
            EXPECT_LE(n.count[i], 8u) << what;
            for (uint32_t k = n.child[i]; k < n.child[i] + n.count[i]; ++k) {
                const uint32_t p = bvh.prims[k];
                ++seen[p];
                if (scene.is_triangle(p)) {
                    const TriangleVerts& t = scene.tris[p];
                    EXPECT_TRUE(inside(t.a, b) && inside(t.b, b) && inside(t.c, b))
                        << what << ": triangle " << p;
                } else {
                    // The object's box (csg_box) within the cube around its sphere.
                    const Sphere& s = scene.prim_sphere[p];
                    const WorldBox& w = scene.analytic_box[p - scene.tris.size()];
                    EXPECT_TRUE(inside(vmax(s.center - Vec3(s.radius), w.lo), b) &&
                                inside(vmin(s.center + Vec3(s.radius), w.hi), b))
                        << what << ": shape " << p;
                }
            }
        }
        EXPECT_GE(children, it.node == 0 ? 1 : 2) << what;
    }
    EXPECT_EQ(visited, bvh.nodes.size()) << what << ": every node reached once";
    EXPECT_EQ(deepest, bvh.depth) << what;
    for (size_t p = 0; p < seen.size(); ++p) EXPECT_EQ(seen[p], 1) << what << ": primitive " << p;
}

using test::accel_scenes;

TEST(Bvh, IsValidOnEveryTestScene) {
    for (const auto& [name, scene] : accel_scenes()) {
        expect_valid(scene, build_bvh(scene), name);
        expect_valid(scene, build_bvh_in_order(scene), name + ", in order");
    }
}

TEST(Bvh, IsValidOnManyRandomTriangles) {
    // Enough for the parallel binning and builds, with clusters, coincident centroids and
    // degenerate triangles.
    std::mt19937 g(7);
    std::uniform_real_distribution<float> u(-1, 1);
    Scene s;
    s.add_material(Material{});
    Mesh m;
    for (int t = 0; t < 150000; ++t) {
        const Vec3 c = t % 5 == 0 ? Vec3(2, 2, 2) : Vec3(u(g) * 50, u(g) * 5, u(g) * 50);
        const float size = t % 7 == 0 ? 0.0f : 0.3f;
        for (int k = 0; k < 3; ++k) m.positions.push_back(c + Vec3(u(g), u(g), u(g)) * size);
        for (int k = 0; k < 3; ++k) m.indices.push_back(uint32_t(m.positions.size() - 3 + k));
    }
    s.add_mesh_object("cloud", std::move(m), 0);
    const PreparedScene scene = prepare_scene(s);
    const Bvh a = build_bvh(scene);
    expect_valid(scene, a, "cloud");
    // The same tree on every run, whatever the threads did.
    const Bvh b = build_bvh(scene);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)));
    EXPECT_EQ(a.prims, b.prims);
    // Split in the primitives' order: valid, and the same on every run.
    const Bvh c = build_bvh_in_order(scene), d = build_bvh_in_order(scene);
    expect_valid(scene, c, "cloud, in order");
    ASSERT_EQ(c.nodes.size(), d.nodes.size());
    EXPECT_EQ(0, std::memcmp(c.nodes.data(), d.nodes.data(), c.nodes.size() * sizeof(BvhNode)));
    EXPECT_EQ(c.prims, d.prims);
}

TEST(Bvh, IsBuiltOncePerScene) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    RenderSettings s;
    s.accel = Accel::Bvh;
    const auto a = cull_units_for(scene, s), b = cull_units_for(scene, s);
    ASSERT_TRUE(a->bvh);
    EXPECT_EQ(a->bvh.get(), b->bvh.get());
    EXPECT_EQ(a->bvh.get(), bvh_for(scene).get());
    s.accel = Accel::CrshBvh;
    EXPECT_EQ(cull_units_for(scene, s)->bvh.get(), a->bvh.get());
    s.accel = Accel::Crsh;
    EXPECT_FALSE(cull_units_for(scene, s)->bvh);
}

// accel=bvh renders the frames of the other modes: images and primary passes equal value for
// value, through the host exec and the wavefront pipeline's CPU exec.
TEST(Bvh, FramesEqualEveryOtherMode) {
    for (const auto& [name, scene] : accel_scenes()) {
        const RenderSettings crsh = test::settings_for(scene, {}, 40, 30);
        const RenderSettings brute = test::settings_for(scene, {{"accel", "brute"}}, 40, 30);
        const RenderSettings bvh = test::settings_for(scene, {{"accel", "bvh"}}, 40, 30);
        const Frame ref = render_frame_cpu(scene, crsh);
        const Frame got = render_frame_cpu(scene, bvh);
        test::expect_same_image(ref, got, name + ", bvh against crsh");
        test::expect_same_image(render_frame_cpu(scene, brute), got, name + ", bvh against brute");
        test::expect_same_image(got, render_frame_wavefront_cpu(scene, bvh), name + ", wavefront");
        EXPECT_GT(got.stats.get("tests.shadow.nodes.tests"), 0.0) << name;
        EXPECT_LT(got.stats.get("tests.shadow.final.tests"),
                  got.stats.get("tests.shadow.brute_force") + 1)
            << name;
        // The ray hierarchies over the BVH and the strips: the same frame on both pipelines.
        for (const char* accel : {"crsh-bvh", "rah-bvh", "strips"}) {
            const RenderSettings over = test::settings_for(scene, {{"accel", accel}}, 40, 30);
            const Frame f = render_frame_cpu(scene, over);
            test::expect_same_image(got, f, name + ", " + accel);
            test::expect_same_image(f, render_frame_wavefront_cpu(scene, over),
                                    name + ", " + accel + ", wavefront");
            EXPECT_GT(f.stats.get("tests.shadow.nodes.tests"), 0.0) << name << " " << accel;
            EXPECT_FALSE(f.stats.has("tests.shadow.objects.tests")) << name << " " << accel;
        }
    }
}

} // namespace
} // namespace sheaf

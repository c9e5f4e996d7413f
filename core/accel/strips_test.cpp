// The strips are valid (every bounded primitive once, in a strip or as an item; a strip's
// triangles the scene's own corners; every plane of a strip's hierarchy on the right side of
// its part's vertices; the top level's boxes around what they hold), compact, and a ray finds
// through them exactly what brute force finds, also where it passes through vertices and
// along edges. The frames of accel=strips are checked with every other mode's in bvh_test.cpp.
#include "core/accel/strips.h"

#include "core/accel/stripify.h"
#include "core/frame/host_tracer.h"
#include "core/geometry/ray_triangle.h"
#include "core/rsh/cull_units.h"
#include "tests/support/accel_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <random>

namespace sheaf {
namespace {

struct Box3 {
    Vec3 lo{3e38f}, hi{-3e38f};
    bool holds(const Vec3& p) const {
        return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y &&
               p.z <= hi.z;
    }
};

bool same_bits(const Vec3& a, const Vec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

class Checker {
  public:
    Checker(const PreparedScene& scene, const Strips& s, const std::string& what)
        : scene_(scene), s_(s), what_(what), seen_(scene.prim_count(), 0) {}

    void run() {
        for (uint32_t p : s_.top.unbounded) ++seen_[p];
        for (const BvhNode& n : s_.top.nodes)
            for (int i = 0; i < kBvhWidth; ++i) {
                if (n.child[i] == kBvhNoChild || n.count[i] == 0) continue;
                Box3 box;
                box.lo = {n.lo[0][i], n.lo[1][i], n.lo[2][i]};
                box.hi = {n.hi[0][i], n.hi[1][i], n.hi[2][i]};
                ASSERT_LE(size_t(n.child[i]) + n.count[i], s_.top.prims.size()) << what_;
                for (uint32_t k = n.child[i]; k < n.child[i] + n.count[i]; ++k)
                    item(s_.top.prims[k], box);
            }
        for (size_t p = 0; p < seen_.size(); ++p)
            EXPECT_EQ(seen_[p], 1) << what_ << ": primitive " << p;
        EXPECT_EQ(nodes_, s_.planes.size()) << what_ << ": every strip node reached once";
    }

  private:
    void item(uint32_t it, const Box3& box) {
        if (!(it & kStripItem)) {
            ASSERT_LT(it, scene_.prim_count()) << what_;
            ++seen_[it];
            if (scene_.is_triangle(it)) {
                const TriangleVerts& t = scene_.tris[it];
                EXPECT_TRUE(box.holds(t.a) && box.holds(t.b) && box.holds(t.c)) << what_;
            }
            return;
        }
        const uint32_t k = it & ~kStripItem;
        ASSERT_LT(k, s_.strips.size()) << what_;
        const StripHeader& h = s_.strips[k];
        ASSERT_LE(size_t(h.first) + h.tris + 2, s_.index.size()) << what_;
        Box3 own;
        for (int a = 0; a < 3; ++a) own.lo[a] = h.lo[a], own.hi[a] = h.hi[a];
        const auto vert = [&](uint32_t q) {
            return s_.verts[h.base_vertex + s_.index[h.first + q]];
        };
        for (uint32_t q = 0; q < h.tris + 2; ++q) {
            ASSERT_LT(size_t(h.base_vertex) + s_.index[h.first + q], s_.verts.size()) << what_;
            EXPECT_TRUE(own.holds(vert(q)) && box.holds(vert(q))) << what_ << ": strip " << k;
        }
        for (uint32_t j = 0; j < h.tris; ++j) {
            const uint16_t id = s_.ids[h.first + j];
            if (id == kStripJoin) continue;
            const uint32_t p = h.base_prim + id;
            ASSERT_TRUE(scene_.is_triangle(p)) << what_;
            ++seen_[p];
            // The strip's triangle is the scene's: the same three corners, bit for bit.
            const TriangleVerts& t = scene_.tris[p];
            std::array<Vec3, 3> mine = {vert(j), vert(j + 1), vert(j + 2)};
            for (const Vec3& c : {t.a, t.b, t.c}) {
                auto at = std::find_if(mine.begin(), mine.end(),
                                       [&](const Vec3& v) { return same_bits(v, c); });
                ASSERT_NE(at, mine.end()) << what_ << ": triangle " << p;
                *at = Vec3(NAN);
            }
            for (const Vec3& e : {t.b - t.a, t.c - t.b, t.a - t.c})
                EXPECT_LE(std::fabs(e.x) + std::fabs(e.y) + std::fabs(e.z), h.edge) << what_;
        }
        const uint32_t leaves = (h.tris + kStripLeaf - 1) / kStripLeaf;
        ASSERT_LE(size_t(h.first_node) + leaves - 1, s_.planes.size()) << what_;
        if (h.tris > kStripLeaf) node(h, vert, 0, 0, h.tris, leaves - 1);
    }

    // Node k over triangles [l, l + m): each part's vertices on their side of its plane.
    template <class Vert>
    void node(const StripHeader& h, const Vert& vert, uint32_t k, uint32_t l, uint32_t m,
              uint32_t count) {
        ASSERT_LT(k, count) << what_;
        ++nodes_;
        uint32_t first, span;
        strip_split(m, first, span);
        EXPECT_GT(first, 0u);
        EXPECT_LT(first, m);
        const uint8_t meta = s_.meta[h.first_node + k];
        const StripPlanes pl = s_.planes[h.first_node + k];
        const int axis = meta & 3;
        ASSERT_LT(axis, 3) << what_;
        const bool first_upper = (meta & 4) != 0;
        for (uint32_t q = l; q < l + first + 2; ++q)
            EXPECT_TRUE(first_upper ? vert(q)[axis] >= pl.above : vert(q)[axis] <= pl.below)
                << what_;
        for (uint32_t q = l + first; q < l + m + 2; ++q)
            EXPECT_TRUE(first_upper ? vert(q)[axis] <= pl.below : vert(q)[axis] >= pl.above)
                << what_;
        if (first > kStripLeaf) node(h, vert, k + 1, l, first, count);
        if (m - first > kStripLeaf) node(h, vert, k + span, l + first, m - first, count);
    }

    const PreparedScene& scene_;
    const Strips& s_;
    std::string what_;
    std::vector<int> seen_;
    size_t nodes_ = 0;
};

// A height field of g x g quads, two triangles each, `offset` away from the origin.
Mesh terrain(int g, float cell, Vec3 offset, uint32_t seed) {
    std::mt19937 r(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    Mesh m;
    for (int y = 0; y <= g; ++y)
        for (int x = 0; x <= g; ++x)
            m.positions.push_back(offset + Vec3(float(x) * cell, u(r) * cell, float(y) * cell));
    const uint32_t w = uint32_t(g) + 1;
    for (uint32_t y = 0; y < uint32_t(g); ++y)
        for (uint32_t x = 0; x < uint32_t(g); ++x) {
            const uint32_t a = y * w + x, b = a + 1, c = a + w, d = c + 1;
            for (uint32_t v : {a, c, b, b, c, d}) m.indices.push_back(v);
        }
    return m;
}

TEST(Strips, AreValidOnEveryTestScene) {
    for (const auto& [name, scene] : test::accel_scenes())
        Checker(scene, build_strips(scene), name).run();
}

TEST(Strips, AreValidAndTheSameOnEveryRun) {
    // Clusters, repeated and degenerate triangles, primitive numbers further apart than 16
    // bits in one leaf, an analytic shape among them.
    std::mt19937 g(5);
    std::uniform_real_distribution<float> u(-1, 1);
    Scene s;
    s.add_material(Material{});
    Mesh cloud;
    for (int t = 0; t < 90000; ++t) {
        const Vec3 c = t % 5 == 0 ? Vec3(2, 2, 2) : Vec3(u(g) * 20, u(g) * 5, u(g) * 20);
        const float size = t % 7 == 0 ? 0.0f : 0.3f;
        for (int k = 0; k < 3; ++k) cloud.positions.push_back(c + Vec3(u(g), u(g), u(g)) * size);
        for (int k = 0; k < 3; ++k)
            cloud.indices.push_back(uint32_t(cloud.positions.size() - 3 + k));
    }
    // The same patch of ground at both ends of the primitive numbers.
    s.add_mesh_object("near", terrain(20, 0.5f, Vec3(-5, 0, -5), 1), 0);
    s.add_mesh_object("cloud", std::move(cloud), 0);
    s.add_mesh_object("far", terrain(20, 0.5f, Vec3(-5, 0, -5), 1), 0);
    s.add_shape("ball", Shape{ShapeKind::Sphere}, 0, Affine::translate(Vec3(0, 1, 0)));
    const PreparedScene scene = prepare_scene(s);
    const Strips a = build_strips(scene), b = build_strips(scene);
    Checker(scene, a, "cloud").run();
    EXPECT_GT(a.strips.size(), 100u);
    EXPECT_GT(a.loose, 0u); // the degenerate triangles
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.ids, b.ids);
    EXPECT_EQ(a.top.prims, b.top.prims);
    ASSERT_EQ(a.strips.size(), b.strips.size());
    EXPECT_EQ(0,
              std::memcmp(a.strips.data(), b.strips.data(), a.strips.size() * sizeof(StripHeader)));
}

TEST(Strips, TakeAtMostSixteenBytesATriangleOnAMesh) {
    // A 100,000-triangle height field, as paper 004's Table 1 counts: hierarchy (top level,
    // strip headers and nodes) and geometry (the strips' vertices, indices and ids).
    Scene s;
    s.add_material(Material{});
    s.add_mesh_object("ground", terrain(224, 0.5f, Vec3(0), 3), 0);
    const PreparedScene scene = prepare_scene(s);
    const Strips st = build_strips(scene);
    Checker(scene, st, "ground").run();
    const double tris = double(scene.tris.size());
    EXPECT_EQ(st.loose, 0u);
    EXPECT_LT(double(st.joins) / tris, 0.2);
    EXPECT_LE(double(st.hierarchy_bytes() + st.geometry_bytes()) / tris, 16.0);
}

TEST(Strips, StripifyTakesEveryTriangleOnceInLongPieces) {
    // A grid of 16 x 16 quads: pieces no more than its rows, and each position of the sequence
    // either a join or the triangle of its three vertices.
    std::vector<std::array<uint32_t, 3>> tris;
    const uint32_t w = 17;
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 16; ++x) {
            const uint32_t a = y * w + x, b = a + 1, c = a + w, d = c + 1;
            tris.push_back({a, c, b});
            tris.push_back({b, c, d});
        }
    const Stripified s = stripify(tris);
    ASSERT_EQ(s.tri.size() + 2, s.verts.size());
    std::vector<int> seen(tris.size(), 0);
    size_t joins = 0;
    for (size_t j = 0; j < s.tri.size(); ++j) {
        if (s.tri[j] < 0) {
            ++joins;
            continue;
        }
        ++seen[size_t(s.tri[j])];
        std::array<uint32_t, 3> have = {s.verts[j], s.verts[j + 1], s.verts[j + 2]};
        std::array<uint32_t, 3> want = tris[size_t(s.tri[j])];
        std::sort(have.begin(), have.end());
        std::sort(want.begin(), want.end());
        EXPECT_EQ(have, want) << j;
    }
    for (int n : seen) EXPECT_EQ(n, 1);
    EXPECT_LE(joins, 2u * 15u);
}

// Rays through vertices, along and just beside edges, grazing the surface, far from the
// origin: the strips' edge tests never turn away a triangle the exact test takes.
TEST(Strips, FindWhatBruteForceFindsOnEdgesAndVertices) {
    for (const Vec3 offset : {Vec3(0), Vec3(1000, -300, 2000), Vec3(-3e4f, 50, 7)}) {
        Scene s;
        s.add_material(Material{});
        s.add_mesh_object("ground", terrain(30, 0.25f, offset, 9), 0);
        const PreparedScene scene = prepare_scene(s);
        std::mt19937 g(17);
        std::uniform_real_distribution<float> u(0, 1);
        MemoryTracker mem;
        RayBatch batch(RayType::Reflection, mem);
        const auto add = [&](const Vec3& from, const Vec3& to) {
            Ray r;
            r.origin = from;
            r.dir = normalize(to - from);
            r.tmin = 0;
            r.tmax = 1e30f;
            batch.resize(batch.size() + 1);
            batch.rays.back() = r;
            batch.pixel.back() = uint32_t(batch.size() - 1);
        };
        for (size_t t = 0; t < scene.tris.size(); ++t) {
            const TriangleVerts& tri = scene.tris[t];
            const Vec3 above = offset + Vec3(u(g) * 8, 3 + u(g) * 5, u(g) * 8);
            const float e = u(g) * 2e-6f - 1e-6f;
            add(above, tri.a);                                   // a vertex
            add(above, (tri.a + tri.b) * 0.5f);                  // an edge
            add(above, tri.b * (0.5f + e) + tri.c * (0.5f - e)); // beside an edge
            const Vec3 in = (tri.a + tri.b + tri.c) * (1.0f / 3.0f);
            add(in + (tri.a - in) * 40.0f + Vec3(0, 1e-4f, 0), in); // grazing
        }
        RenderSettings brute, strips;
        brute.accel = Accel::Brute;
        strips.accel = Accel::Strips;
        Stats bst, st;
        TraceResult ref, got;
        trace_batch(scene, batch, brute, bst, mem, ref);
        trace_batch(scene, batch, strips, st, mem, got);
        size_t hits = 0;
        for (uint64_t c : ref.closest) hits += c != kNoHit ? 1 : 0;
        EXPECT_GT(hits, batch.rays.size() / 2);
        EXPECT_EQ(got.closest, ref.closest) << "offset " << offset.x;
    }
}

TEST(Strips, AreBuiltOncePerScene) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    RenderSettings s;
    s.accel = Accel::Strips;
    const auto a = cull_units_for(scene, s), b = cull_units_for(scene, s);
    ASSERT_TRUE(a->strips);
    EXPECT_FALSE(a->bvh);
    EXPECT_EQ(a->strips.get(), b->strips.get());
    EXPECT_EQ(a->strips.get(), strips_for(scene).get());
    s.accel = Accel::Bvh;
    EXPECT_FALSE(cull_units_for(scene, s)->strips);
}

} // namespace
} // namespace sheaf

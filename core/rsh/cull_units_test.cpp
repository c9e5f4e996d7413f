// Culling units split large objects into runs whose spheres hold their triangles, and the
// traversal with them finds the same hits with fewer primitive tests.
#include "core/rsh/cull_units.h"

#include "core/backend/backend.h"
#include "core/scenes/builtin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace sheaf {
namespace {

bool inside(const Sphere& s, Vec3 p) {
    return length(p - s.center) <= s.radius;
}

TEST(CullUnits, ZeroKeepsEveryObjectWhole) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    const CullUnits u = make_cull_units(scene, 0);
    ASSERT_EQ(u.count(), scene.object_count());
    EXPECT_EQ(u.begin, scene.object_begin);
    for (uint32_t o = 0; o < scene.object_count(); ++o) {
        EXPECT_FALSE(u.split(o));
        EXPECT_EQ(u.object[o], o);
        EXPECT_EQ(u.sphere[o].center.x, scene.object_sphere[o].center.x);
        EXPECT_EQ(u.sphere[o].radius, scene.object_sphere[o].radius);
    }
}

TEST(CullUnits, LargeObjectsSplitIntoRunsThatHoldTheirTriangles) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("colonnade"));
    for (int k : {1, 7, 64, 1000}) {
        const CullUnits u = make_cull_units(scene, k);
        ASSERT_EQ(u.object_units.size(), scene.object_count() + 1) << k;
        ASSERT_EQ(u.begin.size(), u.count() + 1) << k;
        EXPECT_EQ(u.begin.front(), 0u);
        EXPECT_EQ(u.begin.back(), uint32_t(scene.prim_count()));
        size_t split = 0;
        for (uint32_t o = 0; o < scene.object_count(); ++o) {
            const uint32_t prims = scene.object_begin[o + 1] - scene.object_begin[o];
            const uint32_t u0 = u.object_units[o], u1 = u.object_units[o + 1];
            EXPECT_EQ(u.begin[u0], scene.object_begin[o]) << k;
            EXPECT_EQ(u.begin[u1], scene.object_begin[o + 1]) << k;
            EXPECT_EQ(u1 - u0, prims > uint32_t(k) ? (prims + k - 1) / uint32_t(k) : 1u) << k;
            split += u.split(o) ? 1 : 0;
            for (uint32_t i = u0; i < u1; ++i) {
                EXPECT_EQ(u.object[i], o);
                if (!u.split(o)) continue;
                EXPECT_LE(u.begin[i + 1] - u.begin[i], uint32_t(k));
                EXPECT_LE(u.sphere[i].radius, scene.object_sphere[o].radius * 1.0001f);
                for (uint32_t p = u.begin[i]; p < u.begin[i + 1]; ++p) {
                    const TriangleVerts& t = scene.tris[p];
                    ASSERT_TRUE(inside(u.sphere[i], t.a) && inside(u.sphere[i], t.b) &&
                                inside(u.sphere[i], t.c))
                        << "cluster " << k << " unit " << i << " primitive " << p;
                }
            }
        }
        EXPECT_GT(split, 0u) << k; // the colonnade's mesh is split at every size tried
    }
}

TEST(CullUnits, ComputedOncePerSceneAndClusterSize) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    Settings s;
    s.set("accel", "crsh");
    const RenderSettings r64 = RenderSettings::resolve(s);
    s.set("cull.cluster", "16");
    const RenderSettings r16 = RenderSettings::resolve(s);
    s.set("cull.objects", "false");
    const RenderSettings whole = RenderSettings::resolve(s);
    const auto a = cull_units_for(scene, r64);
    EXPECT_EQ(a, cull_units_for(scene, r64));      // the frames of one scene share them
    EXPECT_EQ(a, cull_units_for(PreparedScene(scene), r64)); // and its copies
    EXPECT_NE(a, cull_units_for(scene, r16));
    EXPECT_EQ(cull_units_for(scene, r16)->count(), make_cull_units(scene, 16).count());
    EXPECT_EQ(cull_units_for(scene, whole)->count(), scene.object_count()); // not culling
    EXPECT_NE(cull_units_for(prepare_scene(make_builtin_scene("office")), r64), a);
}

Frame render(const PreparedScene& scene, const std::string& cluster) {
    Settings s;
    s.set("width", "48"), s.set("height", "36"), s.set("ao.samples", "2");
    s.set("accel", "crsh"), s.set("cull.cluster", cluster);
    return render_frame(scene, RenderSettings::resolve(s, scene.settings));
}

TEST(CullUnits, SplittingFindsTheSameHitsWithFewerTests) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("colonnade"));
    const Frame whole = render(scene, "0");
    for (const char* k : {"1", "16", "64"}) {
        const Frame split = render(scene, k);
        EXPECT_EQ(whole.rgba, split.rgba) << k;
        for (const char* t : {"shadow", "ao"}) {
            const std::string p = std::string("tests.") + t + ".";
            EXPECT_GT(whole.stats.get("rays." + std::string(t)), 0) << t;
            EXPECT_EQ(whole.stats.get("rays." + std::string(t)),
                      split.stats.get("rays." + std::string(t)));
            // Fewer top-level candidates; the run spheres cost object tests instead.
            EXPECT_LT(split.stats.get(p + "level2.tests"), whole.stats.get(p + "level2.tests"))
                << k << " " << t;
            EXPECT_GT(split.stats.get(p + "objects.tests"), whole.stats.get(p + "objects.tests"))
                << k << " " << t;
        }
        EXPECT_LT(split.stats.get("tests.total"), whole.stats.get("tests.total")) << k;
    }
}

TEST(CullUnits, RunsStayCompactWhateverOrderTheMeshCameIn) {
    // The colonnade's mesh with its triangles shuffled: prepare_scene puts them back in a
    // spatial order, so runs of 64 cull about as well as in the generated order.
    Scene shuffled = make_builtin_scene("colonnade");
    Mesh& mesh = shuffled.meshes[0];
    const size_t n = mesh.triangle_count();
    std::vector<uint32_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
    std::mt19937 g(7);
    std::shuffle(order.begin(), order.end(), g);
    std::vector<uint32_t> indices(mesh.indices.size());
    for (size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.indices[3 * order[t] + k];
    mesh.indices = indices;
    const Frame a = render(prepare_scene(make_builtin_scene("colonnade")), "64");
    const Frame b = render(prepare_scene(shuffled), "64");
    const Frame whole = render(prepare_scene(shuffled), "0");
    // Top-level tests: what the runs cut (the final tests are the same rays' anyway).
    auto top = [](const Frame& f) {
        return f.stats.get("tests.shadow.level2.tests") + f.stats.get("tests.ao.level2.tests");
    };
    EXPECT_LT(top(b), 1.1 * top(a));
    EXPECT_LT(top(b), 0.5 * top(whole));
    EXPECT_LT(b.stats.get("tests.total"), whole.stats.get("tests.total"));
}

TEST(CullUnits, PreparationKeepsEveryTriangleOfEachObject) {
    const Scene scene = make_builtin_scene("office");
    const PreparedScene p = prepare_scene(scene);
    size_t base = 0;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const Mesh& m = scene.meshes[obj.mesh];
        std::vector<std::array<float, 9>> want, got;
        for (size_t t = 0; t < m.triangle_count(); ++t) {
            const Vec3 a = obj.transform.point(m.positions[m.indices[3 * t]]);
            const Vec3 b = obj.transform.point(m.positions[m.indices[3 * t + 1]]);
            const Vec3 c = obj.transform.point(m.positions[m.indices[3 * t + 2]]);
            want.push_back({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z});
            const TriangleVerts& v = p.tris[base + t];
            got.push_back({v.a.x, v.a.y, v.a.z, v.b.x, v.b.y, v.b.z, v.c.x, v.c.y, v.c.z});
            EXPECT_EQ(p.prim_object[base + t], o);
        }
        std::sort(want.begin(), want.end());
        std::sort(got.begin(), got.end());
        ASSERT_EQ(want, got) << "object " << o;
        base += m.triangle_count();
    }
}

} // namespace
} // namespace sheaf

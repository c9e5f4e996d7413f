// Tracing: every accel, hash and sort mode finds exactly what brute force finds, and the
// hierarchy never loses a true (ray, primitive) hit: its final-test hits equal the number of
// true intersections.
#include "core/frame/host_tracer.h"

#include "core/accel/bvh_trace.h"
#include "core/geometry/ray_triangle.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

// Clusters of small random triangles, one object per cluster.
PreparedScene random_scene(uint32_t seed) {
    std::mt19937 g(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    Scene s;
    s.add_material(Material{});
    for (int o = 0; o < 6; ++o) {
        Mesh m;
        const Vec3 c(u(g) * 6, u(g) * 6, u(g) * 6);
        for (int t = 0; t < 120; ++t) {
            const Vec3 p = c + Vec3(u(g), u(g), u(g)) * 1.5f;
            for (int k = 0; k < 3; ++k) m.positions.push_back(p + Vec3(u(g), u(g), u(g)) * 0.4f);
            for (int k = 0; k < 3; ++k) m.indices.push_back(uint32_t(m.positions.size() - 3 + k));
        }
        s.add_mesh_object("cluster" + std::to_string(o), std::move(m), 0);
    }
    s.add_light(Light{Vec3(0, 9, 0), Vec3(1.0f)});
    s.add_light(Light{Vec3(9, 0, 0), Vec3(1.0f)});
    return prepare_scene(s);
}

RayBatch random_batch(RayType type, MemoryTracker& mem, uint32_t seed, size_t n) {
    std::mt19937 g(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    RayBatch b(type, mem);
    b.resize(n);
    for (size_t i = 0; i < n; ++i) {
        Ray r;
        if (type == RayType::Shadow) {
            // From one of two lights towards a point: bounded, like shadow rays.
            const Vec3 light = i % 2 ? Vec3(0, 9, 0) : Vec3(9, 0, 0);
            const Vec3 target(u(g) * 7, u(g) * 7, u(g) * 7);
            r.origin = light;
            r.dir = normalize(target - light);
            r.tmin = 0;
            r.tmax = length(target - light);
            b.light[i] = i % 2;
        } else {
            r.origin = Vec3(u(g) * 8, u(g) * 8, u(g) * 8);
            r.dir = normalize(Vec3(u(g), u(g), u(g)) + Vec3(0.3f, 0.2f, 0.1f));
            r.tmin = 0;
            r.tmax = 1e30f;
        }
        b.rays[i] = r;
        b.pixel[i] = uint32_t(i);
    }
    return b;
}

uint64_t true_pairs(const PreparedScene& s, const RayBatch& b) {
    uint64_t n = 0;
    for (const Ray& r : b.rays)
        for (const TriangleVerts& t : s.tris) {
            TriangleHit h;
            n += intersect_triangle(r, t.a, t.b, t.c, h);
        }
    return n;
}

struct Mode {
    Accel accel;
    HashMode hash;
    SortMode sort;
    int depth, arity;
    bool cull;
    long long batch;
};

// Every tracer (the CPU backend's, the wavefront's) under every accel finds brute force's hits.
TEST(Trace, EveryModeFindsWhatBruteForceFinds) {
    const PreparedScene scene = random_scene(3);
    MemoryTracker mem;
    for (RayType type : {RayType::Reflection, RayType::Shadow}) {
        const RayBatch batch = random_batch(type, mem, 11, 3000);
        const std::string p = std::string("tests.") + ray_type_name(type) + ".";
        RenderSettings brute;
        brute.accel = Accel::Brute;
        TraceResult ref;
        Stats bst;
        trace_batch(scene, batch, brute, bst, mem, ref);
        const uint64_t pairs = true_pairs(scene, batch);
        EXPECT_GT(pairs, 100u); // the scene is not trivially empty along the rays
        if (type == RayType::Reflection) EXPECT_EQ(bst.get(p + "final.hits"), double(pairs));
        EXPECT_EQ(bst.get(p + "brute_force"), 3000.0 * double(scene.prim_count()));

        const Mode modes[] = {
            {Accel::Rah, HashMode::None, SortMode::None, 2, 8, false, 1 << 20},
            {Accel::Crsh, HashMode::Crsh, SortMode::Csd, 2, 8, true, 1 << 20},
            {Accel::Crsh, HashMode::Crsh, SortMode::Full, 1, 2, true, 1 << 20},
            {Accel::Crsh, HashMode::Hash32, SortMode::Csd, 3, 4, true, 1024},
            {Accel::Crsh, HashMode::Hash192, SortMode::Full, 4, 3, false, 1024},
            {Accel::Crsh, HashMode::None, SortMode::None, 2, 16, true, 1 << 20},
            {Accel::CrshBvh, HashMode::Crsh, SortMode::Csd, 2, 8, true, 1 << 20},
            {Accel::CrshBvh, HashMode::Hash32, SortMode::Full, 3, 4, false, 1024},
            {Accel::RahBvh, HashMode::None, SortMode::None, 1, 16, true, 256},
        };
        for (const Mode& m : modes) {
            RenderSettings s;
            s.accel = m.accel, s.hash = m.hash, s.sort = m.sort, s.hierarchy_depth = m.depth;
            s.hierarchy_arity = m.arity, s.cull_objects = m.cull, s.batch_pairs = m.batch;
            TraceResult got;
            Stats st;
            trace_batch(scene, batch, s, st, mem, got);
            const std::string what = std::string(ray_type_name(type)) + " " + to_string(m.accel) +
                                     " " + to_string(m.hash) + " " + to_string(m.sort) + " d" +
                                     std::to_string(m.depth) + " a" + std::to_string(m.arity);
            EXPECT_EQ(got.closest, ref.closest) << what;
            EXPECT_EQ(got.occluded, ref.occluded) << what;
            // Conservative: every true (ray, primitive) hit reached the final tests. Over the
            // BVH the rays finish on their own, past their best or first opaque hit no more.
            if (uses_bvh(m.accel))
                EXPECT_LE(st.get(p + "final.hits"), double(pairs)) << what;
            else
                EXPECT_EQ(st.get(p + "final.hits"), double(pairs)) << what;
            // The counts add up level by level.
            double above_hits = -1;
            for (int k = m.depth; k >= 1; --k) {
                const std::string lk = p + "level" + std::to_string(k) + ".";
                EXPECT_EQ(st.get(lk + "tests"), st.get(lk + "hits") + st.get(lk + "misses"))
                    << what;
                if (above_hits >= 0) EXPECT_LE(st.get(lk + "tests"), above_hits * m.arity) << what;
                above_hits = st.get(lk + "hits");
            }
            if (!uses_bvh(m.accel))
                EXPECT_LE(st.get(p + "final.tests"), above_hits * m.arity) << what;
            EXPECT_EQ(st.has(p + "objects.tests"), m.cull && !uses_bvh(m.accel)) << what;
            // Over the BVH: its boxes tested at the top, and counted in the total.
            EXPECT_EQ(st.has(p + "nodes.tests"), uses_bvh(m.accel)) << what;
            if (uses_bvh(m.accel)) {
                EXPECT_EQ(st.get(p + "nodes.tests"),
                          st.get(p + "nodes.hits") + st.get(p + "nodes.misses"))
                    << what;
                double sum = st.get(p + "nodes.tests") + st.get(p + "final.tests");
                for (int k = m.depth; k >= 1; --k)
                    sum += st.get(p + "level" + std::to_string(k) + ".tests");
                EXPECT_EQ(st.get(p + "total"), sum) << what;
            }
            // The wavefront tracer: the same hits, per-ray tests and counts.
            TraceResult wave;
            Stats wst;
            trace_batch(scene, batch, s, wst, mem, wave, wavefront::Traversal::Wavefront);
            EXPECT_EQ(wave.closest, ref.closest) << what << " (wavefront)";
            EXPECT_EQ(wave.occluded, ref.occluded) << what << " (wavefront)";
            EXPECT_EQ(wave.tests, got.tests) << what << " (wavefront)";
            for (const auto& [k, v] : st.entries())
                if (k.rfind("time_ms.", 0) != 0) EXPECT_EQ(wst.get(k), v) << what << " " << k;
        }
    }
}

// accel=bvh and accel=strips: each ray through the structure finds what brute force finds
// (closest hits, occlusion, what shadow rays keep through transparent surfaces), with fewer
// exact tests; the wavefront path runs the same launch and counts the same.
TEST(Trace, PerRayStructuresFindWhatBruteForceFinds) {
    const PreparedScene scene = random_scene(4);
    MemoryTracker mem;
    for (Accel accel : {Accel::Bvh, Accel::Strips})
        for (RayType type : {RayType::Reflection, RayType::Shadow, RayType::Ao}) {
            const RayBatch batch = random_batch(type, mem, 13, 4000);
            const std::string p = std::string("tests.") + ray_type_name(type) + ".";
            RenderSettings brute, s;
            brute.accel = Accel::Brute;
            s.accel = accel;
            TraceResult ref, got, wave;
            Stats bst, st, wst;
            trace_batch(scene, batch, brute, bst, mem, ref);
            trace_batch(scene, batch, s, st, mem, got);
            trace_batch(scene, batch, s, wst, mem, wave, wavefront::Traversal::Wavefront);
            const std::string what = std::string(to_string(accel)) + " " + ray_type_name(type);
            EXPECT_EQ(got.closest, ref.closest) << what;
            EXPECT_EQ(got.occluded, ref.occluded) << what;
            EXPECT_EQ(got.pass_log, ref.pass_log) << what;
            EXPECT_EQ(wave.closest, got.closest) << what;
            EXPECT_EQ(wave.tests, got.tests) << what;
            EXPECT_GT(st.get(p + "nodes.tests"), 0.0) << what;
            EXPECT_EQ(st.get(p + "nodes.tests"),
                      st.get(p + "nodes.hits") + st.get(p + "nodes.misses"))
                << what;
            EXPECT_LT(st.get(p + "final.tests"), bst.get(p + "final.tests") / 4) << what;
            EXPECT_EQ(st.get(p + "total"), st.get(p + "nodes.tests") + st.get(p + "final.tests"))
                << what;
            for (const auto& [k, v] : st.entries())
                if (k.rfind("time_ms.", 0) != 0) EXPECT_EQ(wst.get(k), v) << what << " " << k;
        }
}

// accel=bvh's two host paths, the eight slab tests of a node as two SSE vectors or one AVX2
// vector (chosen at run time where the processor has AVX2): the same hits, per-ray tests and
// counts, for every ray type and the ray hierarchy over the BVH.
TEST(Trace, Avx2WalkFindsWhatTheSseWalkFinds) {
#if SHEAF_BVH_AVX2
    if (!bvh_avx2()) GTEST_SKIP() << "no AVX2 on this processor (or SHEAF_SIMD=sse)";
    const PreparedScene scene = random_scene(6);
    MemoryTracker mem;
    for (Accel accel : {Accel::Bvh, Accel::CrshBvh, Accel::Strips})
        for (RayType type : {RayType::Reflection, RayType::Shadow, RayType::Ao}) {
            const RayBatch batch = random_batch(type, mem, 21, 4000);
            RenderSettings s;
            s.accel = accel;
            TraceResult avx, sse;
            Stats ast, sst;
            trace_batch(scene, batch, s, ast, mem, avx);
            bvh_set_avx2(false);
            trace_batch(scene, batch, s, sst, mem, sse);
            bvh_set_avx2(true);
            const std::string what = std::string(to_string(accel)) + " " + ray_type_name(type);
            EXPECT_EQ(avx.closest, sse.closest) << what;
            EXPECT_EQ(avx.occluded, sse.occluded) << what;
            EXPECT_EQ(avx.pass_log, sse.pass_log) << what;
            EXPECT_EQ(avx.tests, sse.tests) << what;
            for (const auto& [k, v] : ast.entries())
                if (k.rfind("time_ms.", 0) != 0) EXPECT_EQ(sst.get(k), v) << what << " " << k;
        }
    EXPECT_TRUE(bvh_avx2());
#else
    GTEST_SKIP() << "the AVX2 path is built for x86-64 hosts only";
#endif
}

TEST(Trace, SmallBatchesChangeNeitherResultsNorCounts) {
    const PreparedScene scene = random_scene(5);
    MemoryTracker mem_big, mem_small;
    const RayBatch batch = random_batch(RayType::Reflection, mem_big, 2, 4000);
    RenderSettings big, small;
    small.batch_pairs = 1024;
    TraceResult a, b;
    Stats sa, sb;
    trace_batch(scene, batch, big, sa, mem_big, a);
    trace_batch(scene, batch, small, sb, mem_small, b);
    EXPECT_EQ(a.closest, b.closest);
    for (const char* k : {"tests.reflection.level2.tests", "tests.reflection.level1.hits",
                          "tests.reflection.final.tests"})
        EXPECT_EQ(sa.get(k), sb.get(k)) << k;
}

TEST(Trace, PackedHitsOrderByDistanceThenPrimitive) {
    EXPECT_LT(pack_hit(1.0f, 7), pack_hit(2.0f, 1));
    EXPECT_LT(pack_hit(1.0f, 1), pack_hit(1.0f, 2));
    EXPECT_FLOAT_EQ(hit_t(pack_hit(3.5f, 9)), 3.5f);
    EXPECT_EQ(hit_prim(pack_hit(3.5f, 9)), 9u);
}

} // namespace
} // namespace sheaf

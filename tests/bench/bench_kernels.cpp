// Micro-benchmarks of the per-element kernels and the sort, and whole frames of the
// built-in scenes. Run: build/tests/bench/sheaf_bench
#include "core/backend/backend.h"
#include "core/frame/cpu_exec.h"
#include "core/frame/scene_copy.h"
#include "core/geometry/cone_sphere.h"
#include "core/geometry/ray_triangle.h"
#include "core/rsh/cull_units.h"
#include "core/scenes/builtin.h"
#include "core/sort/radix_sort.h"

#include <benchmark/benchmark.h>

#include <numeric>
#include <random>

using namespace sheaf;

static void BM_ConeSphereTest(benchmark::State& state) {
    std::mt19937 g(1);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<RayNode> nodes(1024);
    std::vector<Sphere> spheres(1024);
    for (auto& n : nodes)
        n = make_ray_node({Vec3(u(g), u(g), u(g)), 0.1f},
                          {normalize(Vec3(u(g), u(g), u(g))), 0.05f + 0.1f * (u(g) + 1)});
    for (auto& s : spheres) s = {Vec3(u(g), u(g), u(g)) * 5.0f, 0.05f};
    size_t i = 0, hits = 0;
    for (auto _ : state) {
        hits += node_hits_sphere(nodes[i & 1023], spheres[(i * 7) & 1023]);
        ++i;
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_ConeSphereTest);

static void BM_RayTriangle(benchmark::State& state) {
    std::mt19937 g(2);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<Ray> rays(1024);
    std::vector<TriangleVerts> tris(1024);
    for (auto& r : rays)
        r = {Vec3(u(g), u(g), -3), 0, normalize(Vec3(u(g) * 0.2f, u(g) * 0.2f, 1)), 1e30f};
    for (auto& t : tris) {
        const Vec3 c(u(g), u(g), u(g));
        t = {c, c + Vec3(0.3f, 0, 0), c + Vec3(0, 0.3f, 0)};
    }
    size_t i = 0, hits = 0;
    for (auto _ : state) {
        TriangleHit h;
        const TriangleVerts& t = tris[(i * 7) & 1023];
        hits += intersect_triangle(rays[i & 1023], t.a, t.b, t.c, h);
        ++i;
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_RayTriangle);

static void BM_RadixSort(benchmark::State& state) {
    const int words = int(state.range(1));
    const size_t n = size_t(state.range(0));
    std::mt19937 g(3);
    std::vector<uint32_t> keys(n * words);
    for (auto& k : keys) k = g();
    for (auto _ : state) {
        state.PauseTiming();
        std::vector<uint32_t> k = keys, v(n);
        std::iota(v.begin(), v.end(), 0u);
        state.ResumeTiming();
        radix_sort_pairs(k, words, v);
        benchmark::DoNotOptimize(v.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations() * n));
}
BENCHMARK(BM_RadixSort)
    ->Args({1 << 18, 1})
    ->Args({1 << 18, 6})
    ->Args({1 << 20, 1})
    ->Unit(benchmark::kMillisecond);

static void BM_Frame(benchmark::State& state, const char* scene_name, const char* accel) {
    const PreparedScene scene = prepare_scene(make_builtin_scene(scene_name));
    Settings s;
    s.set("width", "256"), s.set("height", "256"), s.set("accel", accel);
    if (std::string(accel) == "rah") s.set("cull.objects", "false");
    const RenderSettings rs = RenderSettings::resolve(s, scene.settings);
    double rays = 0;
    for (auto _ : state) {
        Frame f = render_frame(scene, rs);
        rays += f.stats.get("rays.secondary");
    }
    state.counters["secondary_rays_per_s"] = benchmark::Counter(rays, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_Frame, cornell_crsh, "cornell", "crsh")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, cornell_rah, "cornell", "rah")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, office_crsh, "office", "crsh")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, office_rah, "office", "rah")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, colonnade_crsh, "colonnade", "crsh")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Frame, colonnade_rah, "colonnade", "rah")->Unit(benchmark::kMillisecond);

// What keeping a scene's copy between frames (wavefront::SceneKeep) saves and costs on the
// host: packing and copying the scene's arrays (here into host memory, the CPU policy's
// "device"), against the digest of the same arrays that decides whether the kept copy serves.
static void BM_SceneCopy(benchmark::State& state, const char* scene_name, bool digest_only) {
    const PreparedScene scene = prepare_scene(make_builtin_scene(scene_name));
    Settings s;
    const RenderSettings rs = RenderSettings::resolve(s, scene.settings);
    const std::shared_ptr<const CullUnits> units = cull_units_for(scene, rs);
    wavefront::CpuExec exec;
    size_t bytes = 0;
    for (auto _ : state) {
        if (digest_only) {
            benchmark::DoNotOptimize(
                wavefront::DeviceScene<wavefront::CpuExec>::content(scene, *units, nullptr));
        } else {
            wavefront::DeviceScene<wavefront::CpuExec> copy(exec, scene, *units);
            bytes = copy.bytes();
            benchmark::DoNotOptimize(copy.view);
        }
    }
    if (!digest_only) state.counters["bytes"] = double(bytes);
}
BENCHMARK_CAPTURE(BM_SceneCopy, cornell_copy, "cornell", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneCopy, cornell_digest, "cornell", true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneCopy, office_copy, "office", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneCopy, office_digest, "office", true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneCopy, colonnade_copy, "colonnade", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneCopy, colonnade_digest, "colonnade", true)->Unit(benchmark::kMicrosecond);

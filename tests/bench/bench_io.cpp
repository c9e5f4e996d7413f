// What the IO extras cost, side by side in one run (docs/performance.md, "Cost of the IO
// extras"):
//  - the default scene (built-in cornell) at 512x512: the frame alone, the frame written as an
//    OpenEXR of the colour only, and as an OpenEXR with every pass (depth, normal, albedo,
//    object id, tests), which is what `render -o x.exr` writes; and the two writes alone;
//  - scenes/textured.xml at 512x512 with its image textures, and the same scene with every
//    material's texture removed (same geometry, lights and colours);
//  - reading the XML scenes (parse, mesh files, subdivision), without rendering;
//  - subdividing a cage (a 2x2 and a 100x100 grid of quads at level 3).
// Times are wall-clock ("Time") and the CPU time of every thread of the process ("CPU"): on a
// shared machine the second is the steadier measure of the work done.
// Run: build/tests/bench/sheaf_bench_io
#include "core/backend/backend.h"
#include "core/scenes/builtin.h"
#include "io/color/color.h"
#include "io/image/image_io.h"
#include "io/image/texture_sampler.h"
#include "io/scene/scene_file.h"
#include "io/subdiv/subdivide.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

using namespace sheaf;

namespace {

const std::string kScenes = SHEAF_SOURCE_SCENES_DIR;

std::string out_path(const char* name) {
    return (std::filesystem::temp_directory_path() / name).string();
}

RenderSettings settings_512(const Scene& s) {
    RenderSettings rs = RenderSettings::resolve({}, s.settings);
    rs.width = rs.height = 512;
    return rs;
}

const PreparedScene& default_scene() {
    static const Scene s = make_builtin_scene(default_builtin_scene());
    static const PreparedScene p = prepare_scene(s);
    return p;
}

void set_frame_counters(benchmark::State& state) {
    state.SetLabel(std::string(default_builtin_scene()) + " 512x512");
}

enum class Output { None, ExrColour, ExrPasses };

void BM_DefaultScene(benchmark::State& state, Output output) {
    const PreparedScene& p = default_scene();
    const RenderSettings rs = settings_512(make_builtin_scene(default_builtin_scene()));
    const std::string path = out_path("sheaf_bench_io.exr");
    for (auto _ : state) {
        const Frame f = render_frame(p, rs);
        if (output == Output::ExrColour)
            write_pixels(path, f.width, f.height, 4, f.rgba.data(), false, display_options(f));
        else if (output == Output::ExrPasses)
            write_image(f, path);
        benchmark::DoNotOptimize(f.rgba.data());
    }
    set_frame_counters(state);
}
BENCHMARK_CAPTURE(BM_DefaultScene, frame_only, Output::None)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DefaultScene, frame_and_exr_colour, Output::ExrColour)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DefaultScene, frame_and_exr_passes, Output::ExrPasses)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

/// The writes alone, of one frame of the default scene.
void BM_WriteDefaultFrame(benchmark::State& state, Output output) {
    static const Frame f =
        render_frame(default_scene(), settings_512(make_builtin_scene(default_builtin_scene())));
    const std::string path = out_path("sheaf_bench_io_write.exr");
    for (auto _ : state) {
        if (output == Output::ExrColour)
            write_pixels(path, f.width, f.height, 4, f.rgba.data(), false, display_options(f));
        else
            write_image(f, path);
    }
    set_frame_counters(state);
}
BENCHMARK_CAPTURE(BM_WriteDefaultFrame, exr_colour, Output::ExrColour)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_WriteDefaultFrame, exr_passes, Output::ExrPasses)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_TexturedScene(benchmark::State& state, bool textured) {
    Scene s = io::load_scene_file(kScenes + "/textured.xml").scene;
    if (!textured)
        for (Material& m : s.materials) m.texture = -1;
    PreparedScene p = prepare_scene(s);
    io::attach_texture_sampler(p);
    const RenderSettings rs = settings_512(s);
    for (auto _ : state) {
        const Frame f = render_frame(p, rs);
        benchmark::DoNotOptimize(f.rgba.data());
    }
    state.SetLabel("textured.xml 512x512");
}
BENCHMARK_CAPTURE(BM_TexturedScene, textured, true)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_TexturedScene, untextured, false)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_LoadXmlScene(benchmark::State& state, const char* name) {
    const std::string path = kScenes + "/" + name;
    for (auto _ : state) benchmark::DoNotOptimize(io::load_scene_file(path).scene.meshes.size());
}
BENCHMARK_CAPTURE(BM_LoadXmlScene, xml_showcase, "xml_showcase.xml")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_LoadXmlScene, textured, "textured.xml")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_LoadXmlScene, subdiv, "subdiv.xml")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

/// A grid of n x n quads, bent into a bump, as a Catmull-Clark cage.
io::SubdivCage grid_cage(int n) {
    io::SubdivCage c;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            const float u = float(x) / n - 0.5f, v = float(y) / n - 0.5f;
            c.positions.push_back(Vec3(u, v, 0.3f * std::cos(3 * u) * std::cos(3 * v)));
        }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = uint32_t(y * (n + 1) + x);
            c.face_sizes.push_back(4);
            c.face_indices.insert(c.face_indices.end(),
                                  {a, a + 1, a + uint32_t(n) + 2, a + uint32_t(n) + 1});
        }
    return c;
}

void BM_Subdivide(benchmark::State& state) {
    const int n = int(state.range(0)), level = int(state.range(1));
    const io::SubdivCage cage = grid_cage(n);
    io::SubdivOptions o;
    o.level = level;
    o.limit = state.range(2) != 0;
    size_t triangles = 0;
    for (auto _ : state) triangles = io::subdivide(cage, o).triangle_count();
    state.SetLabel(std::to_string(n * n) + " quads, level " + std::to_string(level) +
                   (o.limit ? ", limit" : "") + ": " + std::to_string(triangles) + " triangles");
}
BENCHMARK(BM_Subdivide)
    ->Args({4, 3, 0})
    ->Args({100, 3, 0})
    ->Args({100, 3, 1})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();

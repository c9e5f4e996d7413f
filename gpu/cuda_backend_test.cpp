// The CUDA backend against the CPU renderer (CTest `cuda`, label cuda): the module loads and
// probes; on a machine with a device, every built-in scene, every scenes/*.pov and *.xml and
// the pipeline test scenes render to the same image, passes and statistics as on the CPU.
// Without a device the comparisons skip, never fail. Run alone: ctest -L cuda
// --output-on-failure (SHEAF_CUDA_MODULE is set to this build's module).
#include "core/backend/backend.h"
#include "core/base/error.h"
#include "core/scenes/builtin.h"
#include "core/scenes/test_scenes.h"
#include "io/scene/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace sheaf {
namespace {

using test::SettingList;

const CudaBackendStatus& status() {
    return cuda_backend();
}

#define SKIP_WITHOUT_DEVICE()                                                                    \
    do {                                                                                         \
        if (!status().usable) GTEST_SKIP() << "no usable CUDA device: " << status().error;       \
    } while (0)

void expect_cuda_matches_cpu(const PreparedScene& scene, const std::string& name,
                             const SettingList& kv, int w = 64, int h = 48) {
    const RenderSettings s = test::settings_for(scene, kv, w, h);
    const std::string label = test::label(name, kv);
    const auto t0 = std::chrono::steady_clock::now();
    const Frame cpu = render_frame_cpu(scene, s);
    const auto t1 = std::chrono::steady_clock::now();
    Frame gpu;
    try {
        gpu = render_frame_cuda(status(), scene, s);
    } catch (const RenderError& e) {
        ADD_FAILURE() << label << ": " << e.what();
        return;
    }
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("%-60s cpu %8.1f ms  cuda %8.1f ms (frame %8.1f ms on the device)\n",
                label.c_str(), std::chrono::duration<double, std::milli>(t1 - t0).count(),
                std::chrono::duration<double, std::milli>(t2 - t1).count(),
                gpu.stats.get("time_ms.frame"));
    test::expect_same_frame(cpu, gpu, label);
}

TEST(Cuda, ModuleLoadsAndProbes) {
    const CudaBackendStatus& st = status();
    ASSERT_NE(st.module, nullptr) << st.detail;
    std::printf("module %s (%s): %s\n", st.path.c_str(), st.module->build,
                st.usable ? (std::string(st.probe.name) + ", compute " +
                             std::to_string(st.probe.cc_major) + "." +
                             std::to_string(st.probe.cc_minor))
                                .c_str()
                          : st.error.c_str());
    if (!st.usable) EXPECT_EQ(st.error.rfind("no CUDA device: ", 0), 0u) << st.error;
}

TEST(Cuda, BuiltinScenesMatchTheCpu) {
    SKIP_WITHOUT_DEVICE();
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (const SettingList& kv :
             {SettingList{}, SettingList{{"accel", "rah"}},
              SettingList{{"hash.mode", "hash192"}, {"ao.samples", "4"}},
              SettingList{{"hash.mode", "static3d"}, {"sort.algorithm", "bitonic"}},
              SettingList{{"aa.samples", "2"}, {"traversal.batch", "65536"}}})
            expect_cuda_matches_cpu(scene, name, kv);
        expect_cuda_matches_cpu(scene, name, {{"accel", "brute"}}, 24, 16);
    }
}

TEST(Cuda, PipelineTestScenesMatchTheCpu) {
    SKIP_WITHOUT_DEVICE();
    const std::vector<SettingList> variants = {
        {{"accel", "brute"}},
        {{"accel", "rah"}, {"cull.objects", "false"}},
        {},
        {{"hash.mode", "hash32"}, {"sort.mode", "full"}, {"ao.samples", "3"}},
        {{"hash.mode", "hash192"}},
        {{"hierarchy.depth", "4"}, {"hierarchy.arity", "5"}, {"traversal.batch", "1024"}},
        {{"hierarchy.depth", "1"}, {"hierarchy.arity", "64"}, {"cull.distance", "false"}},
    };
    const std::vector<std::pair<std::string, Scene>> scenes = {
        {"glass", test::glass_mirror_scene()},    {"lights", test::lights_scene(false)},
        {"ortho", test::lights_scene(true)},      {"csg", test::csg_scene()},
        {"procedural", test::procedural_scene()}, {"media", test::media_scene()},
        {"scattering", test::scattering_scene()}, {"atmosphere", test::atmosphere_scene()},
        {"rainbow", test::rainbow_scene()},       {"photons", test::photon_scene()}};
    for (const auto& [name, s] : scenes) {
        const PreparedScene scene = prepare_scene(s);
        for (const SettingList& kv : variants) expect_cuda_matches_cpu(scene, name, kv);
    }
}

TEST(Cuda, SceneFilesMatchTheCpu) {
    SKIP_WITHOUT_DEVICE();
    io::SceneFileOptions options;
    options.image_width = 64, options.image_height = 48;
    // On a machine without the source tree or POV-Ray's includes (the GPU kit, gpu/kit.sh):
    // $SHEAF_SCENES_DIR and $SHEAF_POV_INCLUDE name copies.
    const char* pov_include = std::getenv("SHEAF_POV_INCLUDE");
    const std::string include = pov_include && *pov_include ? pov_include
                                                            : "/usr/share/povray-3.7/include";
    if (std::filesystem::exists(include)) options.include_paths.push_back(include);
    const char* scenes_env = std::getenv("SHEAF_SCENES_DIR");
    const std::string scenes_dir = scenes_env && *scenes_env ? scenes_env : SHEAF_SCENES_DIR;
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(scenes_dir)) {
        const std::string ext = e.path().extension().string();
        if (ext == ".pov" || ext == ".xml") files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    for (const std::string& f : files) {
        PreparedScene scene;
        try {
            scene = prepare_scene(io::load_scene_file(f, options).scene);
        } catch (const std::exception& e) {
            ADD_FAILURE() << f << ": " << e.what();
            continue;
        }
        const std::string why = choose_backend(scene, Backend::Auto, status()).why_not;
        if (!why.empty()) { // e.g. image textures: auto renders these on the CPU
            std::printf("%-60s on the CPU only: %s\n", f.c_str(), why.c_str());
            continue;
        }
        expect_cuda_matches_cpu(scene, std::filesystem::path(f).filename().string(), {});
    }
}

TEST(Cuda, BackendAutoChoosesTheDevice) {
    SKIP_WITHOUT_DEVICE();
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    const Frame f = render_frame(scene, test::settings_for(scene, {{"backend", "auto"}}, 32, 24));
    EXPECT_EQ(f.backend, "cuda");
    EXPECT_EQ(f.stats.get("backend.cuda"), 1);
    EXPECT_EQ(f.backend_line.rfind("backend: cuda (", 0), 0u) << f.backend_line;
}

TEST(Cuda, CancellingStopsTheFrame) {
    SKIP_WITHOUT_DEVICE();
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    EXPECT_THROW(render_frame_cuda(status(), scene, test::settings_for(scene, {}, 32, 24),
                                   [](float) { return false; }),
                 RenderError);
}

} // namespace
} // namespace sheaf

// The CUDA backend against the CPU backend (CTest `cuda`, label cuda): the module loads and
// probes; on a machine with a device, every built-in scene, every scenes/*.pov and *.xml and
// the pipeline test scenes render to the same image, passes and statistics as on the CPU.
// Without a device the comparisons skip, never fail. Run alone: ctest -L cuda
// --output-on-failure (SHEAF_CUDA_MODULE is set to this build's module).
#include "core/backend/backend.h"
#include "core/base/error.h"
#include "core/scenes/builtin.h"
#include "tests/support/sample_scenes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <thread>

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

// Isosurfaces are the one known exception to bit-for-bit equality (measured on an H200):
// their normals differ in the last bits (at most 1.8e-7 on the helix of functions.pov, 9.9e-5
// on the torus of isosurfaces.pov) and so does their shading (at most 2.9e-5), while depth,
// object ids and every count are equal. Where the device's march first parts from the host's
// is not yet found: the math both call (hd_math, the internal functions) gives the same bits
// on 65,536 random points, and the host's wavefront pipeline equals the CPU backend on these
// scenes; gpu/analytic_bits_test.cu takes the isosurfaces apart ray by ray to find it. So the
// shaded passes of frames with isosurfaces (image, normals, albedo) must agree within
// kIsoTolerance, the rest exactly.
constexpr float kIsoTolerance = 1e-3f;

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
    test::expect_same_frame(cpu, gpu, label, {}, scene.isosurfaces.empty() ? 0.0f : kIsoTolerance);
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
             {SettingList{}, SettingList{{"accel", "rah"}}, SettingList{{"accel", "bvh"}},
              SettingList{{"accel", "crsh-bvh"}}, SettingList{{"accel", "rah-bvh"}},
              SettingList{{"accel", "strips"}},
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
        {{"accel", "bvh"}},
        {{"accel", "strips"}},
        {{"accel", "crsh-bvh"}, {"traversal.batch", "1024"}},
        {{"accel", "rah-bvh"}, {"hierarchy.depth", "3"}, {"hierarchy.arity", "4"}},
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
    io::for_each_sample_scene(
        SHEAF_SCENES_DIR, 64, 48, [](const std::string& name, const PreparedScene& scene) {
            const std::string why = choose_backend(scene, Backend::Auto, status()).why_not;
            if (!why.empty()) { // e.g. image textures: auto renders these on the CPU
                std::printf("%-60s on the CPU only: %s\n", name.c_str(), why.c_str());
                return;
            }
            expect_cuda_matches_cpu(scene, name, {});
            expect_cuda_matches_cpu(scene, name, {{"accel", "bvh"}});
            expect_cuda_matches_cpu(scene, name, {{"accel", "crsh-bvh"}});
            expect_cuda_matches_cpu(scene, name, {{"accel", "strips"}});
        });
}

TEST(Cuda, TheSceneStaysOnTheDeviceBetweenFrames) {
    SKIP_WITHOUT_DEVICE();
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    const RenderSettings s = test::settings_for(office, {{"ao.samples", "2"}}, 64, 48);
    const Frame cpu = render_frame_cpu(office, s);
    render_frame_cuda(status(), office, s); // the module now keeps office
    const Frame kept = render_frame_cuda(status(), office, s);
    EXPECT_EQ(kept.stats.get("device.scene_kept"), 1.0);
    test::expect_same_frame(cpu, kept, "office, kept");

    PreparedScene recoloured = office;
    recoloured.materials.at(0).color = Vec3(0.9f, 0.1f, 0.1f);
    const Frame fresh = render_frame_cuda(status(), recoloured, s);
    EXPECT_EQ(fresh.stats.get("device.scene_kept"), 0.0);
    test::expect_same_frame(render_frame_cpu(recoloured, s), fresh, "office recoloured");
}

TEST(Cuda, FramesAtOnceEachGetTheirOwnAnswer) {
    // Two threads render at once: one on the module's resident exec, the other (finding it
    // busy) on an exec of its own; each frame is the CPU's.
    SKIP_WITHOUT_DEVICE();
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    const PreparedScene cornell = prepare_scene(make_builtin_scene("cornell"));
    const RenderSettings so = test::settings_for(office, {}, 96, 72);
    const RenderSettings sc = test::settings_for(cornell, {}, 96, 72);
    Frame a, b;
    std::string error_a, error_b;
    auto run = [](const PreparedScene& scene, const RenderSettings& s, Frame& f,
                  std::string& error) {
        try {
            for (int i = 0; i < 3; ++i) f = render_frame_cuda(status(), scene, s);
        } catch (const std::exception& e) {
            error = e.what();
        }
    };
    std::thread ta(run, std::cref(office), std::cref(so), std::ref(a), std::ref(error_a));
    std::thread tb(run, std::cref(cornell), std::cref(sc), std::ref(b), std::ref(error_b));
    ta.join(), tb.join();
    ASSERT_EQ(error_a, "");
    ASSERT_EQ(error_b, "");
    test::expect_same_frame(render_frame_cpu(office, so), a, "office, at once");
    test::expect_same_frame(render_frame_cpu(cornell, sc), b, "cornell, at once");
}

TEST(Cuda, PassSubsetsMatchTheCpu) {
    SKIP_WITHOUT_DEVICE();
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    for (const char* passes : {"combined", "combined,tests", "depth,normal,albedo,object_id"})
        expect_cuda_matches_cpu(office, "office", {{"output.passes", passes}});
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

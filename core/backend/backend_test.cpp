// Backend selection: auto falls back to the CPU and says why, cuda without a usable device is
// a clear error, a missing module is no error for libsheaf, and the module, when it loads,
// reports its device or why there is none.
#include "core/backend/backend.h"

#include "core/base/error.h"
#include "core/wavefront/test_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace sheaf {
namespace {

RenderSettings small(const char* backend) {
    Settings s;
    s.set("width", "24"), s.set("height", "16"), s.set("backend", backend);
    return RenderSettings::resolve(s);
}

CudaBackendStatus missing_module() {
    return load_cuda_backend({"/nonexistent/sheaf/" SHEAF_CUDA_MODULE_FILE});
}

TEST(Backend, AMissingModuleIsNoError) {
    const CudaBackendStatus st = missing_module();
    EXPECT_EQ(st.module, nullptr);
    EXPECT_FALSE(st.usable);
    EXPECT_NE(st.error.find("no CUDA module"), std::string::npos) << st.error;
    EXPECT_NE(st.detail.find("/nonexistent/sheaf/"), std::string::npos) << st.detail;
}

TEST(Backend, AutoFallsBackToTheCpuAndSaysWhy) {
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    const BackendChoice c = choose_backend(scene, Backend::Auto, missing_module());
    EXPECT_FALSE(c.cuda);
    EXPECT_EQ(c.line.rfind("backend: cpu (no CUDA module", 0), 0u) << c.line;
    EXPECT_EQ(c.line.find('\n'), std::string::npos) << "one line: " << c.line;

    CudaBackendStatus no_device;
    no_device.error = "no CUDA device: cudaErrorNoDevice: no CUDA-capable device is detected";
    const BackendChoice d = choose_backend(scene, Backend::Auto, no_device);
    EXPECT_FALSE(d.cuda);
    EXPECT_EQ(d.line, "backend: cpu (" + no_device.error + ")");

    CudaBackendStatus device;
    device.usable = true;
    std::snprintf(device.probe.name, sizeof device.probe.name, "NVIDIA H100");
    device.probe.cc_major = 9, device.probe.cc_minor = 0;
    const BackendChoice e = choose_backend(scene, Backend::Auto, device);
    EXPECT_TRUE(e.cuda);
    EXPECT_EQ(e.line, "backend: cuda (NVIDIA H100, compute 9.0)");
    EXPECT_FALSE(choose_backend(scene, Backend::Cpu, device).cuda);

    // Image textures keep even a usable device out.
    PreparedScene textured = scene;
    struct Grey : TextureSampler {
        Vec3 sample(uint32_t, float, float) const override { return Vec3(0.5f); }
    };
    textured.textures.push_back(Texture{});
    textured.sampler = std::make_shared<Grey>();
    const BackendChoice t = choose_backend(textured, Backend::Auto, device);
    EXPECT_FALSE(t.cuda);
    EXPECT_NE(t.line.find("image textures"), std::string::npos) << t.line;
}

TEST(Backend, RenderFrameSaysWhereTheFrameWasComputed) {
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    const Frame cpu = render_frame(scene, small("cpu"));
    EXPECT_EQ(cpu.backend, "cpu");
    EXPECT_EQ(cpu.backend_line, "backend: cpu (backend=cpu)");
    EXPECT_EQ(cpu.stats.get("backend.cuda"), 0);
    const Frame autof = render_frame(scene, small("auto"));
    if (cuda_backend().usable) {
        EXPECT_EQ(autof.backend, "cuda");
        EXPECT_EQ(autof.stats.get("backend.cuda"), 1);
    } else { // this machine: the CPU, and why
        EXPECT_EQ(autof.backend, "cpu");
        EXPECT_EQ(autof.backend_line, "backend: cpu (" + cuda_backend().error + ")");
        EXPECT_EQ(autof.stats.get("backend.cuda"), 0);
        EXPECT_EQ(0, std::memcmp(autof.rgba.data(), cpu.rgba.data(), cpu.rgba.size() * 4));
    }
}

TEST(Backend, CudaWithoutAUsableDeviceIsAClearError) {
    if (cuda_backend().usable) GTEST_SKIP() << "a CUDA device is usable here";
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    try {
        render_frame(scene, small("cuda"));
        FAIL() << "backend=cuda rendered without a device";
    } catch (const RenderError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("backend=cuda: ", 0), 0u) << what;
        EXPECT_NE(what.find(cuda_backend().error), std::string::npos) << what;
    }
}

// The module this build made (when nvcc was found) loads on a machine without a driver and
// says why it has no device; the path comes from the build.
TEST(Backend, TheBuiltModuleLoadsAndProbes) {
    const std::string built = cuda_module_build_path();
    if (built.empty()) GTEST_SKIP() << "this build has no CUDA module (nvcc not found)";
    const CudaBackendStatus st = load_cuda_backend({built});
    ASSERT_NE(st.module, nullptr) << st.detail;
    EXPECT_EQ(st.module->abi_version, SHEAF_CUDA_MODULE_ABI);
    EXPECT_NE(std::string(st.module->build).find("CUDA"), std::string::npos);
    if (st.usable) {
        EXPECT_GT(st.probe.device_count, 0);
        EXPECT_GE(st.probe.cc_major, 8);
    } else {
        EXPECT_EQ(st.error.rfind("no CUDA device: ", 0), 0u) << st.error;
        EXPECT_GT(std::strlen(st.probe.error), 0u);
    }
}

} // namespace
} // namespace sheaf

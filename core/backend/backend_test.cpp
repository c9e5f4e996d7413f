// Backend selection: auto falls back to the CPU and says why, cuda without a usable device is
// a clear error, a missing module is no error for libsheaf, and the module, when it loads,
// reports its device or why there is none.
#include "core/backend/backend.h"
#include "core/backend/device_stack.h"

#include "core/base/error.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// A sphere inside `levels` nested intersections (each with a big box, so the shape is the
// same at every depth).
PreparedScene nested_csg(int levels) {
    Scene s;
    const uint32_t m = s.add_material(Material{});
    ShapeObject o; // children are later nodes: op, its box, the next op, ..., the sphere
    o.name = "nested";
    for (int i = 0; i < levels; ++i) {
        CsgNode op;
        op.op = CsgOp::Intersection;
        op.children = {uint32_t(2 * i + 1), uint32_t(2 * i + 2)};
        o.nodes.push_back(op);
        CsgNode box;
        box.shape = Shape{ShapeKind::Box};
        box.material = m;
        box.transform = Affine::scale(Vec3(4));
        o.nodes.push_back(box);
    }
    CsgNode sphere;
    sphere.shape = Shape{ShapeKind::Sphere};
    sphere.material = m;
    o.nodes.push_back(sphere);
    o.root = 0;
    s.add_shape_object(o);
    s.add_light(Light{Vec3(0, 6, 6), Vec3(1.0f)});
    return prepare_scene(s);
}

// The device stack grows with CSG nesting; past the cap a scene stays on the CPU with auto
// and is an error with cuda, before anything is launched.
TEST(Backend, DeepCsgStaysOnTheCpu) {
    EXPECT_EQ(csg_nesting(prepare_scene(test::glass_mirror_scene())), 0);
    EXPECT_EQ(csg_nesting(nested_csg(1)), 1);
    EXPECT_EQ(csg_nesting(nested_csg(7)), 7);
    const int most = int((kDeviceStackCap - kDeviceStackBase) / kDeviceStackPerCsgLevel);
    EXPECT_LE(device_stack_bytes(nested_csg(most)), kDeviceStackCap);
    EXPECT_GT(device_stack_bytes(nested_csg(most + 1)), kDeviceStackCap);
    // Media containers' span lists (in the shading kernels' frames) and julia fractals' orbits
    // (the deepest leaf) are inside the base; these scenes have one CSG level.
    EXPECT_EQ(device_stack_bytes(prepare_scene(test::media_scene())),
              kDeviceStackBase + kDeviceStackPerCsgLevel);
    EXPECT_EQ(device_stack_bytes(prepare_scene(test::julia_scene())),
              kDeviceStackBase + kDeviceStackPerCsgLevel);
    // Scattering media run the media light kernel, whose chain is deeper.
    Scene scattering = test::media_scene();
    scattering.media[0].scattering = Vec3(0.1f);
    EXPECT_EQ(device_stack_bytes(prepare_scene(scattering)),
              kDeviceStackBase + kDeviceStackPerCsgLevel + kDeviceStackMediaLight);
    // So does a scattering atmosphere; one that only absorbs does not.
    Scene air = test::atmosphere_scene();
    const size_t lit = device_stack_bytes(prepare_scene(air));
    air.media[0].scattering = Vec3(0.0f);
    EXPECT_EQ(lit, device_stack_bytes(prepare_scene(air)) + kDeviceStackMediaLight);

    CudaBackendStatus device;
    device.usable = true;
    std::snprintf(device.probe.name, sizeof device.probe.name, "NVIDIA H100");
    device.probe.cc_major = 9;
    EXPECT_TRUE(choose_backend(nested_csg(most), Backend::Auto, device).cuda);
    const PreparedScene deep = nested_csg(most + 1);
    const BackendChoice c = choose_backend(deep, Backend::Auto, device);
    EXPECT_FALSE(c.cuda);
    EXPECT_NE(c.line.find("CSG nested " + std::to_string(most + 1) + " levels"), std::string::npos)
        << c.line;
    // The CPU renders it, and the sphere is seen.
    const Frame f = render_frame(deep, small("cpu"));
    float peak = 0;
    for (float v : f.rgba) peak = std::max(peak, v);
    EXPECT_GT(peak, 0.0f);
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

// A module whose render loses the device's context: the frame falls back to the CPU, and the
// process stops using that module, saying why; backend=cuda then fails with the reason.
int fake_probe(SheafCudaProbe* out) {
    std::memset(out, 0, sizeof *out);
    out->device_count = 1;
    std::snprintf(out->name, sizeof out->name, "Fake GPU");
    out->cc_major = 9;
    return SHEAF_CUDA_OK;
}
int fake_renders = 0;
int fake_render_breaks(const void*, const void*, const void*, void*, char* error, size_t size) {
    ++fake_renders;
    std::snprintf(error, size, "CUDA rsh.top: cudaErrorIllegalAddress: an illegal memory access");
    return SHEAF_CUDA_BROKEN;
}

TEST(Backend, ALostDeviceIsNotUsedAgain) {
    static const SheafCudaModule fake = {SHEAF_CUDA_MODULE_ABI, 0, "fake", fake_probe,
                                         fake_render_breaks};
    CudaBackendStatus st;
    st.module = &fake;
    st.usable = fake_probe(&st.probe) == SHEAF_CUDA_OK;
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    const Frame cpu = render_frame(scene, small("cpu"));

    const Frame first = render_frame_with(st, scene, small("auto"));
    EXPECT_EQ(fake_renders, 1);
    EXPECT_EQ(first.backend, "cpu");
    EXPECT_NE(first.backend_line.find("cudaErrorIllegalAddress"), std::string::npos)
        << first.backend_line;
    EXPECT_EQ(0, std::memcmp(first.rgba.data(), cpu.rgba.data(), cpu.rgba.size() * 4));

    const Frame second = render_frame_with(st, scene, small("auto"));
    EXPECT_EQ(fake_renders, 1) << "the lost module was asked again";
    EXPECT_EQ(second.backend_line.rfind("backend: cpu (the CUDA device failed earlier", 0), 0u)
        << second.backend_line;
    try {
        render_frame_with(st, scene, small("cuda"));
        FAIL() << "backend=cuda used a lost module";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("failed earlier in this process"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(fake_renders, 1);
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

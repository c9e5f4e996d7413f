// The frame pipeline with its two tracers under the CPU policy: the wavefront tracer (the CUDA
// module's) against the CPU's (the CPU backend's), identical images, passes and statistics on
// the built-in scenes and on scenes exercising every part of the pipeline, under every accel,
// hash, sort, depth and arity. What the CUDA backend runs is this code with another exec;
// this proves its logic on any machine.
#include "core/frame/render_frame.h"

#include "core/base/error.h"
#include "core/frame/cpu_exec.h"
#include "core/frame/order.h"
#include "core/frame/wavefront_tracer.h"
#include "core/raster/camera.h"
#include "core/scenes/builtin.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace sheaf {
namespace {

using test::SettingList;

using test::label;

RenderSettings settings_for(const PreparedScene& scene, const SettingList& kv, int w = 40,
                            int h = 32) {
    return test::settings_for(scene, kv, w, h);
}

Frame expect_identical(const PreparedScene& scene, const std::string& name, const SettingList& kv,
                       int w = 40, int h = 32) {
    const RenderSettings s = settings_for(scene, kv, w, h);
    const Frame cpu = render_frame_cpu(scene, s);
    const Frame wave = render_frame_wavefront_cpu(scene, s);
    test::expect_same_frame(cpu, wave, label(name, kv));
    return cpu;
}

double mean(const Frame& f) {
    double m = 0;
    for (size_t i = 0; i < f.rgba.size(); i += 4) m += f.rgba[i] + f.rgba[i + 1] + f.rgba[i + 2];
    return m / double(f.rgba.size());
}

const std::vector<SettingList>& variants() {
    static const std::vector<SettingList> v = {
        {{"accel", "brute"}},
        {{"accel", "rah"}, {"cull.objects", "false"}},
        {},
        {{"hash.mode", "hash32"}, {"sort.mode", "full"}},
        {{"hash.mode", "hash192"}, {"sort.mode", "csd"}},
        {{"hash.mode", "static3d"}, {"sort.algorithm", "bitonic"}},
        {{"hash.mode", "hash32"}, {"sort.algorithm", "bitonic"}, {"sort.mode", "csd"}},
        {{"hash.mode", "static1d"}, {"cull.distance", "false"}},
        {{"hierarchy.depth", "1"}, {"hierarchy.arity", "2"}},
        {{"hierarchy.depth", "4"}, {"hierarchy.arity", "5"}, {"cull.objects", "false"}},
        {{"hierarchy.arity", "64"}, {"hierarchy.depth", "3"}},
        {{"traversal.batch", "1024"}},
        {{"hash.mode", "none"}, {"sort.mode", "none"}},
        {{"cull.cluster", "0"}},
        {{"cull.cluster", "1"}, {"traversal.batch", "4096"}},
        {{"cull.cluster", "7"}, {"hash.mode", "hash192"}, {"hierarchy.depth", "3"}},
    };
    return v;
}

TEST(Wavefront, BuiltinScenesAreIdentical) {
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (const SettingList& kv :
             {SettingList{}, SettingList{{"accel", "rah"}},
              SettingList{{"hash.mode", "hash192"}, {"ao.samples", "2"}},
              SettingList{{"aa.samples", "2"}, {"traversal.batch", "4096"}}})
            expect_identical(scene, name, kv, 32, 24);
    }
    const PreparedScene cornell = prepare_scene(make_builtin_scene("cornell"));
    expect_identical(cornell, "cornell", {{"accel", "brute"}}, 24, 20);
}

// Each level's hit pairs are compacted on the executing side and the next level is launched
// for the count found there: cutting a group's candidates into more chunks adds launches, not
// host waits (at hierarchy.depth 2 a chunk costs the host none), and changes no count.
TEST(Wavefront, TraversalChunksCostTheHostNoWait) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    const auto run = [&](size_t batch) {
        const RenderSettings s =
            settings_for(scene, {{"accel", "crsh"}, {"traversal.batch", std::to_string(batch)}},
                         192, 144);
        return render_frame_wavefront_cpu(scene, s);
    };
    // Top chunks of 2^27 candidates (one a group), and of the fewest a chunk takes.
    const Frame whole = run(size_t(1) << 30);
    const Frame cut = run(wavefront::kMinTopChunk * 8);
    test::expect_same_frame(whole, cut, "office, chunks of 2^27 and 2^16 candidates");
    const double top_tests = whole.stats.get("tests.shadow.level2.tests");
    ASSERT_GT(top_tests, 4.0 * double(wavefront::kMinTopChunk)) << "too few chunks to compare";
    EXPECT_GT(cut.stats.get("device.launches"), whole.stats.get("device.launches") + 8);
    EXPECT_EQ(cut.stats.get("device.host_waits"), whole.stats.get("device.host_waits"));
    EXPECT_EQ(whole.stats.get("device.batch_pairs"), double(size_t(1) << 30));
}

TEST(Wavefront, PassSubsetsAreIdentical) {
    // Passes left out are neither resolved nor read back, and the per-sample test counts are
    // not gathered without the tests pass; what is kept is the CPU backend's.
    for (const char* name : {"office", "cornell"}) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (const char* passes : {"combined", "combined,tests", "depth,normal,albedo,object_id"})
            expect_identical(scene, name, {{"output.passes", passes}, {"ao.samples", "2"}}, 32, 24);
    }
}

TEST(Wavefront, GlassMirrorsAndAmbientOcclusionAreIdentical) {
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    for (SettingList kv : variants()) {
        kv.push_back({"ao.samples", "3"});
        expect_identical(scene, "glass", kv);
    }
    const Frame f = expect_identical(scene, "glass", {{"ao.samples", "3"}});
    EXPECT_GT(f.stats.get("rays.refraction"), 0);
    EXPECT_GT(f.stats.get("rays.reflection"), 0);
    EXPECT_GT(f.stats.get("rays.ao"), 0);
    EXPECT_GT(mean(f), 0.05);
    expect_identical(scene, "glass", {{"aa.samples", "3"}, {"trace.depth", "7"}}, 24, 20);
}

TEST(Wavefront, RadiosityIsIdentical) {
    // Gather rays from camera, mirror and glass paths, gathered paths going on (depth 2 and 3),
    // under every accel, hash, sort, depth and arity.
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    for (SettingList kv : variants()) {
        kv.push_back({"radiosity.samples", "3"});
        expect_identical(scene, "glass", kv, 24, 20);
    }
    const Frame f = expect_identical(
        scene, "glass",
        {{"radiosity.samples", "4"}, {"radiosity.depth", "3"}, {"ao.samples", "2"}});
    EXPECT_GT(f.stats.get("rays.diffuse"), 0);
    EXPECT_GT(f.stats.get("tests.diffuse.total"), 0);
    expect_identical(scene, "glass",
                     {{"radiosity.samples", "2"},
                      {"aa.samples", "2"},
                      {"radiosity.brightness", "0.5"},
                      {"trace.depth", "1"}},
                     16, 12);
}

TEST(Wavefront, EveryLightKindIsIdentical) {
    for (bool ortho : {false, true}) {
        const PreparedScene scene = prepare_scene(test::lights_scene(ortho));
        for (const SettingList& kv : variants())
            expect_identical(scene, ortho ? "ortho" : "lights", kv);
        const Frame f = expect_identical(scene, "lights", {});
        EXPECT_GT(f.stats.get("rays.shadow"), f.stats.get("rays.primary")); // several lights
        EXPECT_GT(mean(f), 0.05);
    }
}

TEST(Wavefront, AnalyticShapesCsgAndTransparentShadowsAreIdentical) {
    const PreparedScene scene = prepare_scene(test::csg_scene());
    for (const SettingList& kv : variants()) expect_identical(scene, "csg", kv);
    const Frame f = expect_identical(scene, "csg", {{"ao.samples", "2"}, {"aa.samples", "2"}});
    EXPECT_GT(f.stats.get("rays.refraction"), 0);
    EXPECT_GT(f.stats.get("rays.reflection"), 0);
    EXPECT_GT(mean(f), 0.05);
}

TEST(Wavefront, JuliaFractalsAreIdentical) {
    // Marched shapes, refraction through one, a CSG cut, under a share of the variants.
    const PreparedScene scene = prepare_scene(test::julia_scene());
    for (size_t i = 0; i < variants().size(); i += 3)
        expect_identical(scene, "julia", variants()[i], 24, 20);
    const Frame f = expect_identical(scene, "julia", {{"ao.samples", "2"}}, 24, 20);
    EXPECT_GT(f.stats.get("rays.refraction"), 0);
    EXPECT_GT(mean(f), 0.05);
}

TEST(Wavefront, ProceduralTexturesFlagsFogAndSkyAreIdentical) {
    const PreparedScene scene = prepare_scene(test::procedural_scene());
    for (SettingList kv : variants()) {
        kv.push_back({"ao.samples", "2"});
        expect_identical(scene, "procedural", kv);
    }
    const Frame f = expect_identical(scene, "procedural", {});
    EXPECT_GT(f.stats.get("rays.refraction"), 0);
    EXPECT_GT(f.stats.get("rays.reflection"), 0);
    EXPECT_GT(mean(f), 0.05);
}

TEST(Wavefront, TracedProjectionsAreIdentical) {
    // Camera rays through the ray hierarchy instead of the rasteriser: every projection on
    // triangles, analytic shapes and CSG, objects without an image, and a camera normal,
    // under the variants.
    for (int p = 2; p < kProjectionCount; ++p) {
        Scene s = p % 2 ? test::csg_scene() : test::procedural_scene();
        s.camera.projection = Projection(p);
        s.camera.angle_degrees = 150;
        const PreparedScene scene = prepare_scene(s);
        const Frame f = expect_identical(scene, "projection " + std::to_string(p), {}, 24, 20);
        EXPECT_GT(f.stats.get("rays.camera"), 0);
        EXPECT_GT(mean(f), 0.02);
    }
    Scene s = test::csg_scene();
    s.camera.projection = Projection::Fisheye;
    const PreparedScene fisheye = prepare_scene(s);
    for (const SettingList& kv : variants()) expect_identical(fisheye, "fisheye", kv, 24, 20);
    expect_identical(fisheye, "fisheye aa", {{"aa.samples", "2"}}, 16, 12);
    // A camera normal tilts the primary rays, so a perspective camera is traced too.
    Scene tilted = test::procedural_scene();
    tilted.camera.normal = 0;
    const PreparedScene bent = prepare_scene(tilted);
    for (const SettingList& kv : variants()) expect_identical(bent, "camera normal", kv, 24, 20);
    const Frame f = expect_identical(bent, "camera normal aa", {{"aa.samples", "2"}}, 16, 12);
    EXPECT_GT(f.stats.get("rays.camera"), 0);
    // A lens (depth of field): each sample leaves its own point of the lens.
    Scene lens = test::csg_scene();
    lens.camera.lens_radius = 0.3f, lens.camera.focal_distance = 4;
    const PreparedScene blurred = prepare_scene(lens);
    const Frame b = expect_identical(blurred, "lens aa", {{"aa.samples", "3"}}, 16, 12);
    EXPECT_GT(b.stats.get("rays.camera"), 0);
    expect_identical(blurred, "lens", {}, 24, 20);
    // A mesh camera: the rays leave the faces of the scene's camera meshes (two of them, a
    // pixel's samples taking one ray from each), read from the scene on either side.
    Scene meshed = test::csg_scene();
    meshed.camera.projection = Projection::Orthographic;
    meshed.camera.ortho_height = 4;
    const CameraFrame oc = make_camera_frame(meshed.camera, 24, 20);
    Mesh faces;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 24; ++x) {
            const Vec3 o = oc.pixel_ray(x, y).origin;
            const uint32_t base = uint32_t(faces.positions.size());
            faces.positions.insert(faces.positions.end(),
                                   {o, o + oc.up * 1e-3f, o + oc.right * 1e-3f});
            faces.indices.insert(faces.indices.end(), {base, base + 1, base + 2});
        }
    meshed.camera.projection = Projection::Mesh;
    meshed.camera.mesh_rays = 2;
    meshed.camera_meshes = {{faces, Affine()}, {faces, Affine::translate(oc.right * 0.05f)}};
    const PreparedScene mesh_camera = prepare_scene(meshed);
    const Frame m = expect_identical(mesh_camera, "mesh camera aa", {{"aa.samples", "2"}}, 24, 20);
    EXPECT_GT(m.stats.get("rays.camera"), 0);
    EXPECT_GT(mean(m), 0.02);
}

TEST(Wavefront, EmptyAndDegenerateFramesAreIdentical) {
    Scene s; // lights and no shadow casters in view, the camera inside the scene
    Material m;
    s.add_mesh_object("far", make_box(Vec3(10, 10, 10), Vec3(11, 11, 11)), s.add_material(m));
    s.background = Vec3(0.3f, 0.2f, 0.1f);
    expect_identical(prepare_scene(s), "empty", {});
    Scene no_lights = test::glass_mirror_scene();
    no_lights.lights.clear();
    expect_identical(prepare_scene(no_lights), "no lights", {{"ao.samples", "1"}});
    expect_identical(prepare_scene(test::glass_mirror_scene()), "1x1", {}, 1, 1);
    expect_identical(prepare_scene(test::glass_mirror_scene()), "depth 0", {{"trace.depth", "0"}});
}

TEST(Wavefront, CancellingStopsTheFrame) {
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    const RenderSettings s = settings_for(scene, {});
    EXPECT_THROW(render_frame_wavefront_cpu(scene, s, [](float) { return false; }), RenderError);
}

// The seam's order stage against the CPU's for random keys: the same permutation and chunks
// (the CUDA policy's radix sort must give this stable permutation too).
// The order of the rays is the stable sort of their keys (ties by ray index) whatever the
// key width, sort mode and algorithm; csd counts one chunk per run of equal adjacent keys.
TEST(Wavefront, OrderIsTheStableSortOfTheKeys) {
    std::mt19937 g(7);
    for (int words : {1, 2, 6})
        for (SortMode mode : {SortMode::Full, SortMode::Csd})
            for (SortAlgorithm alg : {SortAlgorithm::Radix, SortAlgorithm::Bitonic}) {
                const size_t n = 3001;
                std::vector<uint32_t> keys(n * words);
                for (size_t i = 0; i < n; ++i)
                    for (int w = 0; w < words; ++w) // runs of equal keys, few distinct values
                        keys[i * words + w] = (i / 3 % 5 == 0) && i > 0 ? keys[(i - 1) * words + w]
                                                                        : uint32_t(g() % 97);
                auto key = [&](uint32_t i) {
                    return std::vector<uint32_t>(keys.rbegin() + (n - 1 - i) * words,
                                                 keys.rbegin() + (n - i) * words);
                };
                std::vector<uint32_t> expected(n);
                std::iota(expected.begin(), expected.end(), 0u);
                std::stable_sort(expected.begin(), expected.end(),
                                 [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
                size_t runs = 0;
                for (size_t i = 0; i < n; ++i)
                    runs += i == 0 || key(uint32_t(i)) != key(uint32_t(i - 1)) ? 1 : 0;
                wavefront::CpuExec ex;
                wavefront::DeviceBuffer<uint32_t, wavefront::CpuExec> dk(ex, keys.size());
                dk.upload(keys.data(), keys.size());
                wavefront::PhaseClock<wavefront::CpuExec> clock(ex);
                const auto dev = wavefront::order_rays(ex, dk.data(), words, n, mode, clock, alg);
                EXPECT_EQ(expected, dev.perm.download()) << words << " words";
                EXPECT_EQ(mode == SortMode::Csd ? runs : n, dev.chunks) << words << " words";
                Stats b;
                clock.add_to(b);
                for (const char* k :
                     {"time_ms.sorting", "time_ms.compression", "time_ms.decompression"})
                    EXPECT_EQ(mode == SortMode::Csd || std::string(k) == "time_ms.sorting",
                              b.has(k))
                        << k;
            }
}

TEST(Wavefront, AccumulationKeepsItemOrderPerSample) {
    wavefront::CpuExec ex;
    const size_t n = 5000, samples = 37;
    std::mt19937 g(3);
    std::vector<uint32_t> sample(n);
    std::vector<Vec3> value(n);
    for (size_t i = 0; i < n; ++i)
        sample[i] = g() % samples, value[i] = Vec3(float(g() % 1000) * 1e-3f + 1e-7f * float(i));
    std::vector<Vec3> expected(samples, Vec3(0.5f));
    for (size_t i = 0; i < n; ++i)
        if (i % 3) expected[sample[i]] += value[i];
    wavefront::DeviceBuffer<uint32_t, wavefront::CpuExec> ds(ex, n);
    wavefront::DeviceBuffer<Vec3, wavefront::CpuExec> dv(ex, n), dr(ex, samples);
    ds.upload(sample.data(), n), dv.upload(value.data(), n);
    wavefront::fill(ex, dr.data(), samples, Vec3(0.5f));
    const uint32_t* ps = ds.data();
    const Vec3* pv = dv.data();
    wavefront::accumulate_in_order(
        ex, n, dr.data(), [=](size_t i) { return ps[i]; },
        [=](size_t i, Vec3& v) {
            v = pv[i];
            return i % 3 != 0;
        });
    const std::vector<Vec3> got = dr.download();
    EXPECT_EQ(0, std::memcmp(got.data(), expected.data(), samples * sizeof(Vec3)));
}

// Image textures are sampled through OpenImageIO on the host: the device cannot take them
// (wavefront_unsupported says why), the CPU policy binds the scene, sampler included, and
// both tracers give the same frame of it.
TEST(Wavefront, ImageTexturesRenderOnTheCpuPolicyOnly) {
    Scene built = test::glass_mirror_scene();
    Pigment image;
    image.solid = false;
    image.pattern.kind = PatternKind::Image;
    image.pattern.image = 0;
    Texture file;
    file.path = "stripes.png"; // never opened: the sampler below stands in for OpenImageIO
    built.textures.push_back(file);
    built.pigments.push_back(image);
    for (Material& m : built.materials) m.pigment = 0;
    PreparedScene scene = prepare_scene(built);
    EXPECT_EQ(wavefront_unsupported(prepare_scene(test::glass_mirror_scene())), "");
    struct Stripes : TextureSampler {
        Vec3 sample(uint32_t, float u, float v) const override {
            return Vec3(u, v, 0.5f) * (std::fmod(u * 8.0f, 1.0f) < 0.5f ? 1.0f : 0.25f);
        }
    };
    scene.sampler = std::make_shared<Stripes>();
    EXPECT_NE(wavefront_unsupported(scene).find("image textures"), std::string::npos);
    const Frame textured = expect_identical(scene, "image textures", {});
    const Frame plain = render_frame_cpu(prepare_scene(test::glass_mirror_scene()),
                                         settings_for(scene, {}));
    EXPECT_NE(textured.rgba, plain.rgba) << "the texture shows";
}

} // namespace
} // namespace sheaf

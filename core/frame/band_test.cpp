// Bands (band.samples): the frame shaded a few pixel rows at a time gives the whole frame's
// picture, passes and statistics, on every kind of scene and both tracers, and holds less
// memory at once.
#include "core/frame/render_frame.h"

#include "core/raster/camera.h"
#include "core/scenes/builtin.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cstring>

namespace sheaf {
namespace {

using test::SettingList;

RenderSettings with_band(const PreparedScene& scene, SettingList kv, long long band, int w, int h) {
    kv.push_back({"band.samples", std::to_string(band)});
    return test::settings_for(scene, kv, w, h);
}

// One pixel row a band, a few rows, and the whole frame at once.
void expect_bands_agree(const PreparedScene& scene, const std::string& name, const SettingList& kv,
                        int w = 24, int h = 18) {
    const Frame whole = render_frame_cpu(scene, with_band(scene, kv, 1 << 30, w, h));
    EXPECT_EQ(whole.stats.get("memory.bands"), 1.0) << test::label(name, kv);
    const int aa = [&] {
        for (const auto& [k, v] : kv)
            if (k == "aa.samples") return std::stoi(v);
        return 1;
    }();
    for (long long band : {1LL, 3LL * w * aa * aa}) {
        const std::string what = test::label(name, kv) + " band.samples=" + std::to_string(band);
        const RenderSettings s = with_band(scene, kv, band, w, h);
        const Frame cut = render_frame_cpu(scene, s);
        test::expect_same_frame(whole, cut, what);
        const int rows = band == 1 ? 1 : 3;
        EXPECT_EQ(cut.stats.get("memory.bands"), double((s.region().height + rows - 1) / rows))
            << what;
        EXPECT_EQ(cut.stats.get("memory.band_samples"), double(rows * aa * s.region().width * aa))
            << what;
        // The wavefront tracer (the CUDA module's) cut the same way.
        test::expect_same_frame(cut, render_frame_wavefront_cpu(scene, s), what + " wavefront");
    }
}

TEST(Bands, BuiltinScenesAgreeWithTheWholeFrame) {
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        expect_bands_agree(scene, name, {});
        expect_bands_agree(scene, name, {{"accel", "strips"}, {"ao.samples", "2"}});
        expect_bands_agree(scene, name, {{"accel", "brute"}, {"aa.samples", "2"}});
    }
}

TEST(Bands, EveryStageAgreesWithTheWholeFrame) {
    const PreparedScene glass = prepare_scene(test::glass_mirror_scene());
    expect_bands_agree(glass, "glass", {{"ao.samples", "3"}, {"radiosity.samples", "4"}});
    expect_bands_agree(prepare_scene(test::scattering_scene()), "media", {});
    expect_bands_agree(prepare_scene(test::atmosphere_scene()), "atmosphere", {});
    expect_bands_agree(prepare_scene(test::photon_scene()), "photons", {});
    expect_bands_agree(prepare_scene(test::procedural_scene()), "procedural",
                       {{"output.passes", "combined,depth"}});
    Scene fisheye = test::csg_scene();
    fisheye.camera.projection = Projection::Fisheye;
    expect_bands_agree(prepare_scene(fisheye), "traced camera", {{"aa.samples", "2"}});
    // A region: the bands cut the region's rows, not the frame's.
    expect_bands_agree(glass, "region",
                       {{"region.x", "5"}, {"region.y", "7"}, {"region.height", "8"}});
}

// Under a ray hierarchy a band's rays make their own hierarchy, so the counts differ from the
// whole frame's, but the picture does not; band.samples = 0 keeps the whole frame there.
TEST(Bands, RayHierarchiesGiveTheSamePictureAndKeepTheFrameByDefault) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    for (const char* accel : {"crsh", "rah-bvh"}) {
        const Frame whole =
            render_frame_cpu(scene, with_band(scene, {{"accel", accel}}, 0, 32, 24));
        EXPECT_EQ(whole.stats.get("memory.bands"), 1.0) << accel;
        const Frame cut = render_frame_cpu(scene, with_band(scene, {{"accel", accel}}, 32, 32, 24));
        EXPECT_EQ(cut.stats.get("memory.bands"), 24.0) << accel;
        ASSERT_EQ(whole.rgba.size(), cut.rgba.size());
        EXPECT_EQ(std::memcmp(whole.rgba.data(), cut.rgba.data(), whole.rgba.size() * 4), 0)
            << accel;
        EXPECT_EQ(whole.stats.get("rays.shadow"), cut.stats.get("rays.shadow")) << accel;
    }
}

TEST(Bands, ThePerRayDefaultCutsLargeFramesAndHoldsLessMemory) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    const RenderSettings s = with_band(scene, {}, 0, 256, 192);
    const size_t rays = 2 + scene.lights.size(); // a sample's rays, about
    const size_t band = kCpuBandRays / rays;
    EXPECT_EQ(s.band_or(true, 256 * 192, rays), band);
    EXPECT_EQ(s.band_or(false, 256 * 192, rays), size_t(256 * 192)); // a device: whole frame
    // Many rays a sample: a small band, at least one pixel row.
    EXPECT_EQ(s.band_or(true, 256 * 192, 400), kCpuBandRays / 400);
    EXPECT_EQ(s.band_or(true, 256 * 192, size_t(1) << 20), 1u);
    const Frame cut = render_frame_cpu(scene, s);
    EXPECT_EQ(cut.stats.get("memory.band_samples"), double(band / 256 * 256));
    EXPECT_EQ(cut.stats.get("memory.bands"), double((192 + band / 256 - 1) / (band / 256)));
    EXPECT_GT(cut.stats.get("memory.bands"), 1.0);
    // Radiosity's 400 gathers a sample: a band of one row (163 samples, a row of 256).
    const Frame gathers =
        render_frame_cpu(scene, with_band(scene, {{"radiosity.samples", "400"}}, 0, 256, 3));
    EXPECT_EQ(gathers.stats.get("memory.band_samples"), 256.0);
    const Frame whole = render_frame_cpu(scene, with_band(scene, {}, 1 << 30, 256, 192));
    test::expect_same_frame(whole, cut, "cornell 256x192");
    // The frame's buffers at their peak (counted bytes, not time): a third of the frame's
    // samples at once holds well under the whole frame's.
    EXPECT_LT(cut.stats.get("memory.peak_bytes"), 0.6 * whole.stats.get("memory.peak_bytes"));
}

} // namespace
} // namespace sheaf

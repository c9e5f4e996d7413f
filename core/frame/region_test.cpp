// Regions (region.*): a frame rendered in parts, the parts put together, equals the frame
// rendered whole, byte for byte, in every pass, under every accel, with anti-aliasing, on the
// CPU backend and on the wavefront pipeline (the CUDA module's code path).
#include "core/backend/backend.h"

#include "core/base/error.h"
#include "core/frame/assemble.h"
#include "core/frame/render_frame.h"
#include "core/scenes/builtin.h"
#include "tests/support/same_image.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace sheaf {
namespace {

using KeyValues = std::vector<std::pair<std::string, std::string>>;
using Renderer = std::function<Frame(const PreparedScene&, const RenderSettings&)>;

RenderSettings settings(const PreparedScene& scene, const KeyValues& kv) {
    Settings s;
    for (auto& [k, v] : kv) s.set(k, v);
    return RenderSettings::resolve(s, scene.settings);
}

// Renders `scene` whole and in cols x rows uneven parts, and compares.
void expect_parts_equal_whole(const PreparedScene& scene, const KeyValues& kv, int cols, int rows,
                              const Renderer& render, const std::string& what) {
    const RenderSettings whole_settings = settings(scene, kv);
    const Frame whole = render(scene, whole_settings);
    ASSERT_EQ(whole.x, 0);
    ASSERT_EQ(whole.full_width, whole.width);
    std::vector<Frame> parts;
    const int W = whole.width, H = whole.height;
    // Uneven cuts: the first part one pixel narrower than the rest.
    auto cut = [](int n, int parts, int k) { return k == 0 ? 0 : (n * k) / parts + 1; };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int x0 = cut(W, cols, c), x1 = c + 1 == cols ? W : cut(W, cols, c + 1);
            const int y0 = cut(H, rows, r), y1 = r + 1 == rows ? H : cut(H, rows, r + 1);
            KeyValues part = kv;
            part.insert(part.end(), {{"region.x", std::to_string(x0)},
                                     {"region.y", std::to_string(y0)},
                                     {"region.width", std::to_string(x1 - x0)},
                                     {"region.height", std::to_string(y1 - y0)}});
            const Frame f = render(scene, settings(scene, part));
            ASSERT_EQ(f.width, x1 - x0) << what;
            ASSERT_EQ(f.height, y1 - y0) << what;
            EXPECT_EQ(f.x, x0);
            EXPECT_EQ(f.y, y0);
            parts.push_back(f);
        }
    // In another order than rendered: the parts say where they go.
    std::vector<const Frame*> order;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) order.push_back(&*it);
    const Frame merged = assemble_frame(order);
    EXPECT_EQ(merged.settings, whole.settings) << what;
    EXPECT_EQ(merged.stats.get("frame.parts"), double(parts.size()));
    if (whole_settings.accel == Accel::Brute || whole_settings.accel == Accel::Bvh ||
        whole_settings.accel == Accel::Strips)
        for (const char* k : {"rays.primary", "rays.shadow", "rays.ao", "rays.reflection"})
            EXPECT_EQ(merged.stats.get(k), whole.stats.get(k)) << what << ": " << k;
    test::expect_same_image(whole, merged, what);
    EXPECT_TRUE(merged.depth == whole.depth || std::equal(merged.depth.begin(), merged.depth.end(),
                                                          whole.depth.begin(), [](float a, float b) {
                                                              return std::memcmp(&a, &b, 4) == 0;
                                                          }))
        << what << ": depth";
    EXPECT_EQ(merged.object_id, whole.object_id) << what;
    // The tests pass counts the exact tests a ray's traversal left, which under a ray
    // hierarchy (rah, crsh and their BVH forms) depends on the rays grouped with it: the same only
    // per ray.
    if (!uses_ray_hierarchy(whole_settings.accel)) EXPECT_EQ(merged.tests, whole.tests) << what;
    EXPECT_EQ(0, std::memcmp(merged.normal.data(), whole.normal.data(),
                             whole.normal.size() * sizeof(Vec3)))
        << what << ": normal";
    EXPECT_EQ(0, std::memcmp(merged.albedo.data(), whole.albedo.data(),
                             whole.albedo.size() * sizeof(Vec3)))
        << what << ": albedo";
}

const Renderer kCpu = [](const PreparedScene& s, const RenderSettings& r) {
    return render_frame_cpu(s, r);
};
const Renderer kWavefront = [](const PreparedScene& s, const RenderSettings& r) {
    return render_frame_wavefront_cpu(s, r);
};

TEST(Region, PartsOfAFrameEqualTheWholeUnderEveryAccel) {
    const PreparedScene scene = prepare_scene(test::glass_mirror_scene());
    for (const char* accel : {"brute", "rah", "crsh", "bvh", "crsh-bvh", "rah-bvh", "strips"})
        expect_parts_equal_whole(scene,
                                 {{"width", "37"},
                                  {"height", "29"},
                                  {"aa.samples", "2"},
                                  {"ao.samples", "2"},
                                  {"accel", accel}},
                                 3, 2, kCpu, std::string("glass, accel=") + accel);
}

TEST(Region, PartsEqualTheWholeOnEveryBuiltinSceneAndOnTheWavefrontPipeline) {
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        const KeyValues kv = {{"width", "40"}, {"height", "30"}, {"aa.samples", "3"}};
        expect_parts_equal_whole(scene, kv, 4, 4, kCpu, name + ", cpu");
        expect_parts_equal_whole(scene, kv, 2, 3, kWavefront, name + ", wavefront");
    }
}

TEST(Region, RadiosityMediaAndPhotonsSplitExactly) {
    expect_parts_equal_whole(prepare_scene(test::media_scene()),
                             {{"width", "32"}, {"height", "24"}, {"aa.samples", "2"}}, 2, 2, kCpu,
                             "media");
    expect_parts_equal_whole(prepare_scene(test::photon_scene()),
                             {{"width", "32"}, {"height", "24"}}, 3, 1, kCpu, "photons");
    expect_parts_equal_whole(prepare_scene(make_builtin_scene("cornell")),
                             {{"width", "24"}, {"height", "24"}, {"radiosity.samples", "4"}}, 2, 2,
                             kCpu, "radiosity");
}

TEST(Region, AssemblingRefusesPartsThatDoNotMakeTheFrame) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    const KeyValues base = {{"width", "16"}, {"height", "12"}};
    auto part = [&](int x, int y, int w, int h, KeyValues extra = {}) {
        KeyValues kv = base;
        kv.insert(kv.end(), extra.begin(), extra.end());
        kv.insert(kv.end(), {{"region.x", std::to_string(x)}, {"region.y", std::to_string(y)},
                             {"region.width", std::to_string(w)},
                             {"region.height", std::to_string(h)}});
        Settings explicit_settings;
        for (auto& [k, v] : kv) explicit_settings.set(k, v);
        Frame f = render_frame_cpu(scene, settings(scene, kv));
        f.settings = RenderSettings::effective(explicit_settings, scene.settings);
        return f;
    };
    const Frame left = part(0, 0, 8, 12), right = part(8, 0, 8, 12), wide = part(6, 0, 10, 12);
    const Frame other = part(8, 0, 8, 12, {{"trace.depth", "3"}});
    const Frame bigger = render_frame_cpu(
        scene, settings(scene, {{"width", "20"}, {"height", "12"}, {"region.x", "8"}}));
    auto refused = [&](std::vector<const Frame*> parts, const std::string& says) {
        try {
            assemble_frame(parts);
            ADD_FAILURE() << "accepted; expected: " << says;
        } catch (const RenderError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
    refused({&left}, "the parts leave pixel (8, 0) of the 16x12 frame uncovered");
    refused({&left, &wide}, "part 2 (10x12 at (6, 0)) overlaps part 1 at pixel (6, 0)");
    refused({&left, &other}, "other settings than part 1 (trace.depth=3)");
    refused({&left, &bigger}, "is of a 20x12 frame, part 1 of a 16x12 one");
    refused({}, "no parts");
    EXPECT_EQ(assemble_frame({&right, &left}).width, 16);
}

TEST(Region, ARegionOutsideTheFrameIsAnErrorNamingTheKeys) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    for (const KeyValues& bad : std::vector<KeyValues>{
             {{"width", "32"}, {"region.x", "32"}},
             {{"width", "32"}, {"region.x", "16"}, {"region.width", "17"}},
             {{"height", "20"}, {"region.y", "10"}, {"region.height", "11"}},
         }) {
        try {
            settings(scene, bad);
            FAIL() << bad[1].first << "=" << bad[1].second << " was accepted";
        } catch (const SettingsError& e) {
            EXPECT_NE(std::string(e.what()).find("region."), std::string::npos) << e.what();
        }
    }
    // A size of 0 reaches the edge.
    const RenderSettings r =
        settings(scene, {{"width", "32"}, {"height", "20"}, {"region.x", "30"}, {"region.y", "5"}});
    EXPECT_EQ(r.region().width, 2);
    EXPECT_EQ(r.region().height, 15);
}

} // namespace
} // namespace sheaf

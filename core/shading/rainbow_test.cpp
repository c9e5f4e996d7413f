// Rainbows: what one does to a ray's colour against POV-Ray's formula (in the band, outside
// it, beyond the arc, in the fading part, filter and transmit), several averaging, and frames
// alike on every accel and the wavefront.
#include "core/shading/rainbow.h"

#include "core/backend/backend.h"
#include "core/frame/render_frame.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

// A rainbow around -z, up +y, its band 0.2..0.4 rad off -z, of one colour.
Scene one_bow(Vec3 color, float filter, float transmit) {
    Scene s;
    Rainbow r;
    r.antisolar = Vec3(0, 0, -1), r.up = Vec3(0, 1, 0), r.right = Vec3(-1, 0, 0);
    r.start = 0.2f, r.width = 0.2f, r.distance = 10.0f;
    r.arc = 1.0f, r.falloff = 0.5f;
    r.colors = uint32_t(test::add_pigment(s, PatternKind::Gradient,
                                          {test::pigment_entry(0, color, filter, transmit),
                                           test::pigment_entry(1, color, filter, transmit)}));
    s.rainbows.push_back(r);
    return s;
}

// The unit direction a rad off -z, turned b rad from up around it.
Vec3 toward(float a, float b) {
    return Vec3(-std::sin(a) * std::sin(b), std::sin(a) * std::cos(b), -std::cos(a));
}

TEST(Rainbow, ItIsPovRaysFogOfTheBandsColour) {
    const Vec3 c(0.9f, 0.5f, 0.1f);
    const PreparedScene scene = prepare_scene(one_bow(c, 0.4f, 0.1f));
    const SceneView view(scene);
    Vec3 mul, add;
    // In the band, straight up: k = max(exp(-d / distance), transmit); C keeps k of itself,
    // filtered by the colour as far as filter (1 - k) says, and takes (1 - k) of the colour.
    for (float d : {1.0f, 5.0f, 40.0f}) {
        rainbow_over(view, toward(0.3f, 0.0f), d, 0, mul, add);
        const float k = std::max(std::exp(-d / 10.0f), 0.1f), f = 0.4f * (1 - k);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(mul[i], k * ((1 - f) + f * c[i]), 1e-5f) << d << " " << i;
            EXPECT_NEAR(add[i], (1 - k) * c[i], 1e-5f) << d << " " << i;
        }
    }
    // Outside the band, behind the viewer, and beyond the arc: nothing.
    for (Vec3 dir : {toward(0.1f, 0.0f), toward(0.5f, 0.0f), Vec3(0, 0, 1), toward(0.3f, 1.1f)}) {
        rainbow_over(view, dir, 40.0f, 0, mul, add);
        EXPECT_EQ(mul.x, 1.0f);
        EXPECT_EQ(add.x, 0.0f);
    }
    // Past the falloff the band fades: k rises towards 1 at the arc, smoothly.
    rainbow_over(view, toward(0.3f, 0.75f), 40.0f, 0, mul, add);
    const float t = 0.5f, fade = (3 - 2 * t) * t * t, k = fade * 0.9f + 0.1f;
    EXPECT_NEAR(add.x, (1 - k) * c.x, 1e-4f);
}

TEST(Rainbow, SeveralRainbowsAverage) {
    Scene s = one_bow(Vec3(1, 0, 0), 0, 0);
    Scene other = one_bow(Vec3(0, 0, 1), 0, 0);
    Rainbow r = other.rainbows[0];
    r.colors = uint32_t(test::add_pigment(
        s, PatternKind::Gradient,
        {test::pigment_entry(0, Vec3(0, 0, 1)), test::pigment_entry(1, Vec3(0, 0, 1))}));
    s.rainbows.push_back(r);
    const PreparedScene scene = prepare_scene(s);
    Vec3 mul, add;
    rainbow_over(SceneView(scene), toward(0.3f, 0.0f), kAtmosphereFar, 0, mul, add);
    EXPECT_NEAR(add.x, 0.5f, 1e-5f);
    EXPECT_NEAR(add.z, 0.5f, 1e-5f);
    EXPECT_NEAR(mul.y, 0.0f, 1e-5f);
}

TEST(Rainbow, FramesAgreeOnEveryAccelAndTheWavefront) {
    const PreparedScene scene = prepare_scene(test::rainbow_scene());
    const RenderSettings rs = test::settings_for(scene, {}, 64, 48);
    const Frame crsh = render_frame(scene, rs);
    const PreparedScene plain = prepare_scene([] {
        Scene s = test::rainbow_scene();
        s.rainbows.clear();
        return s;
    }());
    const Frame without = render_frame(plain, rs);
    double changed = 0;
    for (size_t i = 0; i < crsh.rgba.size(); ++i)
        changed += std::fabs(crsh.rgba[i] - without.rgba[i]);
    EXPECT_GT(changed, 20.0); // the bands show
    for (const test::SettingList& kv :
         {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}}}) {
        const Frame other = render_frame(scene, test::settings_for(scene, kv, 64, 48));
        EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
            << kv[0].second;
    }
    test::expect_same_frame(render_frame_cpu(scene, rs), render_frame_wavefront_cpu(scene, rs),
                            "rainbow");
}

} // namespace
} // namespace sheaf

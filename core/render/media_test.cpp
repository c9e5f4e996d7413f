// Interior media: the integral along a ray against its closed forms (emission alone, absorption
// alone, both), what a rendered container gives through its middle, a union whose members
// carry media of their own, solid objects left out, the camera inside, and every accel alike.
#include "core/render/media.h"

#include "core/render/renderer.h"
#include "core/scenes/shapes.h"
#include "core/scenes/test_scenes.h"
#include "core/wavefront/wavefront.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

Frame render(const PreparedScene& scene, const test::SettingList& kv, int w, int h) {
    return render_frame(scene, test::settings_for(scene, kv, w, h));
}

const float* pixel(const Frame& f, int x, int y) {
    return &f.rgba[4 * (size_t(y) * f.width + x)];
}

// One unit sphere at the origin holding `media`, the camera on +z looking at it, black behind.
Scene sphere_of(std::vector<Medium> media) {
    Scene s;
    s.add_shape("container", Shape{ShapeKind::Sphere}, test::add_media_material(s, media));
    s.camera.position = Vec3(0, 0, 5);
    s.camera.look_at = Vec3(0, 0, 0);
    s.camera.fov_y_degrees = 30;
    return s;
}

TEST(Media, TheIntegralMatchesItsClosedForms) {
    Medium glow;
    glow.emission = Vec3(0.3f, 0.2f, 0.1f);
    Medium dark;
    dark.absorption = Vec3(0.5f, 1.0f, 2.0f);
    Medium both = glow;
    both.absorption = dark.absorption;
    both.samples = 64;
    const PreparedScene scene = prepare_scene(sphere_of({glow, dark, both}));
    const SceneView view(scene);
    Material m;
    m.media_count = 1;
    Vec3 keep, add;
    const float d = 1.7f;
    m.media_first = 0; // emission alone: e d, all of the far light
    through_media(view, m, Vec3(0, 0, 1), Vec3(0, 0, -1), d, keep, add);
    EXPECT_NEAR(add.x, 0.3f * d, 1e-5f);
    EXPECT_FLOAT_EQ(keep.y, 1.0f);
    m.media_first = 1; // absorption alone: exp(-a d) of it, nothing added
    through_media(view, m, Vec3(0, 0, 1), Vec3(0, 0, -1), d, keep, add);
    EXPECT_NEAR(keep.z, std::exp(-2.0f * d), 1e-5f);
    EXPECT_EQ(add.x, 0.0f);
    m.media_first = 2; // both: e / a (1 - exp(-a d)), to the midpoint rule's accuracy
    through_media(view, m, Vec3(0, 0, 1), Vec3(0, 0, -1), d, keep, add);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(add[c],
                    both.emission[c] / both.absorption[c] * (1 - std::exp(-both.absorption[c] * d)),
                    2e-4f)
            << c;
    m.media_count = 0; // no media: nothing changes
    through_media(view, m, Vec3(0, 0, 1), Vec3(0, 0, -1), d, keep, add);
    EXPECT_EQ(keep.x, 1.0f);
    EXPECT_EQ(add.x, 0.0f);
}

TEST(Media, AContainerGivesOffItsEmissionTimesTheChord) {
    Medium glow;
    glow.emission = Vec3(0.2f, 0.1f, 0.05f);
    const Frame f = render(prepare_scene(sphere_of({glow})), {}, 33, 33);
    // Through the middle the ray crosses 2 units of the medium.
    EXPECT_NEAR(pixel(f, 16, 16)[0], 0.4f, 1e-4f);
    EXPECT_NEAR(pixel(f, 16, 16)[2], 0.1f, 1e-4f);
    EXPECT_EQ(pixel(f, 0, 0)[0], 0.0f); // beside the sphere nothing glows
    // Seen from inside, the ray crosses 1 unit (the camera at the centre).
    Scene in = sphere_of({glow});
    in.camera.position = Vec3(0, 0, 0), in.camera.look_at = Vec3(0, 0, -1);
    EXPECT_NEAR(pixel(render(prepare_scene(in), {}, 33, 33), 16, 16)[0], 0.2f, 1e-4f);
}

TEST(Media, SolidObjectsInsideAreLeftOut) {
    Medium glow;
    glow.emission = Vec3(0.2f);
    Scene s = sphere_of({glow});
    Material black;
    black.color = Vec3(1.0f);
    black.ambient = black.diffuse = 0, black.transmission = 1, black.ior = 1;
    black.fresnel_split = false;
    const uint32_t core_id = s.add_shape("core", Shape{ShapeKind::Sphere}, s.add_material(black),
                                         Affine::scale(Vec3(0.5f)));
    // A hollow core is filled: the whole 2-unit chord glows.
    EXPECT_NEAR(pixel(render(prepare_scene(s), {}, 33, 33), 16, 16)[0], 0.4f, 1e-4f);
    // A solid one is not: 1 unit of the chord is left.
    s.shape_objects[core_id].flags = kSolid;
    EXPECT_NEAR(pixel(render(prepare_scene(s), {}, 33, 33), 16, 16)[0], 0.2f, 1e-4f);
}

TEST(Media, EveryAccelAndTheWavefrontAgree) {
    for (bool inside : {false, true}) {
        const PreparedScene scene = prepare_scene(test::media_scene(inside));
        const Frame crsh = render(scene, {}, 40, 30);
        double sum = 0;
        for (float v : crsh.rgba) sum += v;
        EXPECT_GT(sum, 40 * 30 * 0.2) << inside;
        for (const test::SettingList& kv :
             {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}}}) {
            const Frame other = render(scene, kv, 40, 30);
            EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
                << kv[0].second << " inside " << inside;
        }
        const RenderSettings rs = test::settings_for(scene, {}, 40, 30);
        test::expect_same_frame(render_frame_cpu(scene, rs), render_frame_wavefront_cpu(scene, rs),
                                inside ? "media inside" : "media");
    }
}

} // namespace
} // namespace sheaf

// Primary visibility traced through the ray hierarchy for the projections no plane holds
// (fisheye, panoramic, cylinder ...): the same surfaces as the rasteriser along the same ray,
// the same picture under every accel, black where the projection has no ray, objects without
// an image left out, the camera rays counted as a ray type of their own; a camera normal
// tilts the primary rays.
#include "core/backend/backend.h"

#include "core/shading/frame_kernels.h"

#include "core/scenes/shapes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cstring>

namespace sheaf {
namespace {

Frame render(const PreparedScene& scene, const test::SettingList& kv, int w, int h) {
    return render_frame(scene, test::settings_for(scene, kv, w, h));
}

Scene with_projection(Scene s, Projection p, float angle) {
    s.camera.projection = p;
    s.camera.angle_degrees = angle;
    return s;
}

const float* pixel(const Frame& f, int x, int y) {
    return &f.rgba[4 * (size_t(y) * f.width + x)];
}

TEST(TracedCamera, TheCentrePixelMatchesTheRasterisedOne) {
    // Every traced projection looks straight ahead at the centre of an odd-sized image, as the
    // perspective camera does: the same surface, shadows, reflections and refraction.
    const Scene base = test::glass_mirror_scene();
    const Frame raster = render(prepare_scene(base), {}, 33, 33);
    for (int p = 2; p < kProjectionCount; ++p) {
        const Frame traced =
            render(prepare_scene(with_projection(base, Projection(p), 120)), {}, 33, 33);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(pixel(traced, 16, 16)[c], pixel(raster, 16, 16)[c], 1e-5f)
                << "projection " << p << " channel " << c;
        EXPECT_GT(traced.stats.get("rays.camera"), 0) << p;
        EXPECT_GT(traced.stats.get("tests.camera.total"), 0) << p;
    }
    EXPECT_EQ(raster.stats.get("rays.camera"), 0);
}

TEST(TracedCamera, ACameraNormalTiltsThePrimaryRays) {
    Scene s = test::glass_mirror_scene();
    s.camera.position = Vec3(0, 0, 5), s.camera.look_at = Vec3(0, 0, 0);
    NormalPattern tilt; // slope 1 along screen x, evaluated at (u, v, 0)
    tilt.pattern.kind = PatternKind::Gradient;
    tilt.pattern.vector = Vec3(1, 0, 0);
    tilt.pattern.to_pattern = Affine::translate(Vec3(0.5f, 0, 0)); // u + 1/2 stays in 0..1
    tilt.amount = 3.75f; // POV-Ray's slope normal: 2/15 of it, half the slope
    s.normal_patterns.push_back(tilt);
    s.camera.normal = int32_t(s.normal_patterns.size() - 1);
    const PreparedScene p = prepare_scene(s);
    const SceneView view(p);
    const CameraFrame cam = make_camera_frame(p.camera, 33, 33);
    EXPECT_TRUE(cam.traced);
    Ray r;
    ASSERT_TRUE(primary_ray(view, cam, 16, 16, r));
    // The centre ray (0, 0, -1) tilts against the slope as a surface normal does.
    const Vec3 want = normalize(Vec3(-0.5f, 0, -1));
    EXPECT_NEAR(r.dir.x, want.x, 1e-4f);
    EXPECT_NEAR(r.dir.y, want.y, 1e-4f);
    EXPECT_NEAR(r.dir.z, want.z, 1e-4f);
    // Without a bump the traced picture is the rasterised one.
    s.normal_patterns.back().amount = 0;
    const Frame flat = render(prepare_scene(s), {}, 33, 33);
    s.camera.normal = -1;
    const Frame raster = render(prepare_scene(s), {}, 33, 33);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pixel(flat, 16, 16)[c], pixel(raster, 16, 16)[c], 1e-5f);
    EXPECT_GT(flat.stats.get("rays.camera"), 0);
    EXPECT_EQ(raster.stats.get("rays.camera"), 0);
}

TEST(TracedCamera, EveryAccelGivesTheSamePicture) {
    const PreparedScene scene =
        prepare_scene(with_projection(test::csg_scene(), Projection::Fisheye, 200));
    const Frame crsh = render(scene, {}, 40, 32);
    for (const test::SettingList& kv :
         {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}},
          test::SettingList{{"hash.mode", "hash192"}, {"hierarchy.depth", "2"}}}) {
        const Frame other = render(scene, kv, 40, 32);
        EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
            << kv[0].first;
    }
}

// Depth of field: the lens camera traces its primary rays; every accel gives the same picture;
// a ball on the sharp plane keeps its outline while one nearer the eye blurs (its edge pixels
// mix with the background).
TEST(TracedCamera, ALensKeepsTheSharpPlaneAndBlursTheRest) {
    Scene s = test::csg_scene();
    const Frame pinhole = render(prepare_scene(s), {{"aa.samples", "3"}}, 40, 32);
    s.camera.lens_radius = 0.4f;
    s.camera.focal_distance = length(s.camera.look_at - s.camera.position);
    const PreparedScene lens = prepare_scene(s);
    const Frame crsh = render(lens, {{"aa.samples", "3"}}, 40, 32);
    EXPECT_GT(crsh.stats.get("rays.camera"), 0);
    EXPECT_EQ(crsh.stats.get("frame.samples_per_pixel"), 9);
    const Frame brute = render(lens, {{"accel", "brute"}, {"aa.samples", "3"}}, 40, 32);
    EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), brute.rgba.data(), crsh.rgba.size() * 4));
    double differ = 0;
    for (size_t i = 0; i < crsh.rgba.size(); ++i)
        differ += std::fabs(crsh.rgba[i] - pinhole.rgba[i]);
    EXPECT_GT(differ / double(crsh.rgba.size()), 1e-3); // the picture blurs somewhere
}

TEST(TracedCamera, PixelsWithoutARayAreBlack) {
    Scene s = with_projection(test::glass_mirror_scene(), Projection::Fisheye, 180);
    s.background = Vec3(0.2f, 0.4f, 0.6f);
    const Frame f = render(prepare_scene(s), {}, 40, 40);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pixel(f, 0, 0)[c], 0.0f); // outside the circle
    double inside = 0;
    for (int c = 0; c < 3; ++c) inside += pixel(f, 20, 20)[c];
    EXPECT_GT(inside, 0.0);
    // Rays only for the samples inside the circle: about pi / 4 of them.
    const double share = f.stats.get("rays.camera") / f.stats.get("rays.primary");
    EXPECT_NEAR(share, kPi / 4, 0.03);
}

TEST(TracedCamera, ObjectsWithoutAnImageAreNotSeen) {
    // A sphere in front of the camera that casts no shadow and shows in no reflection: with
    // no_image the picture is the one without it, without the flag it is seen.
    Scene base;
    Material grey;
    grey.color = Vec3(0.7f);
    const uint32_t m = base.add_material(grey);
    base.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), m);
    base.add_shape("ball", Shape{ShapeKind::Sphere}, m, Affine::translate(Vec3(0, 0, -1)));
    base.add_light(Light{Vec3(2, 5, 4), Vec3(1.0f)});
    base.camera.position = Vec3(0, 1, 5);
    base.camera.look_at = Vec3(0, 0, 0);
    base = with_projection(base, Projection::Panoramic, 90);
    Scene ghost = base;
    const uint32_t g =
        ghost.add_shape("ghost", Shape{ShapeKind::Sphere}, m,
                        Affine::translate(Vec3(0, 0.8f, 3)) * Affine::scale(Vec3(0.5f)));
    ghost.shape_objects[g].flags = kNoImage | kNoShadow | kNoReflection;
    const Frame without = render(prepare_scene(base), {}, 48, 24);
    const Frame hidden = render(prepare_scene(ghost), {}, 48, 24);
    EXPECT_EQ(0, std::memcmp(without.rgba.data(), hidden.rgba.data(), without.rgba.size() * 4));
    ghost.shape_objects[g].flags = kNoShadow | kNoReflection;
    const Frame seen = render(prepare_scene(ghost), {}, 48, 24);
    EXPECT_NE(0, std::memcmp(without.rgba.data(), seen.rgba.data(), without.rgba.size() * 4));
}

} // namespace
} // namespace sheaf

// The traced projections' pixel-to-ray mapping (POV-Ray's camera types): the directions at
// known pixels, the pixels that have no ray, and the eye that moves along a cylinder.
#include "core/raster/camera.h"

#include <gtest/gtest.h>

#include <vector>

namespace sheaf {
namespace {

// A camera at the origin looking down -z with up +y (right is +x), images of odd size so that
// a middle row and column exist.
CameraFrame frame(Projection p, float angle = 90, int w = 101, int h = 101) {
    Camera c;
    c.position = Vec3(0, 0, 0);
    c.look_at = Vec3(0, 0, -1);
    c.projection = p;
    c.angle_degrees = angle;
    return make_camera_frame(c, w, h);
}

// Edge pixels' centres lie half a pixel inside the edge: at most 1% of the angle short of it
// (3.6 degrees of a 360-degree view, 0.032 in a unit vector's components).
void expect_dir(const CameraFrame& f, int x, int y, Vec3 want, const char* what) {
    Ray r;
    ASSERT_TRUE(f.camera_ray(x, y, r)) << what;
    EXPECT_NEAR(r.dir.x, want.x, 0.035f) << what;
    EXPECT_NEAR(r.dir.y, want.y, 0.035f) << what;
    EXPECT_NEAR(r.dir.z, want.z, 0.035f) << what;
    EXPECT_NEAR(length(r.dir), 1.0f, 1e-5f) << what;
}

TEST(CameraProjections, EveryTracedProjectionLooksAheadAtTheImageCentre) {
    for (int p = 2; p < kProjectionCount; ++p) {
        const CameraFrame f = frame(Projection(p));
        EXPECT_TRUE(f.traced);
        Ray r;
        ASSERT_TRUE(f.camera_ray(50, 50, r)) << p;
        EXPECT_NEAR(r.dir.z, -1.0f, 1e-5f) << p;
        EXPECT_NEAR(length(r.origin), 0.0f, 1e-6f) << p;
    }
    EXPECT_FALSE(frame(Projection::Perspective).traced);
    EXPECT_FALSE(frame(Projection::Orthographic).traced);
}

TEST(CameraProjections, FisheyeMapsTheRadiusToTheAngleAndHasNoRayOutsideItsCircle) {
    const CameraFrame f = frame(Projection::Fisheye, 180);
    // The middle of the right edge is 90 degrees off the axis, toward +x; the top, toward +y.
    expect_dir(f, 100, 50, Vec3(1, 0, 0), "right edge");
    expect_dir(f, 50, 0, Vec3(0, 1, 0), "top edge");
    expect_dir(f, 75, 50, Vec3(0.7071f, 0, -0.7071f), "half way");
    Ray r;
    EXPECT_FALSE(f.camera_ray(0, 0, r)); // a corner lies outside the circle
    // 360 degrees: the circle's edge looks backwards.
    expect_dir(frame(Projection::Fisheye, 360), 100, 50, Vec3(0, 0, 1), "360 edge");
}

TEST(CameraProjections, CylindersTurnAcrossTheirAxisAndMoveOrStretchAlongIt) {
    // cylinder 1: angle across, the height as a plane; cylinder 3: the eye moves up instead.
    expect_dir(frame(Projection::Cylinder1, 180), 100, 50, Vec3(1, 0, 0), "cylinder 1 edge");
    Ray r;
    ASSERT_TRUE(frame(Projection::Cylinder3, 180).camera_ray(50, 0, r));
    EXPECT_NEAR(r.origin.y, 0.5f - 0.5f / 101, 1e-5f); // up's length 1, half an image up
    EXPECT_NEAR(r.dir.z, -1.0f, 1e-5f);
    // cylinder 2 and 4: the same about the horizontal axis.
    expect_dir(frame(Projection::Cylinder2, 180), 50, 0, Vec3(0, 1, 0), "cylinder 2 top");
    ASSERT_TRUE(frame(Projection::Cylinder4, 180).camera_ray(100, 50, r));
    EXPECT_NEAR(r.origin.x, 0.5f - 0.5f / 101, 1e-5f);
    EXPECT_NEAR(r.dir.z, -1.0f, 1e-5f);
}

TEST(CameraProjections, PanoramicAndSphericalSpanTheirAngles) {
    // Panoramic: 180 degrees across, from -x on the left to +x on the right.
    expect_dir(frame(Projection::Panoramic), 0, 50, Vec3(-1, 0, 0), "panoramic left");
    expect_dir(frame(Projection::Panoramic), 100, 50, Vec3(1, 0, 0), "panoramic right");
    // Spherical 360 x 180: the left and right edges look backwards, the top straight up.
    CameraFrame s = frame(Projection::Spherical, 360);
    s.v_angle = kPi;
    expect_dir(s, 0, 50, Vec3(0, 0, 1), "spherical left");
    expect_dir(s, 75, 50, Vec3(1, 0, 0), "spherical three quarters");
    expect_dir(s, 50, 0, Vec3(0, 1, 0), "spherical top");
    // Ultra wide angle 180: the right edge looks along +x.
    expect_dir(frame(Projection::UltraWideAngle, 180), 100, 50, Vec3(1, 0, 0), "uwa right");
}

TEST(CameraProjections, OmnimaxSeesNoLowerThanItsDomesEdge) {
    // A square view: the dome's circle fills the image, its axis at the centre. Straight down
    // from the centre the angle passes 45 degrees below the axis before the circle's edge.
    Camera c;
    c.position = Vec3(0, 0, 0), c.look_at = Vec3(0, 0, -1);
    c.projection = Projection::Omnimax;
    const CameraFrame f = make_camera_frame(c, 101, 101);
    Ray r;
    EXPECT_FALSE(f.camera_ray(50, 100, r)); // bottom middle: below the dome's edge
    EXPECT_FALSE(f.camera_ray(0, 0, r));    // a corner: outside the circle
    ASSERT_TRUE(f.camera_ray(50, 0, r));    // top middle: far up the dome, behind the axis
    EXPECT_GT(r.dir.y, 0.95f);
    ASSERT_TRUE(f.camera_ray(50, 70, r)); // a little below the axis
    EXPECT_LT(r.dir.y, 0.0f);
}

TEST(CameraProjections, MirroredCamerasRunTheOtherWay) {
    Camera c;
    c.position = Vec3(0, 0, 0), c.look_at = Vec3(0, 0, -1);
    c.projection = Projection::Cylinder1;
    c.angle_degrees = 180;
    c.mirror = true;
    expect_dir(make_camera_frame(c, 101, 101), 100, 50, Vec3(-1, 0, 0), "mirrored edge");
}

// Depth of field: a pixel's n x n samples leave from points spread over the lens (each within
// its radius, no two the same, centred on the eye on average) and all pass through the point
// the pixel's centre sees on the sharp plane; without a lens every sample leaves the eye.
TEST(CameraLens, APixelsSamplesCrossTheLensAndMeetOnTheSharpPlane) {
    for (const Projection p : {Projection::Perspective, Projection::Orthographic}) {
        Camera c;
        c.position = Vec3(1, 2, 3), c.look_at = Vec3(1, 2, -7);
        c.projection = p;
        c.lens_radius = 0.5f, c.focal_distance = 4;
        const int n = 4, w = 5, h = 3;
        const CameraFrame f = make_camera_frame(c, w * n, h * n, n);
        EXPECT_TRUE(f.traced);
        Camera still = c;
        still.lens_radius = 0;
        const CameraFrame pin = make_camera_frame(still, w * n, h * n, n);
        EXPECT_FALSE(pin.traced);
        for (int px = 0; px < w; ++px)
            for (int py = 0; py < h; ++py) {
                Vec3 mean(0.0f), sharp_want;
                std::vector<Vec3> origins;
                for (int sy = 0; sy < n; ++sy)
                    for (int sx = 0; sx < n; ++sx) {
                        const int x = px * n + sx, y = py * n + sy;
                        Ray lens, eye;
                        ASSERT_TRUE(f.camera_ray(x, y, lens));
                        ASSERT_TRUE(pin.camera_ray(x, y, eye));
                        // Where the pinhole ray meets the sharp plane (4 ahead of the eye).
                        const float along = dot(eye.dir, f.forward);
                        const Vec3 sharp = eye.origin + eye.dir * (4.0f / along);
                        const Vec3 off = lens.origin - eye.origin;
                        EXPECT_LE(length(off), 0.5f + 1e-5f);
                        EXPECT_NEAR(dot(off, f.forward), 0, 1e-5f); // across the view
                        // The lens ray reaches the same point of the sharp plane.
                        const float t =
                            dot(sharp - lens.origin, f.forward) / dot(lens.dir, f.forward);
                        const Vec3 hit = lens.origin + lens.dir * t;
                        EXPECT_NEAR(length(hit - sharp), 0, 2e-5f * length(sharp));
                        EXPECT_NEAR(length(lens.dir), 1, 1e-5f);
                        for (const Vec3& o : origins) EXPECT_GT(length(o - off), 1e-4f);
                        origins.push_back(off);
                        mean += off;
                    }
                EXPECT_LT(length(mean / float(n * n)), 0.2f);
            }
        // No lens: the pinhole camera's rays.
        Ray a;
        ASSERT_TRUE(pin.camera_ray(7, 4, a));
        if (p == Projection::Perspective) EXPECT_EQ(length(a.origin - c.position), 0);
    }
}

} // namespace
} // namespace sheaf

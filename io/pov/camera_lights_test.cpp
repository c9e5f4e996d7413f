// Tests of the camera (perspective and orthographic), the lights (point, spot, parallel,
// fading, shadowless, area lights as samples), background and global_settings.
#include "tests/support/pov_test_util.h"

#include "core/backend/backend.h"
#include "core/raster/camera.h"
#include "core/shading/frame_kernels.h"

#include <cmath>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

TEST(PovCamera, PerspectiveFromAngleAndLookAt) {
    const PovResult r = load_text("camera { location <0, 2, -5> look_at <0, 2, 0> angle 90 "
                                  "right x * 4/3 up y }");
    const Camera& c = r.scene.camera;
    EXPECT_EQ(c.projection, Projection::Perspective);
    // POV-Ray's -z (in front of the scene) is Sheaf's +z.
    EXPECT_FLOAT_EQ(c.position.z, 5);
    EXPECT_FLOAT_EQ(c.position.y, 2);
    EXPECT_LT(c.look_at.z, c.position.z);
    EXPECT_NEAR(c.up.y, 1, 1e-6);
    // Horizontal 90 degrees over a 4:3 frame: vertical 2 atan(0.75).
    EXPECT_NEAR(c.fov_y_degrees, 2 * std::atan(0.75) * 180 / M_PI, 1e-3);
}

TEST(PovCamera, RightHandedCamerasMirrorThePicture) {
    // right -x makes a right-handed camera; POV-Ray keeps that through look_at.
    EXPECT_FALSE(load_text("camera { location <0, 2, -5> look_at 0 }").scene.camera.mirror);
    EXPECT_TRUE(load_text("camera { location <0, 2, -5> right -x look_at 0 angle 40 }")
                    .scene.camera.mirror);
    EXPECT_TRUE(load_text("camera { location <0, 0, -5> right <-1, 0, 0> }").scene.camera.mirror);
    // An up along the default direction has no handedness, which POV-Ray takes as
    // right-handed (objects/fractal3.pov's camera: up and sky z, looking down y).
    EXPECT_TRUE(
        load_text("camera { location <0, 3, 0> up z sky z look_at 0 }").scene.camera.mirror);
    const PovResult r = load_text("camera { location <0, 2, -5> right -x up y look_at 0 }");
    EXPECT_NEAR(r.scene.camera.up.y, 0.93, 0.01); // up still points up
    // A mirrored camera draws x the other way: the same scene, the image flipped.
    const std::string scene = "light_source { <0, 5, -5> rgb 1 }\n"
                              "sphere { <-1, 0, 0>, 0.5 pigment { rgb <1, 0, 0> } }\n";
    const PreparedScene a =
        prepare_scene(load_text("camera { location <0, 0, -5> look_at 0 }\n" + scene).scene);
    const PreparedScene b = prepare_scene(
        load_text("camera { location <0, 0, -5> right -x * 4/3 look_at 0 }\n" + scene).scene);
    const CameraFrame fa = make_camera_frame(a.camera, 40, 30);
    const CameraFrame fb = make_camera_frame(b.camera, 40, 30);
    EXPECT_NEAR(dot(fa.right, fb.right), -1, 1e-5);
    EXPECT_NEAR(dot(fa.up, fb.up), 1, 1e-5);
}

TEST(PovCamera, DirectionWithoutAngleAndSky) {
    const PovResult r = load_text("camera { location 0 direction z * 2 up y right x sky y }");
    EXPECT_NEAR(r.scene.camera.fov_y_degrees, 2 * std::atan(0.25) * 180 / M_PI, 1e-3);
    EXPECT_NEAR(r.scene.camera.look_at.z, -2, 1e-5);
}

TEST(PovCamera, ShearedCameraIsALensShift) {
    // camera/shear.pov: look_at, then a shear that turns up vertical and leaves the direction
    // leaning up. POV-Ray casts direction + x right + y up: the pixel at the centre looks
    // along the leaning direction, the view's verticals stay vertical.
    const PovResult r =
        load_text("camera { location <0, 1, 25> right x * 4/3 angle 90 look_at <0, 10, 0> "
                  "matrix <1, 0, 0, 0, 1, -0.36, 0, 0, 1, 0, 0, 0> }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    const Camera& c = r.scene.camera;
    EXPECT_NEAR(c.shift_x, 0, 1e-5);
    EXPECT_GT(c.shift_y, 0.1); // the centre ray rises above the image plane's normal
    const CameraFrame f = make_camera_frame(c, 40, 30);
    EXPECT_NEAR(f.up.y, 1, 1e-5);      // up stays vertical
    EXPECT_NEAR(f.forward.y, 0, 1e-5); // the image plane is upright
    // The middle of the image: POV-Ray's direction <0, 9, -25> sheared to <0, 9, -28.24>
    // (z mirrored into Sheaf's world).
    const Vec3 mid = normalize(f.pixel_ray(19, 14).dir + f.pixel_ray(20, 15).dir);
    const Vec3 want = normalize(Vec3(0, 9, 28.24f));
    EXPECT_NEAR(dot(mid, want), 1, 1e-4);
    // Right and up that are not perpendicular cannot be drawn: a warning says so.
    const PovResult skew =
        load_text("camera { location <0, 0, -5> look_at 0 matrix <1, 0, 0, 0.5, 1, 0, "
                  "0, 0, 1, 0, 0, 0> }");
    ASSERT_EQ(skew.warnings.size(), 1u);
    EXPECT_NE(skew.warnings[0].find("right and up are not perpendicular"), std::string::npos);
}

// A camera on a face of a box looks into the box, as POV-Ray's does (it ignores hits nearer
// than 1e-4): interior/media/media1.pov's camera stands on its room's front wall.
TEST(PovCamera, ACameraOnAFaceLooksThroughIt) {
    const PovResult r = load_text("camera { location <10, 6, -20> look_at <0, 5, 0> }\n"
                                  "box { <-20, 0, -20>, <20, 20, 20> hollow }\n"
                                  "sphere { <0, 5, 0>, 1 }\n");
    const PreparedScene p = prepare_scene(r.scene);
    const SceneView view(p);
    const CameraFrame f = make_camera_frame(p.camera, 41, 31);
    const uint64_t key = cast_analytic_pixel(view, f, 20, 15, kEmptyPixel);
    ASSERT_NE(key, kEmptyPixel);
    EXPECT_EQ(uint32_t(key), view.tri_count + 1); // the sphere, not the wall at the eye
}

TEST(PovCamera, DefaultAndOrthographic) {
    EXPECT_NEAR(load_text("").scene.camera.fov_y_degrees, 2 * std::atan(0.5) * 180 / M_PI, 1e-3);
    const PovResult r = load_text("camera { orthographic location <0, 0, -10> look_at 0 "
                                  "up y * 6 right x * 8 translate x }");
    EXPECT_EQ(r.scene.camera.projection, Projection::Orthographic);
    EXPECT_FLOAT_EQ(r.scene.camera.ortho_height, 6);
    EXPECT_FLOAT_EQ(r.scene.camera.position.x, 1);
    EXPECT_FLOAT_EQ(r.scene.camera.position.z, 10);
    // Without up and right, POV-Ray shows the area a perspective camera would at the look_at
    // point's distance: up grows by that distance over the direction's length
    // (textures/pigments/transmitfx.pov).
    auto height = [](const std::string& items) {
        return load_text("camera { orthographic " + items + " }").scene.camera.ortho_height;
    };
    EXPECT_FLOAT_EQ(height("location 6 * y look_at 0"), 6);
    EXPECT_FLOAT_EQ(height("location 6 * y look_at 0 direction 2 * z"), 3);
    EXPECT_FLOAT_EQ(height("location <0, 0, -3>"), 4); // the default look_at, <0, 0, 1>
    EXPECT_FLOAT_EQ(height("location 6 * y look_at 0 up 2 * y"), 2); // up given: kept
    EXPECT_FLOAT_EQ(height("location 6 * y look_at 0 right 4 * x"), 1);
}

TEST(PovCamera, TheOtherCameraTypesAreTracedProjections) {
    const std::pair<const char*, Projection> kinds[] = {
        {"fisheye", Projection::Fisheye},      {"ultra_wide_angle", Projection::UltraWideAngle},
        {"omnimax", Projection::Omnimax},      {"panoramic", Projection::Panoramic},
        {"cylinder 1", Projection::Cylinder1}, {"cylinder 2", Projection::Cylinder2},
        {"cylinder 3", Projection::Cylinder3}, {"cylinder 4", Projection::Cylinder4},
        {"spherical", Projection::Spherical}};
    for (const auto& [kw, want] : kinds) {
        const PovResult r =
            load_text(std::string("camera { ") + kw + " location <0, 1, -5> look_at <0, 1, 0> }");
        EXPECT_EQ(r.scene.camera.projection, want) << kw;
        EXPECT_TRUE(r.warnings.empty()) << kw << ": " << r.warnings[0];
        // POV-Ray's defaults: angle 90 (spherical 360 by 180), right 1.33, up 1.
        EXPECT_FLOAT_EQ(r.scene.camera.angle_degrees, want == Projection::Spherical ? 360 : 90);
        EXPECT_NEAR(r.scene.camera.right_length, 1.33f, 1e-5f) << kw;
        EXPECT_NEAR(r.scene.camera.up_length, 1.0f, 1e-5f) << kw;
    }
    // The angle is the projection's own: the direction keeps its length.
    const Camera c = load_text("camera { fisheye angle 270 right x up y direction 2 * z "
                               "location 0 look_at z }")
                         .scene.camera;
    EXPECT_FLOAT_EQ(c.angle_degrees, 270);
    EXPECT_NEAR(c.direction_length, 2.0f, 1e-5f);
    EXPECT_NEAR(c.right_length, 1.0f, 1e-5f);
    // spherical: the vertical angle after a comma, half the horizontal one by default.
    EXPECT_FLOAT_EQ(load_text("camera { spherical angle 180, 60 }").scene.camera.v_angle_degrees,
                    60);
    EXPECT_FLOAT_EQ(load_text("camera { spherical angle 180 }").scene.camera.v_angle_degrees, 90);
    EXPECT_FLOAT_EQ(load_text("camera { spherical }").scene.camera.v_angle_degrees, 180);
}

// mesh_camera: its meshes (declared or written out, with their transforms) become the scene's
// camera meshes in Sheaf's world, each face's normal POV-Ray's cross(c - a, b - a); location
// z is the offset along it, a direction z below 0 reverses it; more rays than one are a
// pixel's anti-aliasing samples.
TEST(PovCamera, MeshCameraTakesItsMeshesAndSettings) {
    const std::string decl = "#declare M = mesh { triangle { <0,0,0>, <0,1,0>, <1,0,0> } }\n";
    PovResult r = load_text(decl + "camera { mesh_camera { 1 0 mesh { M translate 2*x } }\n"
                                   "  location <0, 0, 0.25> }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    const Camera& c = r.scene.camera;
    EXPECT_EQ(c.projection, Projection::Mesh);
    EXPECT_EQ(c.mesh_distribution, 0);
    EXPECT_EQ(c.mesh_rays, 1u);
    EXPECT_FLOAT_EQ(c.mesh_offset, 0.25f);
    EXPECT_FALSE(c.mesh_reverse);
    ASSERT_EQ(r.scene.camera_meshes.size(), 1u);
    // POV-Ray's normal: cross(<1,0,0>, <0,1,0>) = +z, Sheaf's -z; the ray leaves the
    // centroid, moved 0.25 along it.
    PreparedScene p = prepare_scene(r.scene);
    CameraFrame cam = make_camera_frame(p.camera, 1, 1);
    Ray ray;
    ASSERT_TRUE(camera_ray(SceneView(p), cam, 0, 0, ray));
    EXPECT_NEAR(ray.origin.x, 2 + 1.0f / 3, 1e-5f);
    EXPECT_NEAR(ray.origin.y, 1.0f / 3, 1e-5f);
    EXPECT_NEAR(ray.origin.z, -0.25f, 1e-5f);
    EXPECT_NEAR(ray.dir.z, -1.0f, 1e-5f);

    // Two meshes, two rays a pixel: 2 x 2 samples; direction z < 0 reverses the rays.
    r = load_text(decl + "camera { mesh_camera { 2, 0 mesh { M } mesh { M } } direction -z }");
    EXPECT_EQ(r.scene.camera.mesh_rays, 2u);
    EXPECT_TRUE(r.scene.camera.mesh_reverse);
    EXPECT_EQ(r.scene.camera_meshes.size(), 2u);
    EXPECT_EQ(r.scene.settings.at("aa.samples"), "2");
    // Distribution 3 with smooth, from a mesh2 with uv coordinates.
    r = load_text(
        "camera { mesh_camera { 1 3 mesh2 { vertex_vectors { 3, <0,0,0>, y, x }\n"
        "  uv_vectors { 3, <0,0>, <0,1>, <1,0> } face_indices { 1, <0,1,2> } } smooth } }");
    EXPECT_EQ(r.scene.camera.mesh_distribution, 3);
    EXPECT_TRUE(r.scene.camera.mesh_smooth);
    EXPECT_NO_THROW(r.scene.validate());
}

TEST(PovCamera, MeshCameraErrorsNameTheirPlace) {
    const std::string m = "mesh { triangle { 0, y, x } }";
    EXPECT_EQ(error_of("camera { mesh_camera { 0 0 " + m + " } }"),
              "scene.pov:1:24: error: a mesh camera takes 1 to 65536 rays per pixel");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 4 " + m + " } }"),
              "scene.pov:1:26: error: a mesh camera's distribution must be 0, 1, 2 or 3");
    EXPECT_EQ(error_of("camera { mesh_camera { 2 2 " + m + " } }"),
              "scene.pov:1:24: error: a mesh camera of distribution 2 or 3 takes 1 ray per pixel");
    EXPECT_EQ(error_of("camera { mesh_camera { 2 0 " + m + " } }"),
              "scene.pov:1:24: error: a mesh camera of distribution 0 takes at most one ray per "
              "pixel per mesh (2 rays, 1 meshes)");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 0 " + m + " smooth } }"),
              "scene.pov:1:58: error: a mesh camera's smooth needs distribution 3");
    EXPECT_EQ(error_of("camera { mesh_camera { 1 3 " + m + " } }"),
              "scene.pov:1:10: error: a mesh camera of distribution 3 needs its first mesh's "
              "uv_vectors");
    EXPECT_NE(error_of("camera { mesh_camera { 1 0 } }").find("expected mesh or mesh2"),
              std::string::npos);
    EXPECT_NE(error_of("#declare S = sphere { 0, 1 }\ncamera { mesh_camera { 1 0 mesh { S } } }")
                  .find("expected a mesh identifier"),
              std::string::npos);
}

TEST(PovCamera, BadCameraTypesAndAnglesAreErrors) {
    EXPECT_EQ(error_of("camera { cylinder 5 }"),
              "scene.pov:1:19: error: a cylinder camera's type must be 1, 2, 3 or 4, not 5");
    EXPECT_EQ(error_of("camera { fisheye angle -10 }"),
              "scene.pov:1:24: error: a camera's angle must lie between 0 and 3600 degrees");
    EXPECT_EQ(
        error_of("camera { spherical angle 10, -1 }"),
        "scene.pov:1:30: error: a camera's vertical angle must lie between 0 and 3600 degrees");
    EXPECT_EQ(error_of("camera { fisheye angle 1e30 }"),
              "scene.pov:1:24: error: a camera's angle must lie between 0 and 3600 degrees");
    // animations/fractalzoom's deepest frames: narrower than float rays resolve.
    EXPECT_EQ(error_of("camera { location -z look_at 0 angle 2e-13 }"),
              "scene.pov:1:38: error: a camera's angle of 2e-13 degrees is below the 0.0001 "
              "degrees that Sheaf's single-precision rays resolve");
    EXPECT_EQ(error_of("camera { cylinder 1 up 0 }"),
              "scene.pov:1:10: error: this camera's right, up and direction need lengths above 0 "
              "and below 1e6");
}

TEST(PovCamera, RightOverUpIsTheViewsShape) {
    // POV-Ray maps |right| across the image and |up| down it: the default right (1.33) on a
    // square image is stretched, as POV-Ray stretches it.
    PovOptions square;
    square.image_width = 300, square.image_height = 300;
    EXPECT_NEAR(load_text("", square).scene.camera.aspect, 1.33f, 1e-6);
    EXPECT_NEAR(load_text("camera { right 2.5 * x up y }", square).scene.camera.aspect, 2.5f, 1e-6);
    // The usual right x * image_width / image_height follows the image the host renders.
    EXPECT_EQ(
        load_text("camera { right x * image_width / image_height }", square).scene.camera.aspect,
        0.0f);
    PovOptions wide;
    wide.image_width = 400, wide.image_height = 100;
    EXPECT_EQ(load_text("camera { right 4 * x up y }", wide).scene.camera.aspect, 0.0f);
    // The frame: |right| / |up| = 2.5 spans 2.5 times the height, on any image.
    Camera c;
    c.aspect = 2.5f;
    const CameraFrame f = make_camera_frame(c, 100, 100);
    EXPECT_NEAR(f.half_x, 2.5f * f.half_y, 1e-6);
    c.aspect = 0;
    EXPECT_NEAR(make_camera_frame(c, 200, 100).half_x, 2 * make_camera_frame(c, 200, 100).half_y,
                1e-6);
}

// Focal blur: the lens is a quarter of the aperture across, the sharp plane at the focal
// point's distance from the eye, blur_samples become n x n anti-aliasing samples (a default
// the host's own aa.samples overrides); bokeh is warned; a focal point at the eye is an
// error; other camera types keep their picture, warned.
TEST(PovCamera, FocalBlurIsALensCamera) {
    PovResult r = load_text("camera { location <0, 0, -10> look_at 0 aperture 2 "
                            "focal_point <3, 0, -6> blur_samples 4, 20 confidence 0.9 "
                            "variance 1/128 }");
    // Every pixel takes every sample, where POV-Ray stops once they agree: warned.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("1:41: warning: approximated focal blur: every pixel takes 5 x 5 "
                                 "samples"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_FLOAT_EQ(r.scene.camera.lens_radius, 0.5f);
    EXPECT_FLOAT_EQ(r.scene.camera.focal_distance, 5);
    EXPECT_EQ(r.scene.settings.at("aa.samples"), "5"); // 20 samples: 5 x 5
    EXPECT_NO_THROW(r.scene.validate());
    r = load_text("camera { aperture 1 focal_point <0, 0, 4> bokeh { pigment { rgb 1 } } }");
    ASSERT_EQ(r.warnings.size(), 2u);
    EXPECT_NE(r.warnings[0].find("unsupported camera bokeh"), std::string::npos);
    EXPECT_EQ(r.scene.settings.at("aa.samples"), "4"); // 16 when not given
    r = load_text("camera { fisheye aperture 1 focal_point <0, 0, 4> }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("focal blur with this camera type"), std::string::npos);
    EXPECT_EQ(r.scene.camera.lens_radius, 0);
    EXPECT_EQ(r.scene.settings.count("aa.samples"), 0u);
    EXPECT_NE(error_of("camera { location <1, 2, 3> aperture 1 focal_point <1, 2, 3> }")
                  .find("error: a camera with an aperture needs a focal_point away from its "
                        "location"),
              std::string::npos);
    EXPECT_NE(error_of("camera { aperture -1 }").find("scene.pov:1:19: error: a camera's aperture"),
              std::string::npos);
}

TEST(PovCamera, DeclaredCameras) {
    const PovResult r = load_text("#declare C = camera { location <1, 2, 3> look_at 0 }\n"
                                  "camera { C translate y }");
    EXPECT_FLOAT_EQ(r.scene.camera.position.y, 3);
    EXPECT_FLOAT_EQ(r.scene.camera.position.z, -3);
}

TEST(PovLights, PointSpotParallel) {
    const PovResult r = load_text(
        "light_source { <1, 2, 3>, rgb <1, 0.5, 0.25> fade_distance 4 fade_power 2 shadowless }\n"
        "light_source { <0, 10, 0> color rgb 1 spotlight point_at <0, 0, 0> radius 10 falloff 20 "
        "tightness 5 }\n"
        "light_source { <0, 0, -10> rgb 1 parallel point_at <0, 0, 0> }\n");
    ASSERT_EQ(r.scene.lights.size(), 3u);
    const Light& p = r.scene.lights[0];
    EXPECT_EQ(p.type, LightType::Point);
    EXPECT_FLOAT_EQ(p.position.z, -3);
    EXPECT_FLOAT_EQ(p.color.y, 0.5f);
    EXPECT_FLOAT_EQ(p.fade_distance, 4);
    EXPECT_FLOAT_EQ(p.fade_power, 2);
    EXPECT_TRUE(p.shadowless);
    EXPECT_FALSE(p.highlights); // POV-Ray's shadowless lights give no highlight
    const Light& s = r.scene.lights[1];
    EXPECT_EQ(s.type, LightType::Spot);
    EXPECT_NEAR(s.direction.y, -1, 1e-6);
    EXPECT_FLOAT_EQ(s.spot_radius, 10);
    EXPECT_FLOAT_EQ(s.spot_falloff, 20);
    EXPECT_FLOAT_EQ(s.spot_tightness, 5);
    const Light& l = r.scene.lights[2];
    EXPECT_EQ(l.type, LightType::Parallel);
    EXPECT_NEAR(l.direction.z, -1, 1e-6); // towards POV-Ray +z, which is Sheaf -z
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_NO_THROW(r.scene.validate());
}

TEST(PovLights, LooksLikeIsAnObjectAtTheLight) {
    const PovResult r = load_text("#declare Bulb = sphere { 0, 0.25 pigment { rgb 1 } }\n"
                                  "light_source { <1, 4, 2> rgb 1 looks_like { Bulb } "
                                  "translate x }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.lights.size(), 1u);
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const ShapeObject& o = r.scene.shape_objects[0];
    EXPECT_EQ(o.flags & kNoShadow, kNoShadow); // it holds the light: it must not block it
    const Vec3 centre = o.transform.point(o.nodes[0].transform.point(Vec3(0, 0, 0)));
    EXPECT_NEAR(length(centre - r.scene.lights[0].position), 0, 1e-5);
    EXPECT_NEAR(centre.x, 2, 1e-5);
}

TEST(PovLights, AreaLightsBecomeSamples) {
    const PovResult r = load_text("light_source { <0, 5, 0> rgb <1, 1, 1> area_light x * 2, z * 2, "
                                  "3, 4 adaptive 1 jitter circular orient translate y }");
    ASSERT_EQ(r.scene.lights.size(), 12u);
    float sum = 0;
    for (const Light& l : r.scene.lights) {
        sum += l.color.x;
        EXPECT_NEAR(l.position.y, 6, 1e-5);
        EXPECT_LE(std::fabs(l.position.x), 1.0f + 1e-5f);
    }
    EXPECT_NEAR(sum, 1, 1e-5);
    // A fixed seed: the same scene gives the same samples.
    const PovResult again =
        load_text("light_source { <0, 5, 0> rgb <1, 1, 1> area_light x * 2, z * 2, "
                  "3, 4 adaptive 1 jitter circular orient translate y }");
    EXPECT_EQ(again.scene.lights[5].position.x, r.scene.lights[5].position.x);
}

// As POV-Ray lights: an area spotlight's samples take the cone (and the fade) from the area
// light's centre, unless area_illumination gives each sample its own. A cone narrower than
// the area then still lights what the centre aims at.
TEST(PovLights, AreaSpotlightsTakeTheirConeFromTheCentre) {
    const std::string light = "light_source { <0, 100, 0> rgb 1 spotlight point_at <0, 0, 0> "
                              "radius 0.5 falloff 1 area_light x * 40, z * 40, 5, 5 ";
    const PovResult centred = load_text(light + "}");
    const PovResult own = load_text(light + "area_illumination on }");
    ASSERT_EQ(centred.scene.lights.size(), 25u);
    ASSERT_EQ(own.scene.lights.size(), 25u);
    float lit = 0, lit_own = 0;
    for (size_t i = 0; i < 25; ++i) {
        const Light& l = centred.scene.lights[i];
        EXPECT_TRUE(l.centred);
        EXPECT_NEAR(length(l.centre - Vec3(0, 100, 0)), 0, 1e-4);
        EXPECT_FALSE(own.scene.lights[i].centred);
        lit += sample_light(l, Vec3(0, 0, 0), 1e6f).radiance.x;
        lit_own += sample_light(own.scene.lights[i], Vec3(0, 0, 0), 1e6f).radiance.x;
    }
    EXPECT_NEAR(lit, 1, 1e-5); // every sample's share, as the centre sees the point
    EXPECT_LT(lit_own, 0.2f);  // most samples' own cones miss it
}

TEST(PovLights, LightsInsideObjectsMoveWithThem) {
    const PovResult r =
        load_text("union { sphere { 0, 1 } light_source { <0, 2, 0>, 1 } translate x * 3 }");
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.lights[0].position.x, 3);
    EXPECT_FLOAT_EQ(r.scene.lights[0].position.y, 2);
}

TEST(PovSettings, RadiosityBecomesSettingsAndDropsTheAmbientIn37) {
    const std::string scene =
        "global_settings { radiosity { pretrace_start 0.08 pretrace_end 0.01 count 200, 1000 "
        "recursion_limit 3 nearest_count 10, 5 error_bound 0.5 brightness 0.8 "
        "always_sample off normal off save_file \"x.rad\" } }\n"
        "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0.4 } }";
    PovResult r = load_text("#version 3.7;\n" + scene);
    // The one warning: radiosity is gathered otherwise than POV-Ray's (issue 43).
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:2:19: warning: approximated radiosity: gathered "
                                 "anew at every pixel with 200 rays"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.settings.at("radiosity.samples"), "200");
    EXPECT_EQ(r.scene.settings.at("radiosity.depth"), "3");
    EXPECT_EQ(r.scene.settings.at("radiosity.brightness"), "0.8");
    EXPECT_EQ(r.scene.materials.back().ambient, 0); // the gathered light replaces it
    r = load_text("#version 3.6;\n" + scene);       // older scenes keep both
    EXPECT_FLOAT_EQ(r.scene.materials.back().ambient, 0.4f);
    // POV-Ray's defaults; no radiosity, no settings.
    r = load_text("global_settings { radiosity { } }");
    EXPECT_EQ(r.scene.settings.at("radiosity.samples"), "35");
    EXPECT_EQ(r.scene.settings.at("radiosity.depth"), "2");
    EXPECT_EQ(load_text("sphere { 0, 1 }").scene.settings.count("radiosity.samples"), 0u);
    // What Sheaf does not do is warned; bad values are errors where they are written.
    r = load_text("global_settings { radiosity { gray_threshold 0.5 media on } }");
    ASSERT_EQ(r.warnings.size(), 3u);
    EXPECT_NE(r.warnings[0].find("unsupported radiosity gray_threshold"), std::string::npos);
    EXPECT_EQ(error_of("global_settings { radiosity { count 0 } }"),
              "scene.pov:1:37: error: a radiosity count must be a positive number");
    EXPECT_EQ(error_of("global_settings { radiosity { brightness -1 } }"),
              "scene.pov:1:42: error: a radiosity brightness must not be negative");
    // POV-Ray takes larger values than Sheaf renders; they are clamped to the settings
    // registry's range, and the warning says so.
    r = load_text("global_settings { radiosity { count 5000 recursion_limit 20 brightness 200 } }");
    ASSERT_EQ(r.warnings.size(), 4u);
    EXPECT_NE(r.warnings[3].find("with 1024 rays"), std::string::npos) << r.warnings[3];
    EXPECT_NE(r.warnings[0].find("radiosity count 5000 is clamped to 1024 (radiosity.samples is "
                                 "an integer in 0..1024)"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.settings.at("radiosity.samples"), "1024");
    EXPECT_EQ(r.scene.settings.at("radiosity.depth"), "8");
    EXPECT_EQ(r.scene.settings.at("radiosity.brightness"), "100");
    EXPECT_EQ(error_of("global_settings { radiosity { bogus 1 } }"),
              "scene.pov:1:31: error: found 'bogus', expected a radiosity setting (count, "
              "recursion_limit, brightness ...)");
}

TEST(PovSettings, BackgroundGlobalSettingsAtmosphere) {
    const PovResult r = load_text("global_settings { assumed_gamma 1 max_trace_level 3 "
                                  "ambient_light rgb 0.5 }\n"
                                  "background { color rgb <0.1, 0.2, 0.3> }\n"
                                  "fog { distance 10 color rgb 1 }\n"
                                  "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0.4 } }");
    EXPECT_FLOAT_EQ(r.scene.background.z, 0.3f);
    EXPECT_EQ(r.scene.settings.at("trace.depth"), "2");
    // POV-Ray's adc_bailout: 1/255 unless the scene gives one.
    EXPECT_NEAR(std::stod(r.scene.settings.at("trace.bailout")), 1.0 / 255, 1e-9);
    EXPECT_EQ(load_text("global_settings { adc_bailout 0.01 }").scene.settings.at("trace.bailout"),
              "0.01");
    EXPECT_NE(error_of("global_settings { adc_bailout -1 }").find("adc_bailout must lie between"),
              std::string::npos);
    EXPECT_FLOAT_EQ(r.scene.materials.back().ambient, 0.2f);
    ASSERT_EQ(r.scene.fog.count, 1u);
    EXPECT_FLOAT_EQ(r.scene.fog.layer[0].distance, 10);
    EXPECT_FLOAT_EQ(r.scene.fog.layer[0].color.y, 1);
    EXPECT_TRUE(r.warnings.empty());
    // A gamma the working space cannot take is an error where it is written.
    EXPECT_EQ(error_of("global_settings { assumed_gamma 20 }"),
              "scene.pov:1:33: error: assumed_gamma must lie between 0.1 and 10");
    // Ground fog: its height along up (here -z in POV-Ray, +z in Sheaf after the mirror).
    const PovResult g = load_text(
        "fog { fog_type 2 distance 5 color rgb 1 fog_offset 0.5 fog_alt 2 up y rotate x * 90 }");
    EXPECT_TRUE(g.warnings.empty());
    EXPECT_FLOAT_EQ(g.scene.fog.layer[0].alt, 2);
    EXPECT_FLOAT_EQ(g.scene.fog.layer[0].offset, 0.5f);
    EXPECT_NEAR(g.scene.fog.layer[0].up.z, -1, 1e-6); // POV-Ray's y turned by 90 about x: +z
    EXPECT_FLOAT_EQ(load_text("fog { distance 5 color rgb 1 }").scene.fog.layer[0].alt,
                    0); // constant
    // Every fog counts (interior/foglyr2.pov lays two), each with its filter and turbulence.
    const PovResult two =
        load_text("fog { distance 5 color rgbf <1, 0, 0, 0.5> turbulence <0.1, 0.2, 0.3> octaves 3 "
                  "omega 0.4 lambda 1.5 turb_depth 0.25 }\nfog { distance 0 }\n"
                  "fog { fog_type 2 distance 7 color rgbt <0, 0, 1, 0.25> }");
    EXPECT_TRUE(two.warnings.empty()) << two.warnings.front();
    ASSERT_EQ(two.scene.fog.count, 2u); // a fog of no distance is left out, as in POV-Ray
    const Fog& a = two.scene.fog.layer[0];
    EXPECT_FLOAT_EQ(a.filter, 0.5f);
    EXPECT_FLOAT_EQ(a.turb.y, 0.2f);
    EXPECT_FLOAT_EQ(a.turb.z, -0.3f); // POV-Ray's point, mirrored
    EXPECT_EQ(a.octaves, 3);
    EXPECT_FLOAT_EQ(a.turb_depth, 0.25f);
    EXPECT_FLOAT_EQ(two.scene.fog.layer[1].transmit, 0.25f);
    EXPECT_FLOAT_EQ(two.scene.fog.layer[1].alt, 1);
    // octaves clamp to 1..10, as POV-Ray's do (and the patterns' here).
    EXPECT_EQ(load_text("fog { distance 5 turbulence 1 octaves 12 }").scene.fog.layer[0].octaves,
              10);
    EXPECT_EQ(load_text("fog { distance 5 turbulence 1 octaves 0 }").scene.fog.layer[0].octaves, 1);
    EXPECT_EQ(error_of("fog { fog_type 2 distance 5 fog_alt 0 }"),
              "scene.pov:1:37: error: fog_alt must be greater than 0");
    EXPECT_EQ(error_of("fog { fog_type 3 distance 5 }"),
              "scene.pov:1:1: error: fog_type 3 is not 1 (constant) or 2 (ground)");
}

TEST(PovSettings, FogFillsHollowObjectsOnly) {
    // A clear ball of ior 1 before a white wall, in red fog: the way through the ball takes
    // fog only when the ball is hollow, as in POV-Ray (interior/media/hollow1.pov; povray
    // 3.7 draws the centre 55 and 81 of 255 in green, as Sheaf). The camera is inside the
    // plane's solid side, so the plane is hollow too.
    auto centre = [](const std::string& hollow) {
        const PovResult r =
            load_text("global_settings { assumed_gamma 1 }\n"
                      "camera { orthographic location <0, 0, -10> look_at 0 right x*4 up y*4 }\n"
                      "fog { rgb <1, 0, 0> distance 4 }\n"
                      "plane { z, 3 pigment { rgb 1 } finish { ambient 1 diffuse 0 } hollow }\n"
                      "sphere { 0, 1.5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } " +
                      hollow + " }\n");
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
        const PreparedScene p = prepare_scene(r.scene);
        RenderSettings rs = RenderSettings::resolve({}, r.scene.settings);
        rs.width = rs.height = 32;
        const Frame f = render_frame(p, rs);
        return f.rgba[4 * (16 * size_t(32) + 16) + 1]; // green: what the fog leaves of white
    };
    // From the camera at z = -10 to the wall at z = 3: 13 units, 3 of them in the ball.
    EXPECT_NEAR(centre("hollow"), std::exp(-13.0f / 4), 0.01f);
    EXPECT_NEAR(centre(""), std::exp(-10.0f / 4), 0.01f);
}

TEST(PovSettings, FogFadesTheLightOfLightsWithMediaAttenuation) {
    // A white floor lit from 8 units above, seen from 1 unit above it, in fog of distance 4:
    // a light with media_attenuation loses exp(-8 / 4) of its light on the way, less where a
    // solid clear slab 4 thick lies in the way (fog fills only hollow objects).
    auto lit = [](const std::string& light, const std::string& slab) {
        const PovResult r =
            load_text("global_settings { assumed_gamma 1 }\n"
                      "camera { orthographic location <0, 1, 0> look_at 0 right x*0.1 up z*0.1 }\n"
                      "fog { rgb 0 distance 4 }\n"
                      "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
                      "light_source { <0, 8, 0> rgb 1 " +
                      light + " }\n" + slab);
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
        const PreparedScene p = prepare_scene(r.scene);
        RenderSettings rs = RenderSettings::resolve({}, r.scene.settings);
        rs.width = rs.height = 8;
        const Frame f = render_frame(p, rs);
        return f.rgba[4 * (4 * size_t(8) + 4)] / std::exp(-1.0f / 4); // the camera's fog out
    };
    EXPECT_NEAR(lit("", ""), 1.0f, 0.01f);
    EXPECT_NEAR(lit("media_attenuation on", ""), std::exp(-8.0f / 4), 0.01f);
    EXPECT_NEAR(lit("media_attenuation on media_interaction off", ""), 1.0f, 0.01f);
    const std::string slab = "box { <-5, 2, -5>, <5, 6, 5> pigment { rgbt 1 } ";
    EXPECT_NEAR(lit("media_attenuation on", slab + "}"), std::exp(-4.0f / 4), 0.01f);
    EXPECT_NEAR(lit("media_attenuation on", slab + "hollow }"), std::exp(-8.0f / 4), 0.01f);
}

} // namespace
} // namespace sheaf::io::pov

namespace sheaf::io::pov {
namespace {

// Light groups: a group's lights light only its objects, and its objects only its lights (and
// with global_lights on, the lights in no group too).
TEST(PovLights, LightGroupsLightTheirOwnObjects) {
    auto render = [](const std::string& extra, const std::string& global) {
        const PovResult r = load_text(
            "global_settings { assumed_gamma 1 }\n"
            "camera { orthographic location <0, 10, 0> look_at 0 right x*4 up z*4 }\n"
            "#declare W = texture { pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
            "light_group { light_source { <0, 10, 0> rgb 1 } box { <-2, -1, -2>, <0, 0, 2> "
            "texture { W } } " +
            global + " }\nbox { <0, -1, -2>, <2, 0, 2> texture { W } }\n" + extra);
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
        EXPECT_NO_THROW(r.scene.validate());
        const PreparedScene p = prepare_scene(r.scene);
        RenderSettings rs = RenderSettings::resolve({}, r.scene.settings);
        rs.width = rs.height = 32;
        const Frame f = render_frame(p, rs);
        auto at = [&](int x) { return f.rgba[4 * (16 * size_t(32) + size_t(x))]; };
        return std::make_pair(at(24), at(8)); // x < 0 and x > 0 in POV-Ray's world
    };
    const auto alone = render("", "");
    EXPECT_NEAR(alone.first, 1.0f, 0.02f);  // the group's box, under its light
    EXPECT_NEAR(alone.second, 0.0f, 1e-6f); // the other, in no light
    // A light in no group lights the box outside, not the group's ...
    const std::string sun = "light_source { <0, 10, 0> rgb 0.5 }\n";
    const auto other = render(sun, "");
    EXPECT_NEAR(other.first, 1.0f, 0.02f);
    EXPECT_NEAR(other.second, 0.5f, 0.02f);
    // ... unless the group takes the global lights.
    const auto global = render(sun, "global_lights on");
    EXPECT_NEAR(global.first, 1.5f, 0.03f);
    EXPECT_NEAR(global.second, 0.5f, 0.02f);
}

} // namespace
} // namespace sheaf::io::pov

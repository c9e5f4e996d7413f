// The atmosphere's media (POV-Ray's `media { … }` outside any object): read into
// Scene::atmosphere with lights' media_attenuation, densities placed in the world, errors at
// their place, and a render against the numbers povray gives; rainbows likewise.
#include "tests/support/pov_test_util.h"

#include "core/backend/backend.h"
#include "core/shading/media.h"

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

TEST(PovAtmosphere, MediaOutsideObjectsFillTheScene) {
    const PovResult r = load_text(R"(
#declare Glow = media { emission 0.1 }
media { scattering { 2, rgb 0.03 } intervals 1 samples 5 method 3 }
media { Glow density { spherical density_map { [0 rgb 0] [1 rgb 1] } scale 2 } }
light_source { <0, 15, 0> 1 spotlight point_at 0 media_attenuation on }
light_source { <0, 15, 0> 1 media_interaction off }
box { -20, 20 hollow pigment { rgb 1 } })");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Scene& s = r.scene;
    ASSERT_GE(s.atmosphere, 0);
    const Material& air = s.materials[size_t(s.atmosphere)];
    ASSERT_EQ(air.media_count, 2u); // both statements, in their order
    const Medium& hazy = s.media[air.media_first];
    EXPECT_EQ(hazy.scatter_type, ScatterType::MieHazy);
    EXPECT_FLOAT_EQ(hazy.scattering.x, 0.03f);
    EXPECT_EQ(hazy.samples, 32u);
    const Medium& glow = s.media[air.media_first + 1];
    EXPECT_FLOAT_EQ(glow.emission.y, 0.1f);
    ASSERT_EQ(glow.density_count, 1u);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_TRUE(s.lights[0].media_attenuation);
    EXPECT_FALSE(s.lights[1].media_attenuation); // POV-Ray's default
    EXPECT_FALSE(s.lights[1].media_interaction);
    EXPECT_FALSE(s.shape_objects[0].flags & kSolid);
    // The density lies in the world: 1 at the origin, half at 1 unit (spherical, scale 2).
    const PreparedScene p = prepare_scene(s);
    const SceneView view(p);
    EXPECT_NEAR(medium_density(view, glow, Vec3(0, 0, 0)).x, 1.0f, 1e-5f);
    EXPECT_NEAR(medium_density(view, glow, Vec3(1, 0, 0)).x, 0.5f, 1e-5f);
    EXPECT_NEAR(medium_density(view, glow, Vec3(0, 0, -1.5f)).x, 0.25f, 1e-5f);
    // A scene without one has none.
    EXPECT_EQ(load_text("sphere { 0, 1 }").scene.atmosphere, -1);
}

TEST(PovAtmosphere, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("sphere { 0, 1 }\nmedia { scattering { 7, 1 } }"),
              "scene.pov:2:22: error: a scattering type must be 1 (isotropic), 2 (Mie hazy), 3 "
              "(Mie murky), 4 (Rayleigh) or 5 (Henyey-Greenstein)");
    EXPECT_EQ(error_of("media { absorption -1 }"),
              "scene.pov:1:20: error: a medium's absorption must be finite and not negative");
    EXPECT_EQ(error_of("media { glow 1 }"),
              "scene.pov:1:9: error: found 'glow', expected a media item (emission, absorption, "
              "density, samples ...)");
    EXPECT_EQ(error_of("media { emission 1"),
              "scene.pov:1:19: error: found 'end of file', expected a media item or '}'");
}

TEST(PovAtmosphere, ARenderMatchesPovRay) {
    // A clear ball inside a black hollow room, seen through an emitting atmosphere: the middle
    // ray crosses 4 units, then the ball (solid: left out), then 19 units. povray 3.7 gives
    // 0.2307 (sRGB 132 of 255) at the middle; 0.25 with the ball hollow.
    const std::string scene = R"(
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 angle 30 }
media { emission 0.01 }
sphere { 0, 1 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } HOLLOW }
sphere { 0, 20 hollow pigment { rgb 0 } finish { ambient 0 diffuse 0 } })";
    for (const bool hollow : {false, true}) {
        std::string text = scene;
        text.replace(text.find("HOLLOW"), 6, hollow ? "hollow" : "");
        const PovResult r = load_text(text);
        ASSERT_TRUE(r.warnings.empty()) << r.warnings.front();
        RenderSettings rs = RenderSettings::resolve({}, r.scene.settings);
        rs.width = rs.height = 33;
        const Frame f = render_frame(prepare_scene(r.scene), rs);
        EXPECT_NEAR(f.rgba[4 * (16 * 33 + 16)], hollow ? 0.25f : 0.23f, 2e-4f) << hollow;
    }
}

TEST(PovRainbow, ABandAroundTheDirectionAsPovRayDrawsIt) {
    // A grey ramp over the band 15..25 degrees off +z (angle 20, width 10), the camera looking
    // along +z: povray 3.7 gives sRGB 55 (0.037) at 15.38 degrees, 188 (0.503) at 20.05 and
    // nothing past 25 (columns 127, 136, 147 of 200, the middle row).
    const PovResult r = load_text(R"(
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location 0 look_at z angle 90 right x up y }
background { rgb 0 }
rainbow { angle 20 width 10 distance 1e-3 direction <0, 0, 1>
  colour_map { [0 rgb 0] [1 rgb 1] } })");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.rainbows.size(), 1u);
    EXPECT_NEAR(r.scene.rainbows[0].antisolar.z, -1.0f, 1e-6f); // POV-Ray's +z is Sheaf's -z
    RenderSettings rs = RenderSettings::resolve({}, r.scene.settings);
    rs.width = rs.height = 200;
    const Frame f = render_frame(prepare_scene(r.scene), rs);
    const auto at = [&](int x) { return f.rgba[4 * (100 * 200 + size_t(x))]; };
    EXPECT_NEAR(at(127), 0.037f, 0.01f);
    EXPECT_NEAR(at(136), 0.503f, 0.01f);
    EXPECT_EQ(at(147), 0.0f);
    EXPECT_EQ(at(100), 0.0f);
    // No colour map or a zero width: nothing, as in POV-Ray.
    EXPECT_TRUE(load_text("rainbow { angle 40 width 5 direction z }").scene.rainbows.empty());
}

TEST(PovRainbow, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("rainbow { arc_angle 400 }"),
              "scene.pov:1:11: error: a rainbow's arc_angle must lie between 0 and 360 degrees");
    EXPECT_EQ(error_of("rainbow { direction z arc_angle 90 falloff_angle 120 }"),
              "scene.pov:1:1: error: a rainbow's arc_angle is smaller than its falloff_angle");
    EXPECT_EQ(error_of("rainbow { angle 40 }"),
              "scene.pov:1:1: error: a rainbow's direction must not be zero");
    EXPECT_EQ(error_of("rainbow { direction y }"),
              "scene.pov:1:1: error: a rainbow's up vector must not lie along its direction");
    EXPECT_EQ(error_of("rainbow { direction z distance 0 }"),
              "scene.pov:1:23: error: a rainbow's distance must be greater than 0");
    EXPECT_EQ(error_of("rainbow { direction z glow 1 }"),
              "scene.pov:1:23: error: found 'glow', expected a rainbow item (angle, width, "
              "distance, direction, color_map ...)");
}

} // namespace
} // namespace sheaf::io::pov

// POV-Ray's photons: the blocks read, their errors, and renders against povray 3.7's pixels.
#include "core/backend/backend.h"
#include "tests/support/pov_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

// A mirror disc facing down at y = 5 over a white floor, a light at y = 3 between them: the
// floor gets the light's own light and the mirror's photons, as if from the light's image at
// y = 7. Seen from above, 20 units across.
const char* kMirror = R"(
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.1 jitter 0 } }
camera { orthographic location <0, 4, 0> look_at 0 sky z right x * 20 up z * 20 }
light_source { <0, 3, 0> rgb 1 photons { reflection on refraction on } }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
disc { <0, 5, 0>, y, 12 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 }
  photons { target reflection on } })";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

Frame render(const PovResult& r, int w, int h, const std::string& accel = "") {
    Settings explicit_settings;
    explicit_settings.set("aa.samples", "1");
    if (!accel.empty()) explicit_settings.set("accel", accel);
    RenderSettings rs = RenderSettings::resolve(explicit_settings, r.scene.settings);
    rs.width = w, rs.height = h;
    return render_frame(prepare_scene(r.scene), rs);
}

float red(const Frame& f, int x, int y) {
    return f.rgba[4 * (size_t(y) * f.width + x)];
}

TEST(PovPhotons, BlocksAreRead) {
    const PovResult r = load_text(R"(
global_settings { photons { count 5000 gather 10, 50 radius 0.5, 2 jitter 0.2 max_trace_level 4
  adc_bailout 0.01 expand_thresholds 0.3, 30 steps 3 autostop 0 save_file "x.ph" } }
light_source { <0, 9, 0> 1 photons { refraction off reflection on area_light } }
light_source { <0, 9, 0> 1 area_light x, z, 3, 3 }
sphere { 0, 1 photons { target 0.5 refraction on reflection off collect off } }
union { sphere { 3, 1 } box { -1, 1 photons { reflection on } } photons { target pass_through } }
)");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const PhotonSettings& p = r.scene.photons;
    EXPECT_EQ(p.count, 5000u);
    EXPECT_EQ(p.spacing, 0.0f);
    EXPECT_TRUE(p.enabled());
    EXPECT_EQ(p.gather_min, 10u);
    EXPECT_EQ(p.gather_max, 50u);
    EXPECT_FLOAT_EQ(p.radius, 0.5f);
    EXPECT_FLOAT_EQ(p.radius_scale, 2.0f);
    EXPECT_FLOAT_EQ(p.jitter, 0.2f);
    EXPECT_EQ(p.max_trace_level, 4u);
    EXPECT_FLOAT_EQ(p.adc_bailout, 0.01f);
    EXPECT_FLOAT_EQ(p.expand_tolerance, 0.3f);
    EXPECT_EQ(p.expand_min, 30u);
    EXPECT_EQ(p.steps, 3u);
    const Light& l = r.scene.lights[0];
    EXPECT_EQ(l.photon_refraction, PhotonSwitch::Off);
    EXPECT_EQ(l.photon_reflection, PhotonSwitch::On);
    // An area light shoots as one light: its middle sample, for all nine.
    ASSERT_EQ(r.scene.lights.size(), 10u);
    int shooters = 0;
    for (size_t i = 1; i < 10; ++i) {
        const Light& s = r.scene.lights[i];
        if (s.photon_reflection == PhotonSwitch::Off) continue;
        ++shooters;
        EXPECT_EQ(s.photon_weight, 9.0f);
    }
    EXPECT_EQ(shooters, 1);
    ASSERT_EQ(r.scene.shape_objects.size(), 3u);
    const ShapeObject& ball = r.scene.shape_objects[0];
    EXPECT_FLOAT_EQ(ball.photons.target, 0.5f);
    EXPECT_EQ(ball.photons.refraction, PhotonSwitch::On);
    EXPECT_EQ(ball.photons.reflection, PhotonSwitch::Off);
    EXPECT_TRUE(ball.flags & kNoPhotonCollect);
    // The union's parts are targets as the union was; the box's own switch stays.
    for (size_t i = 1; i < 3; ++i) {
        EXPECT_FLOAT_EQ(r.scene.shape_objects[i].photons.target, 1.0f);
        EXPECT_TRUE(r.scene.shape_objects[i].flags & kPassPhotons);
    }
    EXPECT_EQ(r.scene.shape_objects[1].photons.reflection, PhotonSwitch::Unset);
    EXPECT_EQ(r.scene.shape_objects[2].photons.reflection, PhotonSwitch::On);
}

TEST(PovPhotons, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("global_settings { photons { spacing 0 } }"),
              "scene.pov:1:37: error: photons need a spacing above 0");
    EXPECT_EQ(error_of("global_settings { photons { gather 50, 10 } }"),
              "scene.pov:1:36: error: gather needs 0 <= min <= max, and max from 1 to 10000");
    EXPECT_EQ(error_of("global_settings { photons { spread 1 } }"),
              "scene.pov:1:29: error: found 'spread', expected a photons setting (spacing, count, "
              "gather, radius, jitter ...)");
    EXPECT_EQ(error_of("sphere { 0, 1 photons { target -1 } }"),
              "scene.pov:1:32: error: a photon target's spacing multiplier must be above 0");
    EXPECT_EQ(error_of("light_source { 0, 1 photons { collect off } }"),
              "scene.pov:1:31: error: found 'collect', expected refraction, reflection, "
              "area_light or '}'");
    // Photons in media, and loading POV-Ray's photon files, are warned.
    const PovResult r = load_text("global_settings { photons { spacing 1 media 100 } }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("photons in media"), std::string::npos) << r.warnings[0];
}

TEST(PovPhotons, AMirrorLightsTheFloorAsPovRaysPhotonsDo) {
    // povray 3.7 at 40x40 (+FE, linear): 1.977, 1.512, 1.074, 0.882 at columns 20, 27, 34, 39
    // of the middle row (x = 0.25, 3.75, 7.25, 9.75), 0.993, 0.624, 0.382, 0.294 of them the
    // light's own. The photons' share is the light's image's: cos(atan(x / 7)).
    const PovResult r = load_text(kMirror);
    ASSERT_TRUE(r.warnings.empty()) << r.warnings.front();
    const Frame f = render(r, 40, 40);
    const int cols[] = {20, 27, 34, 39};
    const float pov[] = {1.977f, 1.512f, 1.074f, 0.882f};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(red(f, cols[i], 20), pov[i], 0.04f) << cols[i];
    EXPECT_GT(f.stats.get("photons.shot"), 1e5);
    // The light is inside the mirror's bounding sphere: it shoots every way, and the photons
    // that meet the floor first are not the mirror's.
    EXPECT_GT(f.stats.get("photons.stored"), 0.3 * f.stats.get("photons.shot"));
    EXPECT_GE(f.stats.get("rays.photon"),
              f.stats.get("photons.shot") + f.stats.get("photons.stored"));
    EXPECT_GT(f.stats.get("photons.radius"), 0.0);
}

TEST(PovPhotons, TheLightsAndTheTargetsSwitchesDecide) {
    // POV-Ray's rule, measured with povray: a reflection is on when one side turns it on and
    // the other does not turn it off; with neither, the mirror sends nothing.
    const std::string neither =
        replaced(replaced(kMirror, " photons { reflection on refraction on }", ""),
                 "target reflection on", "target");
    const std::string off = replaced(kMirror, "reflection on refraction on", "reflection off");
    for (const std::string& text : {neither, off}) {
        const Frame f = render(load_text(text), 40, 40);
        EXPECT_NEAR(red(f, 20, 20), 0.993f, 0.01f);
        EXPECT_EQ(f.stats.get("photons.stored"), 0.0);
    }
}

TEST(PovPhotons, EveryAccelKeepsTheSamePhotonsAndImage) {
    const PovResult r = load_text(kMirror);
    const Frame a = render(r, 24, 24, "brute"), b = render(r, 24, 24, "rah"),
                c = render(r, 24, 24, "crsh");
    EXPECT_EQ(a.stats.get("photons.stored"), c.stats.get("photons.stored"));
    EXPECT_EQ(b.stats.get("photons.stored"), c.stats.get("photons.stored"));
    EXPECT_EQ(a.rgba, c.rgba);
    EXPECT_EQ(b.rgba, c.rgba);
}

TEST(PovPhotons, GlassCastsAWholeShadowAndACausticInIt) {
    // A glass ball over a white floor, lit from straight above: without photons its shadow is
    // filtered light; with them the ball casts a whole shadow (POV-Ray's rule for targets
    // that refract photons) and focuses them into a spot brighter than the lit floor (povray
    // 3.7 at 160x120: mean error 0.012 against this).
    const std::string glass = R"(
#version 3.7;
global_settings { assumed_gamma 1 PHOTONS }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 40 }
light_source { <0, 10, 0> rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0, 1.5, 0>, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 }
  photons { target refraction on reflection off collect off } })";
    const Frame p =
        render(load_text(replaced(glass, "PHOTONS", "photons { spacing 0.02 }")), 64, 48);
    const Frame n = render(load_text(replaced(glass, "PHOTONS", "")), 64, 48);
    auto brightest = [](const Frame& f) {
        float m = 0;
        for (size_t i = 0; i < f.rgba.size(); i += 4) m = std::max(m, f.rgba[i]);
        return m;
    };
    auto dark = [](const Frame& f) {
        int c = 0;
        for (size_t i = 0; i < f.rgba.size(); i += 4) c += f.rgba[i] < 0.3f;
        return c;
    };
    EXPECT_LE(brightest(n), 1.01f);
    EXPECT_GT(brightest(p), 1.5f);
    EXPECT_TRUE(std::isfinite(brightest(p)));
    EXPECT_GT(dark(p), dark(n) + 20);
}

TEST(PovPhotons, TooFineASpacingIsRefused) {
    const std::string fine = replaced(kMirror, "spacing 0.1", "spacing 1e-5");
    try {
        render(load_text(fine), 8, 8);
        FAIL() << "rendered";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("raise the spacing"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace sheaf::io::pov

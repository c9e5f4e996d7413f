// Interior and atmospheric media: the integral along a ray against its closed forms (emission
// alone, absorption alone, both, stepped anywhere), what a rendered container gives through its
// middle, a union whose members carry media of their own, solid objects left out, the camera
// inside, the atmosphere around solid and hollow objects and its beams, and every accel alike.
#include "core/shading/media.h"

#include "core/backend/backend.h"
#include "core/frame/render_frame.h"
#include "core/scenes/shapes.h"
#include "tests/support/test_scenes.h"

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
    // Stepped at another place than the middle, each step is off, but over a spread of
    // places (media_jitter per sample) the steps are right on average.
    Vec3 mean(0.0f);
    for (int k = 0; k < 16; ++k) {
        through_media(view, m, Vec3(0, 0, 1), Vec3(0, 0, -1), d, keep, add, NoScatterVisit(),
                      (float(k) + 0.5f) / 16.0f);
        EXPECT_NEAR(keep.z, std::exp(-2.0f * d), 1e-5f) << k; // the extinction is exact
        mean += add / 16.0f;
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(mean[c],
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

// Many solids (their BVH) and one lying wholly behind the camera, whose
// bounding sphere holds the camera: the medium in front keeps its whole chord, as the pieces
// of a container keep its media wherever a solid cuts them.
TEST(Media, SolidsBehindTheRayAndManySolidsLeaveTheChordAlone) {
    Medium glow;
    glow.emission = Vec3(0.2f);
    Scene s = sphere_of({glow});
    s.camera.position = Vec3(0, 0, 0), s.camera.look_at = Vec3(0, 0, -1);
    Material grey;
    grey.color = Vec3(0.5f);
    const uint32_t m = s.add_material(grey);
    // A slab just behind the camera (z from 0.1 to 0.2), its sphere around the camera.
    const uint32_t slab =
        s.add_shape("slab", Shape{ShapeKind::Box}, m,
                    Affine::translate(Vec3(0, 0, 0.15f)) * Affine::scale(Vec3(0.5f, 0.5f, 0.05f)));
    s.shape_objects[slab].flags = kSolid;
    for (int i = 0; i < 20; ++i) { // small solid balls around the rim, off the middle ray
        const float a = 2 * kPi * float(i) / 20;
        const uint32_t b =
            s.add_shape("ball", Shape{ShapeKind::Sphere}, m,
                        Affine::translate(Vec3(0.7f * std::cos(a), 0.7f * std::sin(a), -0.3f)) *
                            Affine::scale(Vec3(0.05f)));
        s.shape_objects[b].flags = kSolid;
    }
    const PreparedScene scene = prepare_scene(s);
    EXPECT_GT(scene.media_solid_bvh.nodes.size(), 0u);
    EXPECT_NEAR(pixel(render(scene, {}, 33, 33), 16, 16)[0], 0.2f, 1e-4f);
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

TEST(Media, ShadowRaysFadeByTheExtinctionOnTheirWay) {
    Medium fog;
    fog.absorption = Vec3(0.08f);
    Medium mist; // scattering takes extinction x scattering away too
    mist.scattering = Vec3(0.1f);
    mist.extinction = 0.5f;
    Scene s;
    s.add_shape("container", Shape{ShapeKind::Box}, test::add_media_material(s, {fog, mist}),
                Affine::scale(Vec3(4.0f)));
    const PreparedScene scene = prepare_scene(s);
    const SceneView view(scene);
    const Vec3 p(-2.0f, -1.0f, 1.266f), l(-5, 5, -5);
    const Vec3 d = l - p;
    const float len = length(d);
    // Inside until x = -4: two thirds of the way.
    EXPECT_NEAR(media_transmittance(view, p, d / len, len, false).x,
                std::exp(-(0.08f + 0.05f) * len * 2.0f / 3.0f), 1e-4f);
    // From outside, through the whole box along x: 8 units.
    EXPECT_NEAR(media_transmittance(view, Vec3(-6, 0, 0), Vec3(1, 0, 0), 12.0f, false).y,
                std::exp(-0.13f * 8.0f), 1e-4f);
    EXPECT_EQ(media_transmittance(view, Vec3(-6, 0, 0), Vec3(-1, 0, 0), 12.0f, false).z, 1.0f);
}

TEST(Media, PhaseFunctionsAreTheirPovRayFormulas) {
    Medium md;
    EXPECT_EQ(scatter_phase(md, -1.0f), 1.0f); // isotropic
    md.scatter_type = ScatterType::Rayleigh;
    EXPECT_NEAR(scatter_phase(md, 0.0f), 0.799372f, 1e-6f);
    EXPECT_NEAR(scatter_phase(md, 1.0f), 2 * 0.799372f, 1e-6f);
    md.scatter_type = ScatterType::MieHazy;
    EXPECT_NEAR(scatter_phase(md, 1.0f), 0.576655f * 10, 1e-5f);
    EXPECT_NEAR(scatter_phase(md, -1.0f), 0.576655f, 1e-6f);
    md.scatter_type = ScatterType::MieMurky;
    EXPECT_NEAR(scatter_phase(md, 1.0f), 0.495715f * 51, 1e-4f);
    md.scatter_type = ScatterType::HenyeyGreenstein;
    md.eccentricity = 0.0f;
    EXPECT_NEAR(scatter_phase(md, 0.3f), 1.0f, 1e-6f);
    md.eccentricity = 0.5f; // forward: most where the light lies straight ahead (c = 1)
    EXPECT_NEAR(scatter_phase(md, 1.0f), 0.75f / 0.125f, 1e-4f);
    EXPECT_NEAR(scatter_phase(md, -1.0f), 0.75f / (2.25f * 1.5f), 1e-4f);
}

// A unit sphere of scattering medium (no extinction unless asked), lit from straight above by
// parallel light of colour 1; an opaque slab above its x < 0 half when `shade`.
Scene scattering_sphere(float extinction, bool shade, bool shadowless) {
    Medium mist;
    mist.scattering = Vec3(0.2f, 0.1f, 0.05f);
    mist.extinction = extinction;
    Scene s = sphere_of({mist});
    Light sun;
    sun.type = LightType::Parallel;
    sun.direction = Vec3(0, -1, 0);
    sun.shadowless = shadowless;
    s.add_light(sun);
    if (shade)
        s.add_shape("slab", Shape{ShapeKind::Box}, s.add_material(Material{}),
                    Affine::translate(Vec3(-2.0f, 2.0f, 0)) *
                        Affine::scale(Vec3(2.0f, 0.1f, 2.0f)));
    return s;
}

TEST(Media, ScatteredLightIsTheScatteringTimesTheChordAndShadowsCutIt) {
    // Through the middle the ray crosses 2 units: 2 x scattering x the light, phase 1.
    const Frame lit = render(prepare_scene(scattering_sphere(0, false, false)), {}, 33, 33);
    EXPECT_NEAR(pixel(lit, 16, 16)[0], 0.4f, 1e-4f);
    EXPECT_NEAR(pixel(lit, 16, 16)[1], 0.2f, 1e-4f);
    EXPECT_NEAR(pixel(lit, 16, 16)[2], 0.1f, 1e-4f);
    EXPECT_EQ(pixel(lit, 0, 0)[0], 0.0f);
    // A shadowless light needs no shadow rays and gives the same.
    const Frame fill = render(prepare_scene(scattering_sphere(0, false, true)), {}, 33, 33);
    EXPECT_NEAR(pixel(fill, 16, 16)[0], pixel(lit, 16, 16)[0], 1e-5f);
    EXPECT_NEAR(pixel(fill, 10, 20)[1], pixel(lit, 10, 20)[1], 1e-5f);
    // With extinction the light fades on its way in and on its way out.
    const Frame dim = render(prepare_scene(scattering_sphere(1, false, false)), {}, 33, 33);
    EXPECT_LT(pixel(dim, 16, 16)[0], 0.8f * pixel(lit, 16, 16)[0]);
    EXPECT_GT(pixel(dim, 16, 16)[0], 0.4f * pixel(lit, 16, 16)[0]);
    // The slab shades the x < 0 half: nothing scattered there, the other half as before.
    const Frame shaded = render(prepare_scene(scattering_sphere(0, true, false)), {}, 33, 33);
    EXPECT_LT(pixel(shaded, 10, 16)[0], 1e-4f);
    EXPECT_NEAR(pixel(shaded, 22, 16)[0], pixel(lit, 22, 16)[0], 1e-5f);
    // A light that does not interact with media scatters nothing.
    Scene off = scattering_sphere(0, false, false);
    off.lights[0].media_interaction = false;
    EXPECT_EQ(pixel(render(prepare_scene(off), {}, 33, 33), 16, 16)[0], 0.0f);
}

TEST(Media, ScatteringIsTheSameOnEveryAccelAndTheWavefront) {
    const Scene s = test::scattering_scene();
    const PreparedScene scene = prepare_scene(s);
    const Frame crsh = render(scene, {}, 40, 30);
    Scene clear = s; // the media's own shadow rays: 32 steps a crossing, 4 lights a step
    clear.media[0].scattering = Vec3(0.0f);
    EXPECT_GT(crsh.stats.get("rays.shadow"),
              render(prepare_scene(clear), {}, 40, 30).stats.get("rays.shadow") + 10000);
    for (const test::SettingList& kv :
         {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}}}) {
        const Frame other = render(scene, kv, 40, 30);
        EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
            << kv[0].second;
    }
    const RenderSettings rs = test::settings_for(scene, {}, 40, 30);
    test::expect_same_frame(render_frame_cpu(scene, rs), render_frame_wavefront_cpu(scene, rs),
                            "scattering");
}

// Scene s with `md` as its atmosphere.
void add_atmosphere(Scene& s, const Medium& md) {
    Material m;
    m.media_first = uint32_t(s.media.size());
    m.media_count = 1;
    s.media.push_back(md);
    s.atmosphere = int32_t(s.add_material(m));
}

TEST(Media, TheAtmosphereFillsSpaceOutsideSolidObjects) {
    // A clear ball at the origin inside a black hollow room of radius 20, the camera at z = 5:
    // the middle ray crosses 4 units, the ball's 2 and then 19 more to the wall.
    Medium glow;
    glow.emission = Vec3(0.01f, 0.02f, 0.0f);
    Scene s = sphere_of({});
    Material& clear = s.materials[s.shape_objects[0].nodes[0].material];
    clear.media_count = 0;
    Material black;
    black.ambient = black.diffuse = 0;
    s.add_shape("room", Shape{ShapeKind::Sphere}, s.add_material(black),
                Affine::scale(Vec3(20.0f)));
    add_atmosphere(s, glow);
    // POV-Ray's objects are solid: the atmosphere leaves the ball out.
    s.shape_objects[0].flags = kSolid;
    const Frame solid = render(prepare_scene(s), {}, 33, 33);
    EXPECT_NEAR(pixel(solid, 16, 16)[0], 0.23f, 1e-4f);
    EXPECT_NEAR(pixel(solid, 16, 16)[1], 0.46f, 2e-4f);
    // A hollow ball is filled.
    s.shape_objects[0].flags = 0;
    EXPECT_NEAR(pixel(render(prepare_scene(s), {}, 33, 33), 16, 16)[0], 0.25f, 1e-4f);
    // Without the room, rays that leave the scene cross kAtmosphereFar units (as POV-Ray's
    // do: an atmosphere wants a room around the scene).
    Scene open = sphere_of({});
    open.materials[open.shape_objects[0].nodes[0].material].media_count = 0;
    glow.emission = Vec3(1e-10f);
    add_atmosphere(open, glow);
    EXPECT_NEAR(pixel(render(prepare_scene(open), {}, 33, 33), 0, 0)[0], 1e-10f * kAtmosphereFar,
                1e-3f);
}

TEST(Media, OnlyLightsWithMediaAttenuationFadeThroughTheAtmosphere) {
    Medium haze;
    haze.absorption = Vec3(0.1f, 0.2f, 0.3f);
    Scene s;
    const uint32_t ball = s.add_shape("ball", Shape{ShapeKind::Sphere}, s.add_material(Material{}),
                                      Affine::translate(Vec3(5, 0, 0)));
    s.shape_objects[ball].flags = kSolid;
    add_atmosphere(s, haze);
    const PreparedScene scene = prepare_scene(s);
    const SceneView view(scene);
    EXPECT_EQ(media_transmittance(view, Vec3(0, 0, 0), Vec3(0, 1, 0), 10.0f, false).z, 1.0f);
    EXPECT_NEAR(media_transmittance(view, Vec3(0, 0, 0), Vec3(0, 1, 0), 10.0f, true).z,
                std::exp(-3.0f), 1e-5f);
    // Along x the solid ball takes 2 of the 10 units.
    EXPECT_NEAR(media_transmittance(view, Vec3(0, 0, 0), Vec3(1, 0, 0), 10.0f, true).y,
                std::exp(-0.2f * 8.0f), 1e-5f);
    // A floor lit from above: its light fades over the 4 units only with media_attenuation.
    Scene lit;
    Material floor;
    floor.color = Vec3(1.0f), floor.ambient = 0, floor.diffuse = 1;
    lit.add_shape("floor", Shape{ShapeKind::Box}, lit.add_material(floor),
                  Affine::scale(Vec3(4.0f, 0.5f, 4.0f)));
    lit.add_light(Light{Vec3(0, 4.5f, 0), Vec3(1.0f)});
    Medium clear_air = haze;
    clear_air.absorption = Vec3(0.05f);
    add_atmosphere(lit, clear_air);
    lit.camera.position = Vec3(0, 8, 0.01f);
    lit.camera.look_at = Vec3(0, 0, 0);
    lit.camera.fov_y_degrees = 10;
    const float plain = pixel(render(prepare_scene(lit), {}, 9, 9), 4, 4)[0];
    lit.lights[0].media_attenuation = true;
    const float faded = pixel(render(prepare_scene(lit), {}, 9, 9), 4, 4)[0];
    EXPECT_GT(plain, 0.1f);
    EXPECT_NEAR(faded / plain, std::exp(-0.05f * 4.0f), 1e-3f);
}

TEST(Media, AStepScattersTheLightsThatReachIt) {
    // A narrow spotlight's beam crosses the middle ray; seven more spotlights shine behind
    // the camera, where no step in view lies. Each step takes at most kMediaLights lights of
    // those whose light arrives there, so the beam is as bright as with its light alone.
    Medium mist;
    mist.scattering = Vec3(0.1f);
    mist.extinction = 0;
    Scene s;
    Material black;
    black.ambient = black.diffuse = 0;
    s.add_shape("room", Shape{ShapeKind::Sphere}, s.add_material(black),
                Affine::scale(Vec3(20.0f)));
    add_atmosphere(s, mist);
    Light spot{Vec3(0, 8, -8), Vec3(1.0f)};
    spot.type = LightType::Spot;
    spot.direction = Vec3(0, -1, 0);
    spot.spot_radius = 4, spot.spot_falloff = 5;
    s.add_light(spot);
    s.camera.position = Vec3(0, 0, 0);
    s.camera.look_at = Vec3(0, 0, -1);
    s.camera.fov_y_degrees = 30;
    const Frame alone = render(prepare_scene(s), {}, 33, 33);
    for (int i = 0; i < 7; ++i) {
        Light back = spot;
        back.position = Vec3(float(i) - 3.0f, 8.0f, 8.0f);
        s.add_light(back);
    }
    const Frame many = render(prepare_scene(s), {}, 33, 33);
    EXPECT_GT(pixel(alone, 16, 16)[0], 0.01f); // in the beam
    EXPECT_LT(pixel(alone, 2, 16)[0], 1e-6f);  // beside it
    for (int x = 0; x < 33; ++x)
        EXPECT_NEAR(pixel(many, x, 16)[0], pixel(alone, x, 16)[0], 1e-6f) << x;
}

TEST(Media, TheAtmosphereIsTheSameOnEveryAccelAndTheWavefront) {
    const PreparedScene scene = prepare_scene(test::atmosphere_scene());
    const Frame crsh = render(scene, {}, 48, 36);
    double sum = 0;
    for (float v : crsh.rgba) sum += v;
    EXPECT_GT(sum, 48 * 36 * 0.1);
    for (const test::SettingList& kv :
         {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}}}) {
        const Frame other = render(scene, kv, 48, 36);
        EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
            << kv[0].second;
    }
    const RenderSettings rs = test::settings_for(scene, {}, 48, 36);
    test::expect_same_frame(render_frame_cpu(scene, rs), render_frame_wavefront_cpu(scene, rs),
                            "atmosphere");
}

} // namespace
} // namespace sheaf

// The frame pipeline: exact accel modes agree byte for byte, frames are deterministic, the
// statistics add up, and a scene with a known answer renders to it.
#include "core/backend/backend.h"

#include "core/base/error.h"
#include "core/base/memory.h"
#include "core/scenes/builtin.h"
#include "core/scenes/shapes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace sheaf {
namespace {

Frame render(const PreparedScene& scene,
             std::initializer_list<std::pair<const char*, const char*>> kv) {
    Settings s;
    for (auto& [k, v] : kv) s.set(k, v);
    return render_frame(scene, RenderSettings::resolve(s, scene.settings));
}

bool same_image(const Frame& a, const Frame& b) {
    return a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * 4) == 0;
}

double mean(const Frame& f) {
    double m = 0;
    for (size_t i = 0; i < f.rgba.size(); i += 4) m += f.rgba[i] + f.rgba[i + 1] + f.rgba[i + 2];
    return m / double(f.rgba.size());
}

// A glass sphere and a mirror box over a floor: refraction, total internal reflection and
// reflection in one small scene.
PreparedScene glass_scene() {
    return prepare_scene(test::glass_mirror_scene());
}

// A frame whose per-sample arrays alone exceed what the machine has is refused before any of
// it is allocated, with the numbers (the system would otherwise stop the process part way).
TEST(Renderer, AFrameTooLargeForTheMachineIsRefusedAtOnce) {
    const int64_t available = available_memory_bytes();
    if (available == 0 || available > (int64_t(1) << 40))
        GTEST_SKIP() << "available memory unknown, or more than the 1 TB such a frame needs";
    try {
        render(glass_scene(),
               {{"width", "16384"}, {"height", "16384"}, {"aa.samples", "8"}, {"backend", "cpu"}});
        FAIL() << "a 16384x16384 frame with 8x8 samples rendered";
    } catch (const OutOfMemory& e) {
        EXPECT_NE(std::string(e.what()).find("a 16384x16384 frame with 8x8 samples per pixel "
                                             "needs at least"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Renderer, AccelModesGiveIdenticalImagesOnTheBuiltinScenes) {
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        const Frame brute = render(scene, {{"width", "40"}, {"height", "32"}, {"accel", "brute"}});
        const Frame rah = render(
            scene,
            {{"width", "40"}, {"height", "32"}, {"accel", "rah"}, {"cull.objects", "false"}});
        const Frame crsh = render(scene, {{"width", "40"}, {"height", "32"}});
        EXPECT_TRUE(same_image(brute, rah)) << name;
        EXPECT_TRUE(same_image(brute, crsh)) << name;
        EXPECT_GT(mean(crsh), 0.01) << name;
        // Same rays, whichever accel traced them.
        for (const char* k : {"rays.shadow", "rays.reflection", "rays.refraction"}) {
            EXPECT_EQ(brute.stats.get(k), crsh.stats.get(k)) << name << " " << k;
            EXPECT_EQ(rah.stats.get(k), crsh.stats.get(k)) << name << " " << k;
        }
        EXPECT_LT(crsh.stats.get("tests.total"), brute.stats.get("tests.total")) << name;
    }
}

TEST(Renderer, HashSortDepthAndArityNeverChangeThePicture) {
    const PreparedScene scene = glass_scene();
    const Frame ref =
        render(scene, {{"width", "48"}, {"height", "40"}, {"accel", "brute"}, {"ao.samples", "3"}});
    EXPECT_GT(ref.stats.get("rays.refraction"), 0);
    EXPECT_GT(ref.stats.get("rays.reflection"), 0);
    EXPECT_GT(ref.stats.get("rays.ao"), 0);
    const std::vector<std::vector<std::pair<const char*, const char*>>> variants = {
        {{"hash.mode", "crsh"}, {"sort.mode", "csd"}},
        {{"hash.mode", "hash32"}, {"sort.mode", "full"}},
        {{"hash.mode", "hash192"}, {"sort.mode", "csd"}},
        {{"hash.mode", "hash32"}, {"sort.algorithm", "bitonic"}},
        {{"hash.mode", "static1d"}},
        {{"cull.distance", "false"}},
        {{"cull.cluster", "0"}},
        {{"cull.cluster", "1"}},
        {{"cull.cluster", "5"}, {"hash.mode", "hash192"}},
        {{"hash.mode", "static3d"}, {"sort.algorithm", "bitonic"}},
        {{"hash.mode", "none"}, {"sort.mode", "none"}},
        {{"hierarchy.depth", "1"}, {"hierarchy.arity", "2"}},
        {{"hierarchy.depth", "4"}, {"hierarchy.arity", "5"}, {"cull.objects", "false"}},
        {{"traversal.batch", "1024"}},
        {{"threads", "1"}},
    };
    for (const auto& v : variants) {
        Settings s;
        s.set("width", "48"), s.set("height", "40"), s.set("ao.samples", "3");
        for (auto& [k, val] : v) s.set(k, val);
        const Frame f = render_frame(scene, RenderSettings::resolve(s));
        EXPECT_TRUE(same_image(ref, f)) << v[0].first << "=" << v[0].second;
    }
}

TEST(Renderer, FramesAreDeterministic) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    const Frame a = render(scene, {{"width", "32"}, {"height", "32"}});
    const Frame b = render(scene, {{"width", "32"}, {"height", "32"}});
    EXPECT_TRUE(same_image(a, b));
    for (const auto& [k, v] : a.stats.entries())
        if (k.rfind("time_ms.", 0) != 0 && k.rfind("memory.", 0) != 0)
            EXPECT_EQ(v, b.stats.get(k)) << k;
}

TEST(Renderer, AFrameKeepsOnlyThePassesAskedFor) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    const Frame all = render(scene, {{"width", "40"}, {"height", "30"}, {"ao.samples", "2"}});
    const Frame some = render(scene, {{"width", "40"},
                                      {"height", "30"},
                                      {"ao.samples", "2"},
                                      {"output.passes", "combined,tests"}});
    EXPECT_EQ(some.rgba, all.rgba);
    EXPECT_EQ(some.tests, all.tests);
    EXPECT_TRUE(some.depth.empty() && some.normal.empty() && some.albedo.empty() &&
                some.object_id.empty());
    EXPECT_TRUE(frame_has_pass(some, "combined"));
    EXPECT_FALSE(frame_has_pass(some, "depth"));
    for (const auto& [k, v] : all.stats.entries()) // the same work: every count
        if (k.rfind("time_ms.", 0) != 0 && k.rfind("memory.", 0) != 0)
            EXPECT_EQ(v, some.stats.get(k)) << k;

    const Frame depth =
        render(scene, {{"width", "40"}, {"height", "30"}, {"output.passes", "depth,object_id"}});
    EXPECT_TRUE(depth.rgba.empty() && depth.tests.empty());
    EXPECT_EQ(depth.depth, all.depth);
    EXPECT_EQ(depth.object_id, all.object_id);
}

// Under crsh a ray type's total is its hierarchy levels plus its exact tests; under bvh (the
// default), its box tests plus its exact tests.
void expect_statistics_add_up(const PreparedScene& scene, const char* accel) {
    SCOPED_TRACE(accel);
    const bool crsh = std::string(accel) == "crsh";
    const Frame f = render(scene, {{"width", "32"}, {"height", "32"}, {"accel", accel}});
    const Stats& st = f.stats;
    // The scene asks for two bounces: two reflection rays for every pixel that sees a mirror.
    EXPECT_EQ(st.get("rays.primary"), 32.0 * 32.0);
    EXPECT_GT(st.get("rays.reflection"), 32.0 * 32.0);
    EXPECT_LE(st.get("rays.reflection"), 2 * 32.0 * 32.0);
    double total = 0, brute = 0;
    for (const char* t : {"shadow", "reflection", "refraction", "ao"}) {
        const std::string p = std::string("tests.") + t + ".";
        total += st.get(p + "total");
        brute += st.get(p + "brute_force");
        EXPECT_EQ(st.get(p + "brute_force"),
                  st.get(std::string("rays.") + t) * st.get("scene.primitives"));
        if (st.get(std::string("rays.") + t) == 0) continue;
        const double walk = crsh ? st.get(p + "level2.tests") + st.get(p + "level1.tests")
                                 : st.get(p + "nodes.tests");
        EXPECT_GT(walk, 0) << t;
        EXPECT_EQ(st.get(p + "total"), walk + st.get(p + "final.tests"));
    }
    EXPECT_EQ(st.get("tests.total"), total);
    // The per-pixel pass holds every exact test once.
    double pass = 0, finals = 0;
    for (uint32_t v : f.tests) pass += v;
    for (const char* t : {"shadow", "reflection", "refraction", "ao"})
        finals += st.get(std::string("tests.") + t + ".final.tests");
    EXPECT_EQ(pass, finals);
    EXPECT_GT(pass, 0);
    EXPECT_EQ(st.get("tests.brute_force"), brute);
    EXPECT_GT(st.get("memory.peak_bytes"), 0);
    EXPECT_GT(st.get("time_ms.frame"), 0);
    EXPECT_GE(st.get("time_ms.frame"), st.get("time_ms.traversal"));
    const std::string row = crsh ? "level2" : "nodes";
    EXPECT_NE(st.to_json().find("\"tests.shadow." + row + ".tests\""), std::string::npos);
    EXPECT_NE(st.to_table().find(crsh ? "  level 2 " : "  nodes "), std::string::npos);
    EXPECT_EQ(st.to_table().find("top nodes") != std::string::npos, crsh);
}

TEST(Renderer, StatisticsAddUp) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    expect_statistics_add_up(scene, "bvh");
    expect_statistics_add_up(scene, "crsh");
}

// A quad facing the camera, a light on the view axis: the centre pixel receives ambient +
// diffuse (cos = 1) and no specular, 0.7 of the colour (0.5, 0.25, 1).
Scene lit_quad() {
    Scene s;
    Material m;
    m.color = Vec3(0.5f, 0.25f, 1.0f), m.ambient = 0.1f, m.diffuse = 0.6f;
    s.add_mesh_object("quad", make_box(Vec3(-2, -2, -0.1f), Vec3(2, 2, 0)), s.add_material(m));
    s.add_light(Light{Vec3(0, 0, 3), Vec3(1.0f)});
    s.camera.position = Vec3(0, 0, 5), s.camera.look_at = Vec3(0, 0, 0);
    return s;
}

TEST(Renderer, ALitQuadHasTheAnalyticRadiance) {
    const PreparedScene scene = prepare_scene(lit_quad());
    const Frame f = render(scene, {{"width", "33"}, {"height", "33"}});
    const size_t c = (16 * 33 + 16) * 4;
    EXPECT_NEAR(f.rgba[c + 0], 0.5f * 0.7f, 1e-4f);
    EXPECT_NEAR(f.rgba[c + 1], 0.25f * 0.7f, 1e-4f);
    EXPECT_NEAR(f.rgba[c + 2], 1.0f * 0.7f, 1e-4f);
    EXPECT_NEAR(f.depth[16 * 33 + 16], 5.0f, 1e-4f);
    EXPECT_NEAR(f.normal[16 * 33 + 16].z, 1.0f, 1e-5f);
    // The corner sees the background (black).
    EXPECT_EQ(f.rgba[0], 0.0f);
}

TEST(Renderer, RadiosityInAFurnaceIsTheDiffuseColourTimesTheEmission) {
    // A box lit only by the inside of an enclosure that emits 1 everywhere: every gather ray
    // finds radiance 1, so the box's face shows colour x diffuse x brightness (POV-Ray's
    // radiosity gives the same), whatever the number of rays or the depth.
    Scene s;
    Material wall;
    wall.color = Vec3(1.0f), wall.emission = Vec3(1.0f), wall.diffuse = 0, wall.ambient = 0;
    Material box;
    box.color = Vec3(0.5f, 0.25f, 1.0f), box.ambient = 0.3f, box.diffuse = 0.6f;
    s.add_mesh_object("enclosure", make_box(Vec3(-10), Vec3(10)), s.add_material(wall));
    s.add_mesh_object("box", make_box(Vec3(-2, -2, -0.1f), Vec3(2, 2, 0)), s.add_material(box));
    s.camera.position = Vec3(0, 0, 5), s.camera.look_at = Vec3(0, 0, 0);
    const PreparedScene scene = prepare_scene(s);
    const size_t c = (8 * 17 + 8) * 4;
    for (const char* n : {"1", "7"})
        for (const char* depth : {"1", "3"}) {
            const Frame f = render(scene, {{"width", "17"},
                                           {"height", "17"},
                                           {"radiosity.samples", n},
                                           {"radiosity.depth", depth},
                                           {"radiosity.brightness", "0.5"}});
            // The ambient term stays: the scene reader drops it where POV-Ray does.
            EXPECT_NEAR(f.rgba[c + 0], 0.5f * (0.6f * 0.5f + 0.3f), 1e-5f) << n << " " << depth;
            EXPECT_NEAR(f.rgba[c + 1], 0.25f * (0.6f * 0.5f + 0.3f), 1e-5f);
            EXPECT_NEAR(f.rgba[c + 2], 1.0f * (0.6f * 0.5f + 0.3f), 1e-5f);
            // n rays from each pixel that sees the box; the enclosure has no diffuse to gather.
            double box_pixels = 0;
            for (uint32_t id : f.object_id) box_pixels += id == 1;
            EXPECT_EQ(f.stats.get("rays.diffuse"), box_pixels * std::atoi(n));
        }
    const Frame off = render(scene, {{"width", "17"}, {"height", "17"}});
    EXPECT_NEAR(off.rgba[c + 0], 0.5f * 0.3f, 1e-6f);
    EXPECT_EQ(off.stats.get("rays.diffuse"), 0);
}

TEST(Renderer, RadiosityBringsTheColourOfNearbyWalls) {
    // A white floor beside a red wall under one light: with radiosity the floor near the wall
    // turns red (more red than green), and a second bounce adds light.
    Scene s;
    Material white, red;
    white.color = Vec3(0.8f), white.ambient = 0;
    red.color = Vec3(0.9f, 0.05f, 0.05f), red.ambient = 0;
    s.add_mesh_object("floor", make_box(Vec3(-3, -1.1f, -3), Vec3(3, -1, 3)),
                      s.add_material(white));
    s.add_mesh_object("wall", make_box(Vec3(-3.1f, -1, -3), Vec3(-3, 3, 3)), s.add_material(red));
    s.add_light(Light{Vec3(0, 4, 2), Vec3(1.0f)});
    s.camera.position = Vec3(0, 2, 6), s.camera.look_at = Vec3(-1, -1, 0);
    const PreparedScene scene = prepare_scene(s);
    auto floor_tint = [&](const Frame& f) {
        double r = 0, g = 0;
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
                if (f.object_id[size_t(y) * f.width + x] == 0) { // the floor
                    r += f.rgba[(size_t(y) * f.width + x) * 4 + 0];
                    g += f.rgba[(size_t(y) * f.width + x) * 4 + 1];
                }
        return std::make_pair(r, g);
    };
    const auto [r0, g0] = floor_tint(render(scene, {{"width", "48"}, {"height", "36"}}));
    EXPECT_NEAR(r0, g0, 1e-3 * r0); // a white floor under a white light
    const auto [r1, g1] = floor_tint(render(scene, {{"width", "48"},
                                                    {"height", "36"},
                                                    {"radiosity.samples", "16"},
                                                    {"radiosity.depth", "1"}}));
    EXPECT_GT(r1, g1 * 1.02);
    EXPECT_GT(g1, g0); // the wall reflects a little green too
    const auto [r2, g2] = floor_tint(render(scene, {{"width", "48"},
                                                    {"height", "36"},
                                                    {"radiosity.samples", "16"},
                                                    {"radiosity.depth", "2"}}));
    EXPECT_GT(r2, r1);
}

TEST(Renderer, AWorkingGammaDecodesTheAveragedPixel) {
    // The lit quad in a gamma-2.2 working space (POV-Ray's assumed_gamma 2.2): the same
    // computation, then light = value^2.2, after the anti-aliasing average.
    Scene s = lit_quad();
    s.background = Vec3(0.5f, 0, 2);
    s.working_gamma = 2.2f;
    const Frame f = render(prepare_scene(s), {{"width", "33"}, {"height", "33"}});
    const size_t c = (16 * 33 + 16) * 4;
    EXPECT_NEAR(f.rgba[c + 0], std::pow(0.5f * 0.7f, 2.2f), 1e-5f);
    EXPECT_NEAR(f.rgba[c + 1], std::pow(0.25f * 0.7f, 2.2f), 1e-5f);
    EXPECT_NEAR(f.rgba[c + 2], std::pow(1.0f * 0.7f, 2.2f), 1e-5f);
    EXPECT_NEAR(f.rgba[0], std::pow(0.5f, 2.2f), 1e-6f); // the background
    EXPECT_EQ(f.rgba[1], 0.0f);
    EXPECT_NEAR(f.rgba[2], std::pow(2.0f, 2.2f), 1e-5f); // above 1 too, as light
    s.working_gamma = 0;
    EXPECT_THROW(prepare_scene(s), SceneError);
}

// The quad of the analytic test under other lights: the centre pixel's radiance.
Vec3 centre_radiance(const Light& light, const Material& m, bool occluder = false) {
    Scene s;
    s.add_mesh_object("quad", make_box(Vec3(-2, -2, -0.1f), Vec3(2, 2, 0)), s.add_material(m));
    // Halfway to a light at (3, 0, 1.5), outside the orthographic view of the centre.
    if (occluder)
        s.add_mesh_object("occluder", make_box(Vec3(1.4f, -0.1f, 0.7f), Vec3(1.6f, 0.1f, 0.8f)), 0);
    s.add_light(light);
    s.camera.position = Vec3(0, 0, 5), s.camera.look_at = Vec3(0, 0, 0);
    s.camera.projection = Projection::Orthographic,
    s.camera.ortho_height = 0.5f; // no occluder in view
    const Frame f = render(prepare_scene(s), {{"width", "33"}, {"height", "33"}});
    const size_t c = (16 * 33 + 16) * 4;
    return Vec3(f.rgba[c], f.rgba[c + 1], f.rgba[c + 2]);
}

TEST(Renderer, LightTypesFollowTheirFormulas) {
    Material m;
    m.color = Vec3(1.0f), m.ambient = 0.1f, m.diffuse = 0.6f;
    Light parallel;
    parallel.type = LightType::Parallel;
    parallel.direction = Vec3(0, -1, -1); // 45 degrees to the quad's normal
    EXPECT_NEAR(centre_radiance(parallel, m).x, 0.1f + 0.6f * std::sqrt(0.5f), 1e-4f);

    Light spot{Vec3(0, 0, 3), Vec3(1.0f)};
    spot.type = LightType::Spot;
    spot.direction = Vec3(0, 0, -1);
    spot.spot_radius = 10, spot.spot_falloff = 20;
    EXPECT_NEAR(centre_radiance(spot, m).x, 0.7f, 1e-4f); // on the axis: full
    spot.direction = Vec3(1, 0, -1);                      // 45 degrees away: outside the falloff
    EXPECT_NEAR(centre_radiance(spot, m).x, 0.1f, 1e-4f);
    // 15 degrees away, between the cosines of radius and falloff: POV-Ray's cubic of t.
    spot.direction = Vec3(std::tan(15 * kPi / 180), 0, -1);
    const double cr = std::cos(10 * kPi / 180), cf = std::cos(20 * kPi / 180);
    const double t = (std::cos(15 * kPi / 180) - cf) / (cr - cf);
    EXPECT_NEAR(centre_radiance(spot, m).x, 0.1f + 0.6f * (3 - 2 * t) * t * t, 1e-3f);
    // A radius of 90 degrees or more is no cone: only cos^tightness (POV-Ray's radius -90
    // falloff 90 tightness 1, a cosine falloff), and nothing behind the light.
    spot.spot_radius = 90, spot.spot_falloff = 90, spot.spot_tightness = 1;
    spot.direction = Vec3(std::tan(60 * kPi / 180), 0, -1);
    EXPECT_NEAR(centre_radiance(spot, m).x, 0.1f + 0.6f * 0.5f, 1e-3f);

    Light faded{Vec3(0, 0, 3), Vec3(1.0f)};
    faded.fade_distance = 3, faded.fade_power = 2; // at d = 3: 2 / (1 + 1) = 1
    EXPECT_NEAR(centre_radiance(faded, m).x, 0.7f, 1e-4f);
    faded.fade_distance = 1.5f; // 2 / (1 + 4)
    EXPECT_NEAR(centre_radiance(faded, m).x, 0.1f + 0.6f * 0.4f, 1e-4f);

    Light point{Vec3(3, 0, 1.5f), Vec3(1.0f)};
    const float lit = 0.1f + 0.6f * 1.5f / std::sqrt(9.0f + 2.25f);
    EXPECT_NEAR(centre_radiance(point, m, false).x, lit, 1e-4f);
    EXPECT_NEAR(centre_radiance(point, m, true).x, 0.1f, 1e-4f); // shadowed by the occluder
    point.shadowless = true;
    EXPECT_NEAR(centre_radiance(point, m, true).x, lit, 1e-4f);
    // A light without highlights (POV-Ray's shadowless lights) gives diffuse light only: the
    // light straight above the centre reflects straight back into the camera.
    Material shiny = m;
    shiny.specular = 0.5f, shiny.phong_exponent = 40, shiny.blinn = 0.3f;
    Light above{Vec3(0, 0, 3), Vec3(1.0f)};
    EXPECT_NEAR(centre_radiance(above, shiny).x, 0.7f + 0.5f + 0.3f, 1e-3f);
    above.shadowless = true; // a shadowless light still has its highlights
    EXPECT_NEAR(centre_radiance(above, shiny).x, 0.7f + 0.5f + 0.3f, 1e-3f);
    above.highlights = false;
    EXPECT_NEAR(centre_radiance(above, shiny).x, 0.7f, 1e-4f);
    above.shadowless = false; // also when it casts shadows
    EXPECT_NEAR(centre_radiance(above, shiny).x, 0.7f, 1e-4f);

    Material glow = m;
    glow.emission = Vec3(0.25f, 0, 0);
    EXPECT_NEAR(centre_radiance(Light{Vec3(0, 0, 3), Vec3(1.0f)}, glow).x, 0.95f, 1e-4f);
}

TEST(Renderer, IridescenceFollowsItsFormula) {
    // Light and view along the normal: the phase is 2 pi thickness (1 + 1), and each channel's
    // direct light is scaled by 1 + irid cos(phase / wavelength); ambient is not.
    Material m;
    m.color = Vec3(1.0f), m.ambient = 0.1f, m.diffuse = 0.6f;
    m.irid = 0.5f, m.irid_thickness = 0.3f;
    const Vec3 c = centre_radiance(Light{Vec3(0, 0, 3), Vec3(1.0f)}, m);
    const float phase = 2 * kPi * 0.3f * 2;
    const float wl[3] = {0.25f, 0.18f, 0.14f};
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(c[i], 0.1f + 0.6f * (1 + 0.5f * std::cos(phase / wl[i])), 1e-4f) << i;
    // No irid, no change; the wavelengths are the material's.
    m.irid_wavelength = Vec3(0.3f);
    const Vec3 grey = centre_radiance(Light{Vec3(0, 0, 3), Vec3(1.0f)}, m);
    EXPECT_NEAR(grey.x, grey.z, 1e-6f);
    m.irid = 0;
    EXPECT_NEAR(centre_radiance(Light{Vec3(0, 0, 3), Vec3(1.0f)}, m).y, 0.7f, 1e-4f);
    // What a mirror reflects is tinted the same way: a black mirror facing an emitting quad.
    Material mirror;
    mirror.color = Vec3(0.0f), mirror.ambient = 0, mirror.diffuse = 0, mirror.mirror = 1;
    mirror.irid = 0.5f, mirror.irid_thickness = 0.3f;
    Material glow;
    glow.color = Vec3(0.0f), glow.ambient = 0, glow.diffuse = 0, glow.emission = Vec3(0.5f);
    Scene s;
    s.add_mesh_object("mirror", make_box(Vec3(-2, -2, -0.1f), Vec3(2, 2, 0)),
                      s.add_material(mirror));
    s.add_mesh_object("sky", make_box(Vec3(-50, -50, 20), Vec3(50, 50, 20.1f)),
                      s.add_material(glow));
    s.camera.position = Vec3(0, 0, 5), s.camera.look_at = Vec3(0, 0, 0);
    s.camera.projection = Projection::Orthographic, s.camera.ortho_height = 0.5f;
    const Frame f = render(prepare_scene(s), {{"width", "33"}, {"height", "33"}});
    const size_t centre = (16 * 33 + 16) * 4;
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(f.rgba[centre + size_t(i)], 0.5f * (1 + 0.5f * std::cos(phase / wl[i])), 1e-4f)
            << i;
}

TEST(Renderer, SpotAndParallelLightsKeepTheAccelModesIdentical) {
    Scene s;
    Material floor;
    const uint32_t mf = s.add_material(floor);
    s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), mf);
    s.add_mesh_object("ball", make_uv_sphere(Vec3(0, 0, 0), 1.0f, 10, 20), mf);
    Light spot{Vec3(2, 4, 2), Vec3(0.7f)};
    spot.type = LightType::Spot, spot.direction = Vec3(-2, -4, -2), spot.spot_radius = 15,
    spot.spot_falloff = 30;
    Light sun;
    sun.type = LightType::Parallel, sun.direction = Vec3(1, -2, 0.5f), sun.color = Vec3(0.5f);
    s.add_light(spot);
    s.add_light(sun);
    s.camera.position = Vec3(0, 2, 6);
    const PreparedScene scene = prepare_scene(s);
    const Frame brute = render(scene, {{"width", "40"}, {"height", "30"}, {"accel", "brute"}});
    const Frame crsh = render(scene, {{"width", "40"}, {"height", "30"}});
    EXPECT_TRUE(same_image(brute, crsh));
    EXPECT_GT(crsh.stats.get("rays.shadow"), 0);
}

TEST(Renderer, AntiAliasingKeepsTheImageSize) {
    const PreparedScene scene = glass_scene();
    const Frame f = render(scene, {{"width", "20"}, {"height", "10"}, {"aa.samples", "3"}});
    EXPECT_EQ(f.width, 20);
    EXPECT_EQ(f.height, 10);
    EXPECT_EQ(f.rgba.size(), 20u * 10u * 4u);
    EXPECT_EQ(f.stats.get("rays.primary"), 20.0 * 10.0 * 9.0);
}

TEST(Renderer, ProgressCanCancel) {
    const PreparedScene scene = glass_scene();
    RenderSettings s;
    s.width = s.height = 16;
    int calls = 0;
    EXPECT_THROW(render_frame(scene, s, [&](float) { return ++calls < 2; }), RenderError);
    EXPECT_EQ(calls, 2);
    float last = 0;
    render_frame(scene, s, [&](float done) {
        EXPECT_GE(done, last);
        last = done;
        return true;
    });
    EXPECT_FLOAT_EQ(last, 1.0f);
}

TEST(Renderer, CudaBackendIsAClearErrorInThisBuild) {
    const PreparedScene scene = glass_scene();
    RenderSettings s;
    s.width = s.height = 8;
    s.backend = Backend::Cuda;
    try {
        render_frame(scene, s);
        FAIL() << "expected an error";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("cuda"), std::string::npos);
    }
}

// Rays leaving a surface are offset by the objects' extent, not the lights': a light 5,000
// units away must not make rays through a clear box skip the red floor 0.001 below its top
// (POV-Ray's media3.pov went black so).
TEST(Renderer, AFarLightDoesNotPushRaysPastCloseSurfaces) {
    Scene s;
    Material clear;
    clear.ambient = clear.diffuse = 0, clear.transmission = 1, clear.ior = 1;
    clear.fresnel_split = false;
    s.add_shape("clear", Shape{ShapeKind::Box}, s.add_material(clear),
                Affine::translate(Vec3(0, -0.4995f, 0)) * Affine::scale(Vec3(2, 0.5005f, 2)));
    Material red;
    red.color = Vec3(1, 0, 0);
    s.add_shape("floor", Shape{ShapeKind::Box}, s.add_material(red),
                Affine::translate(Vec3(0, -0.5f, 0)) * Affine::scale(Vec3(1, 0.5f, 1)));
    s.add_light(Light{Vec3(3000, 3000, -3000), Vec3(1.0f)});
    s.camera.position = Vec3(0, 3, -3);
    s.camera.look_at = Vec3(0, 0, 0);
    Settings st;
    st.set("width", "16"), st.set("height", "16");
    const Frame f = render_frame(prepare_scene(s), RenderSettings::resolve(st, {}));
    const float* centre = &f.rgba[4 * (8 * 16 + 8)];
    EXPECT_GT(centre[0], 0.3f);
    EXPECT_LT(centre[1], 0.01f);
}

} // namespace
} // namespace sheaf

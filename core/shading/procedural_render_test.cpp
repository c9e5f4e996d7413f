// Procedural textures, object flags, fog and sky through the whole pipeline: the exact accel
// modes still agree byte for byte, no_shadow objects cast no shadow, no_image objects are not
// seen but still shade, fog and sky colour what they should, inside materials show from inside.
#include "core/backend/backend.h"

#include "core/base/error.h"
#include "core/scenes/shapes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace sheaf {
namespace {

Frame render(const PreparedScene& scene,
             std::initializer_list<std::pair<const char*, const char*>> kv) {
    Settings s;
    s.set("width", "40"), s.set("height", "32");
    for (auto& [k, v] : kv) s.set(k, v);
    return render_frame(scene, RenderSettings::resolve(s, scene.settings));
}

double mean(const Frame& f) {
    double m = 0;
    for (size_t i = 0; i < f.rgba.size(); i += 4) m += f.rgba[i] + f.rgba[i + 1] + f.rgba[i + 2];
    return m / double(f.rgba.size());
}

void expect_color_near(Vec3 got, Vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-5);
    EXPECT_NEAR(got.y, want.y, 1e-5);
    EXPECT_NEAR(got.z, want.z, 1e-5);
}

bool same_image(const Frame& a, const Frame& b) {
    return a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * 4) == 0;
}

Vec3 pixel(const Frame& f, int x, int y) {
    const float* p = &f.rgba[4 * (size_t(y) * f.width + x)];
    return Vec3(p[0], p[1], p[2]);
}

TEST(ProceduralRender, AccelModesStayIdentical) {
    // Every procedural feature at once (patterned, layered and transmitting pigments, a normal,
    // variable and Fresnel reflection, a texture map, flags, fog and sky).
    const PreparedScene scene = prepare_scene(test::procedural_scene());
    const Frame brute = render(scene, {{"accel", "brute"}, {"ao.samples", "2"}});
    EXPECT_GT(brute.stats.get("rays.refraction"), 0);
    EXPECT_GT(brute.stats.get("rays.reflection"), 0);
    for (const auto& v : std::vector<std::pair<const char*, const char*>>{
             {"accel", "rah"}, {"accel", "crsh"}, {"hash.mode", "hash192"}}) {
        Settings s;
        s.set("width", "40"), s.set("height", "32"), s.set("ao.samples", "2");
        s.set(v.first, v.second);
        const Frame f = render_frame(scene, RenderSettings::resolve(s, scene.settings));
        EXPECT_TRUE(same_image(brute, f)) << v.first << "=" << v.second;
    }
}

// A floor under a light with a box between them, seen from above at a slant: the box's
// shadow darkens the picture unless the box has no_shadow.
double shadow_scene_mean(uint8_t flags) {
    Scene s;
    Material m;
    const uint32_t mat = s.add_material(m);
    s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), mat);
    const uint32_t box =
        s.add_mesh_object("box", make_box(Vec3(-0.5f, 1, -0.5f), Vec3(0.5f, 1.2f, 0.5f)), mat);
    s.objects[box].flags = flags;
    s.add_light(Light{Vec3(0, 5, 0), Vec3(1.0f)});
    s.camera.position = Vec3(0, 4, 6);
    s.camera.look_at = Vec3(0, -1, 0);
    return mean(render(prepare_scene(s), {}));
}

TEST(ProceduralRender, NoShadowObjectsCastNoShadow) {
    const double shadowed = shadow_scene_mean(0), lit = shadow_scene_mean(kNoShadow);
    EXPECT_GT(lit, shadowed * 1.02) << lit << " vs " << shadowed;
    EXPECT_EQ(shadow_scene_mean(kNoReflection), shadowed); // no mirrors here: no change
}

TEST(ProceduralRender, NoImageObjectsAreNotSeenButShadow) {
    auto scene = [](bool ball) {
        Scene s;
        Material m;
        const uint32_t mat = s.add_material(m);
        s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), mat);
        if (ball) {
            const uint32_t id = s.add_shape("ball", Shape{ShapeKind::Sphere}, mat);
            s.shape_objects[id].flags = kNoImage;
        }
        s.add_light(Light{Vec3(0, 5, 0), Vec3(1.0f)});
        s.camera.position = Vec3(0, 4, 6);
        s.camera.look_at = Vec3(0, -1, 0);
        return prepare_scene(s);
    };
    const Frame with = render(scene(true), {}), without = render(scene(false), {});
    for (uint32_t id : with.object_id) EXPECT_NE(id, 1u) << "the no_image ball is seen";
    EXPECT_LT(mean(with), mean(without) * 0.99); // but its shadow is on the floor
}

TEST(ProceduralRender, FogAndSkyColourWhatTheyShould) {
    Scene s;
    Material m;
    m.color = Vec3(1, 0, 0);
    const uint32_t mat = s.add_material(m);
    s.add_shape("ball", Shape{ShapeKind::Sphere}, mat);
    s.add_light(Light{Vec3(0, 5, 5), Vec3(1.0f)});
    s.camera.position = Vec3(0, 0, 6);
    s.camera.look_at = Vec3(0, 0, 0);
    s.background = Vec3(0, 1, 0);
    const Vec3 clear_ball = pixel(render(prepare_scene(s), {}), 20, 16);
    const Vec3 clear_sky = pixel(render(prepare_scene(s), {}), 1, 1);
    EXPECT_NEAR(clear_sky.y, 1.0f, 1e-6);
    s.fog.count = 1;
    s.fog.layer[0].distance = 5, s.fog.layer[0].color = Vec3(0, 0, 1);
    const Frame fog = render(prepare_scene(s), {});
    const Vec3 ball = pixel(fog, 20, 16), sky = pixel(fog, 1, 1);
    EXPECT_LT(ball.x, clear_ball.x * 0.5f); // 5 units of fog keep exp(-1) of the surface
    EXPECT_GT(ball.z, 0.5f);
    EXPECT_NEAR(sky.z, 1.0f, 1e-5); // infinitely far: all fog
    EXPECT_NEAR(sky.y, 0.0f, 1e-5);
    s.fog.count = 0;
    Pigment sky_pigment;
    sky_pigment.color[0] = 0.3f; // solid
    s.pigments.push_back(sky_pigment);
    s.sky = 0;
    EXPECT_NEAR(pixel(render(prepare_scene(s), {}), 1, 1).x, 0.3f, 1e-6);
}

TEST(ProceduralRender, InsideMaterialsShowFromInside) {
    // A red ball and a red box, blue inside (POV-Ray's interior_texture); ambient light only.
    Scene s;
    Material red, blue;
    red.color = Vec3(1, 0, 0), blue.color = Vec3(0, 0, 1);
    red.ambient = blue.ambient = 1, red.diffuse = blue.diffuse = 0;
    red.inside = int32_t(s.add_material(blue));
    const uint32_t mat = s.add_material(red);
    s.add_shape("ball", Shape{ShapeKind::Sphere}, mat);
    s.add_mesh_object("box", make_box(Vec3(4, -1, -1), Vec3(6, 1, 1)), mat);
    s.camera.position = Vec3(0, 0, 6);
    s.camera.look_at = Vec3(0, 0, 0);
    expect_color_near(pixel(render(prepare_scene(s), {}), 20, 16), Vec3(1, 0, 0));
    s.camera.position = Vec3(0, 0, 0.5f); // inside the ball
    expect_color_near(pixel(render(prepare_scene(s), {}), 20, 16), Vec3(0, 0, 1));
    s.camera.position = Vec3(5, 0, 0.5f), s.camera.look_at = Vec3(5, 0, -1); // inside the box
    expect_color_near(pixel(render(prepare_scene(s), {}), 20, 16), Vec3(0, 0, 1));
    // An inside material is one without an inside of its own.
    s.materials[0].inside = 1;
    EXPECT_THROW(s.validate(), SceneError);
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// A floor (material 0) lit from straight above by a light at y = 6, seen from the side with
// no bounces; a test adds what stands between (its materials after the floor's).
Scene lit_floor() {
    Scene s;
    s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)),
                      s.add_material(Material{}));
    s.add_light(Light{Vec3(0, 6, 0), Vec3(1.0f)});
    s.camera.position = Vec3(0, 0, 6); // below y = 1: what stands there hides little floor
    s.camera.look_at = Vec3(0, -1, 0);
    s.settings["trace.depth"] = "0";
    return s;
}

// Material m with a white pigment that transmits `transmit`, lit as POV-Ray's finishes are
// (reflection from the finish only), added to s.
uint32_t white_glass(Scene& s, Material m, float transmit) {
    Pigment pg;
    pg.color[0] = pg.color[1] = pg.color[2] = 1, pg.color[4] = transmit;
    s.pigments.push_back(pg);
    m.pigment = int32_t(s.pigments.size() - 1);
    m.fresnel_split = false;
    return s.add_material(m);
}

// The floor right under the light (the look_at point) at 41 x 31, under crsh and brute, which
// must give the same picture.
Vec3 floor_under(const Scene& s) {
    const PreparedScene p = prepare_scene(s);
    const Frame f = render(p, {{"width", "41"}, {"height", "31"}});
    const Frame brute = render(p, {{"width", "41"}, {"height", "31"}, {"accel", "brute"}});
    EXPECT_TRUE(same_image(f, brute));
    return pixel(f, 20, 15);
}

// A sphere between a light and a floor: opaque, it casts a full shadow; with a pigment that
// transmits half the light, the shadow keeps half of it for each surface the shadow ray
// crosses (POV-Ray's filtered shadows: two surfaces, a quarter).
TEST(ProceduralRender, TransparentSurfacesFilterShadows) {
    auto floor_under_ball = [](float transmit, float filter) {
        Scene s = lit_floor();
        Material ball;
        ball.color = Vec3(1, 0.5f, 0.25f);
        Pigment pg;
        pg.color[0] = 1, pg.color[1] = 0.5f, pg.color[2] = 0.25f, pg.color[3] = filter,
        pg.color[4] = transmit;
        s.pigments.push_back(pg);
        ball.pigment = 0;
        ball.fresnel_split = false;
        s.add_shape("ball", Shape{ShapeKind::Sphere}, s.add_material(ball),
                    Affine::translate(Vec3(0, 1, 0)));
        return floor_under(s);
    };
    const Vec3 opaque = floor_under_ball(0, 0), half = floor_under_ball(0.5f, 0);
    const Vec3 filtered = floor_under_ball(0, 1);
    const Vec3 clear = floor_under_ball(1, 0);
    EXPECT_GT(half.x, opaque.x);
    EXPECT_GT(clear.x, half.x);
    // Direct light on the floor scales by 0.25 (two crossings at 0.5); the ambient term stays.
    const float ambient = opaque.x;
    EXPECT_NEAR((half.x - ambient) / (clear.x - ambient), 0.25f, 0.01f);
    // A filter tints by the colour at each crossing: green 0.5^2, blue 0.25^2 of the light.
    EXPECT_NEAR((filtered.y - ambient) / (clear.y - ambient), 0.25f, 0.01f);
    EXPECT_NEAR((filtered.z - ambient) / (clear.z - ambient), 0.0625f, 0.01f);
}

// POV-Ray's fake caustics: each surface a shadow ray crosses multiplies the light by
// 1 + |n.d|^caustics. Right under a clear ball (or slab) lit from straight above, both
// crossings meet the surface head-on, so the floor gets 4 times the direct light; the gain
// follows the shading normal a normal pattern tilts, and meshes and solids agree.
TEST(ProceduralRender, FakeCausticsBrightenLightThroughGlass) {
    auto floor_under_glass = [](bool slab, float caustics, bool bumpy, float transmit) {
        Scene s = lit_floor();
        Material glass;
        glass.caustics = caustics;
        if (bumpy) {
            Pattern bumps;
            bumps.kind = PatternKind::Bozo;
            bumps.to_pattern = Affine::scale(Vec3(7));
            s.normal_patterns.push_back({bumps, 1.0f});
            glass.normal = 0;
        }
        const uint32_t mg = white_glass(s, glass, transmit);
        if (slab) // off centre, so that the shadow ray misses the faces' diagonals
            s.add_mesh_object("slab", make_box(Vec3(-1, 0.9f, -0.7f), Vec3(1.3f, 1.1f, 1)), mg);
        else
            s.add_shape("ball", Shape{ShapeKind::Sphere}, mg, Affine::translate(Vec3(0, 1, 0)));
        return floor_under(s);
    };
    for (const bool slab : {false, true}) {
        const float ambient = floor_under_glass(slab, 0, false, 0).x; // opaque: ambient only
        const float clear = floor_under_glass(slab, 0, false, 1).x - ambient;
        ASSERT_GT(clear, 0.0f);
        EXPECT_NEAR((floor_under_glass(slab, 45, false, 1).x - ambient) / clear, 4.0f, 0.02f)
            << (slab ? "slab" : "ball");
        // Half the light through each surface, doubled by each: as bright as without glass.
        EXPECT_NEAR((floor_under_glass(slab, 45, false, 0.5f).x - ambient) / clear, 1.0f, 0.01f);
        // Bumps tilt the normal away from the ray: less gain than head-on, still some.
        const float bumpy = (floor_under_glass(slab, 45, true, 1).x - ambient) / clear;
        EXPECT_LT(bumpy, 3.9f) << (slab ? "slab" : "ball");
        EXPECT_GT(bumpy, 1.0f);
    }
}

// A transparent `inverse` sphere with a fading interior: its spans start or end at no
// surface (everything outside the ball is inside the solid). Shadow rays crossing it fade by
// the interior of the surface they do cross, and nothing reads the missing surface's material.
TEST(ProceduralRender, ShadowsThroughAnInverseSolidFade) {
    Scene s = lit_floor();
    Material ball;
    ball.fade_distance = 4, ball.fade_power = 2, ball.fade_color = Vec3(0.5f);
    const uint32_t mb = white_glass(s, ball, 1); // fully transmitting
    ShapeObject o;
    o.name = "inverse ball";
    CsgNode leaf;
    leaf.shape = Shape{ShapeKind::Sphere};
    leaf.material = mb;
    leaf.inverse = true;
    o.nodes.push_back(leaf);
    o.transform = Affine::translate(Vec3(0, 1, 0));
    s.add_shape_object(o);
    const Vec3 under = floor_under(s);
    EXPECT_TRUE(std::isfinite(under.x) && std::isfinite(under.y) && std::isfinite(under.z));
}

// A clipped object is an open surface, but its interior still fades the light that crosses
// it, over the stretch inside it as POV-Ray's inside test has it (inside the object and its
// clip): advanced/wineglass.pov's glass base darkens the floor under it. Here a transmitting
// ball of radius 3 around the floor point, clipped to a column around it: the shadow ray
// crosses its top surface 3 units above the floor, inside all the way down.
TEST(ProceduralRender, ShadowsFadeInsideClippedObjects) {
    auto floor_under_clipped = [](float fade_distance, float transmit) {
        Scene s = lit_floor();
        Material ball;
        ball.fade_distance = fade_distance, ball.fade_power = 1;
        const uint32_t mb = white_glass(s, ball, transmit);
        ShapeObject o;
        o.name = "clipped ball";
        CsgNode clip;
        clip.op = CsgOp::Clip;
        clip.children = {1, 2};
        CsgNode sphere;
        sphere.shape = Shape{ShapeKind::Sphere};
        sphere.material = mb;
        sphere.transform = Affine::translate(Vec3(0, -1, 0)) * Affine::scale(Vec3(3));
        CsgNode column;
        column.shape = Shape{ShapeKind::Box};
        column.material = mb;
        column.transform = Affine::scale(Vec3(0.5f, 5, 0.5f));
        o.nodes = {clip, sphere, column};
        o.root = 0;
        s.add_shape_object(o);
        return floor_under(s).x;
    };
    const float dark = floor_under_clipped(0, 0); // opaque: ambient only
    const float clear = floor_under_clipped(0, 1) - dark;
    ASSERT_GT(clear, 0.0f);
    // 1 / (1 + 3 / 1) of the light after 3 units inside.
    EXPECT_NEAR((floor_under_clipped(1, 1) - dark) / clear, 0.25f, 0.01f);
}

} // namespace
} // namespace sheaf

#include "core/shading/shade.h"

namespace sheaf {
namespace {

TEST(ProceduralShading, MetallicReflectionFollowsPovRaysFresnelTerm) {
    // POV-Ray tints a metallic reflection towards the surface colour by 1 - F, F its
    // empirical Fresnel term: 0 head-on (the full tint), 1 at a grazing angle (none).
    Material m;
    m.mirror = 0.8f, m.mirror_color = Vec3(1.0f), m.mirror_metallic = true;
    SurfaceHit h;
    h.normal = Vec3(0, 0, 1), h.albedo = Vec3(0, 1, 0.5f);
    h.incoming = Vec3(0, 0, -1);
    Vec3 w = mirror_weight(m, h);
    EXPECT_NEAR(w.x, 0.0f, 1e-4f);
    EXPECT_NEAR(w.y, 0.8f, 1e-4f);
    EXPECT_NEAR(w.z, 0.4f, 1e-4f);
    h.incoming = normalize(Vec3(1, 0, -0.001f)); // grazing
    w = mirror_weight(m, h);
    EXPECT_NEAR(w.x, 0.8f, 0.01f);
    // At 60 degrees: x = 2/3, F = 0.014567225 / (2/3 - 1.12)^2 - 0.011612903.
    h.incoming = Vec3(std::sin(1.0471976f), 0, -std::cos(1.0471976f));
    const float f = 0.014567225f / ((2.0f / 3 - 1.12f) * (2.0f / 3 - 1.12f)) - 0.011612903f;
    EXPECT_NEAR(mirror_weight(m, h).x, 0.8f * f, 1e-4f);
    m.mirror_metallic = false;
    EXPECT_NEAR(mirror_weight(m, h).x, 0.8f, 1e-6f);
}

// conserve_energy takes what the mirror reflects from the diffuse too (Sheaf's materials),
// or, as POV-Ray's finishes do, from what passes through only (objects/mesh2.pov's opaque
// floor, reflection 0.2 with conserve_energy, kept its brightness in povray).
TEST(ProceduralShading, ConserveEnergyTakesTheMirrorsShareWhereAsked) {
    Material m;
    m.mirror = 0.25f, m.mirror_color = Vec3(1.0f), m.conserve_energy = true;
    SurfaceHit h;
    h.normal = Vec3(0, 0, 1), h.albedo = Vec3(1.0f), h.incoming = Vec3(0, 0, -1);
    const Vec3 up(0, 0, 1);
    EXPECT_NEAR(direct_light(m, h, up, Vec3(1.0f)).x, m.diffuse * 0.75f, 1e-6f);
    m.conserve_diffuse = false; // POV-Ray's
    EXPECT_NEAR(direct_light(m, h, up, Vec3(1.0f)).x, m.diffuse, 1e-6f);
}

TEST(ProceduralShading, FogAndFadeFollowPovRay) {
    Fogs fs;
    fs.count = 1;
    Fog& f = fs.layer[0];
    f.distance = 10, f.color = Vec3(1), f.transmit = 0.5f;
    Vec3 keep, add;
    const Vec3 o(0.0f), d(1, 0, 0);
    fog_over(fs, o, d, 10, keep, add); // exp(-1) = 0.37 < transmit: the surface keeps half
    EXPECT_FLOAT_EQ(keep.x, 0.5f);
    EXPECT_FLOAT_EQ(add.x, 0.5f);
    fog_over(fs, o, d, 1, keep, add);
    EXPECT_NEAR(keep.y, std::exp(-0.1f), 1e-6);
    // A filtering fog tints what it lets through; a second fog lays its own over it.
    f.transmit = 0, f.filter = 0.5f, f.color = Vec3(1, 0, 0);
    fs.layer[1].distance = 5, fs.layer[1].color = Vec3(0, 0, 1);
    fs.count = 2;
    fog_over(fs, o, d, 10, keep, add);
    const float a = std::exp(-1.0f), b = std::exp(-2.0f);
    EXPECT_NEAR(keep.x, a * b, 1e-6);        // (1 - 0.5) + 0.5 * 1
    EXPECT_NEAR(keep.y, a * 0.5f * b, 1e-6); // (1 - 0.5) + 0.5 * 0
    EXPECT_NEAR(add.x, 1 - a, 1e-6);
    EXPECT_NEAR(add.z, 1 - b, 1e-6);
    // Turbulence shortens a finite way by exp(-d / distance) times the turbulence there.
    Fog t;
    t.distance = 10, t.turb = Vec3(1, 1, 1), t.turb_depth = 0.5f;
    const double n = pov_turbulence(DVec3(5, 0.5, 0.5), 6, 0.5, 2.0, 2);
    EXPECT_NEAR(fog_depth(t, Vec3(0, 0.5f, 0.5f), d, 10),
                (1 - std::exp(-1.0) * std::min(1.0, 0.5 * n)), 1e-6);
    EXPECT_EQ(fog_depth(t, o, d, INFINITY), INFINITY);
    // Ground fog (POV-Ray's fog_type 2): full below the offset, 1 / (1 + Y^2) above.
    Fog g;
    g.distance = 10, g.offset = 1, g.alt = 2, g.up = Vec3(0, 1, 0);
    EXPECT_NEAR(fog_depth(g, Vec3(0, 0.5f, 0), d, 10), 1.0, 1e-9);        // level, below: constant
    EXPECT_NEAR(fog_depth(g, Vec3(0, 5, 0), d, 10), 1.0 / (1 + 4), 1e-7); // level, Y = 2
    // Straight up from the ground through Y = 0..2 (height 1..5): 2 * atan(2) over 10.
    const Vec3 up(0, 1, 0);
    EXPECT_NEAR(fog_depth(g, Vec3(0, 1, 0), up, 4), 2 * std::atan(2.0) / 10, 1e-6);
    // From below the offset: the part below counts fully.
    EXPECT_NEAR(fog_depth(g, Vec3(0, 0, 0), up, 5), (1 + 2 * std::atan(2.0)) / 10, 1e-6);
    // Leaving the scene upwards: finite (2 * (pi / 2) / 10 from the offset); level: all fog.
    EXPECT_NEAR(fog_depth(g, Vec3(0, 1, 0), up, INFINITY), M_PI / 10, 1e-6);
    EXPECT_EQ(fog_depth(g, Vec3(0, 1, 0), d, INFINITY), INFINITY);
    g.transmit = 0;
    fs.layer[0] = g, fs.count = 1;
    fog_over(fs, Vec3(0, 1, 0), up, INFINITY, keep, add);
    EXPECT_NEAR(keep.z, std::exp(-M_PI / 10), 1e-6);
    Material m;
    m.fade_distance = 2, m.fade_power = 2, m.fade_color = Vec3(0.5f, 0, 0);
    EXPECT_NEAR(interior_fade(m, 2).y, 0.5f, 1e-6);  // 1 / (1 + 1)
    EXPECT_NEAR(interior_fade(m, 2).x, 0.75f, 1e-6); // towards the fade colour
    m.fade_power = 1001;                             // exponential absorption
    EXPECT_NEAR(interior_fade(m, 2).y, std::exp(-1.0f), 1e-6);
    EXPECT_NEAR(interior_fade(m, 2).x, std::exp(-0.5f), 1e-6);
    m.fade_distance = 0;
    EXPECT_EQ(interior_fade(m, 5).x, 1.0f);
    // fade_power 0 (POV-Ray's default): a refracted ray keeps half at any depth (1 / (1 + 1)),
    // a shadow ray all of it, as in POV-Ray.
    m.fade_distance = 2, m.fade_power = 0, m.fade_color = Vec3(0.0f);
    EXPECT_NEAR(interior_fade(m, 7).y, 0.5f, 1e-6);
    EXPECT_EQ(interior_fade(m, 7, true).y, 1.0f);
}

} // namespace
} // namespace sheaf

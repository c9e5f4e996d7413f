// Scenes and checks shared by the tests (the frame's, the wavefront tracer's against the CPU
// backend's, the CUDA backend's in gpu/): each scene exercises a part of the pipeline (glass,
// mirrors and AO; every light kind; analytic shapes and CSG with transparent shadows;
// procedural textures, flags, fog and sky), and frames are compared byte for byte. Test code.
#pragma once

#include "core/frame/frame.h"
#include "core/scene/prepared_scene.h"
#include "core/scenes/shapes.h"
#include "core/settings/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sheaf::test {

using SettingList = std::vector<std::pair<std::string, std::string>>;

/// The scene's settings with a w x h frame and `kv` over them.
inline RenderSettings settings_for(const PreparedScene& scene, const SettingList& kv, int w,
                                   int h) {
    Settings s;
    s.set("width", std::to_string(w)), s.set("height", std::to_string(h));
    for (const auto& [k, v] : kv) s.set(k, v);
    return RenderSettings::resolve(s, scene.settings);
}

/// "scene key=value ...", naming a case in failure messages.
inline std::string label(const std::string& scene, const SettingList& kv) {
    std::string l = scene;
    for (const auto& [k, v] : kv) l += " " + k + "=" + v;
    return l;
}

/// A glass sphere and a mirror box over a floor: refraction, total internal reflection,
/// reflection; AO when the settings ask.
inline Scene glass_mirror_scene() {
    Scene s;
    Material floor;
    floor.color = Vec3(0.8f, 0.7f, 0.5f);
    Material glass;
    glass.color = Vec3(0.9f, 1.0f, 0.9f);
    glass.transmission = 0.9f, glass.ior = 1.5f, glass.specular = 0.5f, glass.diffuse = 0.1f;
    Material mirror;
    mirror.mirror = 0.8f;
    const uint32_t mf = s.add_material(floor), mg = s.add_material(glass),
                   mm = s.add_material(mirror);
    s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), mf);
    s.add_mesh_object("glass", make_uv_sphere(Vec3(0, 0, 0), 1.0f, 12, 24), mg);
    s.add_mesh_object("mirror", make_box(Vec3(1.5f, -1, -2), Vec3(2.5f, 1, -1)), mm);
    s.add_light(Light{Vec3(2, 5, 4), Vec3(1.0f)});
    s.camera.position = Vec3(0, 1.5f, 5);
    s.camera.look_at = Vec3(0, 0, 0);
    s.background = Vec3(0.2f, 0.3f, 0.5f);
    return s;
}

/// Point, spot (radius, falloff, tightness, fade), parallel and shadowless lights over a
/// smooth-shaded torus and boxes, seen through an orthographic camera with lens shift.
inline Scene lights_scene(bool orthographic) {
    Scene s;
    Material m;
    m.specular = 0.4f, m.blinn = 0.3f, m.brilliance = 2.0f;
    Material floor;
    floor.color = Vec3(0.6f, 0.6f, 0.7f);
    const uint32_t mm = s.add_material(m), mf = s.add_material(floor);
    s.add_mesh_object("floor", make_box(Vec3(-5, -1.1f, -5), Vec3(5, -1, 5)), mf);
    Mesh torus = make_torus(Vec3(0, 0, 0), Vec3(0, 1, 0.3f), 1.0f, 0.35f, 24, 12);
    s.add_mesh_object("torus", torus, mm);
    s.add_mesh_object("post", make_cylinder(Vec3(-2, -1, -1), Vec3(-2, 1.5f, -1), 0.3f, 16, true),
                      mm);
    Light spot{Vec3(0, 4, 2), Vec3(0.9f, 0.8f, 0.7f)};
    spot.type = LightType::Spot, spot.direction = Vec3(0, -4, -2), spot.spot_radius = 15,
    spot.spot_falloff = 30, spot.spot_tightness = 5, spot.fade_distance = 4, spot.fade_power = 2;
    s.add_light(spot);
    Light sun{Vec3(0, 0, 0), Vec3(0.3f, 0.3f, 0.35f)};
    sun.type = LightType::Parallel, sun.direction = Vec3(-1, -2, -0.5f);
    s.add_light(sun);
    Light fill{Vec3(-3, 2, 4), Vec3(0.2f, 0.25f, 0.2f)};
    fill.shadowless = true;
    s.add_light(fill);
    s.add_light(Light{Vec3(3, 3, 3), Vec3(0.4f)});
    s.camera.position = Vec3(1, 3, 6);
    s.camera.look_at = Vec3(0, 0, 0);
    if (orthographic) {
        s.camera.projection = Projection::Orthographic;
        s.camera.ortho_height = 6;
        s.camera.shift_x = 0.1f;
    } else {
        s.camera.shift_y = -0.05f;
    }
    return s;
}

/// Analytic shapes of every kind and a CSG tree (difference, intersection, merge, inverse,
/// clip), one of them transparent with an interior fade (shadows through it), an unbounded
/// plane as the floor, a mirror torus; the red and the mirror are iridescent.
inline Scene csg_scene() {
    Scene s;
    Material red, blue, glass, mirror, floor;
    red.color = Vec3(0.9f, 0.2f, 0.2f), red.specular = 0.5f;
    red.irid = 0.3f, red.irid_thickness = 0.4f, red.irid_turbulence = 0.3f;
    blue.color = Vec3(0.2f, 0.3f, 0.9f);
    glass.color = Vec3(0.8f, 1.0f, 0.9f), glass.transmission = 0.7f, glass.ior = 1.4f,
    glass.fade_distance = 1, glass.fade_power = 2, glass.fade_color = Vec3(0.2f, 0.6f, 0.2f);
    mirror.mirror = 0.7f, mirror.color = Vec3(0.9f);
    mirror.irid = 0.4f, mirror.irid_thickness = 0.5f;
    floor.color = Vec3(0.7f);
    const uint32_t mr = s.add_material(red), mb = s.add_material(blue), mg = s.add_material(glass),
                   mm = s.add_material(mirror), mf = s.add_material(floor);
    s.add_shape("floor", Shape{ShapeKind::Plane}, mf,
                Affine::translate(Vec3(0, -1, 0)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2));
    ShapeObject o;
    o.name = "csg";
    o.nodes.resize(6);
    o.nodes[0].op = CsgOp::Merge, o.nodes[0].children = {1, 5};
    o.nodes[1].op = CsgOp::Difference, o.nodes[1].children = {2, 3, 4};
    o.nodes[2].shape = {ShapeKind::Sphere}, o.nodes[2].material = mr;
    o.nodes[3].shape = {ShapeKind::Box}, o.nodes[3].material = mb,
    o.nodes[3].transform = Affine::translate(Vec3(0.6f)) * Affine::scale(Vec3(0.5f));
    o.nodes[4].shape = {ShapeKind::Cylinder}, o.nodes[4].material = mb,
    o.nodes[4].transform = Affine::translate(Vec3(0, 0, -2)) * Affine::scale(Vec3(0.3f, 0.3f, 4));
    o.nodes[5].shape = {ShapeKind::Torus, 0.15f}, o.nodes[5].material = mr,
    o.nodes[5].transform = Affine::rotate(Vec3(1, 0, 0), 0.5f) * Affine::scale(Vec3(1.4f));
    o.transform = Affine::translate(Vec3(-1.5f, 0.2f, 0));
    s.add_shape_object(o);
    ShapeObject lens; // intersection of two spheres, transparent
    lens.name = "lens";
    lens.nodes.resize(3);
    lens.nodes[0].op = CsgOp::Intersection, lens.nodes[0].children = {1, 2};
    lens.nodes[1].shape = {ShapeKind::Sphere}, lens.nodes[1].material = mg,
    lens.nodes[1].transform = Affine::translate(Vec3(0, 0, 0.5f));
    lens.nodes[2].shape = {ShapeKind::Sphere}, lens.nodes[2].material = mg,
    lens.nodes[2].transform = Affine::translate(Vec3(0, 0, -0.5f));
    lens.transform = Affine::translate(Vec3(1.2f, 0.5f, 0.5f));
    s.add_shape_object(lens);
    ShapeObject clipped; // a cone clipped by an inverted box
    clipped.name = "clipped";
    clipped.nodes.resize(3);
    clipped.nodes[0].op = CsgOp::Clip, clipped.nodes[0].children = {1, 2};
    clipped.nodes[1].shape = {ShapeKind::Cone, 0.6f, 0.1f}, clipped.nodes[1].material = mb;
    clipped.nodes[2].shape = {ShapeKind::Box}, clipped.nodes[2].material = mb,
    clipped.nodes[2].inverse = true,
    clipped.nodes[2].transform = Affine::translate(Vec3(0.5f, 0, 0.5f)) * Affine::scale(Vec3(0.4f));
    clipped.transform = Affine::translate(Vec3(0, -1, -1.5f)) *
                        Affine::rotate(Vec3(1, 0, 0), -kPi / 2) * Affine::scale(Vec3(1, 1, 1.5f));
    s.add_shape_object(clipped);
    s.add_shape("disc", Shape{ShapeKind::Disc, 0.3f}, mb,
                Affine::translate(Vec3(2.5f, 0, -1.5f)) * Affine::rotate(Vec3(0, 1, 0), 0.7f));
    s.add_shape("open cylinder", Shape{ShapeKind::Cylinder, 0, 0, true}, mr,
                Affine::translate(Vec3(2.3f, -1, 1)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2) *
                    Affine::scale(Vec3(0.3f, 0.3f, 0.8f)));
    s.add_shape("mirror torus", Shape{ShapeKind::Torus, 0.2f}, mm,
                Affine::translate(Vec3(0, 1.6f, -2)) * Affine::scale(Vec3(0.8f)));
    s.add_light(Light{Vec3(2, 6, 4), Vec3(1.0f)});
    s.add_light(Light{Vec3(-4, 3, 2), Vec3(0.4f, 0.4f, 0.5f)});
    s.camera.position = Vec3(0, 2, 6);
    s.camera.look_at = Vec3(0, 0, 0);
    s.background = Vec3(0.1f, 0.1f, 0.2f);
    s.settings["trace.depth"] = "3";
    return s;
}

/// Julia fractals of the three algebras (core/geometry/julia.h): an opaque quaternion square,
/// a refracting hypercomplex one (light crossing it many times), and a quaternion cube cut
/// by a box in a CSG intersection, over a floor.
inline Scene julia_scene() {
    Scene s;
    Material gold, glass, floor;
    gold.color = Vec3(0.9f, 0.6f, 0.3f), gold.specular = 0.6f;
    glass.color = Vec3(0.8f, 0.9f, 1.0f), glass.transmission = 0.8f, glass.ior = 1.5f;
    floor.color = Vec3(0.6f);
    const uint32_t mg = s.add_material(gold), mt = s.add_material(glass),
                   mf = s.add_material(floor);
    s.add_shape("floor", Shape{ShapeKind::Plane}, mf,
                Affine::translate(Vec3(0, -1.4f, 0)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2));
    auto julia = [](JuliaAlgebra a, std::initializer_list<double> c, uint32_t iterations) {
        auto j = std::make_shared<JuliaFractal>();
        std::copy(c.begin(), c.end(), j->c);
        j->algebra = a, j->iterations = iterations;
        return j;
    };
    auto add = [&](const char* name, std::shared_ptr<JuliaFractal> j, uint32_t m, Affine at) {
        ShapeObject o;
        o.name = name;
        o.nodes.resize(1);
        o.nodes[0].shape = {ShapeKind::Julia}, o.nodes[0].julia = std::move(j);
        o.nodes[0].material = m;
        o.transform = at;
        s.add_shape_object(o);
    };
    add("sqr", julia(JuliaAlgebra::QuaternionSqr, {-0.083, 0.0, -0.83, -0.025}, 8), mg,
        Affine::translate(Vec3(-1.6f, 0, 0)) * Affine::rotate(Vec3(0, 1, 0), 0.6f));
    add("hypercomplex", julia(JuliaAlgebra::HypercomplexSqr, {-0.745, 0, 0.113, 0.05}, 9), mt,
        Affine::translate(Vec3(1.4f, 0, 0)) * Affine::scale(Vec3(0.8f)));
    ShapeObject cut;
    cut.name = "cut cube";
    cut.nodes.resize(3);
    cut.nodes[0].op = CsgOp::Intersection, cut.nodes[0].children = {1, 2};
    cut.nodes[1].shape = {ShapeKind::Julia}, cut.nodes[1].material = mg,
    cut.nodes[1].julia = julia(JuliaAlgebra::QuaternionCube, {-0.54, 0.57, 0.0, -0.37}, 8);
    cut.nodes[2].shape = {ShapeKind::Box}, cut.nodes[2].material = mt,
    cut.nodes[2].transform = Affine::translate(Vec3(0, 0, 0.6f));
    cut.transform = Affine::translate(Vec3(0, 1.2f, -1));
    s.add_shape_object(cut);
    s.add_light(Light{Vec3(2, 6, 4), Vec3(1.0f)});
    s.add_light(Light{Vec3(-4, 3, 2), Vec3(0.4f, 0.4f, 0.5f)});
    s.camera.position = Vec3(0, 1.5f, 5);
    s.camera.look_at = Vec3(0, 0, 0);
    s.background = Vec3(0.1f, 0.1f, 0.2f);
    s.settings["trace.depth"] = "4";
    return s;
}

inline PigmentEntry pigment_entry(float value, Vec3 c, float filter = 0, float transmit = 0) {
    PigmentEntry e;
    e.value = value;
    e.color[0] = c.x, e.color[1] = c.y, e.color[2] = c.z, e.color[3] = filter,
    e.color[4] = transmit;
    return e;
}

inline int32_t add_pigment(Scene& s, PatternKind kind, std::vector<PigmentEntry> entries,
                           float scale = 1) {
    Pigment pg;
    pg.solid = false;
    pg.pattern.kind = kind;
    pg.pattern.to_pattern = Affine::scale(Vec3(1.0f / scale));
    pg.first = uint32_t(s.pigment_entries.size());
    pg.count = uint32_t(entries.size());
    s.pigment_entries.insert(s.pigment_entries.end(), entries.begin(), entries.end());
    s.pigments.push_back(pg);
    return int32_t(s.pigments.size() - 1);
}

/// A clear material (light passes straight through, nothing reflects) holding `media`.
inline uint32_t add_media_material(Scene& s, std::vector<Medium> media) {
    Material clear;
    clear.color = Vec3(1.0f);
    clear.ambient = 0, clear.diffuse = 0, clear.transmission = 1, clear.ior = 1;
    clear.fresnel_split = false;
    clear.media_first = uint32_t(s.media.size());
    clear.media_count = uint32_t(media.size());
    s.media.insert(s.media.end(), media.begin(), media.end());
    return s.add_material(clear);
}

/// Interior media: a sphere giving off light through a gradient density, a union of two
/// spheres with media of their own (one absorbing) and a solid ball inside one of them that
/// media leave out, over a floor, with the camera outside; `inside`: the camera inside the
/// first sphere.
inline Scene media_scene(bool inside = false) {
    Scene s;
    Material floor;
    floor.color = Vec3(0.6f, 0.6f, 0.5f);
    s.add_mesh_object("floor", make_box(Vec3(-6, -1.1f, -6), Vec3(6, -1, 6)),
                      s.add_material(floor));
    Medium glow;
    glow.emission = Vec3(0.4f, 0.2f, 0.1f);
    glow.density_first = uint32_t(s.medium_densities.size());
    glow.density_count = 1;
    s.medium_densities.push_back(
        uint32_t(add_pigment(s, PatternKind::Gradient,
                             {pigment_entry(0, Vec3(0.2f)), pigment_entry(1, Vec3(1.0f))}, 2.0f)));
    s.add_shape("glow", Shape{ShapeKind::Sphere}, add_media_material(s, {glow}),
                Affine::translate(Vec3(-1.2f, 0, 0)));
    Medium haze;
    haze.emission = Vec3(0.1f, 0.3f, 0.3f), haze.absorption = Vec3(0.5f, 0.2f, 0.1f);
    haze.samples = 16;
    Medium tint;
    tint.emission = Vec3(0.2f, 0.0f, 0.2f);
    ShapeObject pair;
    pair.name = "pair";
    CsgNode u;
    u.op = CsgOp::Union;
    u.children = {1, 2};
    CsgNode a, b;
    a.shape = b.shape = Shape{ShapeKind::Sphere};
    a.material = add_media_material(s, {haze, tint});
    b.material = add_media_material(s, {tint});
    a.transform = Affine::translate(Vec3(1.0f, 0, 0)) * Affine::scale(Vec3(0.8f));
    b.transform = Affine::translate(Vec3(1.8f, 0.6f, -0.5f)) * Affine::scale(Vec3(0.6f));
    pair.nodes = {u, a, b};
    s.add_shape_object(std::move(pair));
    Material solid_m;
    solid_m.color = Vec3(0.2f, 0.8f, 0.2f);
    const uint32_t ball =
        s.add_shape("ball", Shape{ShapeKind::Sphere}, s.add_material(solid_m),
                    Affine::translate(Vec3(-1.2f, 0, 0)) * Affine::scale(Vec3(0.3f)));
    s.shape_objects[ball].flags = kSolid;
    s.add_light(Light{Vec3(2, 5, 4), Vec3(1.0f)});
    s.camera.position = inside ? Vec3(-1.2f, 0.1f, 0.6f) : Vec3(0, 1, 5);
    s.camera.look_at = inside ? Vec3(-1.2f, 0, -1) : Vec3(0, 0, 0);
    s.settings["trace.depth"] = "6";
    return s;
}

/// Scattering media: a unit sphere of Henyey-Greenstein medium with extinction under a parallel
/// light, an opaque slab shading half of it, five more lights (more than a step's share of
/// four; two shadowless) and a mirror floor seen through it (reflection rays' segments).
inline Scene scattering_scene() {
    Scene s;
    Medium mist;
    mist.scattering = Vec3(0.2f, 0.1f, 0.05f);
    mist.scatter_type = ScatterType::HenyeyGreenstein;
    mist.eccentricity = 0.4f;
    s.add_shape("container", Shape{ShapeKind::Sphere}, add_media_material(s, {mist}));
    Light sun;
    sun.type = LightType::Parallel;
    sun.direction = Vec3(0, -1, 0);
    s.add_light(sun);
    s.add_shape("slab", Shape{ShapeKind::Box}, s.add_material(Material{}),
                Affine::translate(Vec3(-2.0f, 2.0f, 0)) * Affine::scale(Vec3(2.0f, 0.1f, 2.0f)));
    for (int i = 0; i < 5; ++i) {
        Light l{Vec3(float(i) - 2.0f, 3.0f, 1.0f), Vec3(0.3f, 0.2f, 0.1f * float(i))};
        l.shadowless = i % 3 == 1;
        s.add_light(l);
    }
    Material mirror;
    mirror.mirror = 0.6f;
    s.add_shape("floor", Shape{ShapeKind::Box}, s.add_material(mirror),
                Affine::translate(Vec3(0, -1.5f, 0)) * Affine::scale(Vec3(4, 0.1f, 4)));
    s.camera.position = Vec3(0, 1, 5);
    s.camera.look_at = Vec3(0, 0, 0);
    s.camera.fov_y_degrees = 30;
    return s;
}

/// The atmosphere (Scene::atmosphere): a scattering, absorbing medium everywhere outside solid
/// objects, inside a hollow room; a spotlight fading through it (media_attenuation) whose beam
/// crosses the view past a solid ball, a transparent solid ball the atmosphere leaves out, six
/// more spotlights behind the camera (more lights than a step takes, none reaching the
/// steps in view) and a point light.
/// Photons (core/frame/photon_pass.h): a glass ball and a mirror ball, both targets, over a
/// floor inside a room, lit by a spotlight and a fading point light; the glass focuses a
/// caustic under it, the mirror throws one on the wall.
inline Scene photon_scene() {
    Scene s;
    Material wall;
    wall.color = Vec3(0.8f, 0.75f, 0.7f), wall.diffuse = 0.8f, wall.ambient = 0.05f;
    s.add_shape("room", Shape{ShapeKind::Sphere}, s.add_material(wall), Affine::scale(Vec3(8.0f)));
    Material glass;
    glass.color = Vec3(0.9f, 1.0f, 0.9f);
    glass.ambient = glass.diffuse = 0, glass.transmission = 1, glass.ior = 1.5f;
    const uint32_t ball = s.add_shape("glass", Shape{ShapeKind::Sphere}, s.add_material(glass),
                                      Affine::translate(Vec3(-1.0f, -1.0f, 0.0f)));
    s.shape_objects[ball].photons.target = 1.0f;
    s.shape_objects[ball].photons.refraction = PhotonSwitch::On;
    s.shape_objects[ball].flags = kNoPhotonCollect;
    Material mirror;
    mirror.color = Vec3(0.2f), mirror.diffuse = 0.1f, mirror.mirror = 0.9f;
    const uint32_t chrome =
        s.add_shape("mirror", Shape{ShapeKind::Sphere}, s.add_material(mirror),
                    Affine::translate(Vec3(1.6f, -1.3f, -0.5f)) * Affine::scale(Vec3(0.7f)));
    s.shape_objects[chrome].photons.target = 1.5f;
    s.shape_objects[chrome].photons.reflection = PhotonSwitch::On;
    Light spot{Vec3(-1.0f, 5.0f, 0.5f), Vec3(1.5f)};
    spot.type = LightType::Spot;
    spot.direction = Vec3(0, -1, -0.1f);
    spot.spot_radius = 25, spot.spot_falloff = 35;
    s.add_light(spot);
    Light lamp{Vec3(3.0f, 3.0f, 3.0f), Vec3(0.8f)};
    lamp.fade_distance = 4, lamp.fade_power = 2;
    s.add_light(lamp);
    s.photons.spacing = 0.02f;
    s.camera.position = Vec3(0, 1.5f, 6);
    s.camera.look_at = Vec3(0, -1.5f, 0);
    s.camera.fov_y_degrees = 55;
    return s;
}

inline Scene atmosphere_scene() {
    Scene s;
    Material wall;
    wall.color = Vec3(0.6f), wall.diffuse = 0.7f;
    s.add_shape("room", Shape{ShapeKind::Sphere}, s.add_material(wall), Affine::scale(Vec3(12.0f)));
    Material white;
    const uint32_t ball = s.add_shape("ball", Shape{ShapeKind::Sphere}, s.add_material(white),
                                      Affine::translate(Vec3(-1.0f, 1.0f, -2.0f)));
    s.shape_objects[ball].flags = kSolid;
    Material glass;
    glass.color = Vec3(1.0f);
    glass.ambient = glass.diffuse = 0, glass.transmission = 1, glass.ior = 1;
    glass.fresnel_split = false;
    const uint32_t clear =
        s.add_shape("glass", Shape{ShapeKind::Sphere}, s.add_material(glass),
                    Affine::translate(Vec3(1.5f, -0.5f, 0.0f)) * Affine::scale(Vec3(0.8f)));
    s.shape_objects[clear].flags = kSolid;
    Medium air;
    air.scattering = Vec3(0.05f, 0.04f, 0.03f);
    air.absorption = Vec3(0.01f);
    air.samples = 40;
    air.light_samples = 4;
    Material atmosphere;
    atmosphere.media_first = uint32_t(s.media.size());
    atmosphere.media_count = 1;
    s.media.push_back(air);
    s.atmosphere = int32_t(s.add_material(atmosphere));
    Light spot{Vec3(-1.0f, 6.0f, -2.0f), Vec3(3.0f)};
    spot.type = LightType::Spot;
    spot.direction = Vec3(0, -1, 0);
    spot.spot_radius = 12, spot.spot_falloff = 16;
    spot.media_attenuation = true;
    s.add_light(spot);
    for (int i = 0; i < 6; ++i) {
        Light back = spot;
        back.position = Vec3(float(i) - 2.5f, 6.0f, 9.0f);
        back.media_attenuation = i % 2 == 0;
        s.add_light(back);
    }
    s.add_light(Light{Vec3(3.0f, 4.0f, 4.0f), Vec3(0.5f)});
    s.camera.position = Vec3(0, 0.5f, 6);
    s.camera.look_at = Vec3(0, 0.5f, 0);
    s.camera.fov_y_degrees = 50;
    return s;
}

/// Two rainbows (core/shading/rainbow.h) over a sky: one whose band fills part of an arc and
/// fades out beyond its falloff, its colours filtering and letting through what is behind,
/// over a ball and a floor near enough to take some of it; one jittered, its band turned round
/// (negative width).
inline Scene rainbow_scene() {
    Scene s = lights_scene(false);
    s.background = Vec3(0.2f, 0.3f, 0.6f);
    Rainbow bow;
    bow.antisolar = normalize(Vec3(0.1f, 0.0f, -1.0f));
    bow.right = normalize(cross(Vec3(0, 1, 0), bow.antisolar));
    bow.up = cross(bow.antisolar, bow.right);
    bow.start = 0.2f, bow.width = 0.25f, bow.distance = 8.0f;
    bow.arc = 1.2f, bow.falloff = 0.6f;
    bow.colors = uint32_t(add_pigment(s, PatternKind::Gradient,
                                      {pigment_entry(0, Vec3(1, 0, 0), 0.5f),
                                       pigment_entry(0.5f, Vec3(0, 1, 0), 0, 0.4f),
                                       pigment_entry(1, Vec3(0, 0, 1), 0.3f, 0.2f)}));
    s.rainbows.push_back(bow);
    Rainbow pale = bow;
    pale.start = 0.9f, pale.width = -0.15f, pale.jitter = 0.05f, pale.distance = 1e7f;
    pale.arc = pale.falloff = 1e30f;
    pale.colors = uint32_t(add_pigment(
        s, PatternKind::Gradient, {pigment_entry(0, Vec3(1.0f)), pigment_entry(1, Vec3(1, 1, 0))}));
    s.rainbows.push_back(pale);
    return s;
}

/// Every procedural feature: patterned, layered and transmitting pigments, turbulence, a
/// normal pattern with a slope map, normal maps (a list and an average), an inside material,
/// variable, Fresnel and metallic reflection, conserve_energy, a texture map by slope and
/// altitude, a slope-patterned transparent pigment, no_shadow / no_image
/// / no_reflection objects, fog and a sky pigment.
inline Scene procedural_scene() {
    Scene s;
    Material floor;
    floor.pigment = add_pigment(s, PatternKind::Checker,
                                {pigment_entry(0, Vec3(0.9f)), pigment_entry(0, Vec3(0.2f))}, 0.5f);
    floor.mirror = 0.5f, floor.mirror_min = 0.05f, floor.mirror_falloff = 2;
    Material marble;
    marble.pigment = add_pigment(
        s, PatternKind::Marble,
        {pigment_entry(0, Vec3(0.9f, 0.8f, 0.7f)), pigment_entry(1, Vec3(0.2f, 0.1f, 0.1f))});
    s.pigments.back().pattern.has_turbulence = true;
    s.pigments.back().pattern.turbulence = Vec3(0.3f);
    s.pigments.back().pattern.wave = Wave::Sine;
    Pattern bumps;
    bumps.kind = PatternKind::Bozo;
    bumps.to_pattern = Affine::scale(Vec3(5));
    s.normal_patterns.push_back({bumps, 0.6f});
    s.slope_entries = {{0, 0, 2}, {0.5f, 1, 0}, {1, 0, -2}}; // a scallop wave, steep
    s.normal_patterns.back().slope_count = 3;
    marble.normal = 0;
    marble.blinn = 0.5f, marble.blinn_exponent = 30, marble.metallic = 0.5f;
    marble.mirror = 0.3f, marble.mirror_metallic = true, marble.conserve_energy = true;
    Material glass;
    glass.pigment = add_pigment(
        s, PatternKind::Gradient,
        {pigment_entry(0, Vec3(1), 0, 0.9f), pigment_entry(1, Vec3(0.8f, 1, 0.8f), 0.3f, 0.3f)});
    // Clearer where it faces up (a slope pattern, also seen by shadow rays crossing it).
    set_slope(s.pigments[size_t(glass.pigment)].pattern, Vec3(0, 1, 0), 0, 0, Vec3(0.0f), 0, 0,
              false);
    glass.ior = 1.5f, glass.fresnel_split = false, glass.mirror = 1, glass.mirror_min = 0,
    glass.mirror_fresnel = true, glass.fade_distance = 1, glass.fade_power = 2;
    Material layered;
    const int32_t spots = add_pigment(
        s, PatternKind::Crackle,
        {pigment_entry(0, Vec3(0.1f, 0.1f, 0.4f)), pigment_entry(0.3f, Vec3(1.0f), 0, 1.0f)}, 0.3f);
    const int32_t base = add_pigment(
        s, PatternKind::Wood,
        {pigment_entry(0, Vec3(0.6f, 0.4f, 0.2f)), pigment_entry(1, Vec3(0.3f, 0.2f, 0.1f))}, 0.2f);
    Pigment layers;
    layers.solid = false, layers.layers = true;
    layers.first = uint32_t(s.pigment_entries.size()), layers.count = 2;
    PigmentEntry bottom, top;
    bottom.pigment = base, top.pigment = spots;
    s.pigment_entries.push_back(bottom), s.pigment_entries.push_back(top);
    s.pigments.push_back(layers);
    layered.pigment = int32_t(s.pigments.size() - 1);
    // Normal maps: the layered box's checker picks the bumps (0) or its own normal; the
    // floor averages the bumps and its own normal, 1 : 2.
    NormalPattern tiles, mean;
    tiles.pattern.kind = PatternKind::Checker;
    tiles.pattern.to_pattern = Affine::scale(Vec3(4));
    tiles.map_count = 2;
    mean.average = true;
    mean.map_first = 2, mean.map_count = 2;
    s.normal_map_entries = {{0, 0}, {0, -1}, {1, 0}, {2, -1}};
    layered.normal = int32_t(s.normal_patterns.size());
    s.normal_patterns.push_back(tiles);
    floor.normal = int32_t(s.normal_patterns.size());
    s.normal_patterns.push_back(mean);
    Material a, b, picked;
    a.color = Vec3(1, 0.2f, 0.2f), b.color = Vec3(0.2f, 0.2f, 1);
    const uint32_t ma = s.add_material(a), mb = s.add_material(b);
    MaterialSwitch sw; // by slope and altitude: the box's top and upper sides differ
    set_slope(sw.pattern, Vec3(0, 3, 0), 0, 0, Vec3(0, 1, 0), -1, 0, false);
    sw.first = 0, sw.count = 2;
    s.material_switches.push_back(sw);
    s.material_entries = {{0.0f, ma}, {1.0f, mb}};
    picked.select = 0;
    // From inside, the glass is plain and greener (POV-Ray's interior_texture).
    Material glass_inside = glass;
    glass_inside.pigment = -1, glass_inside.color = Vec3(0.8f, 1, 0.8f);
    glass_inside.transmission = 0.8f;
    glass.inside = int32_t(s.add_material(glass_inside));
    const uint32_t mf = s.add_material(floor), mm = s.add_material(marble),
                   mg = s.add_material(glass), mp = s.add_material(picked),
                   ml = s.add_material(layered);
    s.add_mesh_object("floor", make_box(Vec3(-4, -1.1f, -4), Vec3(4, -1, 4)), mf);
    s.add_shape("marble", Shape{ShapeKind::Sphere}, mm, Affine::translate(Vec3(-1.2f, 0, 0)));
    s.add_shape("glass", Shape{ShapeKind::Sphere}, mg,
                Affine::translate(Vec3(1.2f, 0, 0.5f)) * Affine::scale(Vec3(0.8f)));
    s.add_mesh_object("layered", make_box(Vec3(-0.4f, -1, 1.2f), Vec3(0.4f, -0.2f, 2.0f)), ml);
    const uint32_t box =
        s.add_mesh_object("picked", make_box(Vec3(-0.5f, -1, -2), Vec3(0.5f, 0, -1.5f)), mp);
    s.objects[box].flags = kNoShadow;
    const uint32_t ghost =
        s.add_shape("ghost", Shape{ShapeKind::Sphere}, ma,
                    Affine::translate(Vec3(0, 2, -1)) * Affine::scale(Vec3(0.5f)));
    s.shape_objects[ghost].flags = kNoImage | kNoReflection;
    s.add_light(Light{Vec3(2, 5, 4), Vec3(1.0f)});
    s.camera.position = Vec3(0, 1.5f, 5);
    s.camera.look_at = Vec3(0, 0, 0);
    s.fog.count = 1;
    Fog& fog = s.fog.layer[0];
    fog.distance = 20, fog.color = Vec3(0.5f, 0.5f, 0.6f), fog.transmit = 0.2f;
    s.sky = add_pigment(s, PatternKind::Gradient,
                        {pigment_entry(0, Vec3(1)), pigment_entry(1, Vec3(0.1f, 0.2f, 0.8f))});
    s.settings["trace.depth"] = "3";
    return s;
}

/// Byte-for-byte equality of two frames: image, passes, and every statistic in the same
/// order with the same value, except measurements (time_ms.*, memory.*), the wavefront
/// pipeline's own counts (device.*) and `ignore`. With a `tolerance`, the shaded passes
/// (image, normals, albedo) may differ by that much a value; depth, object ids, per-pixel
/// tests and statistics stay exact.
inline void expect_same_frame(const Frame& a, const Frame& b, const std::string& what,
                              const std::vector<std::string>& ignore = {}, float tolerance = 0) {
    auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() &&
               (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    // Float passes equal bit for bit, or within `tolerance`.
    auto close = [&](const auto& xv, const auto& yv) {
        static_assert(sizeof(xv[0]) % sizeof(float) == 0, "passes of floats");
        if (same(xv, yv)) return true;
        if (tolerance <= 0 || xv.size() != yv.size()) return false;
        const size_t n = xv.size() * (sizeof(xv[0]) / sizeof(float));
        const float* x = reinterpret_cast<const float*>(xv.data());
        const float* y = reinterpret_cast<const float*>(yv.data());
        for (size_t i = 0; i < n; ++i)
            if (!(std::fabs(x[i] - y[i]) <= tolerance) &&
                std::memcmp(&x[i], &y[i], sizeof(float)) != 0)
                return false;
        return true;
    };
    // Where two float passes differ: how many values, the largest difference, the first
    // pixel and its object (channels per pixel: `per`).
    auto where = [&](const auto& xv, const auto& yv, size_t per) {
        static_assert(sizeof(xv[0]) % sizeof(float) == 0, "passes of floats");
        if (xv.size() != yv.size()) return std::string(" (sizes differ)");
        const size_t n = xv.size() * (sizeof(xv[0]) / sizeof(float));
        const float* x = reinterpret_cast<const float*>(xv.data());
        const float* y = reinterpret_cast<const float*>(yv.data());
        size_t count = 0, first = n;
        double most = 0;
        for (size_t i = 0; i < n; ++i) {
            if (std::memcmp(&x[i], &y[i], sizeof(float)) == 0) continue;
            if (count++ == 0) first = i;
            most = std::max(most, double(std::fabs(x[i] - y[i])));
        }
        if (count == 0) return std::string();
        const size_t px = first / per;
        const size_t w = size_t(a.width > 0 ? a.width : 1);
        std::ostringstream o;
        o.precision(9);
        o << " (" << count << " of " << n << " values, at most " << most
          << " apart; first at pixel " << px % w << "," << px / w << " (object "
          << (px < a.object_id.size() ? int64_t(a.object_id[px]) : -1) << "): " << x[first]
          << " and " << y[first] << ")";
        return o.str();
    };
    EXPECT_EQ(a.width, b.width) << what;
    EXPECT_EQ(a.height, b.height) << what;
    EXPECT_TRUE(close(a.rgba, b.rgba)) << what << ": the images differ" << where(a.rgba, b.rgba, 4);
    EXPECT_TRUE(same(a.depth, b.depth)) << what << ": depth differs" << where(a.depth, b.depth, 1);
    EXPECT_TRUE(close(a.normal, b.normal))
        << what << ": normals differ" << where(a.normal, b.normal, 3);
    EXPECT_TRUE(close(a.albedo, b.albedo))
        << what << ": albedo differs" << where(a.albedo, b.albedo, 3);
    EXPECT_TRUE(same(a.object_id, b.object_id)) << what << ": object ids differ";
    EXPECT_TRUE(same(a.tests, b.tests)) << what << ": per-pixel tests differ";
    auto measured = [&](const std::string& k) {
        if (k.rfind("time_ms.", 0) == 0 || k.rfind("memory.", 0) == 0 || k.rfind("device.", 0) == 0)
            return true;
        for (const std::string& i : ignore)
            if (k == i) return true;
        return false;
    };
    std::vector<std::pair<std::string, double>> ka, kb;
    for (const auto& e : a.stats.entries())
        if (!measured(e.first)) ka.push_back(e);
    for (const auto& e : b.stats.entries())
        if (!measured(e.first)) kb.push_back(e);
    // By key: a key first counted in a later band (band.samples) comes later in the list.
    std::sort(ka.begin(), ka.end());
    std::sort(kb.begin(), kb.end());
    EXPECT_EQ(ka.size(), kb.size()) << what << ": statistics keys differ";
    for (size_t i = 0; i < ka.size() && i < kb.size(); ++i) {
        EXPECT_EQ(ka[i].first, kb[i].first) << what << ": statistic " << i;
        EXPECT_EQ(ka[i].second, kb[i].second) << what << ": " << ka[i].first;
    }
}

} // namespace sheaf::test

// Scene::validate on analytic objects: what neither backend can render is an error at commit,
// not a crash or a shape that silently vanishes.
#include "core/scene/scene.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace sheaf {
namespace {

std::string error_of(const Scene& s) {
    try {
        s.validate();
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

Scene one_sphere(const Affine& shape_transform, const Affine& object_transform = {}) {
    Scene s;
    const uint32_t m = s.add_material(Material{});
    ShapeObject o;
    o.name = "ball";
    o.nodes.resize(1);
    o.nodes[0].shape = {ShapeKind::Sphere};
    o.nodes[0].material = m;
    o.nodes[0].transform = shape_transform;
    o.transform = object_transform;
    s.add_shape_object(o);
    return s;
}

// A NaN transform has a NaN determinant, which no "smaller than" test catches: such a sphere
// passed and was never seen (found by tests/fuzz/regressions/pov_nan_sphere.pov).
TEST(SceneValidate, ShapesWithTransformsThatAreNotFiniteAreErrors) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(error_of(one_sphere(Affine::scale(Vec3(1.0f)))), "");
    EXPECT_EQ(error_of(one_sphere(Affine::scale(Vec3(nan)))),
              "shape object 0 'ball': a shape's transform is not finite");
    EXPECT_EQ(error_of(one_sphere(Affine::scale(Vec3(inf)))),
              "shape object 0 'ball': a shape's transform is not finite");
    EXPECT_EQ(error_of(one_sphere(Affine::scale(Vec3(0.0f)))),
              "shape object 0 'ball': a shape's transform is singular (a zero scale)");
    EXPECT_EQ(error_of(one_sphere({}, Affine::translate(Vec3(nan, 0, 0)))),
              "shape object 0 'ball' has a transform that is not finite");
}

// A camera lens needs a finite radius, a sharp plane ahead and a camera with a plane of view;
// a conic glyph's base scale lies in [0, 1]; caustics are >= 0.
TEST(SceneValidate, LensesConicGlyphsAndCausticsAreChecked) {
    Scene s = one_sphere({});
    s.camera.lens_radius = 0.5f, s.camera.focal_distance = 3;
    EXPECT_EQ(error_of(s), "");
    s.camera.focal_distance = 0;
    EXPECT_NE(error_of(s).find("focal distance finite and > 0"), std::string::npos);
    s.camera.focal_distance = 3, s.camera.lens_radius = std::numeric_limits<float>::infinity();
    EXPECT_NE(error_of(s).find("lens radius must be finite"), std::string::npos);
    s.camera.lens_radius = 0.5f, s.camera.projection = Projection::Fisheye;
    EXPECT_NE(error_of(s).find("needs a perspective or orthographic camera"), std::string::npos);
    Scene g = one_sphere({});
    auto outline = std::make_shared<GlyphOutline>();
    outline->segments.push_back({0, 0, 0.5f, 0, 1, 0});
    outline->segments.push_back({1, 0, 0.5f, 0.5f, 0, 1});
    outline->segments.push_back({0, 1, 0, 0.5f, 0, 0});
    g.shape_objects[0].nodes[0].shape = {ShapeKind::Glyph, 1.5f, 1};
    g.shape_objects[0].nodes[0].glyph = outline;
    EXPECT_NE(error_of(g).find("a conic glyph's base scale is not in [0, 1]"), std::string::npos);
    g.shape_objects[0].nodes[0].shape.a = 0.25f;
    EXPECT_EQ(error_of(g), "");
    g.materials[0].caustics = -1;
    EXPECT_EQ(error_of(g), "material 0 has caustics that are not finite or < 0");
}

// Found by the C ABI fuzzer: an infinite background or finish value passed commit and put an
// infinite pixel in the frame.
TEST(SceneValidate, BackgroundAndFinishValuesThatAreNotFiniteAreErrors) {
    const float inf = std::numeric_limits<float>::infinity();
    Scene s = one_sphere({});
    s.background = Vec3(0, inf, 0);
    EXPECT_EQ(error_of(s), "the background colour is not finite");
    s.background = Vec3(0.0f);
    s.materials[0].diffuse = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(error_of(s), "material 0 has a finish or interior value that is not finite");
    s.materials[0].diffuse = 0.7f, s.materials[0].mirror_color = Vec3(inf);
    EXPECT_EQ(error_of(s), "material 0 has a reflection or fade colour that is not finite");
    s.materials[0].mirror_color = Vec3(1.0f);
    EXPECT_EQ(error_of(s), "");
}

// Found by the C ABI fuzzer: a point light at 1e30 passed commit, and every shadow ray's
// direction overflowed to NaN. Lights, the camera and placed meshes lie within kMaxCoordinate.
TEST(SceneValidate, PositionsBeyondReachAreErrors) {
    Scene s;
    Mesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    quad.indices = {0, 1, 2};
    s.add_mesh(quad);
    s.add_material(Material{});
    Object o;
    s.add_object(o);
    s.add_light(Light{});
    EXPECT_EQ(error_of(s), "");
    s.lights[0].position = Vec3(1e30f, 0, 0);
    EXPECT_EQ(error_of(s),
              "light 0's position or direction lies farther than 1e12 from the origin");
    s.lights[0].position = Vec3(0.0f);
    s.camera.look_at = Vec3(0, 0, -2e12f);
    EXPECT_NE(error_of(s).find("the camera's position, look_at or up lies farther"),
              std::string::npos);
    s.camera = Camera{};
    s.objects[0].transform = Affine::scale(Vec3(1e13f));
    EXPECT_EQ(error_of(s), "object 0 reaches farther than 1e12 from the origin once placed");
    s.objects[0].transform = Affine{};
    s.meshes[0].positions[1] = Vec3(-5e12f, 0, 0);
    EXPECT_EQ(error_of(s), "mesh 0: vertex 1 lies farther than 1e12 from the origin");
}

// CSG is evaluated recursively on both backends: deeper than kMaxCsgNesting is an error (5,000
// nested differences overflowed the CPU backend's stack).
TEST(SceneValidate, CsgDeeperThanTheLimitIsAnError) {
    auto nested = [](int levels) {
        Scene s;
        const uint32_t m = s.add_material(Material{});
        ShapeObject o;
        o.name = "deep";
        for (int i = 0; i < levels; ++i) { // node 2i: a difference of node 2i+1 minus node 2i+2
            CsgNode d;
            d.op = CsgOp::Difference;
            d.children = {uint32_t(2 * i + 1), uint32_t(2 * i + 2)};
            CsgNode leaf;
            leaf.shape = {ShapeKind::Sphere};
            leaf.material = m;
            leaf.transform = Affine::scale(Vec3(0.1f));
            o.nodes.push_back(d);
            o.nodes.push_back(leaf);
        }
        CsgNode last;
        last.shape = {ShapeKind::Sphere};
        last.material = m;
        o.nodes.push_back(last);
        s.add_shape_object(o);
        return s;
    };
    EXPECT_EQ(error_of(nested(kMaxCsgNesting)), "");
    EXPECT_EQ(error_of(nested(kMaxCsgNesting + 1)),
              "shape object 0 'deep': CSG nested 65 levels deep, more than 64");
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// Warps, pigment patterns and light groups: what the POV reader cannot produce but another
// host could is an error, not a read past an array or a pigment that holds itself.
TEST(SceneValidate, WarpsPigmentPatternsAndLightGroupsAreChecked) {
    auto patterned = [](const Warp& w) {
        Scene s = one_sphere({});
        Pigment pg;
        pg.solid = false;
        pg.pattern.kind = PatternKind::Bozo;
        pg.pattern.warp_count = 1;
        s.pigments.push_back(pg);
        s.warps.push_back(w);
        return s;
    };
    Warp repeat;
    repeat.kind = WarpKind::Repeat;
    repeat.f[0] = 2;
    EXPECT_EQ(error_of(patterned(repeat)), "");
    repeat.f[0] = 0;
    EXPECT_EQ(error_of(patterned(repeat)),
              "pigment 0: a repeat warp needs an axis and a width other than 0");
    Warp hole;
    hole.kind = WarpKind::BlackHole;
    EXPECT_EQ(error_of(patterned(hole)), "pigment 0: a black hole's radius must be above 0");
    Warp cyl;
    cyl.kind = WarpKind::Cylindrical;
    cyl.b = Vec3(0, 2, 0);
    EXPECT_EQ(error_of(patterned(cyl)), "pigment 0: a warp's orientation must be a unit vector");
    Scene outside = patterned(Warp());
    outside.warps.clear();
    EXPECT_EQ(error_of(outside), "pigment 0: its warps lie outside the scene's warps");

    Scene self = one_sphere({});
    Pigment pp;
    pp.solid = false;
    pp.pattern.kind = PatternKind::PigmentPattern;
    pp.pattern.pigment = 0; // itself
    self.pigments.push_back(pp);
    EXPECT_EQ(error_of(self),
              "pigment 0: its pigment pattern names pigment 0, which is not an earlier pigment");

    Scene lit = one_sphere({});
    Light l;
    l.group = kMaxLightGroup + 1;
    lit.add_light(l);
    EXPECT_EQ(error_of(lit), "light 0: a light group above 32767");
    // Which lights reach which surfaces.
    Light grouped;
    grouped.group = 3;
    EXPECT_TRUE(light_reaches_group(grouped, 3));
    EXPECT_FALSE(light_reaches_group(grouped, 0));
    EXPECT_FALSE(light_reaches_group(Light(), 3));
    EXPECT_TRUE(light_reaches_group(Light(), 3 | kGlobalLights));
    EXPECT_TRUE(light_reaches_group(Light(), 0));
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

TEST(SceneValidate, ScatteringMediaAreChecked) {
    auto with = [](const Medium& md) {
        Scene s = one_sphere({});
        s.media.push_back(md);
        return s;
    };
    Medium md;
    md.scattering = Vec3(0.1f);
    md.scatter_type = ScatterType::HenyeyGreenstein;
    md.eccentricity = 0.9f;
    EXPECT_EQ(error_of(with(md)), "");
    md.eccentricity = 1.0f;
    EXPECT_EQ(error_of(with(md)), "medium 0: the eccentricity must lie strictly between -1 and 1");
    md.eccentricity = 0;
    md.scatter_type = ScatterType(6);
    EXPECT_EQ(error_of(with(md)), "medium 0: the scattering type must be 1..5");
    md.scatter_type = ScatterType::Isotropic;
    md.scattering = Vec3(0.1f, -0.1f, 0);
    EXPECT_EQ(error_of(with(md)), "medium 0: scattering and extinction must be finite and >= 0");
    md.scattering = Vec3(0.1f);
    md.extinction = NAN;
    EXPECT_EQ(error_of(with(md)), "medium 0: scattering and extinction must be finite and >= 0");
    md.extinction = 1;
    md.light_samples = 0;
    EXPECT_EQ(error_of(with(md)), "medium 0: samples and light_samples must lie in 1..1024");
}

TEST(SceneValidate, DensityGridsAreChecked) {
    Scene s = one_sphere({});
    s.density_voxels = {0, 0.5f, 1, 0.25f};
    DensityGrid g;
    g.nx = 2, g.ny = 2, g.nz = 1, g.interpolation = 2;
    s.density_grids.push_back(g);
    Pigment pg;
    pg.solid = false;
    pg.pattern.kind = PatternKind::DensityFile;
    pg.pattern.grid = 0;
    pg.first = uint32_t(s.pigment_entries.size());
    pg.count = 1;
    s.pigment_entries.emplace_back();
    s.pigments.push_back(pg);
    EXPECT_EQ(error_of(s), "");
    s.pigments.back().pattern.grid = 1;
    EXPECT_EQ(error_of(s), "pigment " + std::to_string(s.pigments.size() - 1) +
                               ": its density_file names grid 1, which does not exist");
    s.pigments.back().pattern.grid = 0;
    s.density_grids[0].first = 1; // four voxels from 1 pass the end
    EXPECT_EQ(error_of(s), "density grid 0: its voxels lie outside the density voxels");
    s.density_grids[0].first = 0;
    s.density_voxels[2] = 1.5f;
    EXPECT_EQ(error_of(s), "density voxel 2: its value is not in [0, 1]");
    s.density_voxels[2] = 1;
    s.density_grids[0].interpolation = 3;
    EXPECT_NE(error_of(s).find("an interpolation of 0, 1 or 2"), std::string::npos);
}

} // namespace
} // namespace sheaf

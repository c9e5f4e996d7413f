// Tests of objects: each shape on its canonical form, CSG trees, meshes, object references,
// transforms (POV-Ray's rotation order, the z mirror), textures to materials, and unsupported
// features as warnings (errors when strict).
#include "io/pov/builder.h"
#include "tests/support/pov_test_util.h"

#include "core/scene/analytic.h"
#include "core/scene/prepared_scene.h"

#include <cmath>
#include <map>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::first_hit;
using test::load_text;
using test::TempDir;

void expect_near(Vec3 a, Vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

/// Where the canonical point `p` of the single shape of `r` lands in POV-Ray coordinates.
Vec3 pov_point(const PovResult& r, Vec3 p) {
    const ShapeObject& o = r.scene.shape_objects.at(0);
    const Vec3 world = o.transform.point(o.nodes.at(0).transform.point(p));
    return pov_to_sheaf().point(world); // the mirror is its own inverse
}

TEST(PovObjects, SphereAndTheMirror) {
    const PovResult r = load_text("sphere { <1, 2, 3>, 0.5 }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const ShapeObject& o = r.scene.shape_objects[0];
    EXPECT_EQ(o.nodes[0].shape.kind, ShapeKind::Sphere);
    // Sheaf world: z mirrored.
    expect_near(o.transform.point(o.nodes[0].transform.point({0, 0, 0})), {1, 2, -3});
    expect_near(pov_point(r, {1, 0, 0}), {1.5f, 2, 3});
    EXPECT_TRUE(r.warnings.empty());
}

TEST(PovObjects, BoxCylinderCone) {
    PovResult r = load_text("box { <-1, 0, 2>, <3, 2, 4> }");
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].shape.kind, ShapeKind::Box);
    expect_near(pov_point(r, {-1, -1, -1}), {-1, 0, 2});
    expect_near(pov_point(r, {1, 1, 1}), {3, 2, 4});

    r = load_text("cylinder { <0, 1, 0>, <0, 4, 0>, 2 open }");
    const Shape& cyl = r.scene.shape_objects[0].nodes[0].shape;
    EXPECT_EQ(cyl.kind, ShapeKind::Cylinder);
    EXPECT_TRUE(cyl.open);
    expect_near(pov_point(r, {0, 0, 0}), {0, 1, 0});
    expect_near(pov_point(r, {0, 0, 1}), {0, 4, 0});
    EXPECT_NEAR(length(pov_point(r, {1, 0, 0}) - Vec3(0, 1, 0)), 2, 1e-5);

    r = load_text("cone { <0, 0, 0>, 1, <2, 0, 0>, 0.5 }");
    const Shape& cone = r.scene.shape_objects[0].nodes[0].shape;
    EXPECT_EQ(cone.kind, ShapeKind::Cone);
    EXPECT_FLOAT_EQ(cone.a, 1);
    EXPECT_FLOAT_EQ(cone.b, 0.5f);
    EXPECT_FALSE(cone.open);
    expect_near(pov_point(r, {0, 0, 1}), {2, 0, 0});
}

TEST(PovObjects, DiscPlaneTorus) {
    PovResult r = load_text("disc { <0, 1, 0>, y, 2, 0.5 }");
    const Shape& disc = r.scene.shape_objects[0].nodes[0].shape;
    EXPECT_EQ(disc.kind, ShapeKind::Disc);
    EXPECT_FLOAT_EQ(disc.a, 0.25f);
    expect_near(pov_point(r, {0, 0, 1}), {0, 2, 0}); // the normal
    EXPECT_NEAR(length(pov_point(r, {1, 0, 0}) - Vec3(0, 1, 0)), 2, 1e-5);

    r = load_text("plane { <0, 2, 0>, -1 }"); // y = -1, inside below
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].shape.kind, ShapeKind::Plane);
    expect_near(pov_point(r, {0, 0, 0}), {0, -1, 0});
    expect_near(pov_point(r, {0, 0, 1}), {0, 0, 0}); // local +z is the outside normal (+y)

    r = load_text("torus { 2, 0.5 }");
    const Shape& torus = r.scene.shape_objects[0].nodes[0].shape;
    EXPECT_EQ(torus.kind, ShapeKind::Torus);
    EXPECT_FLOAT_EQ(torus.a, 0.25f);
    expect_near(pov_point(r, {0, 0, 1}), {0, 2, 0}); // POV-Ray's torus is around y
    EXPECT_NEAR(std::fabs(pov_point(r, {1, 0, 0}).x), 2, 1e-5);
}

TEST(PovObjects, TransformsFollowPovRay) {
    // rotate <0, 0, 90> turns +x into +y; rotations apply x, then y, then z.
    PovResult r = load_text("sphere { <1, 0, 0>, 1 rotate <0, 0, 90> }");
    expect_near(pov_point(r, {0, 0, 0}), {0, 1, 0});
    r = load_text("sphere { <0, 1, 0>, 1 rotate <90, 90, 0> }");
    // x by 90: (0,1,0) -> (0,0,1); then y by 90: (0,0,1) -> (1,0,0).
    expect_near(pov_point(r, {0, 0, 0}), {1, 0, 0});
    r = load_text("sphere { 0, 1 scale <1, 2, 3> translate <1, 1, 1> }");
    expect_near(pov_point(r, {1, 1, 1}), {2, 3, 4});
    r = load_text("sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 5,6,7> }");
    expect_near(pov_point(r, {0, 0, 0}), {5, 6, 7});
    r = load_text("#declare T = transform { translate x rotate z*90 }\n"
                  "sphere { 0, 1 transform T transform { T inverse } translate y }");
    expect_near(pov_point(r, {0, 0, 0}), {0, 1, 0});
}

TEST(PovObjects, CsgTrees) {
    const PovResult r =
        load_text("difference {\n"
                  "  box { -1, 1 }\n"
                  "  intersection { sphere { 0, 1.2 } cylinder { -2*x, 2*x, 0.5 } }\n"
                  "  sphere { y, 0.3 inverse }\n"
                  "  translate x\n"
                  "}\n");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const ShapeObject& o = r.scene.shape_objects[0];
    ASSERT_EQ(o.nodes.size(), 6u);
    const CsgNode& root = o.nodes[o.root];
    EXPECT_EQ(root.op, CsgOp::Difference);
    ASSERT_EQ(root.children.size(), 3u);
    EXPECT_EQ(o.nodes[root.children[0]].shape.kind, ShapeKind::Box);
    EXPECT_EQ(o.nodes[root.children[1]].op, CsgOp::Intersection);
    EXPECT_TRUE(o.nodes[root.children[2]].inverse);
    for (size_t i = 0; i < o.nodes.size(); ++i)
        for (uint32_t c : o.nodes[i].children) EXPECT_GT(c, i); // parents first
    // The CSG's translate reached the leaves.
    const Vec3 c = pov_to_sheaf().point(
        o.transform.point(o.nodes[root.children[0]].transform.point({0, 0, 0})));
    expect_near(c, {1, 0, 0});
    EXPECT_NO_THROW(r.scene.validate());
}

// A solid scaled to a segment or a point shows nothing, in POV-Ray either: among unions it is
// left out silently, and an intersection with it or a difference from it is empty
// (advanced/swirlbox.pov's last ring, scaled by a rounding error of 1 - 1 in x and z; a
// scale of exactly 0 is 1, as in POV-Ray). A flat one (scaled to a plane) would show, and is
// warned.
TEST(PovObjects, SolidsSqueezedToALineVanishExactly) {
    PovResult r =
        load_text("sphere { 0, 1 scale <1e-25, 1, 1e-25> }\n"
                  "union { box { -1, 1 } sphere { 0, 1 scale <1e-30, 2, 1e-30> rotate 30*x } }\n"
                  "intersection { box { -1, 1 } box { -1, 1 inverse } scale <1e-25, 1, 1e-25> }\n"
                  "difference { box { -1, 1 scale <1, 1e-25, 1e-25> } sphere { 0, 2 } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0);
    ASSERT_EQ(r.scene.shape_objects.size(), 1u); // the box of the union
    EXPECT_EQ(r.scene.shape_objects[0].nodes.at(0).shape.kind, ShapeKind::Box);
    // Not exact where a dropped leaf would change what is left: warned, as a flat solid is.
    for (const std::string& warned :
         {"sphere { 0, 1 scale <1e-25, 1, 1> }",
          "intersection { box { -1, 1 } sphere { 0, 1 scale <1e-25, 1, 1e-25> inverse } inverse }",
          "difference { box { -1, 1 } sphere { 0, 1 scale <1e-25, 1, 1e-25> } }"}) {
        r = load_text(warned);
        ASSERT_EQ(r.warnings.size(), 1u) << warned;
        EXPECT_NE(r.warnings[0].find("unsupported degenerate shape"), std::string::npos);
    }
}

TEST(PovObjects, UnionsSplitAndMergesStay) {
    PovResult r = load_text("union { sphere { 0, 1 } box { 2, 3 } }");
    EXPECT_EQ(r.scene.shape_objects.size(), 2u);
    r = load_text("merge { sphere { 0, 1 } sphere { x, 1 } }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].op, CsgOp::Merge);
}

TEST(PovObjects, AUnionInsideCsgSeenThroughGlassIsWarned) {
    // Inside an intersection or difference a union is drawn as a merge: its members' inner
    // surfaces are left out, which shows only where its material lets light through.
    const std::string u = "difference { union { sphere { 0, 1 } sphere { x, 1 } } "
                          "box { <-3, -3, -3>, <3, 0, 3> } pigment { ";
    const PovResult clear = load_text(u + "rgbf <1, 1, 1, 0.9> } }");
    ASSERT_EQ(clear.warnings.size(), 1u);
    EXPECT_NE(clear.warnings[0].find("scene.pov:1:14: warning: approximated union inside an "
                                     "intersection or difference: drawn as a merge"),
              std::string::npos)
        << clear.warnings[0];
    EXPECT_TRUE(load_text(u + "rgb 1 } }").warnings.empty()); // opaque: nothing to see
    // A union of separate objects is exact, clear or not.
    EXPECT_TRUE(load_text("union { sphere { 0, 1 } sphere { x, 1 } pigment { rgbf 0.9 } }")
                    .warnings.empty());
    PovOptions strict;
    strict.strict = true;
    EXPECT_NE(test::error_of(u + "rgbf 0.9 } }", strict).find("error: approximated union"),
              std::string::npos);
}

TEST(PovObjects, TexturesAndMaterials) {
    const PovResult r = load_text(
        "global_settings { assumed_gamma 1.0 }\n"
        "#declare Glass = material { texture { pigment { rgbf <1, 1, 1, 0.9> }\n"
        "  finish { phong 0.8 phong_size 120 reflection 0.2 } } interior { ior 1.33 } }\n"
        "union { sphere { 0, 1 material { Glass } }\n"
        "  sphere { x * 3, 1 }\n"
        "  pigment { color rgb <1, 0, 0> } finish { ambient 0.2 diffuse 0.5 emission 2 } }\n");
    ASSERT_EQ(r.scene.shape_objects.size(), 2u);
    const Material& glass = r.scene.materials[r.scene.shape_objects[0].nodes[0].material];
    EXPECT_FLOAT_EQ(glass.transmission, 0.9f);
    EXPECT_FLOAT_EQ(glass.specular, 0.8f);
    EXPECT_FLOAT_EQ(glass.phong_exponent, 120);
    EXPECT_FLOAT_EQ(glass.mirror, 0.2f);
    EXPECT_FLOAT_EQ(glass.ior, 1.33f);
    const Material& red = r.scene.materials[r.scene.shape_objects[1].nodes[0].material];
    EXPECT_FLOAT_EQ(red.color.x, 1);
    EXPECT_FLOAT_EQ(red.color.y, 0);
    EXPECT_FLOAT_EQ(red.ambient, 0.2f);
    EXPECT_FLOAT_EQ(red.diffuse, 0.5f);
    EXPECT_FLOAT_EQ(red.emission.x, 2); // pigment times emission
    EXPECT_TRUE(r.warnings.empty());
}

TEST(PovObjects, LegacyGammaComputesInItsOwnSpace) {
    // As POV-Ray 3.7: colours stay as written and the frame is decoded by the gamma at the end.
    PovResult r = load_text("global_settings { assumed_gamma 2.2 }\n"
                            "sphere { 0, 1 pigment { rgb 0.5 } }\nbackground { rgb 0.5 }");
    EXPECT_FLOAT_EQ(r.scene.materials[r.scene.shape_objects[0].nodes[0].material].color.x, 0.5f);
    EXPECT_FLOAT_EQ(r.scene.background.x, 0.5f);
    EXPECT_FLOAT_EQ(r.scene.working_gamma, 2.2f);
    EXPECT_FLOAT_EQ(load_text("#version 3.6;").scene.working_gamma, 2.2f);
    EXPECT_FLOAT_EQ(load_text("#version 3.7;").scene.working_gamma, 1.0f);
    // No #version anywhere: a pre-3.7 scene, gamma correction off (POV-Ray 3.7's warning).
    EXPECT_FLOAT_EQ(load_text("sphere { 0, 1 }").scene.working_gamma, 2.2f);
    // A #version in between that comes back to 3.7 (as the standard includes do) is 3.7.
    EXPECT_FLOAT_EQ(
        load_text("#declare V = version; #version 3.5; #version V;").scene.working_gamma, 1.0f);
}

TEST(PovObjects, UnsupportedPatternsAreAveragedWithAWarning) {
    const PovResult r =
        load_text("sphere { 0, 1 pigment { tiling 12 color_map { [0 rgb 0] [1 rgb <1, "
                  "0.5, 0>] } } }\n"
                  "box { 0, 1 pigment { checker rgb 1, rgb 0 scale 0.5 } normal { bumps 0.3 } }\n");
    const Material& m = r.scene.materials[r.scene.shape_objects[0].nodes[0].material];
    EXPECT_FLOAT_EQ(m.color.x, 0.5f);
    EXPECT_FLOAT_EQ(m.color.y, 0.25f);
    EXPECT_EQ(m.pigment, -1);
    const Material& c = r.scene.materials[r.scene.shape_objects[1].nodes[0].material];
    EXPECT_GE(c.pigment, 0); // checker and bumps are supported
    EXPECT_GE(c.normal, 0);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:25: warning: unsupported pigment pattern 'tiling'"),
              std::string::npos);
}

TEST(PovObjects, TrianglesMeshesPolygons) {
    const PovResult r = load_text(
        "triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
        "triangle { <0,0,1>, <1,0,1>, <0,1,1> }\n"
        "smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,0,1>, y }\n"
        "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } smooth_triangle { 0, y, x, y, z, y }\n"
        "  inside_vector y translate x }\n"
        "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
        "  normal_vectors { 1, z } face_indices { 2, <0,1,2>, <0,2,3> } normal_indices { 2, "
        "<0,0,0>, <0,0,0> } }\n"
        "polygon { 5, <0,0>, <2,0>, <2,2>, <1,1>, <0,2> }\n");
    // Two loose triangles share one object; the others are their own meshes.
    ASSERT_EQ(r.scene.objects.size(), 5u);
    size_t total = 0;
    for (const Object& o : r.scene.objects) total += r.scene.meshes[o.mesh].triangle_count();
    EXPECT_EQ(total, 2u + 1u + 2u + 2u + 3u);
    const Mesh& smooth = r.scene.meshes[r.scene.objects[0].mesh];
    EXPECT_EQ(smooth.normals.size(), smooth.positions.size());
    EXPECT_NO_THROW(r.scene.validate());
    EXPECT_TRUE(r.warnings.empty());
}

/// The uv coordinates of corner k (0, 1, 2) of triangle t of mesh m.
std::pair<float, float> corner_uv(const Mesh& m, size_t t, int k) {
    const uint32_t i = m.indices[3 * t + size_t(k)];
    return {m.uvs[2 * i], m.uvs[2 * i + 1]};
}

TEST(PovObjects, MeshesKeepTheirUvCoordinates) {
    using UV = std::pair<float, float>;
    // mesh: a triangle's uv_vectors; a triangle without takes (0, 0), as in POV-Ray.
    PovResult r = load_text("mesh { triangle { 0, x, y uv_vectors <0.5,0>, <1,0.25>, <0,1> }\n"
                            "       triangle { 0, y, -x } }\n");
    const Mesh& m = r.scene.meshes[r.scene.objects[0].mesh];
    ASSERT_EQ(m.uvs.size(), 2 * m.positions.size());
    EXPECT_EQ(corner_uv(m, 0, 0), UV(0.5f, 0.0f));
    EXPECT_EQ(corner_uv(m, 0, 1), UV(1.0f, 0.25f));
    EXPECT_EQ(corner_uv(m, 0, 2), UV(0.0f, 1.0f));
    EXPECT_EQ(corner_uv(m, 1, 1), UV(0.0f, 0.0f));
    // A mesh without any keeps none.
    r = load_text("mesh { triangle { 0, x, y } }");
    EXPECT_TRUE(r.scene.meshes[0].uvs.empty());

    // mesh2: uv_vectors by the face indices (shared vertices) ...
    const std::string quad = "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n";
    r = load_text(quad + "uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }\n"
                         "face_indices { 2, <0,1,2>, <0,2,3> } }");
    const Mesh& shared = r.scene.meshes[0];
    EXPECT_EQ(shared.positions.size(), 4u);
    EXPECT_EQ(corner_uv(shared, 1, 1), UV(1.0f, 1.0f));
    EXPECT_EQ(corner_uv(shared, 1, 2), UV(0.0f, 1.0f));
    // ... or by uv_indices of their own: corners of their own.
    r = load_text(quad + "uv_vectors { 2, <0.25,0.5>, <0.75,1> }\n"
                         "face_indices { 2, <0,1,2>, <0,2,3> }\n"
                         "uv_indices { 2, <0,1,1>, <1,0,0> } }");
    const Mesh& own = r.scene.meshes[0];
    EXPECT_EQ(own.triangle_count(), 2u);
    EXPECT_EQ(own.uvs.size(), 2 * own.positions.size());
    EXPECT_EQ(corner_uv(own, 0, 0), UV(0.25f, 0.5f));
    EXPECT_EQ(corner_uv(own, 0, 2), UV(0.75f, 1.0f));
    EXPECT_EQ(corner_uv(own, 1, 0), UV(0.75f, 1.0f));
    EXPECT_EQ(corner_uv(own, 1, 1), UV(0.25f, 0.5f));
    EXPECT_EQ(own.positions[own.indices[5]], Vec3(0, 1, 0));
    EXPECT_NO_THROW(r.scene.validate());

    // Wrong counts and indices are errors at the mesh.
    EXPECT_NE(error_of(quad + "uv_vectors { 1, <0,0> } face_indices { 1, <0,1,2> } "
                              "uv_indices { 1, <0,0,3> } }")
                  .find("index 3 out of range (1)"),
              std::string::npos);
    EXPECT_NE(error_of(quad + "uv_vectors { 1, <0,0> } face_indices { 1, <0,1,2> } "
                              "uv_indices { 2, <0,0,0>, <0,0,0> } }")
                  .find("uv_indices and face_indices differ in count"),
              std::string::npos);
}

// mesh2's texture_list and a mesh triangle's own texture: the faces that name a texture wear
// it (one mesh object per texture), the others the object's, all moved with the object.
TEST(PovObjects, FacesWearTheTexturesTheyName) {
    const std::string quad = "vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n";
    PovResult r = load_text("mesh2 { " + quad +
                            "texture_list { 2, texture { pigment { rgb <1,0,0> } } texture { "
                            "pigment { rgb <0,0,1> } } }\n"
                            "face_indices { 3, <0,1,2>, 1, <0,2,3>, 0, <0,1,3> }\n"
                            "pigment { rgb <0,1,0> } translate 5*x }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    ASSERT_EQ(r.scene.objects.size(), 3u);
    std::vector<Vec3> colours;
    size_t faces = 0;
    for (const Object& o : r.scene.objects) {
        colours.push_back(r.scene.materials[o.material].color);
        faces += r.scene.meshes[o.mesh].triangle_count();
        EXPECT_FLOAT_EQ(o.transform.point(Vec3(0)).x, 5.0f);
    }
    EXPECT_EQ(faces, 3u);
    // The object's own (face 2), then textures 0 and 1.
    EXPECT_EQ(colours[0], Vec3(0, 1, 0));
    EXPECT_EQ(colours[1], Vec3(1, 0, 0));
    EXPECT_EQ(colours[2], Vec3(0, 0, 1));
    // A texture for each corner: the first is used, warned.
    r = load_text(
        "mesh2 { " + quad +
        "texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }\n"
        "face_indices { 1, <0,1,2>, 0, 1, 1 } }\n");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("a texture for each corner"), std::string::npos);
    EXPECT_NE(error_of("mesh2 { " + quad +
                       "texture_list { 1, texture { pigment { rgb 1 } } }\n"
                       "face_indices { 1, <0,1,2>, 3 } }\n")
                  .find("mesh2 face 0 names texture 3 of a texture_list of 1"),
              std::string::npos);
    // A mesh triangle's own texture.
    r = load_text("mesh { triangle { 0, x, y texture { pigment { rgb <1,0,0> } } }\n"
                  "  triangle { x, y, <1,1,0> } pigment { rgb <0,0,1> } }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
    ASSERT_EQ(r.scene.objects.size(), 2u);
    EXPECT_EQ(r.scene.materials[r.scene.objects[0].material].color, Vec3(0, 0, 1));
    EXPECT_EQ(r.scene.materials[r.scene.objects[1].material].color, Vec3(1, 0, 0));
}

/// The area of a mesh's triangles.
float mesh_area(const Mesh& m) {
    float a = 0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
        a += 0.5f * length(cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                 m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]));
    return a;
}

TEST(PovObjects, PolygonsFillTheirOutlinesEvenOdd) {
    // POV-Ray's polygon.pov: an O (a 4 x 6 frame round a 2 x 4 hole) and a P (its hole 2 x 1).
    PovResult r = load_text("polygon { 10, <0, 0>, <0, 6>, <4, 6>, <4, 0>, <0, 0>,\n"
                            "  <1, 1>, <1, 5>, <3, 5>, <3, 1>, <1, 1> }\n"
                            "polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1, 0>, <0, 0>,"
                            "  <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4> }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.objects.size(), 2u);
    EXPECT_NEAR(mesh_area(r.scene.meshes[r.scene.objects[0].mesh]), 24 - 8, 1e-4);
    EXPECT_NEAR(mesh_area(r.scene.meshes[r.scene.objects[1].mesh]), 15 - 2, 1e-4);
    // Two holes (either way round) and an island in one of them; a square beside it all.
    r = load_text("polygon { 25, <0, 0>, <10, 0>, <10, 10>, <0, 10>, <0, 0>,\n"
                  "  <1, 1>, <4, 1>, <4, 4>, <1, 4>, <1, 1>,\n"
                  "  <6, 6>, <6, 9>, <9, 9>, <9, 6>, <6, 6>,\n"
                  "  <2, 2>, <3, 2>, <3, 3>, <2, 3>, <2, 2>,\n"
                  "  <20, 0>, <21, 0>, <21, 1>, <20, 1>, <20, 0> }\n");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_NEAR(mesh_area(r.scene.meshes[r.scene.objects[0].mesh]), 100 - 9 - 9 + 1 + 1, 1e-3);
}

TEST(PovObjects, ObjectReferences) {
    const PovResult r = load_text("#declare Ball = sphere { 0, 1 pigment { rgb x } }\n"
                                  "object { Ball translate y*2 }\n"
                                  "object { Ball pigment { rgb y } }\n"
                                  "#declare Arr = array[1] { box { 0, 1 } }\nobject { Arr[0] }\n");
    ASSERT_EQ(r.scene.shape_objects.size(), 3u);
    expect_near(pov_point(r, {0, 0, 0}), {0, 2, 0});
    EXPECT_FLOAT_EQ(r.scene.materials[r.scene.shape_objects[1].nodes[0].material].color.y, 1);
    EXPECT_EQ(r.scene.shape_objects[2].nodes[0].shape.kind, ShapeKind::Box);
}

TEST(PovObjects, MeshesInsideCsg) {
    const PovResult r = load_text("union { sphere { 0, 1 } triangle { 0, x, y } }\n"
                                  "difference { box { -1, 1 } triangle { 0, x, y } }\n");
    EXPECT_EQ(r.scene.objects.size(), 1u);       // the union's triangle, plainly
    EXPECT_EQ(r.scene.shape_objects.size(), 2u); // sphere, and the box without the triangle
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:2:28: warning: unsupported mesh inside intersection or "
                                 "difference"),
              std::string::npos);
}

TEST(PovObjects, ClippedByIsAnOpenSurface) {
    const PovResult r =
        load_text("sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { box { -1, 1 } } }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const ShapeObject& o = r.scene.shape_objects[0];
    EXPECT_EQ(o.nodes[o.root].op, CsgOp::Clip);
    EXPECT_EQ(o.nodes[o.root].children.size(), 2u);
    // The lower half of the sphere, open at the top: a ray down the y axis from above passes
    // the cut (no cap) and meets the inside of the bowl at y = -1.
    const PreparedScene p = prepare_scene(r.scene);
    Ray down;
    down.origin = Vec3(0, 3, 0), down.dir = Vec3(0, -1, 0), down.tmin = 0, down.tmax = 100;
    AnalyticHit h;
    ASSERT_TRUE(analytic_first_hit(p, 0, down, h));
    EXPECT_NEAR(h.t, 4.0f, 1e-5);
    // A ray through the upper half misses the clipped sphere entirely.
    Ray across;
    across.origin = Vec3(-3, 0.5f, 0), across.dir = Vec3(1, 0, 0), across.tmin = 0;
    across.tmax = 100;
    EXPECT_FALSE(analytic_first_hit(p, 0, across, h));
}

TEST(PovObjects, QuadricCubicQuarticPoly) {
    // A sphere of radius 2 around <0, 1, 0>.
    PovResult r = load_text("quadric { <1, 1, 1>, <0, 0, 0>, <0, -2, 0>, -3 }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].shape.kind, ShapeKind::Poly);
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 2.0f, 1e-5);
    EXPECT_NEAR(first_hit(r, {-5, 1, 0}, {1, 0, 0}), 3.0f, 1e-5);
    // An infinite cylinder along y, radius 1 (shapes.inc's Cylinder_Y), moved by a transform.
    r = load_text("quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 translate <3, 0, 0> }");
    EXPECT_NEAR(first_hit(r, {0, 50, 0}, {1, 0, 0}), 2.0f, 1e-5);
    EXPECT_LT(first_hit(r, {0, 50, 0}, {0, 0, 1}), 0.0f);
    // POV-Ray's term order for order 2: x^2, xy, xz, x, y^2, yz, y, z^2, z, 1.
    r = load_text("poly { 2 <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> sturm }"); // no comma: as POV-Ray
    EXPECT_NEAR(first_hit(r, {0, 0, -4}, {0, 0, 1}), 3.0f, 1e-5);
    // A torus around y (major 1, minor 0.25) as a quartic: (|p|^2 + 1 - r^2)^2 - 4 (x^2 + z^2).
    std::string c(35, '0');
    std::string quartic = "quartic { <";
    const double k = 1 - 0.0625;
    // x^4 x^2y^2 x^2z^2 x^2 y^4 y^2z^2 y^2 z^4 z^2 1
    const std::map<int, double> terms = {{0, 1},          {4, 2},     {7, 2},      {9, 2 * k - 4},
                                         {20, 1},         {23, 2},    {25, 2 * k}, {30, 1},
                                         {32, 2 * k - 4}, {34, k * k}};
    for (int t = 0; t < 35; ++t)
        quartic += (t ? ", " : "") + std::to_string(terms.count(t) ? terms.at(t) : 0.0);
    r = load_text(quartic + "> }");
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_NEAR(first_hit(r, {0, 3, 1}, {0, -1, 0}), 2.75f, 1e-4); // top of the tube
    EXPECT_NEAR(first_hit(r, {-3, 0, 0}, {1, 0, 0}), 1.75f, 1e-4); // outer equator
    EXPECT_LT(first_hit(r, {0, 3, 0}, {0, -1, 0}), 0.0f);          // through the hole

    EXPECT_EQ(error_of("cubic { <1, 2, 3> }"),
              "scene.pov:1:9: error: 'cubic' needs 20 coefficients, found 3");
    EXPECT_EQ(error_of("quadric { <0, 0, 0>, <0, 0, 0>, <0, 0, 0>, 0 }"),
              "scene.pov:1:1: error: every coefficient of the quadric is zero");
    EXPECT_EQ(error_of("poly { 1, <1, 2> }"),
              "scene.pov:1:8: error: a poly's order must be a whole number from 2 to 15");
    // Orders above 4 are left out with a warning, like other unsupported objects.
    r = load_text("poly { 5, <1, 2, 3> }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:1: warning: unsupported poly of order 5"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

TEST(PovObjects, Superellipsoid) {
    // <1, 1>: the unit ball; <0.2, 0.2>: nearly the box [-1, 1]^3, round at its corners.
    PovResult r = load_text("superellipsoid { <1, 1> scale 2 translate y }");
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(r.scene.shape_objects.at(0).nodes.at(0).shape.kind, ShapeKind::Superellipsoid);
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 2.0f, 1e-4);
    EXPECT_NEAR(first_hit(r, {0, 1, -5}, {0, 0, 1}), 3.0f, 1e-4);
    r = load_text("superellipsoid { <0.2, 0.2> }");
    EXPECT_NEAR(first_hit(r, {0.5f, 0.5f, -5}, {0, 0, 1}), 4.0f, 1e-3);
    const Vec3 corner = normalize(Vec3(1, 1, 1));
    const float t = first_hit(r, corner * 5.0f, -corner);
    EXPECT_GT(t, 5.0f - std::sqrt(3.0f)); // the corner is rounded off
    EXPECT_LT(t, 4.0f);
    EXPECT_EQ(error_of("superellipsoid { <0, 1> }"),
              "scene.pov:1:18: error: a superellipsoid's exponents <e, n> must be greater than 0");
}

TEST(PovObjects, UnsupportedIsAWarningOrStrictError) {
    const std::string s = "sphere { 0, 1 }\n  ovus { 1, 0.5 }\nbox { 0, 1 no_shadow }";
    const PovResult r = load_text(s);
    EXPECT_EQ(r.scene.shape_objects.size(), 2u);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:2:3: warning: unsupported object 'ovus'"),
              std::string::npos);
    EXPECT_EQ(r.scene.shape_objects[1].flags & ~kSolid, kNoShadow);
    PovOptions strict;
    strict.strict = true;
    EXPECT_EQ(error_of(s, strict), "scene.pov:2:3: error: unsupported object 'ovus'");
}

TEST(PovObjects, SyntaxErrorsNameFileLineColumnAndToken) {
    EXPECT_EQ(error_of("sphere { <0, 0, 0>, 1\n  pigment { rgb 1 }\n  wobble 3 }"),
              "scene.pov:3:3: error: found 'wobble', expected an object modifier or '}'");
    EXPECT_EQ(error_of("box { 0, 1 "),
              "scene.pov:1:12: error: found 'end of file', expected an object "
              "modifier or '}'");
    EXPECT_EQ(error_of("42"), "scene.pov:1:1: error: found '42', expected an object, camera, "
                              "light_source or directive");
    TempDir d;
    d.write("bad.inc", "\n\n   sphere { 0 1 ] }");
    try {
        load_pov_scene(d.write("s.pov", "#include \"bad.inc\""), {});
        FAIL();
    } catch (const SceneError& e) {
        // The include follows on a line of its own.
        EXPECT_EQ(std::string(e.what()), d.path() +
                                             "/bad.inc:3:17: error: found ']', expected an "
                                             "object modifier or '}'\n  in 'bad.inc' "
                                             "included at " +
                                             d.path() + "/s.pov:1:2");
    }
}

// Numbers the core cannot use are errors where the object starts, not shapes that vanish
// (a NaN transform passed every "smaller than" test) or a commit error without a place.
TEST(PovObjects, NonFiniteNumbersAreErrorsAtTheObject) {
    const std::string finite = "error: the shape's size or placement is not a finite number";
    EXPECT_NE(error_of("\nsphere { 0, 0/0 }").find("scene.pov:2:1: " + finite), std::string::npos);
    EXPECT_NE(error_of("box { 0, 1 scale 1e30 scale 1e30 }").find("scene.pov:1:1: " + finite),
              std::string::npos);
    EXPECT_NE(error_of("triangle { <0/0, 0, 0>, <1, 0, 0>, <0, 1, 0> }")
                  .find("scene.pov:1:1: error: a vertex is not a finite number"),
              std::string::npos);
    EXPECT_EQ(error_of("light_source { <1, 2, 3> rgb 1e39 }"),
              "scene.pov:1:1: error: the light's position, colour or aim is not a finite number");
}

// CSG deeper than the core renders is an error at the outermost object; nested unions of
// separate objects are taken apart first, so they may nest deeper.
TEST(PovObjects, CsgNestingIsLimited) {
    std::string deep, unions;
    for (int i = 0; i < 70; ++i) deep += "difference { ", unions += "union { ";
    deep += "sphere { 0, 1 }";
    unions += "sphere { 0, 1 }";
    for (int i = 0; i < 70; ++i) deep += " sphere { 0, 0.1 } }", unions += " }";
    EXPECT_EQ(error_of(deep), "scene.pov:1:1: error: CSG nested 70 levels deep; Sheaf renders 64 "
                              "(unions of separate objects do not count)");
    EXPECT_EQ(load_text(unions).scene.shape_objects.size(), 1u);
}

} // namespace
} // namespace sheaf::io::pov

namespace sheaf::io::pov {
namespace {

using test::first_hit;

TEST(PovObjects, PrismSweepsItsSplinesAlongY) {
    // A 2 x 2 square with a square hole (even-odd: the inner contour need not run the other
    // way), from y = 0 to 1; heights given the other way round are swapped, as POV-Ray does.
    const std::string square_ring = "10, <0, 0>, <2, 0>, <2, 2>, <0, 2>, <0, 0>, <0.5, 0.5>, "
                                    "<1.5, 0.5>, <1.5, 1.5>, <0.5, 1.5>, <0.5, 0.5>";
    PovResult r = load_text("prism { linear_sweep linear_spline 1, 0, " + square_ring + " }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects[0].nodes[0].shape.kind, ShapeKind::Glyph);
    EXPECT_NEAR(first_hit(r, {0.25f, 5, 0.25f}, {0, -1, 0}), 4.0f, 1e-5); // the top
    EXPECT_LT(first_hit(r, {1, 5, 1}, {0, -1, 0}), 0.0f);                 // down the hole
    EXPECT_NEAR(first_hit(r, {-5, 0.5f, 1}, {1, 0, 0}), 5.0f, 1e-5);      // the outer wall
    EXPECT_NEAR(first_hit(r, {1, 0.5f, 1}, {1, 0, 0}), 0.5f, 1e-5);       // from the hole
    EXPECT_NEAR(first_hit(r, {1, -5, 0.25f}, {0, 1, 0}), 5.0f, 1e-5);     // the base
    // Without commas, as POV-Ray's atten2.pov writes it: "4 <-1, ...>" is no comparison.
    r = load_text("prism { -0.5, 0.5, 4 <-1, -0.3>, <1, 0>, <-1, 0.3>, <-1, -0.3> }");
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(r.scene.shape_objects.at(0).nodes.at(0).glyph->segments.size(), 3u);
    // open: no caps, so a ray down inside the wall's footprint passes through; the sides stay.
    r = load_text("prism { 0, 1, " + square_ring + " open }");
    EXPECT_LT(first_hit(r, {0.25f, 5, 0.25f}, {0, -1, 0}), 0.0f);
    EXPECT_NEAR(first_hit(r, {-5, 0.5f, 1}, {1, 0, 0}), 5.0f, 1e-5);
}

TEST(PovObjects, PrismSplinesFollowPovRaysDefinitions) {
    // quadratic_spline: each segment runs from the second point of three to the third, leaving
    // it along (third - first) / 2: a quadratic Bézier with that control point.
    PovResult r = load_text("prism { quadratic_spline 0, 1, 6, <0, -1>, <1, 0>, <0, 1>, "
                            "<-1, 0>, <0, -1>, <1, 0> }");
    EXPECT_TRUE(r.warnings.empty());
    const auto& g = r.scene.shape_objects.at(0).nodes.at(0).glyph;
    ASSERT_TRUE(g);
    EXPECT_TRUE(g->even_odd);
    ASSERT_EQ(g->segments.size(), 4u);
    const GlyphSegment& s = g->segments[0];
    EXPECT_FLOAT_EQ(s.x0, 1); // from <1, 0>
    EXPECT_FLOAT_EQ(s.y0, 0);
    EXPECT_FLOAT_EQ(s.x1, 1); // + (<0, 1> - <0, -1>) / 4
    EXPECT_FLOAT_EQ(s.y1, 0.5f);
    EXPECT_FLOAT_EQ(s.x2, 0); // to <0, 1>
    EXPECT_FLOAT_EQ(s.y2, 1);
    // The rounded diamond's bottom point is <0, -1>, at POV-Ray's z = -1. Its first segment is
    // (1 - s^2, s): at z = 0.5 it bulges out to x = 0.75, beyond the straight diamond's 0.5.
    EXPECT_NEAR(first_hit(r, {0, 0.5f, -5}, {0, 0, 1}), 4.0f, 1e-5);
    EXPECT_NEAR(first_hit(r, {5, 0.5f, 0.5f}, {-1, 0, 0}), 5 - 0.75f, 1e-5);
    // cubic_spline (Catmull-Rom) and bezier_spline: 16 quadratics for each segment.
    r = load_text("prism { cubic_spline 0, 1, 7, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, "
                  "<1, 0>, <0, 1> }");
    EXPECT_EQ(r.scene.shape_objects.at(0).nodes.at(0).glyph->segments.size(), 4u * 16);
    r = load_text("prism { bezier_spline 0, 1, 8, <0, 0>, <0, 1>, <1, 1>, <1, 0>, "
                  "<1, 0>, <1, -1>, <0, -1>, <0, 0> }");
    EXPECT_EQ(r.scene.shape_objects.at(0).nodes.at(0).glyph->segments.size(), 2u * 16);
    EXPECT_NEAR(first_hit(r, {0.5f, 0.5f, -5}, {0, 0, 1}), 5.0f - 0.75f, 1e-3); // its bulge
}

TEST(PovObjects, PrismErrorsAndConicSweep) {
    EXPECT_EQ(error_of("prism { 0, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }"),
              "scene.pov:1:15: error: the prism's points do not close its last contour (a "
              "contour ends where a point repeats the contour's first; its first point)");
    EXPECT_EQ(error_of("prism { 0, 1, 2, <0, 0>, <1, 0> }"),
              "scene.pov:1:15: error: a prism with this spline needs a whole number of at "
              "least 3 points");
    EXPECT_EQ(error_of("prism { bezier_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }"),
              "scene.pov:1:29: error: a prism's bezier_spline takes its points four at a time");
    EXPECT_EQ(error_of("prism { 0, 1, 4, <0, 0>, 1, <1, 1>, <0, 0> }"),
              "scene.pov:1:26: error: found '1', expected the prism's point 2 of 4 (a 2-D "
              "vector <u, v>)");
    EXPECT_EQ(error_of("prism { conic_sweep 0, 1, 4, <0, 0>, <1, 0>, <0, 1> }"),
              "scene.pov:1:53: error: found '}', expected the prism's point 4 of 4 (a 2-D "
              "vector <u, v>)");
    // Heights on both sides of 0 would be two cones meeting at the apex: left out, warned.
    const PovResult r = load_text(
        "prism { conic_sweep -1, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:1: warning: unsupported prism with conic_sweep "
                                 "from below to above height 0"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

// conic_sweep: POV-Ray's point (x, y, z) is inside where (x / y, z / y) is in the outline and
// y is between the heights; below 0 the outline turns through the apex.
TEST(PovObjects, ConicPrismsScaleTheirOutlineByTheHeight) {
    const PovResult square =
        load_text("prism { conic_sweep 0.5, 2, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }");
    ASSERT_TRUE(square.warnings.empty()) << square.warnings[0];
    // At height 1.5 the square reaches x = +-1.5 (POV-Ray's coordinates), z = +-1.5.
    EXPECT_NEAR(first_hit(square, {-10, 1.5f, 0}, {1, 0, 0}), 8.5f, 1e-4f);
    EXPECT_NEAR(first_hit(square, {10, 1.5f, 0.3f}, {-1, 0, 0}), 8.5f, 1e-4f);
    EXPECT_NEAR(first_hit(square, {0.2f, 1.5f, -10}, {0, 0, 1}), 8.5f, 1e-4f);
    EXPECT_LT(first_hit(square, {-10, 0.4f, 0}, {1, 0, 0}), 0);         // below the lower height
    EXPECT_NEAR(first_hit(square, {0.1f, 5, 0}, {0, -1, 0}), 3, 1e-4f); // the top cap
    EXPECT_LT(first_hit(square, {-10, 1.9f, 1.95f}, {1, 0, 0}), 0);     // past z = 1.9
    // Below 0 the outline is turned through the apex: the triangle (0, 0) (1, 0) (0, 1) at
    // height -1.5 reaches from x = -1.5 to 0 along z = -0.01.
    const PovResult turned =
        load_text("prism { conic_sweep -2, -1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }");
    ASSERT_TRUE(turned.warnings.empty()) << turned.warnings[0];
    EXPECT_NEAR(first_hit(turned, {-10, -1.5f, -0.01f}, {1, 0, 0}), 8.5f, 0.02f);
    EXPECT_NEAR(first_hit(turned, {10, -1.5f, -0.01f}, {-1, 0, 0}), 10, 0.02f);
    EXPECT_LT(first_hit(turned, {-10, -1.5f, 0.01f}, {1, 0, 0}), 0);
}

TEST(PovObjects, LatheTurnsItsSplinesAboutY) {
    // A ring of square section: radius 1 to 2, y from 0 to 1, closed.
    PovResult r = load_text("lathe { linear_spline 5, <1, 0>, <2, 0>, <2, 1>, <1, 1>, <1, 0> }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const CsgNode& n = r.scene.shape_objects[0].nodes[0];
    EXPECT_EQ(n.shape.kind, ShapeKind::Revolution);
    EXPECT_FALSE(n.shape.open);
    EXPECT_NEAR(first_hit(r, {-5, 0.5f, 0}, {1, 0, 0}), 3.0f, 1e-5);  // the outer wall
    EXPECT_NEAR(first_hit(r, {0, 0.5f, 0}, {0, 0, 1}), 1.0f, 1e-5);   // from the hole
    EXPECT_NEAR(first_hit(r, {0, 5, 1.5f}, {0, -1, 0}), 4.0f, 1e-5);  // the top
    EXPECT_LT(first_hit(r, {0, 5, 0.5f}, {0, -1, 0}), 0.0f);          // down the hole
    EXPECT_NEAR(first_hit(r, {0, -5, -1.5f}, {0, 1, 0}), 5.0f, 1e-5); // the base
    // An unclosed curve is the surface POV-Ray draws: a tube open at both ends.
    r = load_text("lathe { 2, <1, 0>, <1, 1> }");
    EXPECT_TRUE(r.scene.shape_objects.at(0).nodes.at(0).shape.open);
    EXPECT_NEAR(first_hit(r, {0, 0.5f, -5}, {0, 0, 1}), 4.0f, 1e-5);
    EXPECT_NEAR(first_hit(r, {0, 0.5f, 0}, {0, 0, 1}), 1.0f, 1e-5); // from inside
    EXPECT_LT(first_hit(r, {0, 5, 0}, {0, -1, 0}), 0.0f);           // along the axis
    // From the axis to the axis is closed (along it): a solid.
    r = load_text("lathe { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }");
    EXPECT_FALSE(r.scene.shape_objects.at(0).nodes.at(0).shape.open);
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 4.0f, 1e-5);
}

TEST(PovObjects, LatheSplinesFollowPovRaysDefinitions) {
    // quadratic_spline from the second point: (1, 0) to (1, 1) leaving along ((1,1)-(0,-1))/2,
    // a Bézier with control (1, 0) + (1, 2) / 4.
    PovResult r = load_text("lathe { quadratic_spline 4, <0, -1>, <1, 0>, <1, 1>, <0, 2> }");
    const auto& q = r.scene.shape_objects.at(0).nodes.at(0).revolution;
    ASSERT_TRUE(q);
    ASSERT_EQ(q->segments.size(), 2u);
    EXPECT_EQ(q->segments[0].wdeg, 2u);
    EXPECT_FLOAT_EQ(q->segments[0].w[1], 1.25f);
    EXPECT_FLOAT_EQ(q->segments[0].h[1], 0.5f);
    // cubic_spline: Catmull-Rom from the second point to the last but one.
    r = load_text("lathe { cubic_spline 5, <0, -1>, <1, 0>, <1, 1>, <0, 2>, <0, 3> }");
    const auto& c = r.scene.shape_objects.at(0).nodes.at(0).revolution;
    ASSERT_EQ(c->segments.size(), 2u);
    EXPECT_FLOAT_EQ(c->segments[0].w[1], 1 + 1.0f / 6);
    EXPECT_FLOAT_EQ(c->segments[0].w[2], 1 + 1.0f / 6); // <1, 1> - (<0, 2> - <1, 0>) / 6
    // bezier_spline: a quarter-circle-like bulge of radius about 1 from the axis to the axis.
    r = load_text("lathe { bezier_spline 8, <0, 0>, <0.55, 0>, <1, 0.45>, <1, 1>, "
                  "<1, 1>, <1, 1.55>, <0.55, 2>, <0, 2> }");
    EXPECT_FALSE(r.scene.shape_objects.at(0).nodes.at(0).shape.open);
    EXPECT_NEAR(first_hit(r, {-5, 1, 0}, {1, 0, 0}), 4.0f, 1e-5);
    EXPECT_NEAR(first_hit(r, {0, 5, 0}, {0, -1, 0}), 3.0f, 1e-5);
}

TEST(PovObjects, SorIsACubicInTheHeightWithCaps) {
    // A cylinder of radius 1 from y = 0 to 2 (the points outside steer the slopes to zero).
    const std::string pts = "5, <1, -1>, <1, 0>, <1, 1>, <1, 2>, <1, 3>";
    PovResult r = load_text("sor { " + pts + " }");
    EXPECT_TRUE(r.warnings.empty());
    const CsgNode& n = r.scene.shape_objects.at(0).nodes.at(0);
    EXPECT_EQ(n.shape.kind, ShapeKind::Revolution);
    EXPECT_TRUE(n.revolution->squared);
    EXPECT_NEAR(first_hit(r, {-5, 1, 0}, {1, 0, 0}), 4.0f, 1e-5);    // the side
    EXPECT_NEAR(first_hit(r, {0, 5, 0.5f}, {0, -1, 0}), 3.0f, 1e-5); // the cap at y = 2
    EXPECT_NEAR(first_hit(r, {0, -5, 0}, {0, 1, 0}), 5.0f, 1e-5);    // the base
    // open: no caps.
    r = load_text("sor { " + pts + " open }");
    EXPECT_NEAR(first_hit(r, {0, 5, 0.5f}, {0, -1, 0}), -1.0f, 1e-5);
    EXPECT_NEAR(first_hit(r, {0, 1, 0}, {1, 0, 0}), 1.0f, 1e-5);
    // A bulge: r^2 runs through 1 at y = 0 and 1 with slope 2 r dr/dh from the neighbours.
    r = load_text("sor { 4, <0.5, -1>, <1, 0>, <1, 1>, <0.5, 2> }");
    // r^2(h) with r^2(0) = r^2(1) = 1 and slopes 2 * 1 * (1 - 0.5) / (1 - (-1)) = 0.5 and
    // -0.5: at h = 0.5 the Hermite cubic is 1 + (0.5 - (-0.5)) / 8 = 1.125.
    EXPECT_NEAR(first_hit(r, {-5, 0.5f, 0}, {1, 0, 0}), 5 - std::sqrt(1.125f), 1e-5);
}

TEST(PovObjects, LatheAndSorErrors) {
    EXPECT_EQ(error_of("lathe { 1, <0, 0> }"),
              "scene.pov:1:9: error: a lathe with this spline needs a whole number of at least "
              "2 points");
    EXPECT_EQ(error_of("lathe { bezier_spline 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 2> }"),
              "scene.pov:1:23: error: a lathe's bezier_spline takes its points four at a time");
    EXPECT_EQ(error_of("lathe { 3, <0, 0>, <-1, 0>, <0, 1> }"),
              "scene.pov:1:20: error: the lathe's point 2 has a negative radius (x < 0)");
    EXPECT_EQ(error_of("lathe { 3, <0, 0>, 1, <0, 1> }"),
              "scene.pov:1:20: error: found '1', expected the lathe's point 2 of 3 (a 2-D vector "
              "<r, h>)");
    EXPECT_EQ(error_of("sor { 3, <0, 0>, <1, 1>, <0, 2> }"),
              "scene.pov:1:7: error: a sor needs a whole number of at least 4 points");
    EXPECT_EQ(error_of("sor { 5, <0, 0>, <1, 1>, <1, 3>, <1, 2>, <0, 4> }"),
              "scene.pov:1:34: error: the sor's heights must rise from point to point (point 4 "
              "is not above point 3)");
    EXPECT_EQ(error_of("sor { 4, <0, 1>, <1, 0>, <1, 1>, <0, 2> }"),
              "scene.pov:1:10: error: the sor's first and last points must differ in height "
              "from the curve's second and last but one (they set its slopes there)");
}

TEST(PovObjects, BlobSumsItsComponentsFields) {
    // One sphere component: S (1 - r^2/R^2)^2 = T at r = R sqrt(1 - sqrt(T / S)).
    PovResult r = load_text("blob { threshold 0.25 sphere { <0, 1, 0>, 2, strength 1 } }");
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const CsgNode& n = r.scene.shape_objects[0].nodes[0];
    EXPECT_EQ(n.shape.kind, ShapeKind::Blob);
    ASSERT_TRUE(n.blob);
    EXPECT_FLOAT_EQ(n.blob->threshold, 0.25f);
    const float radius = 2 * std::sqrt(1 - 0.5f);
    EXPECT_NEAR(first_hit(r, {-5, 1, 0}, {1, 0, 0}), 5 - radius, 1e-5);
    // A cylinder has round ends; a negative sphere carves; the old `component` syntax.
    r = load_text("blob { threshold 0.5 cylinder { <-2, 0, 0>, <2, 0, 0>, 1, 1 }\n"
                  "component -4, 1, <0, 0, 0> }");
    const float cr = std::sqrt(1 - std::sqrt(0.5f));
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 3 - cr, 1e-5);  // the round end
    EXPECT_NEAR(first_hit(r, {-1, 5, 0}, {0, -1, 0}), 5 - cr, 1e-5); // the side
    EXPECT_LT(first_hit(r, {0, 5, 0}, {0, -1, 0}), 0.0f);            // carved through
    // A component's own transforms place it: scaled to an ellipsoid, then moved.
    r = load_text("blob { threshold 0.25 sphere { 0, 1, 1 scale <2, 1, 1> translate y } "
                  "translate 3*x }");
    EXPECT_NEAR(first_hit(r, {-5, 1, 0}, {1, 0, 0}), 8 - 2 * std::sqrt(0.5f), 1e-5);
    EXPECT_LT(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 0.0f);
}

TEST(PovObjects, BlobComponentTexturesAndErrors) {
    // Components sharing one texture give it to the blob; differing ones are warned.
    PovResult r =
        load_text("#declare T = texture { pigment { rgb <1, 0, 0> } }\n"
                  "blob { sphere { 0, 1, 1 texture { T } } sphere { x, 1, 1 texture { T } } }");
    EXPECT_TRUE(r.warnings.empty());
    r = load_text("blob { sphere { 0, 1, 1 pigment { rgb 1 } }\n"
                  "sphere { x, 1, 1 pigment { rgb <0, 1, 0> } } }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:2:1: warning: unsupported blob component textures"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(error_of("blob { threshold 0 sphere { 0, 1, 1 } }"),
              "scene.pov:1:18: error: a blob's threshold must be a positive, finite number");
    // Found by the POV fuzzer: 0.1e3086 is infinite.
    EXPECT_EQ(error_of("blob { threshold 0.1e3086 sphere { 0, 1, 1 } }"),
              "scene.pov:1:18: error: a blob's threshold must be a positive, finite number");
    EXPECT_EQ(error_of("blob { sphere { 0, -1, 1 } }"),
              "scene.pov:1:8: error: a blob component's radius must be a positive number");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 matrix <1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0> } }"),
              "scene.pov:1:8: error: a blob component is flattened to nothing by its "
              "transforms");
    EXPECT_EQ(error_of("blob { box { 0, 1 } }"),
              "scene.pov:1:8: error: found 'box', expected a blob component (sphere, cylinder, "
              "component), a modifier or '}'");
    // No component: nothing can be inside; left out with a warning.
    r = load_text("blob { threshold 0.5 }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

} // namespace
} // namespace sheaf::io::pov

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

/// The nearest hit of a ray (POV-Ray coordinates) on any analytic object of `r`; -1 on a miss.
float any_hit(const PovResult& r, Vec3 from, Vec3 dir) {
    const PreparedScene p = prepare_scene(r.scene);
    Ray ray;
    ray.origin = pov_to_sheaf().point(from), ray.dir = pov_to_sheaf().vector(dir);
    ray.tmin = 0, ray.tmax = 100;
    float best = -1;
    for (uint32_t o = 0; o < r.scene.shape_objects.size(); ++o) {
        AnalyticHit h;
        if (analytic_first_hit(p, o, ray, h) && (best < 0 || h.t < best)) best = h.t;
    }
    return best;
}

TEST(PovSphereSweeps, ALinearSweepIsSpheresAndTheirTangentCones) {
    PovResult r = load_text("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <4, 0, 0>, 1 }");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_NEAR(any_hit(r, {2, 5, 0}, {0, -1, 0}), 4.0f, 1e-4); // the tube's top
    EXPECT_NEAR(any_hit(r, {-5, 0, 0}, {1, 0, 0}), 4.0f, 1e-4); // the first sphere
    EXPECT_NEAR(any_hit(r, {9, 0, 0}, {-1, 0, 0}), 4.0f, 1e-4); // the last
    EXPECT_LT(any_hit(r, {2, 5, 1.2f}, {0, -1, 0}), 0.0f);      // beside it
    // Radii 2 and 1, centres 4 apart: the tangent line y = (8 - x) / sqrt(15) over x = 2.
    r = load_text("sphere_sweep { linear_spline 2 <0, 0, 0>, 2 <4, 0, 0>, 1 tolerance 1e-4 }");
    EXPECT_NEAR(any_hit(r, {2, 5, 0}, {0, -1, 0}), 5.0f - 6.0f / std::sqrt(15.0f), 1e-4);
}

TEST(PovSphereSweeps, SplineSweepsFollowTheirSplines) {
    // A uniform B-spline over collinear points runs from (P0 + 4 P1 + P2) / 6 to
    // (P1 + 4 P2 + P3) / 6: x from 1 to 2 here, so the sweep ends at x = 0.5 and 2.5.
    const std::string line = "4, <0, 0, 0>, 0.5, <1, 0, 0>, 0.5, <2, 0, 0>, 0.5, <3, 0, 0>, 0.5 ";
    PovResult r = load_text("sphere_sweep { b_spline " + line + "}");
    EXPECT_NEAR(any_hit(r, {-5, 0, 0}, {1, 0, 0}), 5.5f, 1e-4);
    EXPECT_NEAR(any_hit(r, {8, 0, 0}, {-1, 0, 0}), 5.5f, 1e-4);
    // Catmull-Rom passes through its inner points: the top of the ball at (1, 1, 0).
    r = load_text("sphere_sweep { cubic_spline 4, <0, 0, 0>, 0.25, <1, 1, 0>, 0.25, "
                  "<2, 0, 0>, 0.25, <3, 1, 0>, 0.25 pigment { rgb 1 } translate x }");
    EXPECT_NEAR(any_hit(r, {2, 5, 0}, {0, -1, 0}), 3.75f, 1e-4);
    EXPECT_LT(any_hit(r, {0.5f, 5, 0}, {0, -1, 0}), 0.0f); // before P1: not swept
}

TEST(PovSphereSweeps, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("sphere_sweep { b_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }"),
              "scene.pov:1:25: error: a sphere_sweep with b_spline needs a whole number of at "
              "least 4 spheres");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 0 }"),
              "scene.pov:1:58: error: a sphere_sweep's radius must be greater than 0");
    EXPECT_NE(error_of("sphere_sweep { 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }")
                  .find("expected linear_spline, b_spline or cubic_spline"),
              std::string::npos);
}

} // namespace
} // namespace sheaf::io::pov

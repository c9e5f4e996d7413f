// bounded_by: the box of its objects, moved with the object, bounds what has no bound of its
// own (a quartic) in Sheaf's world, for the parts of a split union too; a bound that bounds
// nothing (a plane, clipped_by) leaves the object as it was, and the picture is the same.
#include "io/pov/builder.h"
#include "tests/support/pov_test_util.h"

#include "core/frame/render_frame.h"
#include "core/scene/prepared_scene.h"

#include <cmath>
#include <cstring>

namespace sheaf::io::pov {
namespace {

using test::load_text;

// A torus as POV-Ray's quartic (major radius 2, minor 0.5, in the x-z plane).
const char* kTorus = R"(
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -8.5,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 7.5, 0, 0, 0, 0,   1, 0, -8.5, 0, 14.0625>
  sturm
)";

TEST(PovBoundedBy, BoundsAQuarticAndMovesWithIt) {
    const PovResult plain = load_text(std::string(kTorus) + "}");
    ASSERT_EQ(plain.scene.shape_objects.size(), 1u);
    EXPECT_FALSE(std::isfinite(plain.scene.shape_objects[0].bound.lo.x));
    const PovResult r =
        load_text(std::string(kTorus) + "bounded_by { box { <-2.5, -0.5, -2.5>, <2.5, 0.5, 2.5> } }"
                                        "translate <1, 2, 3> }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_TRUE(r.warnings.empty());
    const WorldBox& box = r.scene.shape_objects[0].bound; // the box itself, z mirrored
    EXPECT_NEAR(box.lo.x, -1.5, 1e-3);
    EXPECT_NEAR(box.hi.x, 3.5, 1e-3);
    EXPECT_NEAR(box.lo.y, 1.5, 1e-3);
    EXPECT_NEAR(box.hi.y, 2.5, 1e-3);
    EXPECT_NEAR(box.lo.z, -5.5, 1e-3);
    EXPECT_NEAR(box.hi.z, -0.5, 1e-3);
    EXPECT_LE(box.lo.x, -1.5f); // padded outwards
    EXPECT_GE(box.hi.z, -0.5f);
    // The prepared object takes it, and the sphere around it: no longer unbounded.
    const PreparedScene p = prepare_scene(r.scene);
    const Sphere b = p.object_sphere.back();
    EXPECT_NEAR(b.center.x, 1, 1e-5);
    EXPECT_NEAR(b.center.y, 2, 1e-5);
    EXPECT_NEAR(b.center.z, -3, 1e-5); // Sheaf's world: z mirrored
    EXPECT_NEAR(b.radius, std::sqrt(2.5 * 2.5 * 2 + 0.25), 1e-3);
    EXPECT_NEAR(p.analytic_box.back().lo.y, 1.5, 1e-3); // the BVH bounds it by the box
}

TEST(PovBoundedBy, PartsOfASplitUnionKeepTheirOwnSmallerBound) {
    const PovResult r = load_text(std::string("union { ") + kTorus + "}" +
                                  "sphere { <0, 0, 0>, 0.1 }"
                                  "bounded_by { sphere { 0, 3 } } }");
    ASSERT_EQ(r.scene.shape_objects.size(), 2u);               // a union renders as its parts
    EXPECT_NEAR(r.scene.shape_objects[0].bound.hi.x, 3, 1e-3); // the union's bound
    EXPECT_NEAR(r.scene.shape_objects[1].bound.lo.y, -3, 1e-3);
    const PreparedScene p = prepare_scene(r.scene);
    EXPECT_NEAR(p.object_sphere[0].radius, std::sqrt(27.0), 1e-3);
    EXPECT_LT(p.object_sphere[1].radius, 0.2); // the small sphere's own bound is smaller
}

TEST(PovBoundedBy, ABoundThatBoundsNothingIsNone) {
    for (const char* bound : {"bounded_by { plane { y, 0 } }", "bounded_by { clipped_by }",
                              "clipped_by { box { -3, 3 } } bounded_by { clipped_by }"}) {
        const PovResult r = load_text(std::string(kTorus) + bound + " }");
        ASSERT_EQ(r.scene.shape_objects.size(), 1u) << bound;
        EXPECT_FALSE(std::isfinite(r.scene.shape_objects[0].bound.hi.y)) << bound;
    }
}

TEST(PovBoundedBy, ThePictureIsTheSame) {
    const std::string scene = std::string("camera { location <0, 4, -6> look_at 0 }"
                                          "light_source { <3, 8, -4> rgb 1 }"
                                          "plane { y, -1 pigment { rgb 0.8 } }") +
                              kTorus + " pigment { rgb <1, 0.5, 0.2> }";
    const PovResult plain = load_text(scene + "}");
    const PovResult bound =
        load_text(scene + "bounded_by { box { <-2.6, -0.6, -2.6>, <2.6, 0.6, 2.6> } } }");
    Settings s;
    s.set("width", "48"), s.set("height", "36");
    const Frame a = render_frame_cpu(prepare_scene(plain.scene), RenderSettings::resolve(s));
    const Frame b = render_frame_cpu(prepare_scene(bound.scene), RenderSettings::resolve(s));
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    EXPECT_EQ(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)), 0);
    EXPECT_LT(b.stats.get("tests.shadow.final.tests"), a.stats.get("tests.shadow.final.tests"));
}

} // namespace
} // namespace sheaf::io::pov

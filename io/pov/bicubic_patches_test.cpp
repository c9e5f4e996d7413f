// bicubic_patch: the mesh passes through the patch's corners and follows the Bezier surface
// between them, its normals are the surface's, and bad patches are errors or warnings.
#include "tests/support/pov_test_util.h"

#include <cmath>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

// A patch over the unit square in x-z whose inner control points lift to `lift`.
std::string patch(const std::string& settings, float lift) {
    std::string s = "bicubic_patch { " + settings + "\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
            s += (i || j ? ", <" : "<") + std::to_string(j / 3.0) + ", " +
                 std::to_string(inner ? lift : 0.0f) + ", " + std::to_string(i / 3.0) + ">";
        }
    return s + "\n pigment { rgb 1 } }";
}

const Vec3* vertex_at(const Mesh& m, float x, float z) {
    for (const Vec3& p : m.positions)
        if (std::fabs(p.x - x) < 1e-5f && std::fabs(p.z - z) < 1e-5f) return &p;
    return nullptr;
}

TEST(PovBicubicPatches, FollowTheBezierSurface) {
    PovResult r = load_text(patch("type 1 u_steps 3 v_steps 3 flatness 0.01", 0.75f));
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const Mesh& m = r.scene.meshes[0];
    // u_steps 3 asks for 8 segments; Sheaf uses at least 16.
    EXPECT_EQ(m.positions.size(), 17u * 17u);
    EXPECT_EQ(m.triangle_count(), 16u * 16u * 2u);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    // The corners are control points; the centre is the inner points' lift times
    // 4 * (3/8 * 3/8) = 9/16 (the Bernstein weights of the four inner points at u = v = 1/2).
    for (float x : {0.0f, 1.0f})
        for (float z : {0.0f, 1.0f}) {
            const Vec3* p = vertex_at(m, x, z);
            ASSERT_NE(p, nullptr) << x << ", " << z;
            EXPECT_NEAR(p->y, 0, 1e-6);
        }
    const Vec3* c = vertex_at(m, 0.5f, 0.5f);
    ASSERT_NE(c, nullptr);
    EXPECT_NEAR(c->y, 0.75 * 9.0 / 16.0, 1e-5);
    // The normal at the top of the bump is straight up (or down: both sides are seen).
    const size_t k = size_t(c - m.positions.data());
    EXPECT_NEAR(std::fabs(m.normals[k].y), 1, 1e-5);
    // u_steps 6 asks for 64 segments, and gets them.
    r = load_text(patch("type 0 u_steps 6 v_steps 4", 0.5f));
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].positions.size(), 65u * 17u);
    // uv_vectors (the portfolio's allobjects.pov), with and without commas, change nothing.
    r = load_text(patch("type 1 uv_vectors <0,0> <1,0> <1,1> <0,1> flatness 0", 0.75f));
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_NEAR(vertex_at(r.scene.meshes[0], 0.5f, 0.5f)->y, 0.75 * 9.0 / 16.0, 1e-5);
    EXPECT_EQ(
        load_text(patch("uv_vectors <0,0>, <2,0>, <2,2>, <0,2> type 0", 0.5f)).scene.meshes.size(),
        1u);
}

TEST(PovBicubicPatches, ErrorsAndDegeneratePatches) {
    EXPECT_EQ(error_of(patch("u_steps 3", 1)),
              "scene.pov:2:1: error: found '<', expected the bicubic_patch's type (type 0 or "
              "type 1)");
    EXPECT_EQ(error_of(patch("type 2", 1)),
              "scene.pov:1:17: error: a bicubic_patch's type must be 0 or 1");
    EXPECT_EQ(
        error_of("bicubic_patch { type 1 <0, 0, 0>, <1, 0, 0> }"),
        "scene.pov:1:45: error: found '}', expected control point 3 of the bicubic_patch's 16");
    // Every control point in one place: no area, left out with a warning.
    std::string same = "bicubic_patch { type 1 <1, 2, 3>";
    for (int k = 1; k < 16; ++k) same += ", <1, 2, 3>";
    const PovResult r = load_text(same + " }\nsphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("degenerate shape: a bicubic_patch"), std::string::npos);
    EXPECT_TRUE(r.scene.meshes.empty());
}

} // namespace
} // namespace sheaf::io::pov

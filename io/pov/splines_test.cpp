// Splines of the scene language: each type's values against what povray 3.7 prints for the
// same splines (#debug with vstr), mixed dimensions, copies extended, a type given at the
// call, spline functions, and errors at their place.
#include "tests/support/pov_test_util.h"

namespace sheaf::io::pov {
namespace {

using test::declared;
using test::error_of;
using test::load_text;

const char* const kSplines = R"(
#declare B = spline { cubic_spline -1, <0,0> 0, <1,2> 1, <3,1,5> 2, <4,4> 3, <6,0> }
#declare N = spline { natural_spline 0, <0,0,0> 1, <1,2,0> 2.5, <3,1,1> 4, <4,4,2> }
#declare Q = spline { N quadratic_spline }
#declare C = spline { N cubic_spline 5, <9,9,9> }
#declare A = spline { 0, 1 1, 3 }
#declare D = spline { linear_spline 0, 1, 1, 2, 1, 5 }
#declare F = function { spline { linear_spline 0, <0,1,2> 1, <2,3,4> } }
)";

// The value `expr` gives after the splines above.
Value value_of(const std::string& expr) {
    return declared(std::string(kSplines) + "#declare V = " + expr + ";\n", "V");
}

void expect_vector(const Value& v, std::initializer_list<double> want, const std::string& what) {
    ASSERT_EQ(v.type == VType::Float ? 1 : v.dim, int(want.size())) << what;
    int i = 0;
    for (double w : want) EXPECT_NEAR(v.v[i++], w, 5e-7) << what << " component " << i - 1;
}

TEST(PovSplines, EveryTypeGivesPovRaysValues) {
    // povray 3.7.0.10's #debug of the same calls, 6 decimals.
    expect_vector(value_of("N(0.5)"), {0.459459, 1.270270, -0.054054}, "natural");
    expect_vector(value_of("N(2)"), {2.376376, 1.293293, 0.600601}, "natural");
    expect_vector(value_of("N(3.5)"), {3.758759, 2.583584, 1.690691}, "natural");
    expect_vector(value_of("Q(0.5)"), {0.466667, 1.266667, -0.066667}, "quadratic, first");
    expect_vector(value_of("Q(3)"), {3.444444, 1.555556, 1.333333}, "quadratic");
    expect_vector(value_of("N(1.5, linear_spline)"), {1.666667, 1.666667, 0.333333}, "linear");
    expect_vector(value_of("C(3)"), {3.166667, 1.537037, 0.981481}, "Catmull-Rom");
    // Catmull-Rom between its second and next-to-last points, those points outside them.
    expect_vector(value_of("B(1.5)"), {3.5, 2.6875, 5.3125}, "cubic");
    expect_vector(value_of("B(-1.5)"), {1, 2, 0}, "cubic before");
    expect_vector(value_of("B(3.5)"), {4, 4, 5}, "cubic after");
    // Outside the times, the ends; a point shorter than one before keeps its other
    // components (<4, 4> after <3, 1, 5> is <4, 4, 5>, as povray reads it).
    expect_vector(value_of("N(-0.5)"), {0, 0, 0}, "before");
    expect_vector(value_of("N(9)"), {4, 4, 2}, "after");
    // Float points give floats; linear is the default type.
    expect_vector(value_of("A(0.25)"), {1.5}, "float");
    // A time given again: povray 3.7 keeps the first point at the last time.
    expect_vector(value_of("D(0.5)"), {1.5}, "repeated last time");
    // A spline function gives the point in the language.
    expect_vector(value_of("F(0.5)"), {1, 2, 3}, "function");
}

TEST(PovSplines, AnimationPathsMoveObjects) {
    // transforms.inc's Spline_Trans places an object along a spline, facing where it goes.
    const PovResult r = load_text(R"(
#include "transforms.inc"
#declare Path = spline { cubic_spline -1, <-1,0,0> 0, <0,0,0> 1, <1,0,0> 2, <2,1,0> 3, <3,2,0> }
sphere { 0, 0.1 Spline_Trans(Path, 0.5, y, 0.1, 0) })");
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    const PreparedScene p = prepare_scene(r.scene);
    ASSERT_EQ(p.object_count(), 1u);
    EXPECT_NEAR(p.object_sphere[0].center.x, 0.5f, 1e-5f);
    EXPECT_NEAR(p.object_sphere[0].center.y, -0.0625f, 1e-5f); // the curve dips there
}

TEST(PovSplines, SplineFunctionsInFunctionBodiesAreWarned) {
    // Programs cannot run a spline: a pattern of one is warned, also through a pigment
    // function declared before.
    const PovResult r = load_text(R"(
#declare S = function { spline { 0, <0,0,0> 1, <1,1,1> } }
#declare P = function { pigment { function { S(x).y } } }
sphere { 0, 1 pigment { function { P(x, y, z).gray } } })");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("unsupported pigment pattern 'function'"), std::string::npos);
}

TEST(PovSplines, ErrorsNameTheirPlace) {
    EXPECT_EQ(error_of("#declare S = spline { linear_spline 0 1 }"),
              "scene.pov:1:39: error: found '1', expected ','");
    EXPECT_EQ(error_of("#declare S = spline { cubic_spline }"),
              "scene.pov:1:21: error: a spline needs at least one point");
    EXPECT_EQ(error_of("#declare S = spline { 0, \"a\" }"),
              "scene.pov:1:26: error: found '\"a\"', expected a float or vector (the spline's "
              "point)");
    EXPECT_EQ(error_of("#declare S = spline { 0, 1 1, 2 }\n#declare V = S(0.5, wobbly_spline);"),
              "scene.pov:2:21: error: found 'wobbly_spline', expected a spline type "
              "(linear_spline, quadratic_spline, cubic_spline, natural_spline)");
    EXPECT_EQ(error_of("#declare S = spline { 0, 1 1, 2 }\n#declare V = S(0.5;"),
              "scene.pov:2:19: error: found ';', expected ')'");
}

} // namespace
} // namespace sheaf::io::pov

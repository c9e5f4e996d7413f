// julia_fractal in the POV reader: the shape it builds, POV-Ray's defaults and clamps, and the
// errors and warnings of what it refuses or leaves out.
#include "tests/support/pov_test_util.h"

#include <cmath>

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::first_hit;
using test::load_text;

const JuliaFractal& julia_of(const PovResult& r) {
    const CsgNode& n = r.scene.shape_objects.at(0).nodes.at(0);
    EXPECT_EQ(n.shape.kind, ShapeKind::Julia);
    return *n.julia;
}

TEST(PovJulia, TheShapeAndItsSettings) {
    // c = 0: the unit ball, moved by the object's transform.
    PovResult r = load_text("julia_fractal { <0, 0, 0, 0> max_iteration 6 translate 2*x }");
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_NEAR(first_hit(r, {-5, 0, 0}, {1, 0, 0}), 6, 1e-5);
    const JuliaFractal& j = julia_of(r);
    EXPECT_EQ(j.algebra, JuliaAlgebra::QuaternionSqr);
    EXPECT_EQ(j.iterations, 6u);
    EXPECT_DOUBLE_EQ(j.min_step, 1.0 / 20);
    // The slice is normalised; precision and max_iteration below 1 are 1, as in POV-Ray.
    r = load_text("julia_fractal { <0.1, 0.2, 0.3, 0.4> hypercomplex cube slice <0, 0, 3, 4>, "
                  "0.5 precision 0.2 max_iteration -3 }");
    const JuliaFractal& k = julia_of(r);
    EXPECT_EQ(k.algebra, JuliaAlgebra::HypercomplexSqr); // POV-Ray's cube squares too
    EXPECT_DOUBLE_EQ(k.slice[2], 0.6);
    EXPECT_DOUBLE_EQ(k.slice[3], 0.8);
    EXPECT_DOUBLE_EQ(k.slice_dist, 0.5);
    EXPECT_DOUBLE_EQ(k.min_step, 1.0);
    EXPECT_EQ(k.iterations, 1u);
    EXPECT_DOUBLE_EQ(k.c[3], 0.4);
    r = load_text("julia_fractal { <0, 0, 0, 0> quaternion cube precision 400 }");
    EXPECT_EQ(julia_of(r).algebra, JuliaAlgebra::QuaternionCube);
    EXPECT_DOUBLE_EQ(julia_of(r).min_step, 1.0 / 400);
    // A tilted slice, z + w = 0: the ball's slice is an ellipsoid, flat along z.
    r = load_text("julia_fractal { <0, 0, 0, 0> slice <0, 0, 1, 1>, 0 }");
    EXPECT_NEAR(first_hit(r, {0, 0, -5}, {0, 0, 1}), 5 - std::sqrt(0.5), 1e-5);
}

TEST(PovJulia, ErrorsAndWhatIsLeftOut) {
    EXPECT_EQ(error_of("julia_fractal { <1, 2, 3> }"),
              "scene.pov:1:17: error: found '<', expected the Julia parameter, a 4-vector such "
              "as <-0.083, 0, -0.83, 0>");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 0 }"),
              "scene.pov:1:36: error: the slice's w component is zero");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> slice <0, 0, 0, 0>, 0 }"),
              "scene.pov:1:36: error: the slice's normal is zero");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> max_iteration 100 }"),
              "scene.pov:1:44: error: max_iteration above 64 (Sheaf keeps every iterate of a "
              "point)");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> quaternion exp }"),
              "scene.pov:1:41: error: a quaternion julia_fractal takes sqr or cube, not exp "
              "(hypercomplex takes more)");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> rotate }"),
              "scene.pov:1:37: error: found '}', expected a float, vector, colour or string "
              "expression");
    // A hypercomplex function Sheaf does not iterate: warned, and the object left out.
    const PovResult r = load_text("julia_fractal { <0, 0, 0, 0> hypercomplex pwr(2, 0) }\n"
                                  "sphere { 0, 1 }");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:1:43: warning: unsupported julia_fractal function "
                                 "'pwr' (left out)"),
              std::string::npos)
        << r.warnings[0];
    EXPECT_EQ(r.scene.shape_objects.size(), 1u);
}

} // namespace
} // namespace sheaf::io::pov

// Tests of expressions: precedence, vectors, colours, strings, arrays, built-ins and user
// functions.
#include "tests/support/pov_test_util.h"

#include <cmath>

namespace sheaf::io::pov {
namespace {

using test::declared;
using test::error_of;
using test::load_text;
using test::num;

TEST(PovExpressions, Precedence) {
    EXPECT_DOUBLE_EQ(num("1 + 2 * 3"), 7);
    EXPECT_DOUBLE_EQ(num("(1 + 2) * 3"), 9);
    EXPECT_DOUBLE_EQ(num("-2 * -3"), 6);
    EXPECT_DOUBLE_EQ(num("10 - 4 - 3"), 3);
    EXPECT_DOUBLE_EQ(num("8 / 4 / 2"), 1);
    EXPECT_DOUBLE_EQ(num("1 < 2 & 3 > 2"), 1);
    EXPECT_DOUBLE_EQ(num("0 | 0 & 1"), 0);
    EXPECT_DOUBLE_EQ(num("!0 + 1"), 2);
    EXPECT_DOUBLE_EQ(num("1 = 1 ? 5 : 6"), 5);
    EXPECT_DOUBLE_EQ(num("0 ? 5 : 1 ? 7 : 8"), 7);
    EXPECT_DOUBLE_EQ(num("2 != 2"), 0);
    EXPECT_DOUBLE_EQ(num("3 >= 3 & 2 <= 1"), 0);
}

TEST(PovExpressions, VectorsAndMembers) {
    const Value v = declared("#declare V = <1, 2, 3> * 2 + x;", "V");
    ASSERT_EQ(v.type, VType::Vector);
    EXPECT_EQ(v.dim, 3);
    EXPECT_DOUBLE_EQ(v.v[0], 3);
    EXPECT_DOUBLE_EQ(v.v[2], 6);
    EXPECT_DOUBLE_EQ(num("<4, 5, 6>.y"), 5);
    EXPECT_DOUBLE_EQ(num("<1, 2, 3, 4, 5>.t"), 4);
    EXPECT_DOUBLE_EQ(num("vlength(<3, 0, 4>)"), 5);
    EXPECT_DOUBLE_EQ(num("vdot(x, y)"), 0);
    EXPECT_DOUBLE_EQ(num("vcross(x, y).z"), 1);
    EXPECT_NEAR(num("vrotate(x, <0, 0, 90>).y"), 1, 1e-6);
    EXPECT_NEAR(num("vaxis_rotate(x, z, 90).y"), 1, 1e-6);
    EXPECT_NEAR(num("vnormalize(<0, 3, 4>).z"), 0.8, 1e-6);
    EXPECT_EQ(declared("#declare V = <1, 2>;", "V").dim, 2);
    EXPECT_EQ(declared("#declare V = <1 2 3>;", "V").dim, 3); // commas may be left out
}

// vturbulence(lambda, omega, octaves, point): the displacement a turbulence of 1 gives there,
// the same at the same point, smaller for fewer octaves of a smaller omega.
TEST(PovExpressions, VturbulenceDisplacesAsTurbulenceDoes) {
    const double a = num("vlength(vturbulence(2, 0.5, 6, <0.3, 0, 1.7>))");
    EXPECT_GT(a, 0.05);
    EXPECT_LT(a, 8);
    EXPECT_EQ(num("vturbulence(2, 0.5, 6, <0.3, 0, 1.7>).x"),
              num("vturbulence(2, 0.5, 6, <0.3, 0, 1.7>).x"));
    EXPECT_NE(num("vturbulence(2, 0.5, 6, <0.3, 0, 1.7>).x"),
              num("vturbulence(2, 0.5, 6, <2.3, 0, 1.7>).x"));
    EXPECT_NE(error_of("#declare V = vturbulence(2, 0.5, 6);").find("error"), std::string::npos);
    // POV-Ray's own values (povray 3.7.0.10 wrote them).
    EXPECT_NEAR(num("vturbulence(2, 0.5, 6, <0.3, 0.2, 1.7>).x"), -0.06545461124767413, 1e-12);
    EXPECT_NEAR(num("vturbulence(2, 0.5, 6, <0.3, 0.2, 1.7>).y"), 0.32538894209024261, 1e-12);
    EXPECT_NEAR(num("vturbulence(2, 0.5, 6, <0.3, 0.2, 1.7>).z"), -0.02376730271848233, 1e-12);
}

TEST(PovExpressions, Colors) {
    Value c = declared("#declare C = rgb <1, 0.5, 0>;", "C");
    ASSERT_EQ(c.type, VType::Color);
    EXPECT_DOUBLE_EQ(c.v[1], 0.5);
    EXPECT_DOUBLE_EQ(c.v[3], 0);
    c = declared("#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;", "C");
    EXPECT_DOUBLE_EQ(c.v[3], 0.4);
    EXPECT_DOUBLE_EQ(c.v[4], 0.5);
    c = declared("#declare C = rgbt <1, 1, 1, 0.7>;", "C");
    EXPECT_DOUBLE_EQ(c.v[3], 0);
    EXPECT_DOUBLE_EQ(c.v[4], 0.7);
    c = declared("#declare C = color red 1 green 0.5 filter 0.25;", "C");
    EXPECT_DOUBLE_EQ(c.v[0], 1);
    EXPECT_DOUBLE_EQ(c.v[1], 0.5);
    EXPECT_DOUBLE_EQ(c.v[2], 0);
    EXPECT_DOUBLE_EQ(c.v[3], 0.25);
    c = declared("#declare C = srgb <0.5, 1, 0>;", "C");
    EXPECT_NEAR(c.v[0], 0.2140, 1e-4); // linearised
    EXPECT_DOUBLE_EQ(c.v[1], 1);
    c = declared("#declare C = rgb 1 * 0.5;", "C");
    EXPECT_DOUBLE_EQ(c.v[2], 0.5);
    EXPECT_DOUBLE_EQ(num("(rgb <0.2, 0.4, 0.6>).green"), 0.4);
    // The whole expression after rgb is its vector (POV-Ray's Parse_Express): grey, no filter
    // or transmit from the float added.
    c = declared("#declare C = rgb 0.6 + 0.5 * 0.5;", "C");
    EXPECT_DOUBLE_EQ(c.v[0], 0.85);
    EXPECT_DOUBLE_EQ(c.v[2], 0.85);
    EXPECT_DOUBLE_EQ(c.v[3], 0);
    EXPECT_DOUBLE_EQ(c.v[4], 0);
    c = declared("#declare C = rgbt <0.2, 0.2, 0.2, 0.1> + 0.1;", "C");
    EXPECT_DOUBLE_EQ(c.v[0], 0.3);
    EXPECT_DOUBLE_EQ(c.v[4], 0.2);
}

TEST(PovExpressions, ColorsInc) {
    if (!std::filesystem::exists("/usr/share/povray-3.7/include/colors.inc"))
        GTEST_SKIP() << "povray-includes is not installed";
    const Value c = declared("#include \"colors.inc\"\n#declare C = Red;", "C");
    EXPECT_DOUBLE_EQ(c.v[0], 1);
    EXPECT_DOUBLE_EQ(c.v[1], 0);
}

TEST(PovExpressions, FloatBuiltins) {
    EXPECT_NEAR(num("sin(pi / 2)"), 1, 1e-12);
    EXPECT_NEAR(num("cos(0) + tan(0)"), 1, 1e-12);
    EXPECT_NEAR(num("atan2(1, 1)"), M_PI / 4, 1e-12);
    EXPECT_NEAR(num("asin(1) + acos(1) + atan(0)"), M_PI / 2, 1e-12);
    EXPECT_NEAR(num("sinh(0) + cosh(0) + tanh(0) + asinh(0) + acosh(1) + atanh(0)"), 1, 1e-12);
    EXPECT_DOUBLE_EQ(num("pow(2, 10)"), 1024);
    EXPECT_DOUBLE_EQ(num("sqrt(16) + exp(0)"), 5);
    EXPECT_DOUBLE_EQ(num("log(100)"), 2);
    EXPECT_DOUBLE_EQ(num("ln(1)"), 0);
    EXPECT_DOUBLE_EQ(num("abs(-3) + int(-2.5) + floor(-2.5) + ceil(2.1)"), 3 - 2 - 3 + 3);
    EXPECT_DOUBLE_EQ(num("mod(7, 3) + div(7, 2)"), 4);
    EXPECT_DOUBLE_EQ(num("min(3, 1, 2) + max(3, 9)"), 10);
    EXPECT_DOUBLE_EQ(num("select(-1, 10, 20) + select(0, 1, 2, 3)"), 12);
    EXPECT_NEAR(num("degrees(pi) + radians(180)"), 180 + M_PI, 1e-9);
    EXPECT_DOUBLE_EQ(num("true + on + yes + false + off + no"), 3);
    EXPECT_DOUBLE_EQ(num("clock"), 0);
    EXPECT_DOUBLE_EQ(num("bitwise_and(6, 3)"), 2);
}

TEST(PovExpressions, Strings) {
    EXPECT_EQ(declared("#declare S = concat(\"a\", str(1.5, 0, 2), chr(66));", "S").str, "a1.50B");
    EXPECT_EQ(declared("#declare S = substr(\"hello\", 2, 3);", "S").str, "ell");
    EXPECT_EQ(declared("#declare S = strupr(\"ab\");", "S").str, "AB");
    EXPECT_EQ(declared("#declare S = strlwr(\"AB\");", "S").str, "ab");
    EXPECT_EQ(declared("#declare S = str(5, -3, 0);", "S").str, "005");
    EXPECT_DOUBLE_EQ(num("strlen(\"four\") + val(\"2.5\") + asc(\"A\")"), 4 + 2.5 + 65);
    EXPECT_DOUBLE_EQ(num("\"abc\" = \"abc\""), 1);
    EXPECT_DOUBLE_EQ(num("file_exists(\"scene.pov\")"), 1);
    EXPECT_DOUBLE_EQ(num("file_exists(\"nope.inc\")"), 0);
}

TEST(PovExpressions, RandomStreamsAreDeterministic) {
    const std::string s = "#declare S = seed(42); #declare A = rand(S); #declare B = rand(S);";
    const double a = declared(s, "A").v[0], b = declared(s, "B").v[0];
    EXPECT_GE(a, 0);
    EXPECT_LT(a, 1);
    EXPECT_NE(a, b);
    EXPECT_EQ(a, declared(s, "A").v[0]);
    // POV-Ray's streams, value for value (povray 3.7.0.10 wrote them): the classic 32-bit step
    // from the seed, over 2^32 - 1; a seed beyond an int's range starts from INT_MIN.
    const std::string p = "#declare S = seed(12345); #declare A = rand(S); #declare B = rand(S);"
                          "#declare T = seed(-7); #declare C = rand(T);"
                          "#declare U = seed(3000000000); #declare D = rand(U);";
    EXPECT_DOUBLE_EQ(declared(p, "A").v[0], 0.46656368450880137);
    EXPECT_DOUBLE_EQ(declared(p, "B").v[0], 0.24907022883395438);
    EXPECT_DOUBLE_EQ(declared(p, "C").v[0], 0.04607286817535592);
    EXPECT_DOUBLE_EQ(declared(p, "D").v[0], 0.50000287441071189);
}

TEST(PovExpressions, MinAndMaxExtent) {
    auto extent = [](const std::string& object, const char* which) {
        const Value v =
            declared("#declare O = " + object + "\n#declare E = " + which + "(O);", "E");
        return Vec3(float(v.v[0]), float(v.v[1]), float(v.v[2]));
    };
    auto expect = [](Vec3 a, Vec3 b) {
        EXPECT_NEAR(a.x, b.x, 1e-5);
        EXPECT_NEAR(a.y, b.y, 1e-5);
        EXPECT_NEAR(a.z, b.z, 1e-5);
    };
    expect(extent("sphere { <1, 2, 3>, 0.5 }", "min_extent"), {0.5f, 1.5f, 2.5f});
    expect(extent("box { <-1, 0, 2>, <3, 2, 4> rotate y * 90 }", "max_extent"), {4, 2, 1});
    expect(extent("cylinder { 0, y * 2, 0.5 }", "max_extent"), {0.5f, 2, 0.5f});
    expect(extent("torus { 2, 0.5 }", "min_extent"), {-2.5f, -0.5f, -2.5f});
    expect(extent("union { sphere { 0, 1 } box { <2, 2, 2>, <3, 4, 5> } }", "max_extent"),
           {3, 4, 5});
    expect(extent("intersection { sphere { 0, 1 } box { <0, 0, 0>, <3, 4, 5> } }", "min_extent"),
           {0, 0, 0});
    expect(extent("difference { box { -1, 1 } sphere { 0, 3 } }", "max_extent"), {1, 1, 1});
    expect(extent("mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 2, -1> } }", "min_extent"),
           {0, 0, -1});
    expect(extent("plane { y, 0 }", "max_extent"), {2e10f, 2e10f, 2e10f});
    // A blob: POV-Ray's box around its positive components' spheres (language/bounding.pov),
    // not a sphere around them all (the spheres are 1e-5 of their radius larger).
    const std::string blob = "blob { threshold 0.5 sphere { <-2, 0, 0>, 1, 1 } "
                             "sphere { <2, 1, 0>, 1.5, 1 } sphere { <9, 9, 9>, 1, -1 } }";
    const Vec3 hi = extent(blob, "max_extent"), lo = extent(blob, "min_extent");
    EXPECT_NEAR(hi.x, 3.5f, 1e-4);
    EXPECT_NEAR(hi.y, 2.5f, 1e-4);
    EXPECT_NEAR(hi.z, 1.5f, 1e-4);
    EXPECT_NEAR(lo.x, -3, 1e-4);
    EXPECT_NEAR(lo.y, -1, 1e-4);
    EXPECT_NEAR(lo.z, -1.5f, 1e-4);
    EXPECT_NE(error_of("#declare E = min_extent(3);"), "");
}

TEST(PovExpressions, TraceAndInsideQueryAnObject) {
    auto vec = [](const std::string& text, const char* name) {
        const Value v = declared(text, name);
        return Vec3(float(v.v[0]), float(v.v[1]), float(v.v[2]));
    };
    auto expect = [](Vec3 a, Vec3 b) {
        EXPECT_NEAR(a.x, b.x, 1e-5);
        EXPECT_NEAR(a.y, b.y, 1e-5);
        EXPECT_NEAR(a.z, b.z, 1e-5);
    };
    // A sphere moved up and a box: trace finds the nearer surface and its normal.
    const std::string o = "#declare O = union { sphere { <0, 2, 0>, 1 } box { <-1, -1, 3>, "
                          "<1, 1, 4> } }\n";
    expect(vec(o + "#declare P = trace(O, <0, 10, 0>, -y, N);", "P"), {0, 3, 0});
    expect(vec(o + "#declare P = trace(O, <0, 10, 0>, -y, N);", "N"), {0, 1, 0});
    expect(vec(o + "#declare P = trace(O, <0, 0, -5>, z*2);", "P"), {0, 0, 3});   // not the sphere
    expect(vec(o + "#declare P = trace(O, <0, 0, 3.5>, x, N);", "N"), {1, 0, 0}); // from inside
    expect(vec(o + "#declare N = 7; #declare P = trace(O, <5, 5, 5>, x, N);", "P"), {0, 0, 0});
    expect(vec(o + "#declare P = trace(O, <5, 5, 5>, x, N);", "N"), {0, 0, 0}); // missed
    // A mesh's triangle: the normal faces where the ray came from.
    expect(vec("#declare M = mesh { triangle { <-1, 0, -1>, <1, 0, -1>, <0, 0, 1> } }\n"
               "#declare P = trace(M, <0, -3, 0>, y, N);",
               "N"),
           {0, -1, 0});
    // inside: CSG solids, exact, with inverse; meshes enclose nothing.
    auto inside = [&](const std::string& object, const char* point) {
        return declared("#declare O = " + object + "\n#declare V = inside(O, " + point + ");", "V")
            .v[0];
    };
    EXPECT_EQ(inside("difference { sphere { 0, 2 } sphere { 0, 1 } }", "<1.5, 0, 0>"), 1);
    EXPECT_EQ(inside("difference { sphere { 0, 2 } sphere { 0, 1 } }", "<0.5, 0, 0>"), 0);
    EXPECT_EQ(inside("sphere { 0, 1 inverse }", "<3, 0, 0>"), 1);
    EXPECT_EQ(inside("blob { threshold 0.5 sphere { <0, 0, 2>, 1, 1 } }", "<0, 0, 2.3>"), 1);
    EXPECT_EQ(inside("mesh { triangle { 0, x, y } }", "<0.1, 0.1, 0>"), 0);
    EXPECT_EQ(error_of("#declare V = inside(3, 0);"),
              "scene.pov:1:21: error: found '3', expected an object identifier");
    EXPECT_EQ(error_of("#declare O = sphere { 0, 1 }\n#declare V = trace(O, 0);"),
              "scene.pov:2:14: error: trace takes 3 or 4 arguments, not 2");
}

TEST(PovExpressions, Arrays) {
    const std::string s = "#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };\n"
                          "#declare B = array[4];\n#declare B[2] = 7;\n"
                          "#declare V = A[1][2] + B[2] + dimension_size(A, 2) + "
                          "defined(B[2]) + defined(B[0]);";
    EXPECT_DOUBLE_EQ(declared(s, "V").v[0], 6 + 7 + 3 + 1 + 0);
    EXPECT_NE(error_of("#declare B = array[4];\n#declare V = B[1];")
                  .find("scene.pov:2:14: error: element of 'B' used before it was set"),
              std::string::npos);
    EXPECT_EQ(error_of("#declare B = array[4];\n#declare V = B[4];"),
              "scene.pov:2:16: error: index 4 is out of range for 'B' (size 4)");
    // Copies on assignment.
    EXPECT_DOUBLE_EQ(declared("#declare A = array[1] {1}; #declare B = A; #declare B[0] = 2;"
                              "#declare V = A[0];",
                              "V")
                         .v[0],
                     1);
}

TEST(PovExpressions, UserFunctions) {
    EXPECT_DOUBLE_EQ(
        declared("#declare F = function { x * x + y - z }; #declare V = F(3, 1, 2);", "V").v[0], 8);
    EXPECT_DOUBLE_EQ(declared("#declare F = function(a, b) { pow(a, b) + (a < b ? 1 : 0) };"
                              "#declare V = F(2, 3);",
                              "V")
                         .v[0],
                     9);
    EXPECT_DOUBLE_EQ(declared("#declare K = 10; #declare F = function(a) { a * K };"
                              "#declare G = function { F(x) + abs(-y) + max(x, y, z) };"
                              "#declare V = G(1, -2, 5);",
                              "V")
                         .v[0],
                     10 + 2 + 5);
    EXPECT_NE(error_of("#declare F = function(a) { a };\n#declare V = F(1, 2);")
                  .find("'F' takes 1 arguments, not 2"),
              std::string::npos);
}

// A transform function gives the point transformed (transforms.inc's vtransform and
// vinv_transform); a function body cannot use it (warned where it is called).
TEST(PovExpressions, TransformFunctionsTransformPoints) {
    const Value v =
        declared("#include \"transforms.inc\"\n"
                 "#declare V = vtransform(<1, 2, 3>, transform { scale 2 translate x });",
                 "V");
    ASSERT_EQ(v.type, VType::Vector);
    EXPECT_NEAR(v.v[0], 3, 1e-5);
    EXPECT_NEAR(v.v[1], 4, 1e-5);
    EXPECT_NEAR(v.v[2], 6, 1e-5);
    const Value w =
        declared("#include \"transforms.inc\"\n"
                 "#declare V = vinv_transform(<3, 4, 6>, transform { scale 2 translate x });",
                 "V");
    EXPECT_NEAR(w.v[0], 1, 1e-5);
    EXPECT_NEAR(w.v[2], 3, 1e-5);
    const PovResult r = load_text("#declare T = function { transform { rotate 90 * z } }\n"
                                  "#declare V = T(1, 0, 0);\n"
                                  "#declare F = function { T(x, y, z) + 1 }\n"
                                  "#declare W = F(1, 0, 0);\n"
                                  "sphere { 0, W }\n");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("transform function in a function"), std::string::npos);
}

TEST(PovExpressions, TypeErrorsNameTheToken) {
    EXPECT_EQ(error_of("#declare V = 1 + ;"),
              "scene.pov:1:18: error: found ';', expected a float, vector, colour or string "
              "expression");
    EXPECT_EQ(error_of("#declare V = sin(\"a\");"),
              "scene.pov:1:18: error: found '\"a\"', expected a float");
    EXPECT_EQ(error_of("#declare V = <1, 2;"),
              "scene.pov:1:19: error: found ';', expected ',' or '>'");
    EXPECT_NE(error_of("#declare V = Nope + 1;").find("scene.pov:1:14: error: found 'Nope'"),
              std::string::npos);
}

} // namespace
} // namespace sheaf::io::pov

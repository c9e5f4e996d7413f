// Tests of the directives: declarations and scopes, macros, loops, conditionals, #switch,
// #include search, file I/O, #error/#warning, and the limits (loops, recursion, arrays,
// self-includes) that must end in an error with a position, never a hang.
#include "tests/support/pov_test_util.h"

#include "io/pov/model.h"

#include <chrono>
#include <filesystem>
#include <fstream>

namespace sheaf::io::pov {
namespace {

using test::declared;
using test::error_of;
using test::load_text;
using test::TempDir;

TEST(PovDirectives, DeclareLocalUndef) {
    EXPECT_DOUBLE_EQ(declared("#declare A = 1; #local B = A + 1; #declare A = B * 3;", "A").v[0],
                     6);
    EXPECT_THROW(declared("#declare A = 1;\n#undef A\n", "A"), SceneError);
    EXPECT_DOUBLE_EQ(declared("#declare A = 1 #declare B = A + 1", "B").v[0], 2); // no ';'
}

TEST(PovDirectives, MacrosHaveLocalScope) {
    const std::string s = "#declare X = 1;\n"
                          "#macro M(X, Y)\n"
                          "  #local T = X * 10;\n"
                          "  #declare Out = T + Y;\n"
                          "#end\n"
                          "M(2, 3)\n"
                          "#declare Seen = defined(T);\n";
    EXPECT_DOUBLE_EQ(declared(s, "Out").v[0], 23);
    EXPECT_DOUBLE_EQ(declared(s, "X").v[0], 1);    // the parameter shadowed it
    EXPECT_DOUBLE_EQ(declared(s, "Seen").v[0], 0); // T was local
}

TEST(PovDirectives, MacrosReturnValuesAndRecurse) {
    const std::string s = "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
                          "#macro Sq(A) (A * A) #end\n"
                          "#declare V = Fact(5) + Sq(3) + 1;\n";
    EXPECT_DOUBLE_EQ(declared(s, "V").v[0], 120 + 9 + 1);
    // A local counter changed with #declare inside the macro's loop.
    EXPECT_DOUBLE_EQ(declared("#macro Count(N) #local I = 0; #local S = 0;\n"
                              "#while (I < N) #declare S = S + I; #declare I = I + 1; #end S #end\n"
                              "#declare V = Count(5);",
                              "V")
                         .v[0],
                     10);
    EXPECT_NE(error_of("#macro M(A) A #end\n#declare V = M(1, 2);")
                  .find("scene.pov:2:14: error: macro 'M' takes 1 arguments, not 2"),
              std::string::npos);
}

// A macro whose body ends with its own local (an array, a number): the value outlives the
// macro's scope, which closes while the caller reads on (benchmark.pov's L_GetVN).
TEST(PovDirectives, AMacroReturnsItsOwnLocal) {
    const std::string s = "#macro Pair() #local A = array[2] {3, 4}\n A\n#end\n"
                          "#macro Half(N) #local H = N / 2; H #end\n"
                          "#declare B = Pair()\n"
                          "#declare V = dimension_size(B, 1) * 100 + B[1] * 10 + Half(8);\n";
    EXPECT_DOUBLE_EQ(declared(s, "V").v[0], 200 + 40 + 4);
}

TEST(PovDirectives, MacroArgumentsMayGoWithoutCommas) {
    // POV-Ray reads "off <100, 100>" as two arguments (shapes.inc's HF_Square in the portfolio's
    // o_shapes.pov): '<' outside parentheses starts a vector, it is no comparison; inside
    // parentheses it compares.
    const std::string m = "#macro M(A, B, C) (A + B.x * 10 + C) #end\n";
    EXPECT_DOUBLE_EQ(declared(m + "#declare V = M(off <100, 100> 7);", "V").v[0], 1007);
    EXPECT_DOUBLE_EQ(declared(m + "#declare V = M((1 < 2), <3, 0>, 0);", "V").v[0], 31);
    // A directive in a macro called as an argument still compares (shapes.inc's
    // Bevelled_Text inside Center_Object, incdemo/shapes.pov).
    const PovResult r =
        test::load_text("#macro Row(N) union { #local J = 0;\n"
                        "  #while (J < N) sphere { <J, 0, 0>, 0.1 } #local J = J + 1; #end } #end\n"
                        "#macro Moved(O, V) object { O translate V } #end\n"
                        "object { Moved(Row(3) <0, 1, 0>) }\n");
    EXPECT_EQ(r.scene.shape_objects.size(), 3u);
}

TEST(PovDirectives, VariablesPassedToMacrosAreReferences) {
    // As in POV-Ray, an argument that is a variable alone is the variable itself: #local and
    // #declare of the parameter change it; an expression is a value.
    const std::string s = "#macro Inc(P) #local P = P + 1; #end\n"
                          "#macro Set(P) #declare P = 7; #end\n"
                          "#macro Outer() #local L = 1; Inc(L) Inc(L) #declare Got = L; #end\n"
                          "#declare A = 1; Inc(A) #declare B = 5; Set(B) Outer()\n"
                          "#declare C = 1; Inc(C + 0)\n";
    EXPECT_DOUBLE_EQ(declared(s, "A").v[0], 2);
    EXPECT_DOUBLE_EQ(declared(s, "B").v[0], 7);
    EXPECT_DOUBLE_EQ(declared(s, "Got").v[0], 3);
    EXPECT_DOUBLE_EQ(declared(s, "C").v[0], 1);
    EXPECT_THROW(declared(s, "L"), SceneError); // Outer's local, gone with it
    // Passed on through a second macro, still the caller's variable.
    EXPECT_DOUBLE_EQ(
        declared("#macro Inc(P) #local P = P + 1; #end #macro Twice(Q) Inc(Q) Inc(Q) #end\n"
                 "#declare A = 1; Twice(A)",
                 "A")
            .v[0],
        3);
}

TEST(PovDirectives, AMacroMayEndALocalsValueAndRunOnInACondition) {
    // The value's ';' is the macro's last token: the #local still belongs to M's scope.
    EXPECT_DOUBLE_EQ(declared("#macro R() #local Q = 4; Q; #end\n"
                              "#macro M() #local V = R() #declare Got = V; #end M()",
                              "Got")
                         .v[0],
                     4);
    // Inside a parenthesised condition the expression runs on past a macro's #end.
    EXPECT_DOUBLE_EQ(
        declared("#macro Half() 0.5 #end\n"
                 "#if (Half() > 0.2 & 1 < 2) #declare Got = 1; #else #declare Got = 0; "
                 "#end",
                 "Got")
            .v[0],
        1);
}

TEST(PovDirectives, WhileAndFor) {
    EXPECT_DOUBLE_EQ(declared("#declare S = 0; #declare I = 0;\n"
                              "#while (I < 10) #declare S = S + I; #declare I = I + 1; #end",
                              "S")
                         .v[0],
                     45);
    EXPECT_DOUBLE_EQ(
        declared("#declare S = 0; #for (I, 1, 9, 2) #declare S = S + I; #end", "S").v[0], 25);
    EXPECT_DOUBLE_EQ(
        declared("#declare S = 0; #for (I, 3, 1, -1) #declare S = S * 10 + I; #end", "S").v[0],
        321);
    EXPECT_DOUBLE_EQ(declared("#declare S = 0; #for (I, 5, 1) #declare S = 1; #end", "S").v[0], 0);
    // Nested loops and #break out of a loop.
    EXPECT_DOUBLE_EQ(declared("#declare S = 0; #for (I, 1, 3) #for (J, 1, 3) #declare S = S + 1;"
                              " #end #end",
                              "S")
                         .v[0],
                     9);
    // The loop variable is local: a loop inside a macro leaves the caller's loop alone (this
    // hung when it was not), and after a loop it holds End + Step.
    EXPECT_DOUBLE_EQ(declared("#macro M() #for (I, 0, 5) #end #end\n#declare S = 0;"
                              " #for (I, 1, 3) M() #declare S = S + 1; #end",
                              "S")
                         .v[0],
                     3);
    EXPECT_DOUBLE_EQ(declared("#for (I, 1, 5) #end #declare E = I;", "E").v[0], 6);
    EXPECT_DOUBLE_EQ(declared("#declare S = 0; #while (1) #declare S = S + 1;"
                              " #if (S = 4) #break #end #end",
                              "S")
                         .v[0],
                     4);
    // The condition ends at its ')': a vector right after it is the loop's first item (it
    // was read as "(I < 3) < I", and the loop never ran).
    const Value v = declared("#declare I = 0; #declare V = array[3] {\n"
                             "#while (I < 3) <I, 2 * I>, #declare I = I + 1; #end }",
                             "V");
    ASSERT_EQ(v.type, VType::Array);
    EXPECT_DOUBLE_EQ(static_cast<const ArrayValue*>(v.ptr.get())->elements.at(2).v[1], 4);
    EXPECT_DOUBLE_EQ(declared("#declare A = 1; #declare B = 0;\n"
                              "#if ((A < 2) & (B < 1)) #declare C = 7; #else #declare C = 8; #end",
                              "C")
                         .v[0],
                     7);
    EXPECT_DOUBLE_EQ(declared("#declare A = 3; #if (A) #declare C = 7; #end", "C").v[0], 7);
}

TEST(PovDirectives, Conditionals) {
    const std::string base = "#declare A = 2;\n";
    EXPECT_DOUBLE_EQ(declared(base + "#if (A = 1) #declare R = 1; #elseif (A = 2) #declare R = 2;"
                                     " #else #declare R = 3; #end",
                              "R")
                         .v[0],
                     2);
    EXPECT_DOUBLE_EQ(declared(base + "#if (A > 5) #declare R = 1; #else #if (0) #declare R = 9;"
                                     " #end #declare R = 3; #end",
                              "R")
                         .v[0],
                     3);
    EXPECT_DOUBLE_EQ(
        declared(base + "#ifdef (A) #declare R = 1; #else #declare R = 0; #end", "R").v[0], 1);
    EXPECT_DOUBLE_EQ(declared(base + "#ifndef (Q) #declare R = 1; #end", "R").v[0], 1);
}

TEST(PovDirectives, SwitchCaseRangeBreak) {
    auto pick = [](double v) {
        return declared("#declare V = " + std::to_string(v) +
                            ";\n"
                            "#switch (V)\n"
                            "  #case (1) #declare R = 10; #break\n"
                            "  #case (2)\n"
                            "  #case (3) #declare R = 23; #break\n"
                            "  #range (4, 6) #declare R = 46; #break\n"
                            "  #else #declare R = -1;\n"
                            "#end\n",
                        "R")
            .v[0];
    };
    EXPECT_DOUBLE_EQ(pick(1), 10);
    EXPECT_DOUBLE_EQ(pick(2), 23);
    EXPECT_DOUBLE_EQ(pick(3), 23);
    EXPECT_DOUBLE_EQ(pick(5.5), 46);
    EXPECT_DOUBLE_EQ(pick(9), -1);
}

TEST(PovDirectives, IncludeSearchOrder) {
    TempDir d;
    d.write("sub/local.inc", "#declare FromLocal = 1;");
    d.write("lib/a.inc", "#declare FromLib = 2;\n#include \"b.inc\"");
    d.write("lib/b.inc", "#declare FromLibB = 3;");
    const std::string scene =
        d.write("sub/scene.pov", "#include \"local.inc\"\n#include \"a.inc\"\n"
                                 "sphere { 0, FromLocal + FromLib + FromLibB }");
    PovOptions o;
    o.include_paths = {d.path() + "/lib"};
    const PovResult r = load_pov_scene(scene, o);
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.shape_objects[0].nodes[0].transform.m[0][0], 6);
    // Without the path it is an error naming the file and the folders searched.
    try {
        load_pov_scene(scene, {});
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(
            std::string(e.what()).find("scene.pov:2:2: error: cannot find include file 'a.inc'"),
            std::string::npos);
    }
}

TEST(PovDirectives, IncludeLocalsStayInTheFile) {
    TempDir d;
    d.write("a.inc", "#local Hidden = 1; #declare Shown = 2;");
    Parser p(PovOptions{});
    p.parse_scene(d.write("s.pov", "#include \"a.inc\""));
    EXPECT_EQ(p.lookup("Hidden"), nullptr);
    ASSERT_NE(p.lookup("Shown"), nullptr);
}

TEST(PovDirectives, FileReadAndWrite) {
    TempDir d;
    d.write("data.txt", "1, <2, 3, 4>, \"five\", -6\n");
    Parser p(PovOptions{});
    p.parse_scene(d.write("s.pov", "#fopen F \"data.txt\" read\n"
                                   "#read (F, A, B, C)\n#declare Open = defined(F);\n"
                                   "#read (F, D)\n#declare Closed = !defined(F);\n"));
    EXPECT_DOUBLE_EQ(p.lookup("A")->v[0], 1);
    EXPECT_DOUBLE_EQ(p.lookup("B")->v[2], 4);
    EXPECT_EQ(p.lookup("C")->str, "five");
    EXPECT_DOUBLE_EQ(p.lookup("D")->v[0], -6);
    EXPECT_DOUBLE_EQ(p.lookup("Open")->v[0], 1);
    EXPECT_DOUBLE_EQ(p.lookup("Closed")->v[0], 1);
    // Reading outside the scene's folder and writing outside the current folder are errors.
    EXPECT_NE(
        error_of("#fopen F \"/etc/passwd\" read").find("may read only under the scene's folder"),
        std::string::npos);
    EXPECT_NE(
        error_of("#fopen F \"../x.txt\" read").find("scene.pov:1:2: error: #fopen may read only"),
        std::string::npos);
    EXPECT_NE(error_of("#fopen F \"/tmp/../etc/x\" write")
                  .find("may write only under the current folder"),
              std::string::npos);
    // Writing under the current folder works.
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(d.path());
    Parser w(PovOptions{});
    w.parse_scene(d.write("w.pov",
                          "#fopen O \"out.txt\" write\n#write (O, \"v=\", 2, \",\", <1,2>)\n"
                          "#fclose O\n"));
    std::filesystem::current_path(cwd);
    std::ifstream in(d.path() + "/out.txt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "v=2,<1,2>");
}

TEST(PovDirectives, ErrorWarningDebugVersion) {
    EXPECT_EQ(error_of("#declare A = 1;\n  #error concat(\"bad \", str(A, 0, 0))"),
              "scene.pov:2:4: error: bad 1");
    const PovResult r = test::load_text("#version 3.6;\n#warning \"careful\"\n#debug \"dbg\\n\"\n");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("scene.pov:2:2: warning: careful"), std::string::npos);
    EXPECT_DOUBLE_EQ(r.version, 3.6);
    EXPECT_DOUBLE_EQ(r.assumed_gamma, 2.2); // pre-3.7 scenes without assumed_gamma
    EXPECT_DOUBLE_EQ(test::load_text("#version 3.7;").assumed_gamma, 1.0);
    EXPECT_DOUBLE_EQ(declared("#version 3.5; #declare V = version;", "V").v[0], 3.5);
}

TEST(PovDirectives, DefaultTexture) {
    const PovResult r = test::load_text(
        "#default { pigment { rgb <0, 1, 0> } finish { ambient 0.3 } }\nsphere { 0, 1 }");
    ASSERT_EQ(r.scene.shape_objects.size(), 1u);
    const Material& m = r.scene.materials[r.scene.shape_objects[0].nodes[0].material];
    EXPECT_FLOAT_EQ(m.color.y, 1);
    EXPECT_FLOAT_EQ(m.ambient, 0.3f);
}

// ---- limits: each ends quickly in an error with a position ----

template <class F> double seconds(F f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(PovLimits, EndlessWhile) {
    // A lower budget than the default (4,000,000, checked in BudgetsAreSetByTheHostAndReported)
    // keeps the test short under the sanitizers.
    PovOptions o;
    o.limits.loop_iterations = 100000;
    std::string e;
    const double s = seconds(
        [&] { e = error_of("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end", o); });
    EXPECT_EQ(e, "scene.pov:2:2: error: the scene's loops ran more than 100000 times in all "
                 "(this one 100001); if they are meant to, raise the limit: render --limit "
                 "loop_iterations=N, load option limit.loop_iterations");
    EXPECT_LT(s, 60);
}

// Each budget of PovLimits is the host's to set: a scene within it reads, the same scene past
// it is an error at the place it went past, and the result says what the scene used.
TEST(PovLimits, BudgetsAreSetByTheHostAndReported) {
    const std::string loop = "#declare I = 0;\n#while (I < 100)\n  sphere { I, 1 }\n"
                             "  #declare I = I + 1;\n#end";
    const PovResult r = load_text(loop);
    EXPECT_EQ(r.usage.loop_iterations, 100u);
    EXPECT_EQ(r.usage.objects, 100u);
    EXPECT_GT(r.usage.parse_steps, 100u * 10);
    EXPECT_GE(r.usage.data_bytes, 100 * sizeof(PovObject));
    const std::vector<LimitUse> uses = limit_uses(r.usage, PovOptions().limits);
    ASSERT_EQ(uses.size(), 6u);
    EXPECT_EQ(uses[0].name, "parse_steps");
    EXPECT_EQ(uses[3].name, "loop_iterations");
    EXPECT_EQ(uses[3].used, 100);
    EXPECT_EQ(uses[3].limit, 4e6);
    EXPECT_EQ(uses[4].name, "macro_calls");
    EXPECT_EQ(uses[5].name, "function_terms");

    PovOptions o;
    o.limits.loop_iterations = 50;
    EXPECT_NE(error_of(loop, o).find("scene.pov:2:2: error: the scene's loops ran more than 50 "
                                     "times in all"),
              std::string::npos);
    // All loops together: two nested loops of 10 runs each run 110 times (10 outer, 100
    // inner).
    const std::string nested = "#for (I, 1, 10)\n  #for (J, 1, 10)\n  #end\n#end";
    EXPECT_EQ(load_text(nested).usage.loop_iterations, 110u);
    o.limits.loop_iterations = 109;
    EXPECT_NE(error_of(nested, o).find("the scene's loops ran more than 109 times in all"),
              std::string::npos);
    o = {};
    o.limits.objects = 99;
    EXPECT_NE(error_of(loop, o).find("scene.pov:3:3: error: more than 99 objects parsed"),
              std::string::npos);
    o = {};
    o.limits.parse_steps = 500;
    EXPECT_NE(error_of(loop, o).find("error: the scene takes more than 500 parse steps"),
              std::string::npos);
    o = {};
    o.limits.data_bytes = 50 * sizeof(PovObject);
    EXPECT_NE(error_of(loop, o).find("error: the scene's data would exceed"), std::string::npos);

    // Macro calls and the function terms evaluated while reading: each its own budget.
    const std::string calls = "#macro One() 1 #end\n#declare F = function { x + y * z }\n"
                              "#for (I, 1, 10)\n  #declare V = One() + F(I, 2, 3);\n#end";
    const PovResult c = load_text(calls);
    EXPECT_EQ(c.usage.macro_calls, 10u);
    EXPECT_GE(c.usage.function_terms, 10u * 3);
    o = {};
    o.limits.macro_calls = 9;
    EXPECT_NE(error_of(calls, o).find("scene.pov:4:16: error: more than 9 macro calls"),
              std::string::npos);
    o = {};
    o.limits.function_terms = 20;
    EXPECT_NE(error_of(calls, o).find("scene.pov:4:24: error: the scene evaluates more than 20 "
                                      "function terms while it is read"),
              std::string::npos);

    PovLimits l;
    EXPECT_TRUE(set_limit(l, "macro_calls", 7));
    EXPECT_EQ(l.macro_calls, 7u);
    EXPECT_TRUE(reset_limit(l, "function_terms"));
    EXPECT_TRUE(set_limit(l, "data_mib", 3));
    EXPECT_EQ(l.data_bytes, uint64_t(3) << 20);
    EXPECT_FALSE(set_limit(l, "data_mib", 0));
    EXPECT_FALSE(set_limit(l, "tokens", 5));
    EXPECT_FALSE(set_limit(l, "objects", (uint64_t(1) << 50) + 1));
    EXPECT_TRUE(reset_limit(l, "data_mib"));
    EXPECT_EQ(l.data_bytes, PovLimits().data_bytes);
    EXPECT_FALSE(reset_limit(l, "tokens"));
}

// The hostile scenes of tests/fuzz/regressions stop within the default budgets after little
// work: counted, not timed (a second or so on the development machine; docs/pov.md).
TEST(PovLimits, RunawayScenesStopEarly) {
    // Objects inside a union that never closes: the object budget.
    EXPECT_NE(error_of("union {\n#while (1) sphere { 0, 1 } #end\n}")
                  .find("error: more than 200000 objects parsed"),
              std::string::npos);
    // A string doubled without end: one string may take a sixteenth of the data budget.
    EXPECT_NE(error_of("#declare S = \"ab\";\n#while (1)\n  #declare S = concat(S, S);\n#end")
                  .find("scene.pov:3:16: error: a string longer than 8192 KiB"),
              std::string::npos);
    // Macros that each call the one below twice (2^40 calls): the macro-call budget, long
    // before the parse steps.
    std::string doubling = "#macro M0() 1 #end\n";
    for (int i = 1; i <= 40; ++i)
        doubling += "#macro M" + std::to_string(i) + "() M" + std::to_string(i - 1) + "() + M" +
                    std::to_string(i - 1) + "() #end\n";
    EXPECT_NE(
        error_of(doubling + "#declare Y = M40();").find("error: more than 5000000 macro calls"),
        std::string::npos);
    // A function redeclared as the sum of itself twice, 40 times over, evaluated once.
    std::string sums = "#declare F = function { x }\n";
    for (int i = 0; i < 40; ++i) sums += "#declare F = function { F(x,y,z) + F(x,y,z) }\n";
    EXPECT_NE(error_of(sums + "#declare Y = F(1,1,1);")
                  .find("error: the scene evaluates more than 50000000 function terms"),
              std::string::npos);
    // A mesh's triangles count against the data budget.
    PovOptions o;
    o.limits.data_bytes = 100 * 64;
    EXPECT_NE(error_of("mesh {\n#while (1) triangle { 0, x, y } #end\n}", o)
                  .find("error: the scene's data would exceed"),
              std::string::npos);
}

TEST(PovLimits, InfiniteMacroRecursion) {
    // The call chain follows, a recursion as one line with its count.
    EXPECT_EQ(error_of("#macro R(N) R(N + 1) #end\nR(0)"),
              "scene.pov:1:13: error: macro calls nested deeper than 200 (endless recursion?)\n"
              "  in macro 'R' called at scene.pov:1:13 (199 times)\n"
              "  in macro 'R' called at scene.pov:2:1");
}

TEST(PovLimits, HugeArrays) {
    EXPECT_EQ(error_of("#declare A = array[200000000];"),
              "scene.pov:1:20: error: an array of more than 100000000 elements");
    EXPECT_EQ(error_of("#declare A = array[20000][20000];"),
              "scene.pov:1:27: error: an array of more than 100000000 elements");
    // Under the element limit but over the data budget.
    EXPECT_NE(error_of("#declare A = array[90000000];")
                  .find("scene.pov:1:14: error: the scene's data would exceed"),
              std::string::npos);
}

TEST(PovLimits, SelfAndDeepIncludes) {
    TempDir d;
    const std::string self = d.write("self.pov", "\n  #include \"self.pov\"");
    try {
        load_pov_scene(self, {});
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), self + ":2:4: error: 'self.pov' includes itself");
    }
    d.write("a.inc", "#include \"b.inc\"");
    d.write("b.inc", "#include \"a.inc\"");
    EXPECT_THROW(load_pov_scene(d.write("cycle.pov", "#include \"a.inc\""), {}), SceneError);
    for (int i = 0; i < 70; ++i)
        d.write("d" + std::to_string(i) + ".inc",
                "#include \"d" + std::to_string(i + 1) + ".inc\"");
    d.write("d70.inc", "");
    try {
        load_pov_scene(d.write("deep.pov", "#include \"d0.inc\""), {});
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("includes nested deeper than 64"), std::string::npos);
    }
}

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

// The parser recurses into nested constructs: past kMaxNesting levels (all kinds together)
// an error, not a stack overflow (tests/fuzz/regressions/pov_deep_*.pov nest 100,000 deep).
TEST(PovLimits, DeepNesting) {
    // The 501st '(' is column 514.
    EXPECT_EQ(error_of("#declare V = " + repeat("(", 600) + "1" + repeat(")", 600) + ";"),
              "scene.pov:1:514: error: nested deeper than 500 levels (expressions, objects and "
              "textures together)");
    EXPECT_EQ(declared("#declare V = " + repeat("(", 400) + "1" + repeat(")", 400) + ";", "V").v[0],
              1);
    EXPECT_NE(error_of("#declare V = " + repeat("-", 600) + "1;").find("nested deeper than 500"),
              std::string::npos);
    EXPECT_NE(error_of(repeat("union { ", 600) + "sphere { 0, 1 }" + repeat(" }", 600))
                  .find("nested deeper than 500"),
              std::string::npos);
    EXPECT_NE(error_of("#macro M(A) A #end\n#declare V = " + repeat("M(", 600) + "1" +
                       repeat(")", 600) + ";")
                  .find("nested deeper than 500"),
              std::string::npos);
    EXPECT_NE(
        error_of("#declare F = function { " + repeat("(", 600) + "x" + repeat(")", 600) + " }")
            .find("nested deeper than 500"),
        std::string::npos);
}

// Function bodies are evaluated (and freed) recursively: a chain of operators, or of
// functions calling the one declared before, deeper than kMaxFunctionHeight is an error; it
// is built in linear time (it was copied at each operator).
TEST(PovLimits, DeepFunctions) {
    std::string e;
    const double s =
        seconds([&] { e = error_of("#declare F = function { x" + repeat(" + x", 20000) + " }"); });
    EXPECT_NE(e.find("a function body more than 10000 operations deep"), std::string::npos) << e;
    EXPECT_LT(s, 10);
    EXPECT_DOUBLE_EQ(declared("#declare F = function { x" + repeat(" + x", 5000) +
                                  " }\n#declare V = F(1, 0, 0);",
                              "V")
                         .v[0],
                     5001);
    e = error_of("#declare F = function(a) { a }\n#declare I = 0;\n#while (I < 20000)\n"
                 "  #declare F = function(a) { F(a) + 1 }\n  #declare I = I + 1;\n#end");
    EXPECT_NE(e.find("more than 10000 operations deep"), std::string::npos) << e;
}

// Names the system refuses (longer than a path may be) are files that do not exist, not a
// filesystem exception escaping the reader (found by fuzz_pov).
TEST(PovLimits, NamesTooLongForTheSystem) {
    const std::string name = repeat("x", 5000);
    EXPECT_NE(error_of("#include \"" + name + "\"")
                  .find("scene.pov:1:2: error: cannot find include file"),
              std::string::npos);
    EXPECT_DOUBLE_EQ(declared("#declare V = file_exists(\"" + name + "\");", "V").v[0], 0);
    EXPECT_NE(error_of("#fopen F \"" + name + "\" read").find("#fopen may read only under"),
              std::string::npos);
    EXPECT_NE(error_of("#fopen F \"" + name + "\" write").find("#fopen may write only under"),
              std::string::npos);
}

// Found by the POV fuzzer: "woods.inc" followed by NUL bytes included woods.inc (the system
// reads a name up to its NUL), and an error's message ended at the NUL, before its place.
TEST(PovLimits, NulBytesInNamesAndMessages) {
    const std::string nul("a\0b", 3);
    EXPECT_EQ(error_of("#include \"colors.inc" + nul + "\""),
              "scene.pov:1:2: error: the include file's name contains a NUL character");
    EXPECT_EQ(error_of("#declare S = \"x" + nul + "\";\n#error S"), "scene.pov:2:2: error: xa\\0b");
}

TEST(PovLimits, ArrayDimensions) {
    EXPECT_EQ(error_of("#declare A = array[1][1][1][1][1][1];"),
              "scene.pov:1:35: error: an array has at most 5 dimensions");
}

TEST(PovLimits, UnclosedBlocks) {
    EXPECT_EQ(error_of("#if (1)\nsphere { 0, 1 }"), "scene.pov:1:2: error: this block has no #end");
    EXPECT_EQ(error_of("#while (0)\n"), "scene.pov:1:2: error: this block has no #end");
    EXPECT_EQ(error_of("#end"), "scene.pov:1:2: error: #end without a block to close");
}

} // namespace
} // namespace sheaf::io::pov

namespace sheaf::io::pov {
namespace {

using test::error_of;
using test::load_text;

// A declaration that is never used warns about nothing; its first use reports what it holds,
// at the place inside the declaration, once; strict mode fails only at that use.
TEST(PovDirectives, DeclaredUnsupportedFeaturesWarnWhenUsed) {
    const std::string decl = "#declare Q = ovus { 1, 0.5 }\n"
                             "#declare R = Q\n";
    const PovResult unused = load_text(decl + "sphere { 0, 1 }\n");
    EXPECT_TRUE(unused.warnings.empty()) << unused.warnings.front();
    PovOptions strict;
    strict.strict = true;
    EXPECT_EQ(error_of(decl + "sphere { 0, 1 }\n", strict), "");

    const PovResult used = load_text(decl + "object { R }\nobject { Q translate x }\n");
    ASSERT_EQ(used.warnings.size(), 1u);
    EXPECT_NE(used.warnings[0].find("scene.pov:1:14: warning: unsupported object 'ovus'"),
              std::string::npos)
        << used.warnings[0];
    EXPECT_NE(error_of(decl + "object { R }\n", strict).find("scene.pov:1:14: error: unsupported"),
              std::string::npos);
}

TEST(PovDirectives, ImageSizeComesFromTheOptions) {
    PovOptions o;
    o.image_width = 640;
    o.image_height = 480;
    const PovResult r = load_text("#if (image_width / image_height != 640 / 480)\n"
                                  "#error \"wrong size\"\n#end\nsphere { 0, 1 }\n",
                                  o);
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(error_of("#if (image_width != 512 | image_height != 512) #error \"size\" #end\n"), "")
        << "without options the size is 512 x 512";
}

} // namespace
} // namespace sheaf::io::pov

#include "core/scene/function.h"
#include "core/scene/function_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sheaf {
namespace {

using test::op;

/// One program over `params` arguments, checked, with its view.
struct Program {
    std::vector<FnInstr> code;
    std::vector<Pattern> patterns;
    std::vector<FnPigment> pigments;
    std::vector<PigmentEntry> entries;
    FnProgram pg;
    Program(uint32_t params, std::vector<FnInstr> c) : code(std::move(c)) {
        pg.first = 0, pg.count = uint32_t(code.size()), pg.params = params;
    }
    std::string check() const {
        return check_fn_program(pg, code.data(), code.size(), patterns.size(), pigments.size());
    }
    double operator()(std::vector<double> args) const {
        const FnView v{&pg, code.data(), patterns.data(), pigments.data(), entries.data()};
        return fn_eval(v, 0, args.data());
    }
};

TEST(Function, ArithmeticReadsItsParametersWhereTheyLie) {
    // (x - 2 * y) / z, then drop the three parameters under the result.
    Program p(3, {op(FnOp::Load, 0), op(FnOp::Const, 0, 2), op(FnOp::Load, 1), op(FnOp::Mul),
                  op(FnOp::Sub), op(FnOp::Load, 2), op(FnOp::Div), op(FnOp::Drop, 3)});
    EXPECT_EQ(p.check(), "");
    EXPECT_DOUBLE_EQ(p({7, 1, 2}), 2.5);
    EXPECT_DOUBLE_EQ(p({-1, 0.5, 4}), -0.5);
}

TEST(Function, ConditionsSelectAndMathFollowPovRay) {
    Program cond(1, {op(FnOp::Load, 0), op(FnOp::Const, 0, 0), op(FnOp::Gt), op(FnOp::Const, 0, 10),
                     op(FnOp::Const, 0, 20), op(FnOp::Cond), op(FnOp::Drop, 1)});
    EXPECT_EQ(cond.check(), "");
    EXPECT_EQ(cond({1}), 10);
    EXPECT_EQ(cond({-1}), 20);
    Program sel(1, {op(FnOp::Load, 0), op(FnOp::Const, 0, 1), op(FnOp::Const, 0, 2),
                    op(FnOp::Const, 0, 3), op(FnOp::Select4), op(FnOp::Drop, 1)});
    EXPECT_EQ(sel.check(), "");
    EXPECT_EQ(sel({-5}), 1);
    EXPECT_EQ(sel({0}), 2);
    EXPECT_EQ(sel({5}), 3);
    Program m(2, {op(FnOp::Load, 0), op(FnOp::Math, uint16_t(FnMath::Sin)), op(FnOp::Load, 1),
                  op(FnOp::Math, uint16_t(FnMath::Log10)), op(FnOp::Add), op(FnOp::Load, 0),
                  op(FnOp::Load, 1), op(FnOp::Pow), op(FnOp::Max), op(FnOp::Drop, 2)});
    EXPECT_EQ(m.check(), "");
    for (double a : {0.3, 1.7})
        for (double b : {0.5, 3.0})
            EXPECT_NEAR(m({a, b}), std::max(std::sin(a) + std::log10(b), std::pow(a, b)), 1e-14);
}

// The shapes and fractal noises of functions.inc that terrains, water and the internal
// function demo use: each against its definition at points where it is known.
TEST(Function, InternalHelixSuperellipsoidAndFractalNoises) {
    auto f = [](FnInternal id, double x, double y, double z, std::vector<double> p) {
        EXPECT_EQ(int(p.size()), fn_internal_extra(int(id)));
        return fn_internal(int(id), x, y, z, p.data());
    };
    // Superellipsoid 1, 1 is the unit sphere: 1 - r.
    EXPECT_NEAR(f(FnInternal::Superellipsoid, 0, 0, 0, {1, 1}), 1, 1e-12);
    EXPECT_NEAR(f(FnInternal::Superellipsoid, 0.6, 0, 0.8, {1, 1}), 0, 1e-12);
    EXPECT_NEAR(f(FnInternal::Superellipsoid, 0, 2, 0, {1, 1}), -1, 1e-12);
    // Flatter exponents square it off: a box corner's point is inside.
    EXPECT_GT(f(FnInternal::Superellipsoid, 0.7, 0.7, 0.7, {0.1, 0.1}), 0);
    EXPECT_LT(f(FnInternal::Superellipsoid, 0.7, 0.7, 0.7, {1, 1}), 0);
    // One helix of period 1, minor 0.2, major 1, round section: its strand's middle at angle
    // pi (x = -1, y = 0) is minor inside; half a turn up along y the strand has moved away.
    const std::vector<double> helix = {1, 1, 0.2, 1, 1, 1, 0};
    EXPECT_NEAR(f(FnInternal::Helix1, -1, 0, 0, helix), -0.2, 1e-9);
    EXPECT_NEAR(f(FnInternal::Helix1, -1.1, 0, 0, helix), -0.1, 1e-9);
    EXPECT_GT(f(FnInternal::Helix1, -1, 0.5 * 3.14159265358979, 0, helix), 0.5);
    // A square section (0) turned 45 degrees is a diamond: 0.1 out along the axis is
    // 0.1 sqrt(1/2) from its middle in the square's measure (the larger turned coordinate).
    const std::vector<double> square = {1, 1, 0.2, 1, 1, 0, 45};
    EXPECT_NEAR(f(FnInternal::Helix1, -1.1, 0, 0, square), -0.2 + 0.1 * std::sqrt(0.5), 1e-9);

    // One octave of each fractal is its noise n, as its definition shapes it, under the
    // generator its last parameter names (f_noise3d: POV-Ray's default, 2; 0 and 1 the
    // original).
    const double x = 0.3, y = 1.7, z = -2.2;
    const double n = fn_internal(int(FnInternal::Noise3d), x, y, z, nullptr);
    EXPECT_NEAR(f(FnInternal::NoiseGenerator, x, y, z, {2}), n, 0);
    EXPECT_EQ(f(FnInternal::NoiseGenerator, x, y, z, {1}), pov_noise(DVec3(x, y, z), 1));
    EXPECT_EQ(f(FnInternal::NoiseGenerator, x, y, z, {0}), pov_noise(DVec3(x, y, z), 1));
    EXPECT_EQ(f(FnInternal::NoiseGenerator, x, y, z, {7}), pov_noise(DVec3(x, y, z), 3));
    EXPECT_EQ(f(FnInternal::NoiseGenerator, x, y, z, {std::nan("")}), pov_noise(DVec3(x, y, z), 1));
    EXPECT_NEAR(f(FnInternal::RidgedMf, x, y, z, {0.5, 2, 1, 1, 2, 2}),
                (1 - std::fabs(2 * n - 1)) * (1 - std::fabs(2 * n - 1)), 1e-6);
    EXPECT_NEAR(f(FnInternal::HeteroMf, x, y, z, {0.5, 2, 1, 0.3, 1, 2}), 2 * n - 1 + 0.3, 1e-6);
    EXPECT_NEAR(f(FnInternal::Ridge, x, y, z, {2, 1, 0.5, 0.2, 0.4, 2}),
                (std::fabs(n - 0.4) / 0.6 - 0.2) / 0.8, 1e-6);
    // More octaves add detail: a gain of 0 silences the ridged octaves after the first; the
    // heterogeneous one adds weight^k times the signal per octave.
    EXPECT_NEAR(f(FnInternal::RidgedMf, x, y, z, {0.5, 2, 6, 1, 0, 0}),
                f(FnInternal::RidgedMf, x, y, z, {0.5, 2, 1, 1, 2, 0}), 1e-12);
    double sum = 0;
    for (double octaves : {1.0, 2.0, 3.5, 8.0}) {
        const double v = f(FnInternal::RidgedMf, x, y, z, {0.5, 2.1, octaves, 1, 2, 0});
        EXPECT_GE(v, sum - 1e-12) << octaves; // every octave adds a square, weighted >= 0
        EXPECT_LE(v, 1 / (1 - std::pow(2.1, -0.5))) << octaves;
        sum = v;
    }
    // A count of octaves no scene could mean ends, and stays finite.
    EXPECT_TRUE(std::isfinite(f(FnInternal::RidgedMf, x, y, z, {0.5, 2, 1e12, 1, 2, 0})));
    EXPECT_TRUE(std::isfinite(f(FnInternal::HeteroMf, x, y, z, {0.5, 2, 1e12, 0.3, 1e9, 0})));
    EXPECT_TRUE(std::isfinite(f(FnInternal::Ridge, x, y, z, {2, 1e12, 0.5, 0.2, 0.4, 0})));
}

TEST(Function, InternalShapesAndPatterns) {
    const double r5[1] = {0.5};
    EXPECT_NEAR(fn_internal(int(FnInternal::Sphere), 0, 2, 0, r5), 1.5, 1e-12);
    const double torus[2] = {2, 0.5};
    EXPECT_NEAR(fn_internal(int(FnInternal::Torus), 2, 0, 0, torus), -0.5, 1e-12);
    EXPECT_NEAR(fn_internal(int(FnInternal::Torus), 0, 0.5, 2, torus), 0, 1e-12);
    const double box[4] = {0.1, 1, 2, 3};
    EXPECT_NEAR(fn_internal(int(FnInternal::RoundedBox), 1, 0, 0, box), 0, 1e-12);
    EXPECT_NEAR(fn_internal(int(FnInternal::RoundedBox), 0, 0, 3.5, box), 0.5, 1e-12);
    EXPECT_LT(fn_internal(int(FnInternal::RoundedBox), 0, 0, 0, box), 0);
    // The rounded corner: radius 0.1 around the inner box's corner.
    const double c = 0.1 / std::sqrt(3.0);
    EXPECT_NEAR(fn_internal(int(FnInternal::RoundedBox), 0.9 + c, 1.9 + c, 2.9 + c, box), 0, 1e-9);
    const double none[1] = {0};
    const double n = fn_internal(int(FnInternal::Noise3d), 0.3, 1.1, -2.4, none);
    EXPECT_GE(n, 0);
    EXPECT_LE(n, 1);

    Program p(3, {op(FnOp::Load, 0), op(FnOp::Load, 1), op(FnOp::Load, 2), op(FnOp::Pattern, 0),
                  op(FnOp::Drop, 3)});
    Pattern checker;
    checker.kind = PatternKind::Checker;
    p.patterns.push_back(checker);
    EXPECT_EQ(p.check(), "");
    EXPECT_EQ(p({0.5, 0.5, 0.5}), 0);
    EXPECT_EQ(p({1.5, 0.5, 0.5}), 1);
    Program q(3, {op(FnOp::Load, 0), op(FnOp::Load, 1), op(FnOp::Load, 2), op(FnOp::Const, 0, 2),
                  op(FnOp::Internal, uint16_t(FnInternal::Sphere), 0, 4), op(FnOp::Drop, 3)});
    EXPECT_EQ(q.check(), "");
    EXPECT_NEAR(q({3, 0, 4}), 3, 1e-12);
}

TEST(Function, PigmentsGiveAComponentOfTheirMapsColour) {
    // gradient x with black at 0 and (1, 0.5, 0.25) at 1; and a solid colour.
    Program p(3, {op(FnOp::Load, 0), op(FnOp::Load, 1), op(FnOp::Load, 2),
                  op(FnOp::Pigment, 0, 0, uint8_t(FnComponent::Green)), op(FnOp::Drop, 3)});
    Pattern gradient;
    gradient.kind = PatternKind::Gradient;
    gradient.vector = Vec3(1, 0, 0);
    p.patterns.push_back(gradient);
    PigmentEntry black, orange;
    orange.value = 1, orange.color[0] = 1, orange.color[1] = 0.5f, orange.color[2] = 0.25f;
    p.entries = {black, orange};
    FnPigment map;
    map.count = 2;
    p.pigments.push_back(map);
    EXPECT_EQ(p.check(), "");
    EXPECT_NEAR(p({0.5, 7, 7}), 0.25, 1e-6);
    EXPECT_NEAR(p({0.8, 0, 0}), 0.4, 1e-6);
    const FnView v{&p.pg, p.code.data(), p.patterns.data(), p.pigments.data(), p.entries.data()};
    EXPECT_NEAR(fn_pigment(v, map, int(FnComponent::Gray), 0.5, 0, 0),
                0.5 * (0.297 + 0.589 * 0.5 + 0.114 * 0.25), 1e-6);
    FnPigment solid;
    solid.color[3] = 0.75f;
    EXPECT_EQ(fn_pigment(v, solid, int(FnComponent::Filter), 3, 2, 1), 0.75);
    // A list pattern indexes its entries.
    Pattern checker;
    checker.kind = PatternKind::Checker;
    p.patterns[0] = checker;
    p.pigments[0].list = 1;
    EXPECT_NEAR(p({0.5, 0.5, 0.5}), 0, 1e-9);
    EXPECT_NEAR(p({1.5, 0.5, 0.5}), 0.5, 1e-9);
}

TEST(Function, TheCheckRefusesWhatCouldLeaveTheStack) {
    EXPECT_NE(Program(1, {op(FnOp::Add)}).check(), "");                        // underflow
    EXPECT_NE(Program(1, {op(FnOp::Load, 1), op(FnOp::Drop, 1)}).check(), ""); // above the top
    EXPECT_NE(Program(0, {op(FnOp::Const), op(FnOp::Const)}).check(), "");     // two results
    EXPECT_NE(Program(3, {op(FnOp::Load, 0), op(FnOp::Load, 1), op(FnOp::Load, 2),
                          op(FnOp::Pattern, 0), op(FnOp::Drop, 3)})
                  .check(),
              "");                                                    // no such pattern
    EXPECT_NE(Program(3, {op(FnOp::Internal, 5, 0, 3)}).check(), ""); // unknown internal
    EXPECT_NE(Program(0, {op(FnOp::Math, 200)}).check(), "");         // unknown math
    std::vector<FnInstr> deep(kFnStack + 1, op(FnOp::Const, 0, 1));
    for (int i = 0; i < kFnStack; ++i) deep.push_back(op(FnOp::Add));
    EXPECT_NE(Program(0, deep).check(), "");
    std::vector<FnInstr> ok(kFnStack, op(FnOp::Const, 0, 1));
    for (int i = 1; i < kFnStack; ++i) ok.push_back(op(FnOp::Add));
    const Program full(0, ok);
    EXPECT_EQ(full.check(), "");
    EXPECT_EQ(full({}), kFnStack);
    FnProgram outside;
    outside.first = 5, outside.count = 2;
    EXPECT_NE(check_fn_program(outside, ok.data(), 6, 0, 0), "");
    EXPECT_NE(Program(3, {op(FnOp::Load, 0), op(FnOp::Load, 1), op(FnOp::Load, 2),
                          op(FnOp::Pigment, 0), op(FnOp::Drop, 3)})
                  .check(),
              ""); // no such pigment
}

} // namespace
} // namespace sheaf

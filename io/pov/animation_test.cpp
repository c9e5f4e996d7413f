// POV-Ray's animation clock: the values POV-Ray 3.7 gives each frame (measured with povray
// +KFI +KFF +KI +KF +KC +K), and the scene seeing them, in expressions and in functions.
#include "io/pov/animation.h"
#include "tests/support/pov_test_util.h"

#include <gtest/gtest.h>

namespace sheaf::io::pov {
namespace {

TEST(PovAnimation, AStillHasOnlyItsClock) {
    Clock c = clock_for(Animation{});
    EXPECT_EQ(c.clock, 0);
    EXPECT_FALSE(c.clock_on);
    EXPECT_EQ(c.frame_number, 0);
    EXPECT_EQ(c.final_frame, 0);
    EXPECT_EQ(c.final_clock, 0); // povray reports 0, not the default 1, for a still
    Animation a;
    a.clock = 0.7;
    c = clock_for(a);
    EXPECT_EQ(c.clock, 0.7);
    EXPECT_TRUE(c.clock_on);
    EXPECT_EQ(c.clock_delta, 0);
}

TEST(PovAnimation, FramesSpreadTheClockFromFirstToLast) {
    Animation a;
    a.initial_frame = 0, a.final_frame = 10, a.initial_clock = 2, a.final_clock = 3;
    a.frame = 1;
    Clock c = clock_for(a);
    EXPECT_DOUBLE_EQ(c.clock, 2.1);
    EXPECT_DOUBLE_EQ(c.clock_delta, 0.1);
    EXPECT_EQ(c.frame_number, 1);
    EXPECT_EQ(c.initial_frame, 0);
    EXPECT_EQ(c.final_frame, 10);
    EXPECT_TRUE(c.clock_on);
    a.frame = 10;
    EXPECT_DOUBLE_EQ(clock_for(a).clock, 3);
    a.frame.reset(); // the first frame when none is named
    EXPECT_DOUBLE_EQ(clock_for(a).clock, 2);
    EXPECT_EQ(clock_for(a).frame_number, 0);
}

TEST(PovAnimation, ACyclicAnimationStopsOneStepShort) {
    Animation a;
    a.final_frame = 4, a.cyclic = true, a.frame = 4;
    const Clock c = clock_for(a);
    EXPECT_DOUBLE_EQ(c.clock, 0.75);
    EXPECT_DOUBLE_EQ(c.clock_delta, 0.25);
    EXPECT_EQ(c.final_frame, 5); // as povray reports it
}

TEST(PovAnimation, ImpossibleSequencesAreNamed) {
    Animation a;
    a.initial_frame = 3, a.final_frame = 1;
    EXPECT_EQ(animation_problem(a), "final_frame 1 is below initial_frame 3");
    a.final_frame = 5, a.frame = 6;
    EXPECT_EQ(animation_problem(a), "frame 6 is outside the sequence 3..5");
    a.frame = 5;
    EXPECT_EQ(animation_problem(a), "");
}

TEST(PovAnimation, TheSceneSeesTheClockInExpressionsAndFunctions) {
    Animation a;
    a.final_frame = 5, a.frame = 3;
    PovOptions o;
    o.clock = clock_for(a);
    o.declares = {{"Offset", 10}};
    test::TempDir d;
    Parser p(o);
    p.parse_scene(d.write("scene.pov", "#declare C = clock + Offset;\n"
                                       "#declare F = function { clock * 4 + frame_number };\n"
                                       "#declare G = F(0, 0, 0);\n"
                                       "#declare N = final_frame * 100 + clock_on;\n"));
    EXPECT_DOUBLE_EQ(p.lookup("C")->v[0], 10.5);
    EXPECT_DOUBLE_EQ(p.lookup("G")->v[0], 5);
    EXPECT_DOUBLE_EQ(p.lookup("N")->v[0], 501);
}

TEST(PovAnimation, ADeclaredValueYieldsToTheScenesOwn) {
    PovOptions o;
    o.declares = {{"Quality", 2}};
    test::TempDir d;
    Parser p(o);
    p.parse_scene(d.write("scene.pov", "#declare Before = Quality;\n#declare Quality = 7;\n"));
    EXPECT_DOUBLE_EQ(p.lookup("Before")->v[0], 2);
    EXPECT_DOUBLE_EQ(p.lookup("Quality")->v[0], 7);
}

} // namespace
} // namespace sheaf::io::pov

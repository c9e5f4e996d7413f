// The fractal patterns against POV-Ray 3.7: each row is a point of a povray render (200x200,
// orthographic, colour_map black to white, 16-bit linear PNG) of the pattern named, away from
// the chaotic edges, with the value povray gave it.
#include "core/texture/pattern_eval.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sheaf {
namespace {

struct Fractal {
    const char* pov; // what the render's pigment said
    PatternKind kind;
    FractalParams f;
    float points[2][3]; // x, y, povray's value
};

FractalParams params(int iterations, int exponent, int magnet, int interior, float ifactor,
                     int exterior, float efactor, float cr = 0, float ci = 0) {
    FractalParams f;
    f.iterations = uint16_t(iterations);
    f.exponent = uint8_t(exponent);
    f.magnet = uint8_t(magnet);
    f.interior_type = uint8_t(interior), f.interior_factor = ifactor;
    f.exterior_type = uint8_t(exterior), f.exterior_factor = efactor;
    f.c[0] = cr, f.c[1] = ci;
    return f;
}

constexpr PatternKind M = PatternKind::Mandel, J = PatternKind::Julia;

const Fractal kCases[] = {
    {"mandel 30",
     M,
     params(30, 2, 0, 0, 1, 1, 1),
     {{-1.25f, 1.03f, 0.0333f}, {-0.71f, -0.59f, 0.1333f}}},
    {"mandel 30 exterior 2, .5",
     M,
     params(30, 2, 0, 0, 1, 2, 0.5f),
     {{-0.65f, 0.27f, 1.0f}, {-1.01f, 0.11f, 1.0f}}},
    {"mandel 30 exterior 6, .2 interior 1, 1",
     M,
     params(30, 2, 0, 1, 1, 6, 0.2f),
     {{1.25f, -0.39f, 0.598f}, {-0.35f, 0.35f, 0.3221f}}},
    {"mandel 30 exponent 3 exterior 1, 2 interior 2, 1",
     M,
     params(30, 3, 0, 2, 1, 1, 2),
     {{0.31f, 0.25f, 0.2636f}, {0.37f, -0.99f, 0.0667f}}},
    {"julia <.3, .44> 30 interior 1, 1",
     J,
     params(30, 2, 0, 1, 1, 1, 1, 0.3f, 0.44f),
     {{-0.19f, 1.15f, 0.0667f}, {-0.93f, 0.87f, 0.1f}}},
    {"mandel 30 exterior 4, .1 interior 5, 3",
     M,
     params(30, 2, 0, 5, 3, 4, 0.1f),
     {{0.89f, 0.93f, 0.0668f}, {0.61f, -1.37f, 0.0801f}}},
    {"mandel 30 exterior 0, .3 interior 6, 1",
     M,
     params(30, 2, 0, 6, 1, 0, 0.3f),
     {{-0.27f, -0.35f, 0.1196f}, {-1.47f, 0.15f, 0.3f}}},
    {"mandel 30 exterior 3, .4 interior 4, 1",
     M,
     params(30, 2, 0, 4, 1, 3, 0.4f),
     {{-0.51f, 0.35f, 0.1527f}, {-0.29f, 0.23f, 0.0628f}}},
    {"julia <-.5, .5> 20 exponent 4 exterior 5, .3 interior 3, 1",
     J,
     params(20, 4, 0, 3, 1, 5, 0.3f, -0.5f, 0.5f),
     {{-0.79f, -0.83f, 0.0327f}, {-0.79f, -0.83f, 0.0327f}}},
    {"mandel 30 exterior 7, 4",
     M,
     params(30, 2, 0, 0, 1, 7, 4),
     {{-0.29f, -1.27f, 0.25f}, {-0.79f, -0.87f, 0.5f}}},
    {"mandel 30 exterior 8, 4",
     M,
     params(30, 2, 0, 0, 1, 8, 4),
     {{-0.95f, 0.49f, 0.75f}, {0.75f, 0.67f, 0.25f}}},
    {"magnet 1 mandel 30",
     M,
     params(30, 2, 1, 0, 1, 1, 1),
     {{-0.615f, 0.825f, 0.1667f}, {1.365f, -2.565f, 0.1333f}}},
    {"magnet 2 mandel 30",
     M,
     params(30, 2, 2, 0, 1, 1, 1),
     {{0.915f, -2.115f, 0.0667f}, {1.185f, 1.815f, 0.0667f}}},
    {"magnet 1 julia <.3, .44> 30",
     J,
     params(30, 2, 1, 0, 1, 1, 1, 0.3f, 0.44f),
     {{2.505f, 0.045f, 0.2f}, {2.805f, -1.365f, 0.1667f}}},
    {"magnet 2 julia <.3, .44> 30",
     J,
     params(30, 2, 2, 0, 1, 1, 1, 0.3f, 0.44f),
     {{1.965f, 2.685f, 0.2f}, {1.755f, -0.015f, 0.1f}}},
    {"magnet 1 mandel 30 interior 1, 1",
     M,
     params(30, 2, 1, 1, 1, 1, 1),
     {{0.225f, -0.525f, 0.2557f}, {1.245f, -2.205f, 0.2f}}},
    {"magnet 1 mandel 30 exterior 6, .1",
     M,
     params(30, 2, 1, 0, 1, 6, 0.1f),
     {{-1.185f, -0.525f, 0.1005f}, {-0.285f, -1.845f, 0.0995f}}},
    {"magnet 2 julia <.3, .44> 30 interior 1, 1",
     J,
     params(30, 2, 2, 1, 1, 1, 1, 0.3f, 0.44f),
     {{1.875f, -0.405f, 0.5625f}, {-0.075f, 1.305f, 0.4124f}}},
};

TEST(FractalPatterns, MatchPovRay) {
    for (const Fractal& c : kCases) {
        Pattern p;
        p.kind = c.kind;
        p.fractal = c.f;
        for (const auto& pt : c.points)
            EXPECT_NEAR(pattern_value_at(p, Vec3(pt[0], pt[1], 5.0f)), pt[2], 1e-3f)
                << c.pov << " at " << pt[0] << ", " << pt[1];
    }
}

TEST(FractalPatterns, StayFiniteAtPolesAndFarAway) {
    // The magnet formulas divide: z = 0 with c = 2 + 0i makes magnet 1's divisor 0 (a pole).
    Pattern p;
    p.kind = PatternKind::Mandel;
    p.fractal = params(50, 2, 1, 2, 1, 2, 1);
    for (float x : {2.0f, 1.0f, 0.0f, -1e30f, 1e30f}) {
        const float v = pattern_value_at(p, Vec3(x, 0, 0));
        EXPECT_TRUE(v >= 0 && v <= 1) << x << " gave " << v;
    }
    p.fractal = params(50, 33, 0, 6, 1, 6, 1);
    for (float x : {1e30f, -1e30f, 1.9f, 0.0f}) {
        const float v = pattern_value_at(p, Vec3(x, x, 0));
        EXPECT_TRUE(v >= 0 && v <= 1) << x << " gave " << v;
    }
}

} // namespace
} // namespace sheaf

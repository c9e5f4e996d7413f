// Patterns: list patterns alternate where POV-Ray's do, continuous patterns stay in [0, 1] and
// follow frequency, phase and the waves, noise is deterministic and smooth, turbulence moves
// points by about its amount.
#include "core/texture/pattern_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sheaf {
namespace {

Pattern make(PatternKind k) {
    Pattern p;
    p.kind = k;
    return p;
}

// Classic turbulence displaces by the amount times POV-Ray's DTurbulence (pov_noise.h), but
// for marble and wood, which bend their bands by the scalar turbulence themselves; agate and
// the spirals are displaced and bent. warp { turbulence } displaces like the first.
TEST(Patterns, TurbulenceDisplacesAsPovRayDoes) {
    const Vec3 world(0.3f, -1.7f, 2.2f);
    const DVec3 noise = pov_dturbulence(DVec3(world), 6, 0.5, 2.0);
    ASSERT_GT(std::fabs(noise.x) + std::fabs(noise.y) + std::fabs(noise.z), 0.05);
    Pattern pt;
    pt.has_turbulence = true;
    pt.turbulence = Vec3(0.3f, 0.2f, 0.1f);
    for (PatternKind k : {PatternKind::Gradient, PatternKind::Bozo, PatternKind::Checker,
                          PatternKind::Agate, PatternKind::Spiral1, PatternKind::Spiral2}) {
        pt.kind = k;
        const Vec3 d = pattern_point(pt, world, nullptr) - world;
        EXPECT_NEAR(d.x, 0.3 * noise.x, 1e-6);
        EXPECT_NEAR(d.y, 0.2 * noise.y, 1e-6);
        EXPECT_NEAR(d.z, 0.1 * noise.z, 1e-6);
    }
    for (PatternKind k : {PatternKind::Marble, PatternKind::Wood}) {
        pt.kind = k;
        EXPECT_EQ(pattern_point(pt, world, nullptr), world);
    }
    // Marble's band: x plus the amount times the scalar turbulence.
    pt.kind = PatternKind::Marble;
    EXPECT_NEAR(pattern_detail::raw_value(pt, world),
                0.3 + 0.3 * pov_turbulence(DVec3(world), 6, 0.5, 2.0, 2), 1e-6);
    Warp w;
    w.kind = WarpKind::Turbulence;
    w.a = Vec3(0.5f);
    w.f[0] = 0.5f, w.f[1] = 2.0f;
    const Vec3 d = warp_point(w, world) - world;
    EXPECT_NEAR(d.x, 0.5 * pov_dturbulence(DVec3(world), w.octaves, 0.5, 2.0).x, 1e-6);
}

TEST(Patterns, CheckerAlternatesInEveryAxis) {
    const Pattern p = make(PatternKind::Checker);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.5f, 0.5f, 0.5f)), 0);
    EXPECT_EQ(pattern_index_at(p, Vec3(1.5f, 0.5f, 0.5f)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.5f, 1.5f, 0.5f)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.5f, 0.5f, -0.5f)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(-0.5f, -0.5f, 0.5f)), 0);
    // A face on an integer plane takes one side consistently.
    EXPECT_EQ(pattern_index_at(p, Vec3(0.25f, 0.0f, 0.25f)),
              pattern_index_at(p, Vec3(0.25f, 1e-6f, 0.25f)));
}

TEST(Patterns, ListPatternsStayInTheirEntries) {
    std::mt19937 g(3);
    std::uniform_real_distribution<float> u(-20, 20);
    const std::pair<PatternKind, int> kinds[] = {{PatternKind::Checker, 2},
                                                 {PatternKind::Hexagon, 3},
                                                 {PatternKind::Brick, 2},
                                                 {PatternKind::Square, 4},
                                                 {PatternKind::Triangular, 6}};
    for (auto [k, n] : kinds) {
        std::vector<int> seen(size_t(n), 0);
        for (int i = 0; i < 4000; ++i) {
            const int idx = pattern_index_at(make(k), Vec3(u(g), u(g), u(g)));
            ASSERT_GE(idx, 0);
            ASSERT_LT(idx, n);
            seen[size_t(idx)]++;
        }
        for (int i = 0; i < n; ++i) EXPECT_GT(seen[size_t(i)], 0) << int(k) << " entry " << i;
    }
}

TEST(Patterns, HexagonNeighboursDiffer) {
    const Pattern p = make(PatternKind::Hexagon);
    // Centres of a hexagon and its six neighbours (unit side, flat sides along x).
    const Vec3 c(0, 0, 0);
    const float h = std::sqrt(3.0f);
    const Vec3 n[6] = {{1.5f, 0, h / 2},   {1.5f, 0, -h / 2}, {-1.5f, 0, h / 2},
                       {-1.5f, 0, -h / 2}, {0, 0, h},         {0, 0, -h}};
    for (const Vec3& q : n) EXPECT_NE(pattern_index_at(p, c), pattern_index_at(p, q));
}

// POV-Ray's layout: the hexagon around the origin is entry 0, the one above it (+z) 1 and the
// one below 2; the plane is mirrored about x = 0, so the neighbours at -x take the entries of
// those at +x.
TEST(Patterns, HexagonEntriesAreLaidOutAsPovRayLaysThem) {
    const Pattern p = make(PatternKind::Hexagon);
    const float h = std::sqrt(3.0f);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.1f, 0, 0.1f)), 0);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.1f, 0, h)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(0.1f, 0, -h)), 2);
    for (float side : {1.0f, -1.0f}) {
        EXPECT_EQ(pattern_index_at(p, Vec3(1.5f * side, 0, h / 2 + 0.1f)), 2) << side;
        EXPECT_EQ(pattern_index_at(p, Vec3(1.5f * side, 0, -h / 2 - 0.1f)), 1) << side;
    }
    // The slanted sides: (0.9, 0.1) lies in the origin's hexagon, (1.1, 0.1) beyond its side.
    EXPECT_EQ(pattern_index_at(p, Vec3(0.9f, 0, 0.1f)), 0);
    EXPECT_NE(pattern_index_at(p, Vec3(1.1f, 0, 0.1f)), 0);
    // The layout repeats every 3 along x and 3 sqrt(3) along z.
    for (float x : {0.2f, 0.9f, 1.7f, 2.6f})
        for (float z : {0.3f, 1.1f, 2.0f})
            EXPECT_EQ(pattern_index_at(p, Vec3(x, 0, z)),
                      pattern_index_at(p, Vec3(x + 3.0f, 0, z + 3.0f * h)))
                << x << " " << z;
}

TEST(Patterns, BrickHasMortarBetweenBricks) {
    // POV-Ray's layout: each cell starts with its mortar, 0.5 below the cell's edge (its
    // brick pattern offsets the point by the mortar): courses 0..3 of 8 x 3 x 4.5 bricks lie
    // over y in (-0.5, 2.5) mod 3, with the bed joint above in [2.5, 3].
    Pattern p = make(PatternKind::Brick);                    // 8 x 3 x 4.5 bricks, 0.5 mortar
    EXPECT_EQ(pattern_index_at(p, Vec3(4, 1.5f, 1)), 1);     // inside a brick
    EXPECT_EQ(pattern_index_at(p, Vec3(4, 2.75f, 1)), 0);    // the bed joint above it
    EXPECT_EQ(pattern_index_at(p, Vec3(7.75f, 1.5f, 1)), 0); // the end joint at x = 8
    EXPECT_EQ(pattern_index_at(p, Vec3(4, 1.5f, 2)), 0);     // the joint across z
    // The next course is offset by half a brick, along x and along z.
    EXPECT_EQ(pattern_index_at(p, Vec3(7.75f, 4.5f, 1)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(3.75f, 4.5f, 1)), 0);
    EXPECT_EQ(pattern_index_at(p, Vec3(4, 4.5f, 2)), 1);
    EXPECT_EQ(pattern_index_at(p, Vec3(4, 4.5f, -0.25f)), 0);
}

TEST(Patterns, GradientFrequencyPhaseAndWaves) {
    Pattern p = make(PatternKind::Gradient);
    p.vector = Vec3(1, 0, 0);
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.25f, 7, 7)), 0.25f, 1e-6);
    EXPECT_NEAR(pattern_value_at(p, Vec3(2.25f, 0, 0)), 0.25f, 1e-5); // repeats every unit
    EXPECT_NEAR(pattern_value_at(p, Vec3(-0.25f, 0, 0)), 0.75f, 1e-5);
    p.frequency = 2;
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.25f, 0, 0)), 0.5f, 1e-5);
    p.frequency = 1, p.phase = 0.5f;
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.25f, 0, 0)), 0.75f, 1e-5);
    p.phase = 0, p.wave = Wave::Triangle;
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.25f, 0, 0)), 0.5f, 1e-5);
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.75f, 0, 0)), 0.5f, 1e-5);
    p.wave = Wave::Poly, p.wave_exponent = 2;
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.5f, 0, 0)), 0.25f, 1e-5);
}

TEST(Patterns, SpiralsFollowPovRaysFormulas) {
    // spiral1: z + r + arms * angle / 360, the angle counted from -y towards +x;
    // spiral2: that triangle-waved, plus r triangle-waved (the default wave is applied after).
    Pattern p = make(PatternKind::Spiral1);
    p.param[0] = 2;
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.5f, 0, 0.125f)), 0.125f, 1e-5); // 1.125 wraps
    EXPECT_NEAR(pattern_value_at(p, Vec3(0, -0.25f, 0)), 0.25f, 1e-5);     // angle 0
    EXPECT_NEAR(pattern_value_at(p, Vec3(0, 0.25f, 0)), 0.25f, 1e-5);      // 0.25 + 1
    // 0.1 + 1.5, modulo POV-Ray's 1.00001
    EXPECT_NEAR(pattern_value_at(p, Vec3(-0.1f, 0, 0)), 0.59999, 1e-6);
    p.kind = PatternKind::Spiral2;
    // s = 0.2 + 0.5 = 0.7: 0.6 waved; r = 0.2: 0.4 waved; 1.0 stays 1.
    EXPECT_NEAR(pattern_value_at(p, Vec3(0.2f, 0, 0)), 1.0f, 1e-5);
    // s = 0.1 + 0 = 0.1: 0.2; r = 0.1: 0.2.
    EXPECT_NEAR(pattern_value_at(p, Vec3(0, -0.1f, 0)), 0.4f, 1e-5);
}

TEST(Patterns, ContinuousPatternsStayInTheUnitInterval) {
    std::mt19937 g(7);
    std::uniform_real_distribution<float> u(-2, 2); // the bounded patterns vary within 1
    for (int k = int(PatternKind::Gradient); k < int(PatternKind::Image); ++k) {
        if (PatternKind(k) == PatternKind::Function) continue; // runs a program: function_test
        if (PatternKind(k) == PatternKind::Slope)
            continue; // reads the surface: surface_texture_test
        Pattern p = make(PatternKind(k));
        p.param[0] = 3;
        float lo = 1, hi = 0;
        for (int i = 0; i < 2000; ++i) {
            const float v = pattern_value_at(p, Vec3(u(g), u(g), u(g)));
            ASSERT_TRUE(v >= 0 && v <= 1) << "pattern " << k << " gave " << v;
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        EXPECT_GT(hi - lo, 0.2f) << "pattern " << k << " hardly varies";
    }
}

TEST(Patterns, MapSpansBlendBetweenEntriesAndClampOutside) {
    PigmentEntry e[3];
    e[0].value = 0.2f, e[1].value = 0.6f, e[2].value = 0.6f; // a sharp step at 0.6
    auto same = [](MapSpan m, uint32_t i) { return m.lo == i && m.hi == i && m.t == 0.0f; };
    EXPECT_TRUE(same(map_span(e, 3, 0.1f), 0)); // below the first entry
    EXPECT_TRUE(same(map_span(e, 3, 0.2f), 0)); // on it
    EXPECT_TRUE(same(map_span(e, 3, 0.9f), 2)); // above the last
    EXPECT_TRUE(same(map_span(e, 3, 0.6f), 1)); // on the step: the first of the two
    EXPECT_TRUE(same(map_span(e, 3, std::nanf("")), 0));
    EXPECT_TRUE(same(map_span(e, 1, 0.5f), 0)); // one entry
    const MapSpan m = map_span(e, 3, 0.3f);
    EXPECT_EQ(m.lo, 0u);
    EXPECT_EQ(m.hi, 1u);
    EXPECT_FLOAT_EQ(m.t, 0.25f);
}

TEST(Noise, TurbulenceMovesPointsByAboutItsAmount) {
    Pattern p = make(PatternKind::Gradient);
    p.turbulence = Vec3(0.5f);
    p.has_turbulence = true;
    std::mt19937 g(5);
    std::uniform_real_distribution<float> u(-10, 10);
    double moved = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 q(u(g), u(g), u(g));
        moved += length(pattern_point(p, q, nullptr) - q);
    }
    moved /= 1000;
    EXPECT_GT(moved, 0.05);
    EXPECT_LT(moved, 1.5);
    p.has_turbulence = false;
    EXPECT_EQ(length(pattern_point(p, Vec3(1, 2, 3), nullptr) - Vec3(1, 2, 3)), 0.0f);
}

void expect_near(Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

Warp warp(WarpKind k) {
    Warp w;
    w.kind = k;
    return w;
}

TEST(Warps, RepeatCopiesASlabWithItsOffsetAndFlips) {
    Warp w = warp(WarpKind::Repeat);
    w.axis = 0, w.f[0] = 2, w.b = Vec3(1.0f), w.a = Vec3(0, 0, 0.25f);
    expect_near(warp_point(w, Vec3(5, 1, 0)), Vec3(1, 1, 0.5f));    // slab 2: two offsets
    expect_near(warp_point(w, Vec3(-1, 1, 0)), Vec3(1, 1, -0.25f)); // slab -1
    w.a = Vec3(0.0f), w.b = Vec3(1, -1, 1);                         // odd slabs mirrored in y
    expect_near(warp_point(w, Vec3(3, 1, 0)), Vec3(1, -1, 0));
    expect_near(warp_point(w, Vec3(5, 1, 0)), Vec3(1, 1, 0));
    w.b = Vec3(-1, 1, 1); // mirrored along the axis itself: 2.5 is 0.5's mirror image
    expect_near(warp_point(w, Vec3(2.5f, 0, 0)), Vec3(1.5f, 0, 0));
}

TEST(Warps, MappingWarpsFollowPovRaysFormulas) {
    Warp planar = warp(WarpKind::Planar);
    planar.f[0] = 0.5f;
    expect_near(warp_point(planar, Vec3(1, 2, 3)), Vec3(1, 2, 0.5f));
    Warp cyl = warp(WarpKind::Cylindrical); // a quarter turn from +x towards +z
    expect_near(warp_point(cyl, Vec3(0, 3, 2)), Vec3(0.25f, 3, 2));
    cyl.f[0] = 1; // dist_exp 1: the angle times the distance
    expect_near(warp_point(cyl, Vec3(0, 3, 2)), Vec3(0.5f, 3, 2));
    cyl.f[0] = 0, cyl.b = Vec3(0, 1, 0); // orientation y
    expect_near(warp_point(cyl, Vec3(0, 3, 2)), Vec3(0.25f, -2, 3));
    expect_near(warp_point(cyl, Vec3(0, 3, 0)), Vec3(0, 3, 0)); // on the axis: unmoved
    Warp sph = warp(WarpKind::Spherical);
    expect_near(warp_point(sph, Vec3(0, 0, -2)), Vec3(0.75f, 0.5f, 2));
    expect_near(warp_point(sph, Vec3(0, 2, 0)), Vec3(0, 1, 2)); // the pole
    Warp tor = warp(WarpKind::Toroidal);
    tor.f[1] = 2; // major radius
    expect_near(warp_point(tor, Vec3(3, 0, 0)), Vec3(0, 0.5f, 1));
    expect_near(warp_point(tor, Vec3(2, -1, 0)), Vec3(0, 0.25f, 1));
    Warp hole = warp(WarpKind::BlackHole); // radius 2 at the origin, falloff 1, strength 1
    hole.f[0] = 2, hole.f[1] = 1, hole.f[2] = 1, hole.b = Vec3(0.0f);
    expect_near(warp_point(hole, Vec3(1, 0, 0)), Vec3(1.5f, 0, 0)); // half its distance out
    expect_near(warp_point(hole, Vec3(3, 0, 0)), Vec3(3, 0, 0));    // outside: unmoved
    hole.axis = 1;                                                  // inverse: pulled in
    expect_near(warp_point(hole, Vec3(1, 0, 0)), Vec3(0.5f, 0, 0));
    hole.b = Vec3(10, 0, 0); // repeated along x: the copy around x = 10
    expect_near(warp_point(hole, Vec3(11, 0, 0)), Vec3(10.5f, 0, 0));
    const Warp cubic = warp(WarpKind::Cubic);
    expect_near(warp_point(cubic, Vec3(2, 0, 0)), Vec3(0.625f, 0.5f, 2));
    expect_near(warp_point(cubic, Vec3(0, -2, 0)), Vec3(0.375f, 1.0f / 6, 2));
}

TEST(Warps, TheChainRunsFromTheLastDeclaredToTheFirst) {
    // World -> the warp's space halves, the repeat folds x into [0, 1), then to_inner shifts.
    Pattern p = make(PatternKind::Gradient);
    p.to_pattern = Affine::scale(Vec3(0.5f));
    Warp w = warp(WarpKind::Repeat);
    w.axis = 0, w.f[0] = 1, w.b = Vec3(1.0f);
    w.to_inner = Affine::translate(Vec3(0, 10, 0));
    const Warp warps[] = {Warp(), w};
    p.warp_first = 1, p.warp_count = 1;
    expect_near(pattern_point(p, Vec3(5, 2, 4), warps), Vec3(0.5f, 11, 2));
    // Gradients come back through every transform's transpose.
    expect_near(pattern_gradient_to_world(p, warps, Vec3(1, 1, 1)), Vec3(0.5f, 0.5f, 0.5f));
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// POV-Ray's cells and crackle (default; metric 1, offset 0.1, form <0.5, 0.3, 0.2>; solid)
// at four points, as povray 3.7.0.10 evaluates `function { pattern { ... } }` there.
TEST(Patterns, CellsAndCrackleArePovRays) {
    const double want[4][4] = {
        {0.39901996450498700, 0.08676050859337586, 0.77447832572832698, 0.77237578689026376},
        {0.52463734569028020, 0.34518710392702778, 1.00000000000000000, 0.49430087288027696},
        {0.67901675496250391, 0.48237545345591054, 1.00000000000000000, 0.80495245791649772},
        {0.39232046902179718, 0.54412552966243477, 0.90342817318625734, 0.48555898345455134}};
    Pattern cells = make(PatternKind::Cells), crackle = make(PatternKind::Crackle);
    set_crackle_defaults(crackle);
    Pattern metric = crackle, solid = crackle;
    metric.param[0] = 1, metric.param[1] = 0.1f, metric.vector = Vec3(0.5f, 0.3f, 0.2f);
    solid.param[2] = 1;
    for (int i = 0; i < 4; ++i) {
        const Vec3 p(0.37f + i * 1.3f, -2.11f + i * 0.7f, 5.3f - i * 2.9f);
        EXPECT_NEAR(pattern_value_at(cells, p), want[i][0], 1e-6) << i;
        EXPECT_NEAR(pattern_value_at(crackle, p), want[i][1], 1e-5) << i;
        EXPECT_NEAR(pattern_value_at(metric, p), want[i][2], 1e-5) << i;
        EXPECT_NEAR(pattern_value_at(solid, p), want[i][3], 1e-5) << i;
    }
}

// Values povray 3.7.0.10 wrote (#debug of function { pattern { radial } }): a quarter turn on
// from atan2(x, z), 0.25 on the axis, wrapped by the frequency's modulo.
TEST(Patterns, RadialIsPovRays) {
    const Vec3 at[4] = {{0.5f, 0.3f, 0.25f},
                        {-0.75f, 2.0f, 0.125f},
                        {0.0625f, 0.0f, -0.5f},
                        {0.0005f, 1.0f, 0.0002f}};
    const double want[4] = {0.926208191175, 0.526284228356, 0.230198287920, 0.25};
    const Pattern radial = make(PatternKind::Radial);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(pattern_value_at(radial, at[i]), want[i], 1e-6) << i;
}

// Values povray 3.7.0.10 wrote (#debug of function { pattern { quilted … } }): the default
// control points (1, 1) and control0 0.3, control1 -0.6.
TEST(Patterns, QuiltedIsPovRays) {
    const Vec3 at[4] = {{0.125f, 0.25f, 0.375f},
                        {1.75f, -2.375f, 0.0625f},
                        {-0.5f, 3.96875f, 12.25f},
                        {0.5f, 0.5f, 0.5f}};
    const double want[4][2] = {{0.245137862071, 0.003460333206},
                               {0.277964778706, 0.004590737304},
                               {0.248153240525, 0.004664533133},
                               {0.0, 0.0}};
    Pattern plain = make(PatternKind::Quilted), shaped = plain;
    plain.param[0] = plain.param[1] = 1;
    plain.frequency = shaped.frequency = 0; // POV-Ray's quilted has none
    shaped.param[0] = 0.3f, shaped.param[1] = -0.6f;
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(pattern_value_at(plain, at[i]), want[i][0], 1e-7) << i;
        EXPECT_NEAR(pattern_value_at(shaped, at[i]), want[i][1], 1e-8) << i;
    }
}

} // namespace
} // namespace sheaf

// Procedural textures at surface points: colour maps blend between entries, list patterns pick
// entries, pigment maps nest, layers compose by filter and transmit, texture maps pick
// materials, normals tilt by the pattern's slope, and the sky follows the ray's direction.
#include "core/shading/surface_texture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sheaf {
namespace {

PigmentEntry color_entry(float value, Vec3 c, float filter = 0, float transmit = 0) {
    PigmentEntry e;
    e.value = value;
    e.color[0] = c.x, e.color[1] = c.y, e.color[2] = c.z, e.color[3] = filter,
    e.color[4] = transmit;
    return e;
}

// A pigment over the given entries, appended to p.
int32_t add_pigment(PreparedScene& p, Pattern pattern, std::vector<PigmentEntry> entries,
                    bool layers = false, bool average = false) {
    Pigment pg;
    pg.solid = false;
    pg.layers = layers;
    pg.average = average;
    pg.pattern = pattern;
    pg.first = uint32_t(p.pigment_entries.size());
    pg.count = uint32_t(entries.size());
    p.pigment_entries.insert(p.pigment_entries.end(), entries.begin(), entries.end());
    p.pigments.push_back(pg);
    return int32_t(p.pigments.size() - 1);
}

Pattern gradient_x() {
    Pattern g;
    g.kind = PatternKind::Gradient;
    g.vector = Vec3(1, 0, 0);
    return g;
}

SurfaceColor as_color(Vec3 c) {
    return {c, 0, 0};
}

void expect_vec(Vec3 got, Vec3 want, float tol = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

void expect_color(const SurfaceColor& c, Vec3 want, float tol = 1e-5f) {
    EXPECT_NEAR(c.rgb.x, want.x, tol);
    EXPECT_NEAR(c.rgb.y, want.y, tol);
    EXPECT_NEAR(c.rgb.z, want.z, tol);
}

// facets: over the normal, nearby normals in one cell turn to the same facet, a few degrees
// from where they were; with coords, the point's cell tilts the normal by noise.
TEST(SurfaceTexture, FacetsTurnNormalsToTheirCellsPoint) {
    Pattern pt;
    pt.kind = PatternKind::Facets;
    pt.param[0] = 0.1f, pt.param[2] = 2; // size 0.1, metric 2 (POV-Ray's defaults)
    const auto facet = [&](Vec3 q, Vec3 m) {
        return normalize(texture_detail::facets_normal(pt, q, DVec3(m)).to_float());
    };
    const Vec3 n = normalize(Vec3(0.3f, 0.8f, -0.5f));
    const Vec3 a = facet(Vec3(0.0f), n);
    EXPECT_NEAR(length(a), 1.0f, 1e-5f);
    EXPECT_GT(dot(a, n), std::cos(0.25f)); // within a cell of 0.1 at distance 1 of the origin
    int same = 0, differ = 0;
    for (int i = 1; i <= 40; ++i) {
        const Vec3 m = normalize(n + Vec3(0.002f * float(i), 0, 0));
        const Vec3 b = facet(Vec3(0.0f), m);
        (length(b - a) < 1e-6f ? same : differ)++;
        EXPECT_GT(dot(b, m), std::cos(0.25f));
    }
    EXPECT_GT(same, 0);   // flat facets
    EXPECT_GT(differ, 0); // and edges between them
    pt.param[1] = 0.4f;   // coords 0.4: cells over the point, the normal tilted by noise
    int tilted = 0;
    for (int i = 0; i < 20; ++i) {
        const Vec3 c = facet(Vec3(0.37f * float(i), 0.11f, 0.5f), n);
        EXPECT_NEAR(length(c), 1.0f, 1e-5f);
        EXPECT_GT(dot(c, n), 0.5f);
        if (dot(c, n) < 0.9999f) ++tilted;
    }
    EXPECT_GT(tilted, 10);
}

TEST(SurfaceTexture, ColourMapsBlendBetweenEntries) {
    PreparedScene p;
    const int32_t pg = add_pigment(p, gradient_x(),
                                   {color_entry(0.2f, Vec3(1, 0, 0)), color_entry(0.6f, Vec3(0, 0, 1))});
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(0.1f, 0, 0), 0, 0), Vec3(1, 0, 0));
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(0.4f, 0, 0), 0, 0), Vec3(0.5f, 0, 0.5f));
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(0.9f, 0, 0), 0, 0), Vec3(0, 0, 1));
}

TEST(SurfaceTexture, PatternsLiveInTheirOwnSpace) {
    PreparedScene p;
    Pattern g = gradient_x();
    g.to_pattern = Affine::scale(Vec3(0.5f)); // the pattern scaled by 2 in the world
    const int32_t pg = add_pigment(p, g, {color_entry(0, Vec3(0)), color_entry(1, Vec3(1))});
    EXPECT_NEAR(evaluate_pigment(p, uint32_t(pg), Vec3(0.5f, 0, 0), 0, 0).rgb.x, 0.25f, 1e-5);
}

TEST(SurfaceTexture, UvPatternsFollowTheTextureCoordinates) {
    // A uv pattern (POV-Ray's uv_mapping) reads (u, v, 0), whatever the world point.
    PreparedScene p;
    Pattern g = gradient_x();
    g.uv = true;
    g.to_pattern = Affine::scale(Vec3(2.0f)); // the pattern scaled by 1/2 in uv space
    const int32_t pg = add_pigment(p, g, {color_entry(0, Vec3(0)), color_entry(1, Vec3(1))});
    EXPECT_NEAR(evaluate_pigment(p, uint32_t(pg), Vec3(0.1f, 5, 5), 0.125f, 0.9f).rgb.x, 0.25f,
                1e-5);
    EXPECT_NEAR(evaluate_pigment(p, uint32_t(pg), Vec3(0.7f, 0, 0), 0.125f, 0.0f).rgb.x, 0.25f,
                1e-5);
    // Texture maps too.
    p.materials.resize(3);
    p.materials[0].select = 0;
    MaterialSwitch sw;
    sw.pattern = gradient_x();
    sw.pattern.uv = true;
    sw.first = 0, sw.count = 2;
    p.material_switches.push_back(sw);
    p.material_entries = {{0.0f, 1}, {1.0f, 2}};
    EXPECT_EQ(resolve_material(p, 0, Vec3(0.9f, 0, 0), Vec3(0, 1, 0), 0.1f, 0.5f), 1u);
    EXPECT_EQ(resolve_material(p, 0, Vec3(0.1f, 0, 0), Vec3(0, 1, 0), 0.9f, 0.5f), 2u);
}

TEST(SurfaceTexture, ListsAndNestedPigments) {
    PreparedScene p;
    const int32_t inner = add_pigment(p, gradient_x(), {color_entry(0, Vec3(0)), color_entry(1, Vec3(1))});
    Pattern checker;
    checker.kind = PatternKind::Checker;
    PigmentEntry nested = color_entry(0, Vec3(0));
    nested.pigment = inner;
    const int32_t pg = add_pigment(p, checker, {color_entry(0, Vec3(0, 1, 0)), nested});
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(0.5f, 0.5f, 0.5f), 0, 0), Vec3(0, 1, 0));
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(1.25f, 0.5f, 0.5f), 0, 0), Vec3(0.25f));
}

TEST(SurfaceTexture, LayersComposeByFilterAndTransmit) {
    PreparedScene p;
    const int32_t pg = add_pigment(p, Pattern{},
                                   {color_entry(0, Vec3(0.2f, 0.4f, 0.6f)),
                                    color_entry(0, Vec3(1, 0, 0), 0.0f, 0.75f)},
                                   true);
    // 25% of the red top, 75% of what is under it.
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(0), 0, 0),
                 Vec3(0.25f + 0.15f, 0.3f, 0.45f));
    const int32_t filtered = add_pigment(p, Pattern{},
                                         {color_entry(0, Vec3(0.5f)),
                                          color_entry(0, Vec3(1, 0.5f, 0), 1.0f, 0.0f)},
                                         true);
    // A filtering top layer tints what is under it by its colour.
    expect_color(evaluate_pigment(p, uint32_t(filtered), Vec3(0), 0, 0), Vec3(0.5f, 0.25f, 0));
}

TEST(SurfaceTexture, AverageIsTheMeanOfTheEntries) {
    PreparedScene p;
    const int32_t pg = add_pigment(p, Pattern{}, {color_entry(0, Vec3(1, 0, 0)), color_entry(0, Vec3(0, 0, 1))},
                                   false, true);
    expect_color(evaluate_pigment(p, uint32_t(pg), Vec3(3), 0, 0), Vec3(0.5f, 0, 0.5f));
}

TEST(SurfaceTexture, TextureMapsPickTheNearerMaterial) {
    PreparedScene p;
    p.materials.resize(4);
    p.materials[0].select = 0;
    MaterialSwitch sw;
    sw.pattern = gradient_x();
    sw.first = 0, sw.count = 3;
    p.material_switches.push_back(sw);
    p.material_entries = {{0.0f, 1}, {0.5f, 2}, {1.0f, 3}};
    EXPECT_EQ(resolve_material(p, 0, Vec3(0.1f, 0, 0)), 1u);
    EXPECT_EQ(resolve_material(p, 0, Vec3(0.3f, 0, 0)), 2u);
    EXPECT_EQ(resolve_material(p, 0, Vec3(0.9f, 0, 0)), 3u);
    EXPECT_EQ(resolve_material(p, 2, Vec3(0.9f, 0, 0)), 2u); // a plain material stays
}

// POV-Ray's slope normal samples the pattern at four points around the point (a tetrahedron
// 0.02 across) and pushes the unit normal against the rise by 5 * 0.02 * 4/3 = 2/15 of the
// bump size times the slope: a bump size of 3.75 pushes by half the slope.
TEST(SurfaceTexture, NormalsTiltAlongTheSlope) {
    PreparedScene p;
    NormalPattern np;
    np.pattern = gradient_x(); // value rises along +x with slope 1
    np.amount = 3.75f;
    p.normal_patterns.push_back(np);
    const Vec3 n = perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(0, 1, 0));
    EXPECT_NEAR(length(n), 1.0f, 1e-5);
    EXPECT_NEAR(n.x, normalize(Vec3(-0.5f, 1, 0)).x, 1e-4); // tilted against the rising value
    EXPECT_NEAR(n.z, 0.0f, 1e-5);
    // POV-Ray's accuracy: sampled further apart, the same slope tilts as far.
    p.normal_patterns[0].delta = 0.1f;
    EXPECT_NEAR(perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(0, 1, 0)).x, n.x, 1e-4);
    p.normal_patterns[0].delta = 0.02f;
    // A slope along the normal itself tilts nothing.
    const Vec3 m = perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(1, 0, 0));
    EXPECT_NEAR(m.x, 1.0f, 1e-5);
}

TEST(SurfaceTexture, SlopeMapsFollowHermiteCurves) {
    // POV-Ray's triangle wave by slope map: up with slope 1 to the top at 0.5, then down.
    const SlopeEntry tri[] = {{0, 0, 1}, {0.5f, 1, 1}, {0.5f, 1, -1}, {1, 0, -1}};
    EXPECT_FLOAT_EQ(slope_map_height(tri, 4, -1.0f), 0.0f); // before the first entry
    EXPECT_FLOAT_EQ(slope_map_height(tri, 4, 2.0f), 0.0f);  // after the last
    EXPECT_FLOAT_EQ(slope_map_height(tri, 4, std::nanf("")), 0.0f);
    // Between equal-slope end points the cubic is the straight line through them.
    EXPECT_NEAR(slope_map_height(tri, 4, 0.25f), 0.5f, 1e-6);
    EXPECT_NEAR(slope_map_height(tri, 4, 0.75f), 0.5f, 1e-6);
    // Hermite: h(t) = (2t^3 - 3t^2 + 1) h0 + (t^3 - 2t^2 + t) s0 + (-2t^3 + 3t^2) h1 +
    // (t^3 - t^2) s1, with the slopes per unit of the interval's parameter t.
    const SlopeEntry sc[] = {{0, 0, 3}, {1, 1, 0}};
    const float t = 0.3f;
    const float want = (t * t * t - 2 * t * t + t) * 3 + (-2 * t * t * t + 3 * t * t);
    EXPECT_NEAR(slope_map_height(sc, 2, t), want, 1e-6);
}

TEST(SurfaceTexture, SlopeMapsShapeTheTilt) {
    PreparedScene p;
    NormalPattern np;
    np.pattern = gradient_x();
    np.amount = 3.75f;
    p.normal_patterns.push_back(np);
    const Vec3 plain = perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(0, 1, 0));
    // A map falling from height 1 to 0 (slope -1): the same slope, turned the other way.
    p.slope_entries = {{0, 1, -1}, {1, 0, -1}};
    p.normal_patterns[0].slope_count = 2;
    const Vec3 down = perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(0, 1, 0));
    EXPECT_NEAR(down.x, -plain.x, 1e-4);
    EXPECT_NEAR(down.y, plain.y, 1e-4);
    // A flat stretch of the map tilts nothing there.
    p.slope_entries = {{0, 0.5f, 0}, {1, 0.5f, 0}};
    const Vec3 flat = perturb_normal(p, 0, Vec3(0.3f, 0, 0), Vec3(0, 1, 0));
    EXPECT_NEAR(flat.y, 1.0f, 1e-6);
}

TEST(SurfaceTexture, NormalMapsBlendPickAndAverageTheirEntries) {
    PreparedScene p;
    NormalPattern tilt; // entry 0: tilts along x
    tilt.pattern = gradient_x();
    tilt.pattern.to_pattern = Affine::scale(Vec3(0.5f)); // stays in 0..1 over the points used
    tilt.amount = 3.75f;
    p.normal_patterns.push_back(tilt);
    const Vec3 up(0, 1, 0), at(0.6f, 0, 0.3f);
    const Vec3 tilted = perturb_normal(p, 0, at, up);
    ASSERT_LT(tilted.x, -0.1f);

    // A continuous map along z: the surface's own normal at 0, the tilt at 1, blended between.
    NormalPattern map;
    map.pattern = gradient_x();
    map.pattern.vector = Vec3(0, 0, 1);
    map.map_first = 0, map.map_count = 2;
    p.normal_map_entries = {{0, -1}, {1, 0}};
    p.normal_patterns.push_back(map);
    expect_vec(perturb_normal(p, 1, Vec3(0.6f, 0, 0.3f), up), normalize(up * 0.7f + tilted * 0.3f));
    expect_vec(perturb_normal(p, 1, Vec3(0.6f, 0, 0.999999f), up), tilted);

    // A list pattern (checker) indexes its entries: the own normal on one square, the tilt on
    // the other.
    NormalPattern list;
    list.pattern.kind = PatternKind::Checker;
    list.map_first = 0, list.map_count = 2;
    p.normal_patterns.push_back(list);
    expect_vec(perturb_normal(p, 2, Vec3(0.5f, 0.5f, 0.5f), up), up);
    expect_vec(perturb_normal(p, 2, Vec3(0.6f, 0.5f, 1.5f), up), tilted);

    // An average weighs the entries' normals by their values: 3 parts own normal, 1 tilt.
    NormalPattern avg;
    avg.average = true;
    avg.map_first = 2, avg.map_count = 2;
    p.normal_map_entries.push_back({3, -1});
    p.normal_map_entries.push_back({1, 0});
    p.normal_patterns.push_back(avg);
    expect_vec(perturb_normal(p, 3, at, up), normalize(up * 0.75f + tilted * 0.25f));
}

// The slope pattern's value (POV-Ray's): asin(n . d) from [-pi/2, pi/2] to [0, 1], ranges,
// the altitude's share by the directions' lengths, point_at, and 0 off surfaces.
TEST(SurfaceTexture, SlopePatternsMeasureHowSteeplyTheSurfaceFaces) {
    PreparedScene p;
    Pattern up;
    ASSERT_TRUE(set_slope(up, Vec3(0, 2, 0), 0, 0, Vec3(0.0f), 0, 0, false));
    const std::vector<PigmentEntry> grey = {color_entry(0, Vec3(0)), color_entry(1, Vec3(1))};
    const uint32_t pg = uint32_t(add_pigment(p, up, grey));
    auto value = [&](uint32_t pigment, Vec3 at, Vec3 n) {
        return evaluate_pigment(p, pigment, at, 0, 0, n).rgb.x;
    };
    const Vec3 o(0.0f), diag = normalize(Vec3(1, 1, 0));
    EXPECT_NEAR(value(pg, o, Vec3(0, 1, 0)), 1.0f, 1e-6);  // flat ground stays 1, not 0
    EXPECT_NEAR(value(pg, o, Vec3(1, 0, 0)), 0.5f, 1e-6);  // a wall
    EXPECT_NEAR(value(pg, o, Vec3(0, -1, 0)), 0.0f, 1e-6); // a ceiling
    EXPECT_NEAR(value(pg, o, diag), 0.75f, 1e-6);          // 45 degrees
    EXPECT_NEAR(value(pg, o, Vec3(0.0f)), 0.0f, 1e-6);     // no surface
    // The pattern's transform moves the altitude, not the slope's direction.
    Pattern turned = up;
    turned.to_pattern = Affine::rotate(Vec3(0, 0, 1), 1.0f);
    EXPECT_NEAR(value(uint32_t(add_pigment(p, turned, grey)), o, diag), 0.75f, 1e-6);
    // A range remaps [0.5, 1] to [0, 1].
    Pattern ranged;
    ASSERT_TRUE(set_slope(ranged, Vec3(0, 1, 0), 0.5f, 1.0f, Vec3(0.0f), 0, 0, false));
    EXPECT_NEAR(value(uint32_t(add_pigment(p, ranged, grey)), o, diag), 0.5f, 1e-6);
    // Slope 3 : altitude 1, the altitude remapped from [0, 10]: 0.75 * 1 + 0.25 * 0.5 at y 5.
    Pattern mixed;
    ASSERT_TRUE(set_slope(mixed, Vec3(0, 3, 0), 0, 0, Vec3(0, 1, 0), 0, 10, false));
    const uint32_t mg = uint32_t(add_pigment(p, mixed, grey));
    EXPECT_NEAR(value(mg, Vec3(0, 5, 0), Vec3(0, 1, 0)), 0.875f, 1e-6);
    EXPECT_NEAR(value(mg, Vec3(0, 5, 0), Vec3(1, 0, 0)), 0.5f, 1e-6);
    // Towards a point: the direction from the surface point to it.
    Pattern towards;
    ASSERT_TRUE(set_slope(towards, Vec3(0, 10, 0), 0, 0, Vec3(0.0f), 0, 0, true));
    const uint32_t tg = uint32_t(add_pigment(p, towards, grey));
    EXPECT_NEAR(value(tg, o, Vec3(0, 1, 0)), 1.0f, 1e-6);
    EXPECT_NEAR(value(tg, Vec3(10, 0, 0), Vec3(0, 1, 0)), 0.75f, 1e-6);
    // Nothing to measure, or a point with an altitude: refused.
    Pattern bad;
    EXPECT_FALSE(set_slope(bad, Vec3(0.0f), 0, 0, Vec3(0.0f), 0, 0, false));
    EXPECT_FALSE(set_slope(bad, Vec3(0, 1, 0), 0, 0, Vec3(0, 1, 0), 0, 0, true));
    // Texture maps see the normal too.
    p.materials.resize(3);
    p.materials[0].select = 0;
    MaterialSwitch sw;
    sw.pattern = up;
    sw.first = 0, sw.count = 2;
    p.material_switches.push_back(sw);
    p.material_entries = {{0.0f, 1}, {1.0f, 2}};
    EXPECT_EQ(resolve_material(p, 0, o, Vec3(0, 1, 0)), 2u);
    EXPECT_EQ(resolve_material(p, 0, o, Vec3(0, -1, 0)), 1u);
}

TEST(SurfaceTexture, SkyFollowsTheDirection) {
    PreparedScene p;
    p.background = Vec3(0.1f);
    EXPECT_EQ(sky_color(p, Vec3(0, 1, 0)).x, 0.1f);
    Pattern g;
    g.kind = PatternKind::Gradient; // along y
    p.sky = add_pigment(p, g, {color_entry(0, Vec3(1, 1, 1)), color_entry(1, Vec3(0, 0, 1))});
    expect_color(as_color(sky_color(p, Vec3(0, 1, 0))), Vec3(0, 0, 1));
    expect_color(as_color(sky_color(p, Vec3(1, 0, 0))), Vec3(1, 1, 1));
}

} // namespace
} // namespace sheaf

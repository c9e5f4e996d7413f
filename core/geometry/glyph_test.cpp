#include "core/geometry/shape.h"
#include "core/geometry/span_check.h"
#include "core/geometry/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace sheaf {
namespace {

/// Outlines built by hand, with the prepared tables shape_spans reads.
struct Glyphs {
    std::vector<GlyphSegment> segments;
    std::vector<GlyphRef> refs;

    void line(float x0, float y0, float x1, float y1) {
        segments.push_back({x0, y0, 0.5f * (x0 + x1), 0.5f * (y0 + y1), x1, y1});
    }
    void curve(float x0, float y0, float cx, float cy, float x1, float y1) {
        segments.push_back({x0, y0, cx, cy, x1, y1});
    }
    /// A closed polygon, counter-clockwise when `ccw`.
    void polygon(std::vector<std::pair<float, float>> p, bool ccw = true) {
        if (!ccw) std::reverse(p.begin(), p.end());
        for (size_t i = 0; i < p.size(); ++i) {
            const auto& a = p[i];
            const auto& b = p[(i + 1) % p.size()];
            line(a.first, a.second, b.first, b.second);
        }
    }
    /// A circle of quadratic arcs, each spanning 2 pi / n (the control point where the
    /// tangents at its ends meet).
    void circle(float cx, float cy, float r, int n, bool ccw = true) {
        const double step = (ccw ? 2 : -2) * M_PI / n;
        for (int i = 0; i < n; ++i) {
            const double a0 = step * i, a1 = step * (i + 1), am = 0.5 * (a0 + a1);
            const double rc = r / std::cos(0.5 * step);
            curve(float(cx + r * std::cos(a0)), float(cy + r * std::sin(a0)),
                  float(cx + rc * std::cos(am)), float(cy + rc * std::sin(am)),
                  float(cx + r * std::cos(a1)), float(cy + r * std::sin(a1)));
        }
    }
    /// Ends the glyph begun after the last finish().
    uint32_t finish(bool even_odd = false) {
        GlyphRef r;
        r.even_odd = even_odd ? 1 : 0;
        r.first = refs.empty() ? 0 : refs.back().first + refs.back().count;
        r.count = uint32_t(segments.size()) - r.first;
        r.lo_x = r.lo_y = 1e30f, r.hi_x = r.hi_y = -1e30f;
        for (uint32_t i = r.first; i < r.first + r.count; ++i) {
            const GlyphSegment& s = segments[i];
            for (float x : {s.x0, s.x1, s.x2})
                r.lo_x = std::fmin(r.lo_x, x), r.hi_x = std::fmax(r.hi_x, x);
            for (float y : {s.y0, s.y1, s.y2})
                r.lo_y = std::fmin(r.lo_y, y), r.hi_y = std::fmax(r.hi_y, y);
        }
        refs.push_back(r);
        return uint32_t(refs.size() - 1);
    }
    ShapeTables tables() const { return {nullptr, refs.data(), segments.data()}; }

    /// The reference: the winding number of (x, y), every segment flattened into 64 chords
    /// and counted by the textbook crossing rule, written apart from the code under test.
    int winding(uint32_t glyph, double x, double y) const {
        const GlyphRef& r = refs[glyph];
        int w = 0;
        for (uint32_t i = r.first; i < r.first + r.count; ++i) {
            const GlyphSegment& s = segments[i];
            auto at = [&](double t, double& px, double& py) {
                const double u = 1 - t;
                px = u * u * s.x0 + 2 * t * u * s.x1 + t * t * s.x2;
                py = u * u * s.y0 + 2 * t * u * s.y1 + t * t * s.y2;
            };
            double ax, ay;
            at(0, ax, ay);
            for (int k = 1; k <= 64; ++k) {
                double bx, by;
                at(k / 64.0, bx, by);
                const double side = (bx - ax) * (y - ay) - (x - ax) * (by - ay);
                if (ay <= y && by > y && side > 0) ++w;
                if (ay > y && by <= y && side < 0) --w;
                ax = bx, ay = by;
            }
        }
        return w;
    }
    bool inside(uint32_t glyph, Vec3 p) const {
        const int w = winding(glyph, p.x, p.y);
        return p.z >= 0 && p.z <= 1 && (refs[glyph].even_odd ? (w & 1) != 0 : w != 0);
    }
};

Shape glyph_shape(uint32_t index) {
    Shape s;
    s.kind = ShapeKind::Glyph;
    s.index = index;
    return s;
}

using test::ray_from;

/// Checks the spans of random rays through the glyph's box against the reference: points well
/// inside a span are inside, points well inside a gap (or before and after) are outside.
void check_against_reference(const Glyphs& g, uint32_t glyph, unsigned seed, int rays) {
    std::mt19937 rng(seed);
    const GlyphRef& r = g.refs[glyph];
    std::uniform_real_distribution<float> ux(r.lo_x - 0.2f, r.hi_x + 0.2f),
        uy(r.lo_y - 0.2f, r.hi_y + 0.2f), uz(-0.2f, 1.2f);
    int checked = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3 target(ux(rng), uy(rng), uz(rng));
        const Vec3 d = test::random_unit(rng);
        const Ray l = ray_from(target - d * 5.0f, d);
        Span sp[kMaxShapeSpans];
        const int n = shape_spans(glyph_shape(glyph), l, sp, g.tables());
        // The reference flattens the curves: samples near a span's end are left out.
        const int got = test::check_spans(
            sp, n, l, [&](Vec3 p) { return g.inside(glyph, p); }, 10, "ray " + std::to_string(i));
        ASSERT_GE(got, 0);
        checked += got;
    }
    EXPECT_GT(checked, rays * 250);
}

TEST(Glyph, SquareSpansAndNormalsMatchABox) {
    Glyphs g;
    g.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const uint32_t sq = g.finish();
    std::mt19937 rng(7);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        // Aimed at the cube from anywhere around it.
        const Vec3 o = test::random_point(rng, 3.0f);
        const Vec3 d = normalize(test::random_point(rng, 0.6f) + Vec3(0.5f) - o);
        const Ray l = ray_from(o, d);
        Span a[kMaxShapeSpans], b[kMaxShapeSpans];
        const int na = shape_spans(glyph_shape(sq), l, a, g.tables());
        // The same unit cube as a box: [-1, 1]^3 moved to [0, 1]^3.
        const Ray lb = ray_from((o - Vec3(0.5f)) * 2.0f, d * 2.0f);
        const int nb = shape_spans({ShapeKind::Box}, lb, b);
        ASSERT_EQ(na, nb) << i;
        if (na == 0) continue;
        ++hits;
        EXPECT_NEAR(a[0].t0, b[0].t0, 1e-5f);
        EXPECT_NEAR(a[0].t1, b[0].t1, 1e-5f);
        if (a[0].t1 - a[0].t0 > 1e-4f) { // a corner grazed: either face's normal is right
            EXPECT_NEAR(dot(normalize(a[0].n0), b[0].n0), 1, 1e-5f) << i;
            EXPECT_NEAR(dot(normalize(a[0].n1), b[0].n1), 1, 1e-5f) << i;
        }
    }
    EXPECT_GT(hits, 1500);
}

TEST(Glyph, HolesOverlapsAndCurvesAgreeWithTheWindingNumber) {
    Glyphs g;
    // An "O": a circle with a circular hole (the inner contour runs the other way).
    g.circle(0.5f, 0.5f, 0.5f, 8);
    g.circle(0.5f, 0.5f, 0.3f, 8, false);
    const uint32_t o = g.finish();
    // Two squares that overlap, both counter-clockwise: nonzero winding fills the overlap
    // (even-odd would leave a hole there).
    g.polygon({{0, 0}, {0.6f, 0}, {0.6f, 0.6f}, {0, 0.6f}});
    g.polygon({{0.3f, 0.3f}, {0.9f, 0.3f}, {0.9f, 0.9f}, {0.3f, 0.9f}});
    const uint32_t overlap = g.finish();
    // A "C" with a sharp inner corner and curved ends, clockwise as TrueType draws outlines.
    g.curve(0.8f, 0.8f, 0.5f, 1.1f, 0.2f, 0.8f);
    g.curve(0.2f, 0.8f, -0.1f, 0.5f, 0.2f, 0.2f);
    g.curve(0.2f, 0.2f, 0.5f, -0.1f, 0.8f, 0.2f);
    g.line(0.8f, 0.2f, 0.7f, 0.3f);
    g.curve(0.7f, 0.3f, 0.3f, 0.1f, 0.3f, 0.5f);
    g.curve(0.3f, 0.5f, 0.3f, 0.9f, 0.7f, 0.7f);
    g.line(0.7f, 0.7f, 0.8f, 0.8f);
    const uint32_t c = g.finish();
    check_against_reference(g, o, 11, 300);
    check_against_reference(g, overlap, 12, 300);
    check_against_reference(g, c, 13, 300);
    // Along z, through the hole and through the ring.
    Span sp[kMaxShapeSpans];
    EXPECT_EQ(shape_spans(glyph_shape(o), ray_from({0.5f, 0.5f, -1}, {0, 0, 1}), sp, g.tables()),
              0);
    ASSERT_EQ(shape_spans(glyph_shape(o), ray_from({0.1f, 0.5f, -1}, {0, 0, 1}), sp, g.tables()),
              1);
    EXPECT_FLOAT_EQ(sp[0].t0, 1);
    EXPECT_FLOAT_EQ(sp[0].t1, 2);
    EXPECT_EQ(sp[0].n0.z, -1);
    EXPECT_EQ(sp[0].n1.z, 1);
    ASSERT_EQ(
        shape_spans(glyph_shape(overlap), ray_from({0.45f, 0.45f, 2}, {0, 0, -1}), sp, g.tables()),
        1);
    EXPECT_EQ(sp[0].n0.z, 1);
}

TEST(Glyph, EvenOddFillsWhatOverlapsTwiceAsAHole) {
    // POV-Ray's prism: a square inside a square, both the same way round, is a hole; the same
    // overlapping squares as above leave their overlap out.
    Glyphs g;
    g.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    g.polygon({{0.25f, 0.25f}, {0.75f, 0.25f}, {0.75f, 0.75f}, {0.25f, 0.75f}});
    const uint32_t frame = g.finish(true);
    g.polygon({{0, 0}, {0.6f, 0}, {0.6f, 0.6f}, {0, 0.6f}});
    g.polygon({{0.3f, 0.3f}, {0.9f, 0.3f}, {0.9f, 0.9f}, {0.3f, 0.9f}});
    const uint32_t overlap = g.finish(true);
    g.circle(0.5f, 0.5f, 0.5f, 8);
    g.circle(0.5f, 0.5f, 0.3f, 8);
    const uint32_t ring = g.finish(true); // both circles counter-clockwise: still a ring
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(
        shape_spans(glyph_shape(frame), ray_from({-1, 0.5f, 0.5f}, {1, 0, 0}), sp, g.tables()), 2);
    EXPECT_NEAR(sp[0].t1, 1.25f, 1e-6f);
    EXPECT_NEAR(sp[1].t0, 1.75f, 1e-6f);
    EXPECT_EQ(
        shape_spans(glyph_shape(frame), ray_from({0.5f, 0.5f, -1}, {0, 0, 1}), sp, g.tables()), 0);
    EXPECT_EQ(
        shape_spans(glyph_shape(overlap), ray_from({0.45f, 0.45f, -1}, {0, 0, 1}), sp, g.tables()),
        0);
    check_against_reference(g, frame, 21, 200);
    check_against_reference(g, overlap, 22, 200);
    check_against_reference(g, ring, 23, 200);
}

TEST(Glyph, OpenShowsOnlyTheSides) {
    Glyphs g;
    g.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const uint32_t sq = g.finish(true);
    Shape open = glyph_shape(sq);
    open.open = true;
    Span sp[kMaxShapeSpans];
    // Across: both walls, each a surface facing the ray.
    ASSERT_EQ(shape_spans(open, ray_from({-1, 0.5f, 0.5f}, {1, 0, 0}), sp, g.tables()), 2);
    EXPECT_NEAR(sp[0].t0, 1, 1e-6f);
    EXPECT_EQ(sp[0].t0, sp[0].t1);
    EXPECT_NEAR(sp[1].t0, 2, 1e-6f);
    EXPECT_LT(normalize(sp[0].n0).x, -0.999f);
    EXPECT_LT(normalize(sp[1].n0).x, -0.999f);
    // Down through the open top: nothing; from above at a slant: the far wall only.
    EXPECT_EQ(shape_spans(open, ray_from({0.5f, 0.5f, 2}, {0, 0, -1}), sp, g.tables()), 0);
    const float k = float(1 / std::sqrt(2.0));
    ASSERT_EQ(shape_spans(open, ray_from({0.5f, 0.5f, 1.2f}, {k, 0, -k}), sp, g.tables()), 1);
    EXPECT_NEAR(sp[0].t0, 0.5f * std::sqrt(2.0f), 1e-5f);
}

// A conic glyph (a prism's conic_sweep) is its outline scaled by base + (1 - base) z at height
// z: a square around the origin with base 0 is a pyramid (apex at the origin), with base 0.5 a
// frustum; an outline off the origin leans out as it rises. Random rays against the textbook
// test (scale the point back, then ask the winding number), and the pyramid's face normals.
TEST(Glyph, ConicGlyphsAreFrustaOfTheConeThroughTheirOutline) {
    Glyphs g;
    g.polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
    const uint32_t sq = g.finish(true);
    g.polygon({{0.5f, 0.2f}, {1.5f, 0.2f}, {1.5f, 1.2f}, {0.5f, 1.2f}});
    g.circle(1, 0.7f, 0.3f, 8, false); // a round hole
    const uint32_t off = g.finish(true);
    for (const float base : {0.0f, 0.5f}) {
        for (const uint32_t glyph : {sq, off}) {
            Shape s = glyph_shape(glyph);
            s.a = base, s.b = 1;
            std::mt19937 rng(11 + glyph);
            int checked = 0;
            for (int i = 0; i < 400; ++i) {
                const Vec3 target(std::uniform_real_distribution<float>(-1.6f, 1.6f)(rng),
                                  std::uniform_real_distribution<float>(-1.6f, 1.6f)(rng),
                                  std::uniform_real_distribution<float>(-0.2f, 1.2f)(rng));
                const Vec3 d = test::random_unit(rng);
                const Ray l = ray_from(target - d * 5.0f, d);
                Span sp[kMaxShapeSpans];
                const int n = shape_spans(s, l, sp, g.tables());
                const int got = test::check_spans(
                    sp, n, l,
                    [&](Vec3 p) {
                        const double w = base + (1 - base) * double(p.z);
                        if (!(p.z >= 0 && p.z <= 1) || w <= 0) return false;
                        return (g.winding(glyph, p.x / w, p.y / w) & 1) != 0;
                    },
                    10, "ray " + std::to_string(i));
                ASSERT_GE(got, 0) << "base " << base << " glyph " << glyph;
                checked += got;
            }
            EXPECT_GT(checked, 400 * 40);
        }
    }
    // Through the pyramid's side faces (x = z and x = -z) at height 0.5, then down its axis.
    Shape pyramid = glyph_shape(sq);
    pyramid.b = 1;
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(shape_spans(pyramid, ray_from({-2, 0, 0.5f}, {1, 0, 0}), sp, g.tables()), 1);
    EXPECT_NEAR(sp[0].t0, 1.5f, 1e-5f);
    EXPECT_NEAR(sp[0].t1, 2.5f, 1e-5f);
    const float h = float(1 / std::sqrt(2.0));
    EXPECT_NEAR(normalize(sp[0].n0).x, -h, 1e-5f);
    EXPECT_NEAR(normalize(sp[0].n0).z, -h, 1e-5f);
    EXPECT_NEAR(normalize(sp[0].n1).x, h, 1e-5f);
    EXPECT_NEAR(normalize(sp[0].n1).z, -h, 1e-5f);
    ASSERT_EQ(shape_spans(pyramid, ray_from({0.2f, 0.1f, 3}, {0, 0, -1}), sp, g.tables()), 1);
    EXPECT_NEAR(sp[0].t0, 2, 1e-5f);    // the top cap
    EXPECT_NEAR(sp[0].t1, 2.8f, 1e-5f); // out through the face x = z
    EXPECT_GT(normalize(sp[0].n1).x, 0.7f);
    // Open: the faces only, each facing the ray.
    pyramid.open = true;
    ASSERT_EQ(shape_spans(pyramid, ray_from({-2, 0, 0.5f}, {1, 0, 0}), sp, g.tables()), 2);
    EXPECT_NEAR(sp[1].t0, 2.5f, 1e-5f);
    EXPECT_LT(dot(sp[1].n0, Vec3(1, 0, 0)), 0);
}

TEST(Glyph, CubicsBecomeCloseQuadratics) {
    // A wiggly cubic (its third difference 7.4 against a size of about 1.4): the distance from
    // each quadratic piece to the cubic falls with the cube of the number of pieces.
    const double p[4][2] = {{0, 0}, {0.2, 1.5}, {1.3, -0.5}, {1, 1}};
    auto cubic = [&](double t, double& x, double& y) {
        const double v = 1 - t;
        x = v * v * v * p[0][0] + 3 * v * v * t * p[1][0] + 3 * v * t * t * p[2][0] +
            t * t * t * p[3][0];
        y = v * v * v * p[0][1] + 3 * v * v * t * p[1][1] + 3 * v * t * t * p[2][1] +
            t * t * t * p[3][1];
    };
    for (const auto& [pieces, limit] : {std::pair{8, 7e-4}, std::pair{16, 9e-5}}) {
        std::vector<GlyphSegment> q;
        cubic_to_quadratics(p, pieces, q);
        ASSERT_EQ(q.size(), size_t(pieces));
        EXPECT_EQ(q.front().x0, 0.0f);
        EXPECT_EQ(q.back().x2, 1.0f);
        EXPECT_EQ(q.back().y2, 1.0f);
        double worst = 0;
        for (int i = 0; i < pieces; ++i) {
            if (i + 1 < pieces) EXPECT_EQ(q[i].x2, q[i + 1].x0); // chained
            for (int k = 0; k <= 20; ++k) { // the nearest point of the cubic to each sample
                const double s = k / 20.0, u = 1 - s;
                const double qx = u * u * q[i].x0 + 2 * s * u * q[i].x1 + s * s * q[i].x2;
                const double qy = u * u * q[i].y0 + 2 * s * u * q[i].y1 + s * s * q[i].y2;
                double nearest = 1e30;
                for (int j = -400; j <= 400; ++j) {
                    const double t = (i + s) / pieces + j * 1e-6;
                    double cx, cy;
                    cubic(std::clamp(t, 0.0, 1.0), cx, cy);
                    nearest = std::min(nearest, std::hypot(qx - cx, qy - cy));
                }
                worst = std::max(worst, nearest);
            }
        }
        EXPECT_LT(worst, limit) << pieces << " pieces";
    }
}

TEST(Glyph, AcrossTheRingGivesTwoSpansWithOutwardNormals) {
    Glyphs g;
    g.circle(0.5f, 0.5f, 0.5f, 8);
    g.circle(0.5f, 0.5f, 0.3f, 8, false);
    const uint32_t o = g.finish();
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(shape_spans(glyph_shape(o), ray_from({-1, 0.5f, 0.5f}, {1, 0, 0}), sp, g.tables()),
              2);
    EXPECT_NEAR(sp[0].t0, 1.0f, 1e-6f);
    EXPECT_NEAR(sp[0].t1, 1.2f, 1e-6f);
    EXPECT_NEAR(sp[1].t0, 1.8f, 1e-6f);
    EXPECT_NEAR(sp[1].t1, 2.0f, 1e-6f);
    EXPECT_NEAR(normalize(sp[0].n0).x, -1, 1e-5f); // the outer edge, facing the ray
    EXPECT_NEAR(normalize(sp[0].n1).x, 1, 1e-5f);  // the hole's edge, facing into the hole
    EXPECT_NEAR(normalize(sp[1].n0).x, -1, 1e-5f);
    EXPECT_NEAR(normalize(sp[1].n1).x, 1, 1e-5f);
}

TEST(Glyph, RaysThroughVerticesCountEachCrossingOnce) {
    Glyphs g;
    g.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const uint32_t sq = g.finish();
    Span sp[kMaxShapeSpans];
    // The diagonal passes through two corners, where two segments meet.
    const float k = float(1 / std::sqrt(2.0));
    ASSERT_EQ(shape_spans(glyph_shape(sq), ray_from({-1, -1, 0.5f}, {k, k, 0}), sp, g.tables()), 1);
    EXPECT_NEAR(sp[0].t0, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(sp[0].t1, 2 * std::sqrt(2.0f), 1e-5f);
    // Along an edge, and through a corner from outside (a touch): never an open span.
    for (const Ray& l : {ray_from({-1, 0, 0.5f}, {1, 0, 0}), ray_from({-1, 1, 0.5f}, {k, -k, 0}),
                         ray_from({2, -1, 0.5f}, {-k, k, 0}), ray_from({1, 2, 0.5f}, {0, -1, 0})}) {
        const int n = shape_spans(glyph_shape(sq), l, sp, g.tables());
        for (int i = 0; i < n; ++i) EXPECT_LT(sp[i].t1, 1e29f);
        EXPECT_LE(n, 1);
    }
}

TEST(Glyph, ManyTeethKeepTheNearestCrossings) {
    // A comb: 40 teeth along x, so a line along x crosses 80 edges, more than are kept.
    Glyphs g;
    std::vector<std::pair<float, float>> p{{0, 0}, {40, 0}};
    for (int i = 39; i >= 0; --i) {
        p.push_back({i + 0.6f, 0.0f + 1}), p.push_back({i + 0.6f, 2});
        p.push_back({i + 0.2f, 2}), p.push_back({i + 0.2f, 1});
    }
    p.push_back({0.0f, 1.0f});
    g.polygon(p);
    const uint32_t comb = g.finish();
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(shape_spans(glyph_shape(comb), ray_from({-1, 1.5f, 0.5f}, {1, 0, 0}), sp, g.tables()),
              kMaxShapeSpans);
    for (int i = 0; i < kMaxShapeSpans; ++i) {
        EXPECT_NEAR(sp[i].t0, 1.2f + i, 1e-5f);
        EXPECT_NEAR(sp[i].t1, 1.6f + i, 1e-5f);
    }
    // From the far end, the nearest teeth are the last ones.
    ASSERT_EQ(
        shape_spans(glyph_shape(comb), ray_from({41, 1.5f, 0.5f}, {-1, 0, 0}), sp, g.tables()),
        kMaxShapeSpans);
    EXPECT_NEAR(sp[0].t0, 41 - 39.6f, 1e-4f);
}

TEST(Glyph, WithoutTablesThereAreNoSpans) {
    Span sp[kMaxShapeSpans];
    EXPECT_EQ(shape_spans(glyph_shape(0), ray_from({0, 0, -1}, {0, 0, 1}), sp), 0);
}

} // namespace
} // namespace sheaf

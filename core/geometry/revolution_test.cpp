#include "core/geometry/shape.h"
#include "core/geometry/span_check.h"
#include "core/geometry/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace sheaf {
namespace {

/// Profiles built by hand, with the prepared tables shape_spans reads.
struct Profiles {
    std::vector<RevolutionSegment> segments;
    std::vector<RevolutionRef> refs;
    std::vector<RevolutionProfile> profiles;
    RevolutionProfile open_profile;

    void bezier(std::initializer_list<std::pair<float, float>> p) {
        RevolutionSegment s;
        uint32_t i = 0;
        for (const auto& [w, h] : p) s.w[i] = w, s.h[i] = h, ++i;
        s.wdeg = s.hdeg = i - 1;
        open_profile.segments.push_back(s);
    }
    /// A chain of straight segments through the points.
    void polyline(std::initializer_list<std::pair<float, float>> p) {
        const std::vector<std::pair<float, float>> v(p);
        for (size_t i = 0; i + 1 < v.size(); ++i) bezier({v[i], v[i + 1]});
    }
    /// A circle of four cubic arcs about (cw, ch) in the profile plane.
    void circle(float cw, float ch, float r) {
        const float k = 0.5522847f * r;
        bezier({{cw + r, ch}, {cw + r, ch + k}, {cw + k, ch + r}, {cw, ch + r}});
        bezier({{cw, ch + r}, {cw - k, ch + r}, {cw - r, ch + k}, {cw - r, ch}});
        bezier({{cw - r, ch}, {cw - r, ch - k}, {cw - k, ch - r}, {cw, ch - r}});
        bezier({{cw, ch - r}, {cw + k, ch - r}, {cw + r, ch - k}, {cw + r, ch}});
    }
    uint32_t finish(bool squared = false) {
        open_profile.squared = squared;
        RevolutionRef r;
        r.first = uint32_t(segments.size());
        r.count = uint32_t(open_profile.segments.size());
        r.squared = squared ? 1 : 0;
        revolution_bounds(open_profile, r.r_max, r.h_lo, r.h_hi);
        segments.insert(segments.end(), open_profile.segments.begin(), open_profile.segments.end());
        refs.push_back(r);
        profiles.push_back(open_profile);
        flatten(open_profile);
        open_profile = {};
        return uint32_t(refs.size() - 1);
    }
    ShapeTables tables() const { return {nullptr, nullptr, nullptr, refs.data(), segments.data()}; }

    /// The reference: whether (rho, h) lies inside by the even-odd rule, counting where the
    /// level half-line from it outwards crosses the profile flattened into 256 chords a
    /// segment, written apart from the code under test.
    bool inside(uint32_t k, Vec3 p) const {
        const double rho2 = double(p.x) * p.x + double(p.y) * p.y, h = p.z;
        const double rho = profiles[k].squared ? rho2 : std::sqrt(rho2);
        int crossings = 0;
        for (const std::vector<std::pair<double, double>>& chain : flat[k])
            for (size_t i = 1; i < chain.size(); ++i) {
                const auto [aw, ah] = chain[i - 1];
                const auto [bw, bh] = chain[i];
                if ((ah <= h) != (bh <= h) && aw + (bw - aw) * (h - ah) / (bh - ah) > rho)
                    ++crossings;
            }
        return crossings & 1;
    }
    /// Each profile's segments as chains of points, by de Casteljau's construction.
    std::vector<std::vector<std::vector<std::pair<double, double>>>> flat;
    void flatten(const RevolutionProfile& prof) {
        auto at = [](const float* c, uint32_t deg, double t) {
            double b[4] = {c[0], c[1], c[2], c[3]};
            for (uint32_t level = deg; level > 0; --level)
                for (uint32_t i = 0; i < level; ++i) b[i] = b[i] * (1 - t) + b[i + 1] * t;
            return b[0];
        };
        flat.emplace_back();
        for (const RevolutionSegment& s : prof.segments) {
            flat.back().emplace_back();
            for (int i = 0; i <= 256; ++i)
                flat.back().back().push_back(
                    {at(s.w, s.wdeg, i / 256.0), at(s.h, s.hdeg, i / 256.0)});
        }
    }
};

Shape revolution_shape(uint32_t index, bool open = false) {
    Shape s;
    s.kind = ShapeKind::Revolution;
    s.index = index;
    s.open = open;
    return s;
}

using test::ray_from;

/// Checks the spans of one ray against the reference: points well inside a span are inside,
/// points well inside a gap (or before and after) are outside. Returns the samples checked.
int check_ray(const Profiles& g, uint32_t k, const Ray& l, const char* what, int i) {
    Span sp[kMaxShapeSpans];
    const int n = shape_spans(revolution_shape(k), l, sp, g.tables());
    return test::check_spans(
        sp, n, l, [&](Vec3 p) { return g.inside(k, p); }, 10,
        std::string(what) + " ray " + std::to_string(i));
}

/// Random rays through the profile's cylinder, checked against the reference.
void check_against_reference(const Profiles& g, uint32_t k, const char* what, unsigned seed,
                             int rays) {
    std::mt19937 rng(seed);
    const RevolutionRef& r = g.refs[k];
    std::uniform_real_distribution<float> uxy(-r.r_max - 0.2f, r.r_max + 0.2f),
        uz(r.h_lo - 0.2f, r.h_hi + 0.2f);
    int checked = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3 target(uxy(rng), uxy(rng), uz(rng));
        Vec3 d = test::random_unit(rng);
        if (i % 5 == 0) d = normalize(Vec3(d.x, d.y, 0)); // level, as a camera's middle row
        const int c = check_ray(g, k, ray_from(target - d * 5.0f, d), what, i);
        ASSERT_GE(c, 0);
        checked += c;
    }
    EXPECT_GT(checked, rays * 250) << what;
}

TEST(Revolution, RectangleProfileMatchesACylinder) {
    Profiles g;
    g.polyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const uint32_t cyl = g.finish();
    g.polyline({{0, 0}, {1, 0}, {0.5f, 1}, {0, 1}});
    const uint32_t cone = g.finish();
    std::mt19937 rng(5);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o = test::random_point(rng, 3.0f);
        Vec3 d = normalize(test::random_point(rng, 0.6f) + Vec3(0, 0, 0.5f) - o);
        if (i % 4 == 0) d = normalize(Vec3(d.x, d.y, 0)); // level rays
        const Ray l = ray_from(o, d);
        for (const uint32_t k : {cyl, cone}) {
            Span a[kMaxShapeSpans], b[kMaxShapeSpans];
            const int na = shape_spans(revolution_shape(k), l, a, g.tables());
            Shape ref;
            ref.kind = k == cyl ? ShapeKind::Cylinder : ShapeKind::Cone;
            ref.a = 1, ref.b = 0.5f;
            const int nb = shape_spans(ref, l, b);
            ASSERT_EQ(na, nb) << i;
            if (na == 0) continue;
            ++hits;
            EXPECT_NEAR(a[0].t0, b[0].t0, 1e-4f) << i;
            EXPECT_NEAR(a[0].t1, b[0].t1, 1e-4f) << i;
            if (a[0].t1 - a[0].t0 > 1e-3f) { // an edge grazed: either face's normal is right
                EXPECT_NEAR(dot(normalize(a[0].n0), normalize(b[0].n0)), 1, 1e-4f) << i;
                EXPECT_NEAR(dot(normalize(a[0].n1), normalize(b[0].n1)), 1, 1e-4f) << i;
            }
        }
    }
    EXPECT_GT(hits, 2000);
}

TEST(Revolution, CurvedProfilesAgreeWithTheEvenOddRule) {
    Profiles g;
    g.circle(1.2f, 0.5f, 0.4f); // a torus with a round tube
    const uint32_t torus = g.finish();
    // A vase from the axis to the axis: a quadratic foot, a cubic body, a straight rim, and
    // a hollow inside it (the curve comes back down inside).
    g.bezier({{0, 0}, {0.8f, 0}, {0.6f, 0.2f}});
    g.bezier({{0.6f, 0.2f}, {1.4f, 0.6f}, {0.1f, 1.0f}, {0.4f, 1.5f}});
    g.polyline({{0.4f, 1.5f}, {0.3f, 1.5f}, {0.3f, 0.6f}, {0, 0.6f}});
    const uint32_t vase = g.finish();
    // Overlapping loops: even-odd leaves their overlap out.
    g.circle(0.8f, 0.5f, 0.4f);
    g.circle(1.1f, 0.6f, 0.4f);
    const uint32_t loops = g.finish();
    check_against_reference(g, torus, "torus", 21, 400);
    check_against_reference(g, vase, "vase", 22, 400);
    check_against_reference(g, loops, "loops", 23, 400);
}

TEST(Revolution, SquaredRadiusProfileAgreesWithItsCubic) {
    // A sor's segment: r^2 as a cubic Bézier in s, the height linear, closed by flat caps.
    Profiles g;
    RevolutionSegment bottom, body, top;
    bottom.w[0] = 0, bottom.w[1] = 0.3f, bottom.h[0] = bottom.h[1] = 0;
    body.wdeg = 3, body.hdeg = 1;
    body.w[0] = 0.3f, body.w[1] = 1.2f, body.w[2] = -0.2f, body.w[3] = 0.5f;
    body.h[0] = 0, body.h[1] = 2;
    top.w[0] = 0.5f, top.w[1] = 0, top.h[0] = top.h[1] = 2;
    for (const RevolutionSegment& s : {bottom, body, top}) g.open_profile.segments.push_back(s);
    const uint32_t sor = g.finish(true);
    check_against_reference(g, sor, "sor", 31, 400);
    // Its own inside rule, apart from the crossing count: r^2 below the cubic at that height.
    std::mt19937 rng(32);
    for (int i = 0; i < 300; ++i) {
        const Vec3 d = test::random_unit(rng);
        const Ray l = ray_from(Vec3(0, 0, 1) - d * 5.0f, d);
        Span sp[kMaxShapeSpans];
        const int n = shape_spans(revolution_shape(sor), l, sp, g.tables());
        for (int s = 0; s < n; ++s) {
            const Vec3 mid = ray_at(l, 0.5f * (sp[s].t0 + sp[s].t1));
            const double u = mid.z / 2.0, v = 1 - u;
            const double w =
                v * v * v * 0.3 + 3 * v * v * u * 1.2 - 3 * v * u * u * 0.2 + u * u * u * 0.5;
            if (sp[s].t1 - sp[s].t0 > 1e-3f) {
                EXPECT_LT(double(mid.x) * mid.x + double(mid.y) * mid.y, w + 1e-6) << i;
                EXPECT_GE(mid.z, -1e-6f) << i;
                EXPECT_LE(mid.z, 2 + 1e-6f) << i;
            }
        }
    }
}

TEST(Revolution, NearlyLevelRaysAgreeWithLevelOnes) {
    Profiles g;
    g.circle(1.2f, 0.5f, 0.4f);
    const uint32_t torus = g.finish();
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> uz(0.15f, 0.85f), ua(0, 6.2831853f);
    for (int i = 0; i < 500; ++i) {
        const float a = ua(rng), z = uz(rng);
        const Vec3 o(3 * std::cos(a), 3 * std::sin(a), z);
        const Vec3 level = normalize(
            Vec3(-std::cos(a) + 0.2f * std::sin(a), -std::sin(a) - 0.2f * std::cos(a), 0));
        Span a0[kMaxShapeSpans];
        const int n0 = shape_spans(revolution_shape(torus), ray_from(o, level), a0, g.tables());
        for (const float tilt : {1e-7f, 1e-6f, 2e-5f, 1e-4f}) {
            const Vec3 d = normalize(level + Vec3(0, 0, tilt));
            Span a1[kMaxShapeSpans];
            const int n1 = shape_spans(revolution_shape(torus), ray_from(o, d), a1, g.tables());
            ASSERT_EQ(n0, n1) << i << " tilt " << tilt;
            for (int s = 0; s < n0; ++s) {
                EXPECT_NEAR(a0[s].t0, a1[s].t0, 1e-3f) << i << " tilt " << tilt;
                EXPECT_NEAR(a0[s].t1, a1[s].t1, 1e-3f) << i << " tilt " << tilt;
            }
        }
    }
}

TEST(Revolution, RaysThroughVerticesKeepInsideAndOutsideApart) {
    // A diamond's corners at exactly representable points, and rays aimed through them from
    // many directions: a crossing at a shared vertex is counted once, or twice where the ray
    // only touches the corner.
    Profiles g;
    g.polyline({{0, 0}, {1, 0.5f}, {0, 1}, {0.5f, 0.5f}, {0, 0}});
    const uint32_t diamond = g.finish();
    std::mt19937 rng(51);
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3 corner = i % 2 ? Vec3(1, 0, 0.5f) : Vec3(0, 0.5f, 0.5f);
        Vec3 d = test::random_unit(rng);
        if (i % 3 == 0) d = normalize(Vec3(d.x, d.y, 0));
        const int c = check_ray(g, diamond, ray_from(corner - d * 4.0f, d), "diamond", i);
        ASSERT_GE(c, 0);
        checked += c;
    }
    EXPECT_GT(checked, 400 * 200);
}

TEST(Revolution, OpenProfileGivesItsSurfaceOnly) {
    Profiles g;
    g.polyline({{1, 0}, {1, 1}}); // a tube without ends
    const uint32_t tube = g.finish();
    Span sp[kMaxShapeSpans];
    const Ray across = ray_from(Vec3(-3, 0, 0.5f), Vec3(1, 0, 0));
    const int n = shape_spans(revolution_shape(tube, true), across, sp, g.tables());
    ASSERT_EQ(n, 2);
    EXPECT_NEAR(sp[0].t0, 2, 1e-5f);
    EXPECT_EQ(sp[0].t0, sp[0].t1);
    EXPECT_NEAR(sp[1].t0, 4, 1e-5f);
    EXPECT_NEAR(dot(normalize(sp[0].n0), Vec3(-1, 0, 0)), 1, 1e-5f); // facing the ray
    EXPECT_NEAR(dot(normalize(sp[1].n0), Vec3(-1, 0, 0)), 1, 1e-5f);
    // Through the open end, along the axis: nothing.
    EXPECT_EQ(shape_spans(revolution_shape(tube, true), ray_from(Vec3(0, 0, -3), Vec3(0, 0, 1)), sp,
                          g.tables()),
              0);
}

} // namespace
} // namespace sheaf

#include "core/geometry/shape.h"
#include "core/geometry/span_check.h"
#include "core/scene/function_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace sheaf {
namespace {

using test::op;

/// Isosurfaces over programs of x, y, z, with the tables shape_spans reads.
struct Isos {
    std::vector<FnInstr> code;
    std::vector<FnProgram> programs;
    std::vector<IsoRef> refs;

    uint32_t add(std::vector<FnInstr> body, IsoRef iso) {
        FnProgram pg;
        pg.first = uint32_t(code.size());
        body.push_back(op(FnOp::Drop, 3));
        pg.count = uint32_t(body.size());
        pg.params = 3;
        FnProgram alone = pg;
        alone.first = 0;
        EXPECT_EQ(check_fn_program(alone, body.data(), body.size(), 0, 0), "");
        code.insert(code.end(), body.begin(), body.end());
        iso.program = uint32_t(programs.size());
        programs.push_back(pg);
        refs.push_back(iso);
        return uint32_t(refs.size() - 1);
    }
    ShapeTables tables() const {
        ShapeTables t;
        t.isosurfaces = refs.data();
        t.functions = FnView{programs.data(), code.data(), nullptr};
        return t;
    }
};

// |p| - 1, the unit sphere.
std::vector<FnInstr> sphere_body() {
    return {op(FnOp::Load, 0),     op(FnOp::Load, 0), op(FnOp::Mul),
            op(FnOp::Load, 1),     op(FnOp::Load, 1), op(FnOp::Mul),
            op(FnOp::Add),         op(FnOp::Load, 2), op(FnOp::Load, 2),
            op(FnOp::Mul),         op(FnOp::Add),     op(FnOp::Math, uint16_t(FnMath::Sqrt)),
            op(FnOp::Const, 0, 1), op(FnOp::Sub)};
}

TEST(Isosurface, ASphereFunctionMatchesTheSphereShape) {
    Isos isos;
    IsoRef iso;
    iso.lo = Vec3(-2), iso.hi = Vec3(2);
    Shape s;
    s.kind = ShapeKind::Isosurface;
    s.index = isos.add(sphere_body(), iso);
    Shape exact;
    std::mt19937 g(3);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o(u(g) * 3, u(g) * 3, -4);
        const Vec3 d = normalize(Vec3(u(g) * 0.3f, u(g) * 0.3f, 1) - o * 0.2f);
        const Ray r = test::ray_from(o, d);
        Span a[kMaxShapeSpans], b[kMaxShapeSpans];
        const int na = shape_spans(s, r, a, isos.tables()), nb = shape_spans(exact, r, b);
        ASSERT_EQ(na, nb) << i;
        for (int k = 0; k < na; ++k) {
            hits++;
            // Found within a thousandth of the accuracy (0.001) along the ray.
            EXPECT_NEAR(a[k].t0, b[k].t0, 2e-6f * 1000) << i;
            EXPECT_NEAR(a[k].t0, b[k].t0, 5e-6f) << i;
            EXPECT_NEAR(a[k].t1, b[k].t1, 5e-6f) << i;
            EXPECT_GT(dot(normalize(a[k].n0), normalize(b[k].n0)), 0.99999f) << i;
            EXPECT_GT(dot(normalize(a[k].n1), normalize(b[k].n1)), 0.99999f) << i;
        }
    }
    EXPECT_GT(hits, 200);
}

TEST(Isosurface, ANearerEndFindsTheSameCrossing) {
    // The renderer tests a hit again with tmax just past it, for its normal and material.
    Isos isos;
    IsoRef iso;
    iso.lo = Vec3(-2), iso.hi = Vec3(2);
    Shape s;
    s.kind = ShapeKind::Isosurface;
    s.index = isos.add(sphere_body(), iso);
    std::mt19937 g(5);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
        Ray r = test::ray_from(Vec3(u(g), u(g), -4), normalize(Vec3(u(g) * 0.2f, u(g) * 0.2f, 1)));
        Span sp[kMaxShapeSpans];
        if (shape_spans(s, r, sp, isos.tables()) == 0) continue;
        const float t = sp[0].t0;
        r.tmax = std::nextafter(t, INFINITY);
        Span again[kMaxShapeSpans];
        ASSERT_GE(shape_spans(s, r, again, isos.tables()), 1) << i;
        EXPECT_EQ(again[0].t0, t) << i;
        EXPECT_EQ(again[0].n0, sp[0].n0) << i;
    }
}

TEST(Isosurface, TheContainerCapsTheSolidUnlessOpen) {
    Isos isos;
    // y < 0 in the box [-1, 1]^3: a slab, capped by the box's walls.
    IsoRef iso;
    const uint32_t closed = isos.add({op(FnOp::Load, 1)}, iso);
    iso.open = true;
    const uint32_t open = isos.add({op(FnOp::Load, 1)}, iso);
    Shape s;
    s.kind = ShapeKind::Isosurface;
    Span sp[kMaxShapeSpans];
    // Along x under the plane: inside from wall to wall.
    s.index = closed;
    const Ray along = test::ray_from(Vec3(-5, -0.5f, 0), Vec3(1, 0, 0));
    ASSERT_EQ(shape_spans(s, along, sp, isos.tables()), 1);
    EXPECT_NEAR(sp[0].t0, 4, 1e-6f);
    EXPECT_NEAR(sp[0].t1, 6, 1e-6f);
    EXPECT_EQ(sp[0].n0, Vec3(-1, 0, 0));
    EXPECT_EQ(sp[0].n1, Vec3(1, 0, 0));
    // Down through it: enters at y = 0 (normal up), leaves by the floor.
    const Ray down = test::ray_from(Vec3(0.2f, 5, 0.3f), Vec3(0, -1, 0));
    ASSERT_EQ(shape_spans(s, down, sp, isos.tables()), 1);
    EXPECT_NEAR(sp[0].t0, 5, 1e-5f);
    EXPECT_NEAR(sp[0].t1, 6, 1e-6f);
    EXPECT_GT(normalize(sp[0].n0).y, 0.9999f);
    // Open: only the surface y = 0.
    s.index = open;
    EXPECT_EQ(shape_spans(s, along, sp, isos.tables()), 0);
    ASSERT_EQ(shape_spans(s, down, sp, isos.tables()), 1);
    EXPECT_EQ(sp[0].t0, sp[0].t1);
    EXPECT_NEAR(sp[0].t0, 5, 1e-5f);
}

TEST(Isosurface, ASearchFromInsideStartsBeforeTheRay) {
    Isos isos;
    IsoRef iso;
    iso.sphere = true, iso.lo = Vec3(0), iso.hi = Vec3(3, 0, 0);
    Shape s;
    s.kind = ShapeKind::Isosurface;
    s.index = isos.add(sphere_body(), iso);
    Ray r = test::ray_from(Vec3(0), Vec3(0, 0, 1));
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(shape_spans(s, r, sp, isos.tables()), 1);
    EXPECT_EQ(sp[0].t0, -FLT_MAX); // inside where the search starts: from before it
    EXPECT_NEAR(sp[0].t1, 1, 1e-5f);
    r.tmin = -10; // the whole line: from the sphere's far side
    ASSERT_EQ(shape_spans(s, r, sp, isos.tables()), 1);
    EXPECT_NEAR(sp[0].t0, -1, 1e-5f);
}

TEST(Isosurface, ManyShellsFillTheSpansInOrder) {
    // sin(4 |p|) < 0: shells 0.785 apart; the search must not step over any of them.
    Isos isos;
    IsoRef iso;
    iso.lo = Vec3(-6), iso.hi = Vec3(6);
    iso.max_gradient = 4.1f;
    std::vector<FnInstr> body = sphere_body();
    body.push_back(op(FnOp::Const, 0, 4));
    body.push_back(op(FnOp::Mul));
    body.push_back(op(FnOp::Math, uint16_t(FnMath::Sin)));
    Shape s;
    s.kind = ShapeKind::Isosurface;
    s.index = isos.add(body, iso);
    const Ray r = test::ray_from(Vec3(0.3f, 0.2f, -20), Vec3(0, 0, 1));
    Span sp[kMaxShapeSpans];
    ASSERT_EQ(shape_spans(s, r, sp, isos.tables()), kMaxShapeSpans);
    auto inside = [](Vec3 p) { return std::sin(4 * (std::sqrt(double(dot(p, p))) - 1)) < 0; };
    for (int k = 0; k < kMaxShapeSpans; ++k) {
        EXPECT_LT(sp[k].t0, sp[k].t1);
        const Vec3 mid = r.origin + r.dir * (0.5f * (sp[k].t0 + sp[k].t1));
        EXPECT_TRUE(inside(mid)) << k;
        if (k > 0) {
            const Vec3 gap = r.origin + r.dir * (0.5f * (sp[k - 1].t1 + sp[k].t0));
            EXPECT_FALSE(inside(gap)) << k;
        }
    }
    // The first span is the outermost shell the ray meets.
    EXPECT_LT(sp[0].t0, 20 - 5.5f + 0.8f);
}

} // namespace
} // namespace sheaf

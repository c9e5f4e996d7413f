#include "core/geometry/blob_build.h"
#include "core/geometry/shape.h"
#include "core/geometry/span_check.h"
#include "core/geometry/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace sheaf {
namespace {

/// Blobs built by the builder, with the prepared tables shape_spans reads, and each one's
/// field written apart from the code under test, as a function of the blob's point.
struct Blobs {
    std::vector<BlobRef> refs;
    std::vector<BlobElement> elements;
    std::vector<std::function<double(double, double, double)>> fields;
    std::vector<float> thresholds;

    uint32_t add(const BlobModel& m, std::function<double(double, double, double)> field) {
        BlobRef r;
        r.first = uint32_t(elements.size());
        r.count = uint32_t(m.elements.size());
        r.threshold = m.threshold;
        blob_bound(m, r.bound);
        elements.insert(elements.end(), m.elements.begin(), m.elements.end());
        refs.push_back(r);
        fields.push_back(std::move(field));
        thresholds.push_back(m.threshold);
        return uint32_t(refs.size() - 1);
    }
    ShapeTables tables() const {
        ShapeTables t;
        t.blobs = refs.data(), t.blob_elements = elements.data();
        return t;
    }
    bool inside(uint32_t k, Vec3 p) const { return fields[k](p.x, p.y, p.z) > thresholds[k]; }
};

/// S (1 - d^2 / R^2)^2 within R.
double falloff(double d2, double radius, double strength) {
    const double x = 1 - d2 / (radius * radius);
    return d2 < radius * radius ? strength * x * x : 0;
}

double sphere_field(double x, double y, double z, Vec3 c, double radius, double strength) {
    const double dx = x - c.x, dy = y - c.y, dz = z - c.z;
    return falloff(dx * dx + dy * dy + dz * dz, radius, strength);
}

/// The squared distance from (x, y, z) to the segment from a to b.
double segment_d2(double x, double y, double z, Vec3 a, Vec3 b) {
    const double ax = b.x - a.x, ay = b.y - a.y, az = b.z - a.z;
    const double px = x - a.x, py = y - a.y, pz = z - a.z;
    double s = (px * ax + py * ay + pz * az) / (ax * ax + ay * ay + az * az);
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    const double ex = px - s * ax, ey = py - s * ay, ez = pz - s * az;
    return ex * ex + ey * ey + ez * ez;
}

Shape blob_shape(uint32_t index) {
    Shape s;
    s.kind = ShapeKind::Blob;
    s.index = index;
    return s;
}

using test::ray_from;

/// Checks one ray's spans against the reference field; returns the samples checked.
int check_ray(const Blobs& g, uint32_t k, const Ray& l, int i) {
    Span sp[kMaxShapeSpans];
    const int n = shape_spans(blob_shape(k), l, sp, g.tables());
    const int checked = test::check_spans(
        sp, n, l, [&](Vec3 p) { return g.inside(k, p); }, 12, "ray " + std::to_string(i));
    if (checked <= 0) return checked;
    // Each end lies on the surface, its normal along the field's falling gradient.
    for (int s = 0; s < n; ++s)
        for (int e = 0; e < 2; ++e) {
            const float t = e ? sp[s].t1 : sp[s].t0;
            const Vec3 p = ray_at(l, t), nv = e ? sp[s].n1 : sp[s].n0;
            const auto& f = g.fields[k];
            const double h = 1e-4;
            const double gx = f(p.x + h, p.y, p.z) - f(p.x - h, p.y, p.z),
                         gy = f(p.x, p.y + h, p.z) - f(p.x, p.y - h, p.z),
                         gz = f(p.x, p.y, p.z + h) - f(p.x, p.y, p.z - h);
            const double gl = std::sqrt(gx * gx + gy * gy + gz * gz);
            EXPECT_NEAR(f(p.x, p.y, p.z), g.thresholds[k], 2e-3 * (1 + gl / (2 * h)))
                << "ray " << i;
            if (gl / (2 * h) < 1e-2) continue; // a flat spot: any normal will do
            const Vec3 ref(float(-gx / gl), float(-gy / gl), float(-gz / gl));
            EXPECT_GT(dot(normalize(nv), ref), 0.999f) << "ray " << i << " end " << e;
        }
    return checked;
}

/// Random rays through the blob's bound, checked against the reference.
void check_against_reference(const Blobs& g, uint32_t k, unsigned seed, int rays) {
    std::mt19937 rng(seed);
    const BlobRef& b = g.refs[k];
    const Vec3 c(b.bound[0], b.bound[1], b.bound[2]);
    int checked = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3 target = c + test::random_point(rng, b.bound[3] * 0.8f);
        const Vec3 d = test::random_unit(rng);
        const int got = check_ray(g, k, ray_from(target - d * 6.0f, d), i);
        ASSERT_GE(got, 0);
        checked += got;
    }
    EXPECT_GT(checked, rays * 400);
}

TEST(Blob, OneSphereComponentIsASphere) {
    // S (1 - r^2/R^2)^2 = T at r = R sqrt(1 - sqrt(T / S)).
    BlobModel m;
    m.threshold = 0.25f;
    add_blob_sphere(m, Vec3(0.5f, 0, 0), 2, 1, Affine());
    Blobs g;
    const uint32_t k = g.add(m, [](double x, double y, double z) {
        return sphere_field(x, y, z, Vec3(0.5f, 0, 0), 2, 1);
    });
    const double radius = 2 * std::sqrt(1 - std::sqrt(0.25));
    std::mt19937 rng(3);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 o = test::random_point(rng, 4);
        const Vec3 d = normalize(test::random_point(rng, 1.5f) - o);
        Span a[kMaxShapeSpans], b[kMaxShapeSpans];
        const int na = shape_spans(blob_shape(k), ray_from(o, d), a, g.tables());
        Shape sph; // the unit sphere, the ray carried to its space
        const Ray l = ray_from((o - Vec3(0.5f, 0, 0)) / float(radius), d / float(radius));
        const int nb = shape_spans(sph, l, b);
        ASSERT_EQ(na, nb) << i;
        if (na == 0) continue;
        ++hits;
        EXPECT_NEAR(a[0].t0, b[0].t0, 1e-4f) << i;
        EXPECT_NEAR(a[0].t1, b[0].t1, 1e-4f) << i;
        EXPECT_NEAR(dot(normalize(a[0].n0), normalize(b[0].n0)), 1, 1e-5f) << i;
        EXPECT_NEAR(dot(normalize(a[0].n1), normalize(b[0].n1)), 1, 1e-5f) << i;
    }
    EXPECT_GT(hits, 200);
}

TEST(Blob, SpheresAndCylindersAgreeWithTheField) {
    // POV-Ray's blob1a: two crossed cylinders and a negative sphere above them.
    BlobModel m;
    m.threshold = 0.5f;
    add_blob_cylinder(m, Vec3(-2.5f, 0, 0), Vec3(2.5f, 0, 0), 1.4f, 2, Affine());
    add_blob_cylinder(m, Vec3(0, 0, -2.5f), Vec3(0, 0.5f, 2.5f), 1.4f, 2, Affine());
    add_blob_sphere(m, Vec3(0, 1, 0), 0.9f, -4, Affine());
    add_blob_sphere(m, Vec3(1.5f, -1, 1), 1.2f, 1, Affine());
    Blobs g;
    const uint32_t k = g.add(m, [](double x, double y, double z) {
        return falloff(segment_d2(x, y, z, Vec3(-2.5f, 0, 0), Vec3(2.5f, 0, 0)), 1.4, 2) +
               falloff(segment_d2(x, y, z, Vec3(0, 0, -2.5f), Vec3(0, 0.5f, 2.5f)), 1.4, 2) +
               sphere_field(x, y, z, Vec3(0, 1, 0), 0.9, -4) +
               sphere_field(x, y, z, Vec3(1.5f, -1, 1), 1.2, 1);
    });
    check_against_reference(g, k, 41, 600);
}

TEST(Blob, ComponentsCarryTheirOwnTransforms) {
    // A sphere squashed into an ellipsoid, and a cylinder turned and stretched.
    BlobModel m;
    m.threshold = 0.3f;
    add_blob_sphere(m, Vec3(0), 1, 1,
                    Affine::translate(Vec3(0.3f, 0, 0)) * Affine::scale(Vec3(1.5f, 0.6f, 1)));
    const Affine turn = Affine::rotate(Vec3(0, 0, 1), 0.5f) * Affine::scale(Vec3(1, 2, 1));
    add_blob_cylinder(m, Vec3(0, -0.5f, 0), Vec3(0, 0.5f, 0), 0.5f, 1.5f, turn);
    const Affine inv = turn.inverse();
    Blobs g;
    const uint32_t k = g.add(m, [inv](double x, double y, double z) {
        const double ex = (x - 0.3) / 1.5, ey = y / 0.6, ez = z;
        const Vec3 p = inv.point(Vec3(float(x), float(y), float(z)));
        return falloff(ex * ex + ey * ey + ez * ez, 1, 1) +
               falloff(segment_d2(p.x, p.y, p.z, Vec3(0, -0.5f, 0), Vec3(0, 0.5f, 0)), 0.5, 1.5);
    });
    check_against_reference(g, k, 42, 600);
}

TEST(Blob, ManyComponentsOnARayKeepTheNearestExact) {
    // 100 separate spheres in a row: the ray along the row meets more than it follows; the
    // pieces it reports are exactly the nearest ones.
    BlobModel m;
    m.threshold = 0.25f;
    for (int i = 0; i < 100; ++i) add_blob_sphere(m, Vec3(float(3 * i), 0, 0), 1, 1, Affine());
    Blobs g;
    const uint32_t k = g.add(m, [](double, double, double) { return 0.0; });
    Span sp[kMaxShapeSpans];
    const int n =
        shape_spans(blob_shape(k), ray_from(Vec3(-5, 0, 0), Vec3(1, 0, 0)), sp, g.tables());
    ASSERT_EQ(n, kMaxShapeSpans);
    const float r = std::sqrt(1 - 0.5f);
    for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(sp[i].t0, 5 + 3 * i - r, 1e-4f);
        EXPECT_NEAR(sp[i].t1, 5 + 3 * i + r, 1e-4f);
    }
    // From the far end, the ray meets them in the opposite order.
    const int back =
        shape_spans(blob_shape(k), ray_from(Vec3(305, 0, 0), Vec3(-1, 0, 0)), sp, g.tables());
    ASSERT_EQ(back, kMaxShapeSpans);
    EXPECT_NEAR(sp[0].t0, 8 - r, 1e-4f);
}

TEST(Blob, RaysAlongACapsulesAxisAndThroughItsEndPlanes) {
    BlobModel m;
    m.threshold = 0.4f;
    add_blob_cylinder(m, Vec3(0, 0, 0), Vec3(0, 0, 2), 1, 1, Affine());
    Blobs g;
    const uint32_t k = g.add(m, [](double x, double y, double z) {
        return falloff(segment_d2(x, y, z, Vec3(0, 0, 0), Vec3(0, 0, 2)), 1, 1);
    });
    const double r = std::sqrt(1 - std::sqrt(0.4));
    Span sp[kMaxShapeSpans];
    // Along the axis: from the bottom cap's pole to the top one's.
    ASSERT_EQ(shape_spans(blob_shape(k), ray_from(Vec3(0, 0, -3), Vec3(0, 0, 1)), sp, g.tables()),
              1);
    EXPECT_NEAR(sp[0].t0, 3 - r, 1e-5f);
    EXPECT_NEAR(sp[0].t1, 5 + r, 1e-5f);
    // Level rays in the end planes and between them, and rays through the planes' circles.
    std::mt19937 rng(7);
    int i = 0;
    for (float z : {0.0f, 1.0f, 2.0f}) {
        ASSERT_EQ(
            shape_spans(blob_shape(k), ray_from(Vec3(-3, 0.1f, z), Vec3(1, 0, 0)), sp, g.tables()),
            1);
        const double half = std::sqrt(r * r - 0.01);
        EXPECT_NEAR(sp[0].t0, 3 - half, 1e-5f);
        EXPECT_NEAR(sp[0].t1, 3 + half, 1e-5f);
        for (int j = 0; j < 100; ++j, ++i) {
            const Vec3 d = test::random_unit(rng);
            const float a = float(j) * 0.0628f;
            const Vec3 on(float(r) * std::cos(a), float(r) * std::sin(a), z);
            ASSERT_GE(check_ray(g, k, ray_from(on - d * 4.0f, d), i), 0);
        }
    }
}

TEST(Blob, BoundHoldsThePositiveComponents) {
    BlobModel m;
    add_blob_sphere(m, Vec3(-2, 0, 0), 1, 1, Affine());
    add_blob_sphere(m, Vec3(2, 0, 0), 1, 1, Affine());
    add_blob_sphere(m, Vec3(0, 9, 0), 1, -1, Affine()); // negative: cannot be inside
    float b[4];
    blob_bound(m, b);
    EXPECT_NEAR(b[0], 0, 1e-6f);
    EXPECT_NEAR(b[1], 0, 1e-6f);
    EXPECT_NEAR(b[3], 3, 1e-3f);
    BlobModel none;
    add_blob_sphere(none, Vec3(0), 1, -1, Affine());
    blob_bound(none, b);
    EXPECT_EQ(b[3], 0);
}

TEST(Blob, BadComponentsAreErrors) {
    BlobModel m;
    EXPECT_THROW(add_blob_sphere(m, Vec3(0), 0, 1, Affine()), BlobError);
    EXPECT_THROW(add_blob_sphere(m, Vec3(0), -1, 1, Affine()), BlobError);
    EXPECT_THROW(add_blob_sphere(m, Vec3(0), 1, NAN, Affine()), BlobError);
    EXPECT_THROW(add_blob_cylinder(m, Vec3(0), Vec3(INFINITY, 0, 0), 1, 1, Affine()), BlobError);
    EXPECT_THROW(add_blob_sphere(m, Vec3(0), 1, 1, Affine::scale(Vec3(1, 0, 1))), BlobError);
    EXPECT_TRUE(m.elements.empty());
    add_blob_cylinder(m, Vec3(1), Vec3(1), 1, 1, Affine()); // no length: a sphere
    ASSERT_EQ(m.elements.size(), 1u);
    EXPECT_EQ(m.elements[0].len, 0);
}

} // namespace
} // namespace sheaf

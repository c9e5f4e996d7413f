// Analytic objects in the pipeline: CSG spans against point membership, conservative bounds,
// and the invariant of the core: brute, rah and crsh give the same picture with analytic
// shapes, CSG and an unbounded plane in the scene.
#include "core/scene/analytic.h"

#include "core/backend/backend.h"
#include "core/scenes/shapes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace sheaf {
namespace {

Affine place(Vec3 t, float s) {
    return Affine::translate(t) * Affine::scale(Vec3(s));
}

// A ray from a random point within `from` of the origin towards one within `to` of it.
Ray random_ray(std::mt19937& g, float from, float to) {
    std::uniform_real_distribution<float> u(-1, 1);
    Ray r;
    r.origin = Vec3(u(g), u(g), u(g)) * from;
    r.dir = normalize(Vec3(u(g), u(g), u(g)) * to - r.origin);
    r.tmin = 0, r.tmax = 1e30f;
    return r;
}

// A sphere minus a box, intersected with a slab, plus a torus: one object.
ShapeObject csg_object(uint32_t m0, uint32_t m1) {
    ShapeObject o;
    o.name = "csg";
    o.nodes.resize(6);
    o.nodes[0].op = CsgOp::Merge, o.nodes[0].children = {1, 5};
    o.nodes[1].op = CsgOp::Difference, o.nodes[1].children = {2, 3, 4};
    o.nodes[2].shape = {ShapeKind::Sphere}, o.nodes[2].material = m0,
    o.nodes[2].transform = place(Vec3(0.0f), 1.0f);
    o.nodes[3].shape = {ShapeKind::Box}, o.nodes[3].material = m1,
    o.nodes[3].transform = place(Vec3(0.6f, 0.6f, 0.6f), 0.5f);
    o.nodes[4].shape = {ShapeKind::Cylinder}, o.nodes[4].material = m1,
    o.nodes[4].transform = Affine::translate(Vec3(0, 0, -2)) * Affine::scale(Vec3(0.3f, 0.3f, 4));
    o.nodes[5].shape = {ShapeKind::Torus, 0.15f}, o.nodes[5].material = m0,
    o.nodes[5].transform = Affine::rotate(Vec3(1, 0, 0), 0.5f) * Affine::scale(Vec3(1.4f));
    o.transform = Affine::translate(Vec3(0, 0.2f, 0));
    return o;
}

bool inside_csg(Vec3 p) {
    p = p - Vec3(0, 0.2f, 0);
    const bool sphere = length(p) < 1;
    const Vec3 b = (p - Vec3(0.6f)) / 0.5f;
    const bool box = std::fabs(b.x) < 1 && std::fabs(b.y) < 1 && std::fabs(b.z) < 1;
    const bool cyl = p.x * p.x + p.y * p.y < 0.09f && p.z > -2 && p.z < 2;
    const Vec3 q = Affine::rotate(Vec3(1, 0, 0), -0.5f).point(p) / 1.4f;
    const float ring = std::sqrt(q.x * q.x + q.y * q.y) - 1;
    const bool torus = ring * ring + q.z * q.z < 0.15f * 0.15f;
    return (sphere && !box && !cyl) || torus;
}

PreparedScene csg_scene() {
    Scene s;
    Material red, blue, floor;
    red.color = Vec3(0.9f, 0.2f, 0.2f), red.specular = 0.4f;
    blue.color = Vec3(0.2f, 0.3f, 0.9f), blue.mirror = 0.3f;
    floor.color = Vec3(0.7f);
    const uint32_t m0 = s.add_material(red), m1 = s.add_material(blue), mf = s.add_material(floor);
    s.add_shape_object(csg_object(m0, m1));
    // An unbounded floor plane (z <= 0 rotated to y <= -1.2), a glass sphere, a cone, a disc.
    s.add_shape("floor", {ShapeKind::Plane}, mf,
                Affine::translate(Vec3(0, -1.2f, 0)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2));
    Material glass;
    glass.transmission = 0.9f, glass.ior = 1.5f, glass.diffuse = 0.1f;
    s.add_shape("glass", {ShapeKind::Sphere}, s.add_material(glass),
                place(Vec3(1.8f, -0.5f, 0.8f), 0.6f));
    s.add_shape("cone", {ShapeKind::Cone, 0.5f, 0.0f}, m1,
                Affine::translate(Vec3(-1.8f, -1.2f, 0)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2));
    s.add_shape("disc", {ShapeKind::Disc, 0.3f}, m0,
                Affine::translate(Vec3(0, 0.5f, -2)) * Affine::scale(Vec3(0.8f)));
    s.add_mesh_object("box", make_box(Vec3(-3.4f, -1.2f, -2.0f), Vec3(-2.6f, -0.4f, -1.2f)), mf);
    s.add_light(Light{Vec3(3, 5, 4), Vec3(0.9f)});
    s.camera.position = Vec3(0.5f, 1.5f, 6), s.camera.look_at = Vec3(0, 0, 0);
    s.background = Vec3(0.1f, 0.1f, 0.2f);
    return prepare_scene(s);
}

TEST(Analytic, CsgSpansMatchMembership) {
    const PreparedScene scene = csg_scene();
    std::mt19937 g(3);
    int hits = 0;
    for (int k = 0; k < 300; ++k) {
        const Ray r = random_ray(g, 4.0f, 0.8f);
        const SpanList spans = csg_spans(scene, scene.analytic_root[0], r);
        hits += spans.n > 0;
        for (float t = 0; t < 8; t += 0.005f) {
            const Vec3 p = ray_at(r, t);
            bool in = false, near = false;
            for (int i = 0; i < spans.n; ++i) {
                in |= t >= spans.s[i].a.t && t <= spans.s[i].b.t;
                near |=
                    std::fabs(t - spans.s[i].a.t) < 2e-3f || std::fabs(t - spans.s[i].b.t) < 2e-3f;
            }
            if (!near) ASSERT_EQ(in, inside_csg(p)) << "ray " << k << " t " << t;
        }
        // The first hit is the first span end, with a unit normal facing out of the solid.
        AnalyticHit h;
        if (analytic_first_hit(scene, 0, r, h)) {
            EXPECT_NEAR(length(h.normal), 1.0f, 1e-4f);
            EXPECT_FALSE(inside_csg(ray_at(r, h.t) + h.normal * 1e-3f));
        }
    }
    EXPECT_GT(hits, 50);
}

// The nodes' boxes only skip what has no spans: with every box made infinite (nothing
// skipped), random rays give the very same spans, on a tree of many small members.
TEST(Analytic, NodeBoxesSkipOnlyWhatTheLineMisses) {
    Scene s;
    const uint32_t m = s.add_material(Material{});
    ShapeObject o;
    o.name = "many";
    o.nodes.resize(1);
    o.nodes[0].op = CsgOp::Union;
    std::mt19937 g(5);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 12; ++i) { // a union of differences of a box and a sphere, or spheres
        const uint32_t at = uint32_t(o.nodes.size());
        o.nodes[0].children.push_back(at);
        const Vec3 c(u(g) * 2, u(g) * 2, u(g) * 2);
        if (i % 2 == 0) {
            o.nodes.resize(at + 3);
            o.nodes[at].op = i % 4 == 0 ? CsgOp::Difference : CsgOp::Intersection;
            o.nodes[at].children = {at + 1, at + 2};
            o.nodes[at + 1].shape = {ShapeKind::Box}, o.nodes[at + 1].material = m;
            o.nodes[at + 1].transform = place(c, 0.3f);
            o.nodes[at + 2].shape = {ShapeKind::Sphere}, o.nodes[at + 2].material = m;
            o.nodes[at + 2].transform = place(c + Vec3(0.2f, 0, 0), 0.35f);
            o.nodes[at + 2].inverse = i % 3 == 0;
        } else {
            o.nodes.resize(at + 1);
            o.nodes[at].shape = {ShapeKind::Sphere}, o.nodes[at].material = m;
            o.nodes[at].transform = place(c, 0.25f);
        }
    }
    s.add_shape_object(o);
    s.add_shape_object(csg_object(m, m));
    const PreparedScene boxed = prepare_scene(s);
    PreparedScene open = boxed;
    int skipped = 0;
    for (PreparedCsgNode& n : open.csg) {
        skipped += std::isfinite(n.box.lo.x);
        n.box = WorldBox();
    }
    EXPECT_GT(skipped, 20); // the members have finite boxes
    int hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const Ray r = random_ray(g, 5.0f, 2.0f);
        for (uint32_t a = 0; a < boxed.analytic_root.size(); ++a)
            for (bool solid : {false, true}) {
                const SpanList want = csg_spans(open, open.analytic_root[a], r, solid);
                const SpanList got = csg_spans(boxed, boxed.analytic_root[a], r, solid);
                ASSERT_EQ(got.n, want.n) << "ray " << k << " object " << a;
                for (int i = 0; i < got.n; ++i) {
                    ASSERT_EQ(got.s[i].a.t, want.s[i].a.t) << "ray " << k;
                    ASSERT_EQ(got.s[i].b.t, want.s[i].b.t) << "ray " << k;
                    ASSERT_EQ(got.s[i].a.leaf, want.s[i].a.leaf) << "ray " << k;
                    ASSERT_EQ(got.s[i].b.leaf, want.s[i].b.leaf) << "ray " << k;
                }
                hits += got.n > 0;
            }
    }
    EXPECT_GT(hits, 500);
}

// Every hit of random rays lies in the object's sphere and in its box (csg_box).
void expect_bounds_hold(const PreparedScene& scene, const std::string& what) {
    std::mt19937 g(4);
    ASSERT_EQ(scene.analytic_box.size(), scene.analytic_root.size());
    for (uint32_t a = 0; a < scene.analytic_root.size(); ++a) {
        const Sphere& s = scene.prim_sphere[scene.tris.size() + a];
        const WorldBox& b = scene.analytic_box[a];
        int hits = 0;
        for (int k = 0; k < 4000; ++k) {
            const Ray r = random_ray(g, 5.0f, 2.0f);
            AnalyticHit h;
            if (!analytic_first_hit(scene, a, r, h)) continue;
            ++hits;
            const Vec3 p = ray_at(r, h.t);
            if (std::isfinite(s.radius))
                ASSERT_LE(length(p - s.center), s.radius) << what << " object " << a;
            // The hit point is rounded to its own magnitude (far along a plane: large).
            const float e = 1e-6f * (std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z) + 1);
            ASSERT_TRUE(p.x >= b.lo.x - e && p.y >= b.lo.y - e && p.z >= b.lo.z - e &&
                        p.x <= b.hi.x + e && p.y <= b.hi.y + e && p.z <= b.hi.z + e)
                << what << " object " << a << ": hit outside its box";
        }
        if (std::isfinite(s.radius)) EXPECT_GT(hits, 0) << what << " object " << a;
    }
}

TEST(Analytic, BoundsHoldEveryHit) {
    const PreparedScene scene = csg_scene();
    expect_bounds_hold(scene, "csg");
    // Every kind with a box of its own, turned and stretched.
    Scene kinds;
    const uint32_t m = kinds.add_material(Material{});
    const Affine turn = Affine::rotate(normalize(Vec3(1, 2, 3)), 0.7f);
    const Shape shapes[] = {{ShapeKind::Sphere},
                            {ShapeKind::Box},
                            {ShapeKind::Cylinder},
                            {ShapeKind::Cone, 0.3f, 1.0f},
                            {ShapeKind::Disc, 0.2f},
                            {ShapeKind::Torus, 0.3f},
                            {ShapeKind::Superellipsoid, 0.5f, 0.5f}};
    for (size_t i = 0; i < std::size(shapes); ++i)
        kinds.add_shape("kind", shapes[i], m,
                        Affine::translate(Vec3(float(i) - 3, 0, 0)) * turn *
                            Affine::scale(Vec3(0.4f, 0.7f, 0.3f)));
    // A cube as the intersection of six planes along the axes: its box is finite though its
    // sphere is not (chess2.pov's pieces).
    ShapeObject cube;
    cube.name = "planes";
    cube.nodes.resize(7);
    cube.nodes[0].op = CsgOp::Intersection, cube.nodes[0].children = {1, 2, 3, 4, 5, 6};
    const Affine sides[6] = {
        Affine::translate(Vec3(1, 0, 0)) * Affine::rotate(Vec3(0, 1, 0), kPi / 2),
        Affine::translate(Vec3(-1, 0, 0)) * Affine::rotate(Vec3(0, 1, 0), -kPi / 2),
        Affine::translate(Vec3(0, 1, 0)) * Affine::rotate(Vec3(1, 0, 0), -kPi / 2),
        Affine::translate(Vec3(0, -1, 0)) * Affine::rotate(Vec3(1, 0, 0), kPi / 2),
        Affine::translate(Vec3(0, 0, 1)),
        Affine::translate(Vec3(0, 0, -1)) * Affine::rotate(Vec3(1, 0, 0), kPi)};
    for (int i = 0; i < 6; ++i)
        cube.nodes[size_t(i) + 1].shape = {ShapeKind::Plane},
                               cube.nodes[size_t(i) + 1].material = m,
                               cube.nodes[size_t(i) + 1].transform = sides[i];
    cube.transform = Affine::translate(Vec3(0, 3, 0)) * Affine::scale(Vec3(0.5f));
    kinds.add_shape_object(cube);
    const PreparedScene k = prepare_scene(kinds);
    expect_bounds_hold(k, "kinds");
    const WorldBox& planes = k.analytic_box.back();
    EXPECT_FALSE(std::isfinite(k.prim_sphere.back().radius));
    EXPECT_NEAR(planes.lo.x, -0.5f, 1e-3f);
    EXPECT_NEAR(planes.hi.y, 3.5f, 1e-3f);
    EXPECT_NEAR(planes.lo.z, -0.5f, 1e-3f);
    // A box's own box is tighter than the cube around its sphere.
    const WorldBox& box = k.analytic_box[1];
    const Sphere& sphere = k.prim_sphere[1];
    EXPECT_LT((box.hi.x - box.lo.x) * (box.hi.y - box.lo.y) * (box.hi.z - box.lo.z),
              0.5f * 8 * sphere.radius * sphere.radius * sphere.radius);
    // The plane is unbounded: a candidate for every ray.
    EXPECT_FALSE(std::isfinite(scene.prim_sphere[scene.tris.size() + 1].radius));
}

TEST(Analytic, AccelModesGiveIdenticalImagesWithShapesAndCsg) {
    const PreparedScene scene = csg_scene();
    auto render = [&](std::initializer_list<std::pair<const char*, const char*>> kv) {
        Settings st;
        st.set("width", "48"), st.set("height", "36"), st.set("ao.samples", "2");
        for (auto& [k, v] : kv) st.set(k, v);
        return render_frame(scene, RenderSettings::resolve(st));
    };
    const Frame brute = render({{"accel", "brute"}});
    const Frame rah = render({{"accel", "rah"}, {"cull.objects", "false"}});
    const Frame crsh = render({});
    const Frame h192 =
        render({{"hash.mode", "hash192"}, {"hierarchy.depth", "3"}, {"hierarchy.arity", "4"}});
    for (const Frame* f : {&rah, &crsh, &h192})
        EXPECT_EQ(std::memcmp(brute.rgba.data(), f->rgba.data(), brute.rgba.size() * 4), 0);
    EXPECT_GT(crsh.stats.get("rays.refraction"), 0);
    EXPECT_EQ(crsh.stats.get("scene.primitives"), 12.0 + 5.0);
    // Every analytic object shows up in the object-id pass.
    std::vector<int> seen(scene.object_count(), 0);
    for (uint32_t id : crsh.object_id)
        if (id != 0xFFFFFFFFu) seen[id] = 1;
    for (size_t o = 0; o < seen.size(); ++o)
        EXPECT_TRUE(seen[o]) << "object " << o << " not visible";
}

} // namespace
} // namespace sheaf

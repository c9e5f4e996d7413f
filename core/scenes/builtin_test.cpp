// Tests of the built-in scenes (sizes, object counts, lights, camera) and of the mesh builders
// they are made from (winding, normals, merging).
#include "core/scenes/builtin.h"

#include "core/base/error.h"
#include "core/scenes/shapes.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

struct Bounds {
    Vec3 lo{1e30f}, hi{-1e30f};
    bool contains(Vec3 p) const {
        return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y &&
               p.z <= hi.z;
    }
};

Bounds world_bounds(const Scene& s) {
    Bounds b;
    for (const Object& o : s.objects)
        for (Vec3 p : s.meshes[o.mesh].positions) {
            p = o.transform.point(p);
            b.lo = vmin(b.lo, p), b.hi = vmax(b.hi, p);
        }
    return b;
}

Vec3 corner(const Mesh& m, size_t tri, int k) {
    return m.positions[m.indices[3 * tri + k]];
}
Vec3 face_normal(const Mesh& m, size_t tri) {
    const Vec3 a = corner(m, tri, 0);
    return cross(corner(m, tri, 1) - a, corner(m, tri, 2) - a);
}
Vec3 centroid(const Mesh& m, size_t tri) {
    return (corner(m, tri, 0) + corner(m, tri, 1) + corner(m, tri, 2)) / 3.0f;
}

/// Every triangle's winding agrees with its vertex normals.
void expect_winding_matches_normals(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3 n = m.normals[m.indices[3 * t]] + m.normals[m.indices[3 * t + 1]] +
                       m.normals[m.indices[3 * t + 2]];
        EXPECT_GT(dot(face_normal(m, t), n), 0) << "triangle " << t;
    }
}

/// Every triangle of a mesh that is convex about `c` faces away from `c`.
void expect_outward(const Mesh& m, Vec3 c) {
    for (size_t t = 0; t < m.triangle_count(); ++t)
        EXPECT_GT(dot(face_normal(m, t), centroid(m, t) - c), 0) << "triangle " << t;
}

TEST(BuiltinScenes, NamesAndDefault) {
    const std::vector<std::string> expected{"cornell", "office", "colonnade"};
    EXPECT_EQ(builtin_scene_names(), expected);
    EXPECT_STREQ(default_builtin_scene(), "cornell");
}

TEST(BuiltinScenes, UnknownNameThrows) {
    try {
        make_builtin_scene("sponza");
        FAIL() << "no exception";
    } catch (const SceneError& e) {
        EXPECT_STREQ(
            e.what(),
            "unknown built-in scene 'sponza'; built-in scenes: cornell, office, colonnade");
    }
}

TEST(BuiltinScenes, EachBuildsAndValidates) {
    struct Expect {
        const char* name;
        size_t min_tris, max_tris;
    };
    for (const Expect& e : {Expect{"cornell", 750, 850}, Expect{"office", 35000, 37000},
                            Expect{"colonnade", 64000, 68000}}) {
        SCOPED_TRACE(e.name);
        const Scene s = make_builtin_scene(e.name);
        EXPECT_NO_THROW(s.validate());
        EXPECT_GE(s.triangle_count(), e.min_tris);
        EXPECT_LE(s.triangle_count(), e.max_tris);
        ASSERT_GE(s.lights.size(), 1u);
        const Bounds b = world_bounds(s);
        for (const Light& l : s.lights) EXPECT_TRUE(b.contains(l.position));
        EXPECT_TRUE(b.contains(s.camera.position));
        EXPECT_TRUE(b.contains(s.camera.look_at));
        EXPECT_GE(s.camera.fov_y_degrees, 45.0f);
        EXPECT_LE(s.camera.fov_y_degrees, 60.0f);
    }
}

TEST(BuiltinScenes, ObjectCounts) {
    const Scene cornell = make_builtin_scene("cornell");
    EXPECT_EQ(cornell.objects.size(), 7u);
    size_t mirrors = 0;
    for (const Object& o : cornell.objects) mirrors += cornell.materials[o.material].mirror >= 0.8f;
    EXPECT_EQ(mirrors, 6u);
    EXPECT_EQ(cornell.settings.at("trace.depth"), "2");
    for (const Material& m : cornell.materials) EXPECT_GT(m.mirror, 0.0f);

    EXPECT_GE(make_builtin_scene("office").objects.size(), 100u);
    const Scene colonnade = make_builtin_scene("colonnade");
    EXPECT_EQ(colonnade.objects.size(), 1u);
    EXPECT_EQ(colonnade.meshes.size(), 1u);
}

TEST(BuiltinScenes, AreDeterministic) {
    const Scene a = make_builtin_scene("office"), b = make_builtin_scene("office");
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        EXPECT_EQ(a.meshes[i].positions.size(), b.meshes[i].positions.size());
        EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
    }
}

TEST(Shapes, BoxIsClosedAndFacesOutward) {
    const Mesh box = make_box({-1, 0, 2}, {3, 1, 5});
    EXPECT_EQ(box.triangle_count(), 12u);
    expect_outward(box, {1, 0.5f, 3.5f});
    expect_winding_matches_normals(box);
    for (size_t t = 0; t < box.triangle_count(); ++t) {
        // Flat faces: all three vertex normals equal the face's.
        const Vec3 n = normalize(face_normal(box, t));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(dot(box.normals[box.indices[3 * t + k]], n), 1.0f, 1e-5f);
    }
}

TEST(Shapes, SphereVerticesLieOnIt) {
    const Vec3 c(1, 2, 3);
    const Mesh s = make_uv_sphere(c, 2.5f, 8, 12);
    EXPECT_EQ(s.triangle_count(), size_t(2 * 12 * (8 - 1)));
    for (size_t i = 0; i < s.positions.size(); ++i) {
        EXPECT_NEAR(length(s.positions[i] - c), 2.5f, 1e-5f);
        EXPECT_NEAR(dot(s.normals[i], normalize(s.positions[i] - c)), 1.0f, 1e-5f);
    }
    expect_outward(s, c);
    expect_winding_matches_normals(s);
}

TEST(Shapes, CylinderConeTorusLatheArchFaceOutward) {
    const Mesh cyl = make_cylinder({0, 0, 0}, {1, 2, 0.5f}, 0.3f, 16, true);
    EXPECT_EQ(cyl.triangle_count(), 64u);
    expect_outward(cyl, {0.5f, 1, 0.25f});
    expect_winding_matches_normals(cyl);

    const Mesh cone = make_cone({0, 0, 0}, {0, 0, -1}, 0.5f, 0.0f, 12, true);
    EXPECT_EQ(cone.triangle_count(), 24u);
    expect_outward(cone, {0, 0, -0.3f});
    expect_winding_matches_normals(cone);

    const Mesh torus = make_torus({0, 1, 0}, {0, 1, 0}, 2.0f, 0.5f, 16, 8);
    EXPECT_EQ(torus.triangle_count(), 256u);
    expect_winding_matches_normals(torus);
    for (size_t t = 0; t < torus.triangle_count(); ++t) {
        // Outward from the tube's centre line.
        Vec3 p = centroid(torus, t) - Vec3(0, 1, 0);
        const Vec3 ring = normalize(Vec3(p.x, 0, p.z)) * 2.0f;
        EXPECT_GT(dot(face_normal(torus, t), p - ring), 0);
    }

    const Mesh lathe = make_lathe({0, 0, 0}, {0, 1, 0}, {{0.3f, 0}, {0.5f, 0.5f}, {0.2f, 1}}, 10);
    EXPECT_EQ(lathe.triangle_count(), 40u);
    expect_winding_matches_normals(lathe);

    const Mesh arch = make_arch({0, 0, 0}, 1.5f, 2.0f, 2.2f, 0.6f, 24);
    EXPECT_EQ(arch.triangle_count(), size_t(6 * 24 + 10));
    expect_winding_matches_normals(arch);
    for (Vec3 p : arch.positions) {
        EXPECT_GE(length(Vec3(p.x, p.y, 0)), 1.5f - 1e-4f);
        EXPECT_LE(std::fabs(p.x), 2.0f + 1e-5f);
        EXPECT_LE(p.y, 2.2f + 1e-5f);
        EXPECT_GE(p.y, 0.0f);
    }
}

TEST(Shapes, QuadNormalFollowsEdges) {
    const Mesh q = make_quad({0, 0, 0}, {0, 0, 2}, {3, 0, 0}, 3, 2);
    EXPECT_EQ(q.triangle_count(), 12u);
    for (size_t t = 0; t < q.triangle_count(); ++t) EXPECT_GT(face_normal(q, t).y, 0);
    expect_winding_matches_normals(q);
}

TEST(Shapes, AppendMeshOffsetsIndicesAndTransforms) {
    Mesh dst = make_box({0, 0, 0}, {1, 1, 1});
    const Mesh src = make_box({0, 0, 0}, {1, 1, 1});
    const size_t before = dst.positions.size();
    append_mesh(dst, src, Affine::translate({5, 0, 0}));
    EXPECT_EQ(dst.triangle_count(), 24u);
    EXPECT_EQ(dst.normals.size(), dst.positions.size());
    for (size_t i = 0; i < src.indices.size(); ++i)
        EXPECT_EQ(dst.indices[src.indices.size() + i], src.indices[i] + before);
    for (size_t i = 0; i < src.positions.size(); ++i)
        EXPECT_EQ(dst.positions[before + i], src.positions[i] + Vec3(5, 0, 0));

    // A mirroring transform keeps the faces outward and the normals consistent.
    Mesh mirrored;
    append_mesh(mirrored, src, Affine::scale({-1, 1, 1}));
    expect_outward(mirrored, {-0.5f, 0.5f, 0.5f});
    expect_winding_matches_normals(mirrored);

    // Rotated normals follow the rotation.
    Mesh turned;
    append_mesh(turned, make_quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                Affine::rotate({0, 1, 0}, 0.5f * kPi));
    EXPECT_NEAR(turned.normals[0].x, 1.0f, 1e-5f);
    expect_winding_matches_normals(turned);
}

} // namespace
} // namespace sheaf

// Subdivision through OpenSubdiv: the counts of a subdivided cube per level, points on the limit
// surface (a cube corner's limit is known in closed form), creases keeping the surface sharper,
// Loop on a triangle cage, normals and texture coordinates, and bad cages as errors.
#include "io/subdiv/subdivide.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sheaf {
namespace {

using io::SubdivCage;
using io::SubdivOptions;
using io::SubdivScheme;

/// The cube [-1, 1]^3 as six quads facing outwards.
SubdivCage cube() {
    SubdivCage c;
    for (int i = 0; i < 8; ++i)
        c.positions.push_back(Vec3(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f));
    c.face_sizes.assign(6, 4);
    c.face_indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
    return c;
}

/// The regular octahedron, eight triangles facing outwards.
SubdivCage octahedron() {
    SubdivCage c;
    c.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    c.face_sizes.assign(8, 3);
    c.face_indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    return c;
}

Mesh run(const SubdivCage& cage, int level, bool limit = false,
         SubdivScheme scheme = SubdivScheme::CatmullClark) {
    SubdivOptions o;
    o.level = level, o.limit = limit, o.scheme = scheme;
    return io::subdivide(cage, o);
}

/// The vertex farthest along (1, 1, 1): the refined image of the cube's corner (1, 1, 1).
Vec3 corner(const Mesh& m) {
    Vec3 best = m.positions[0];
    for (const Vec3& p : m.positions)
        if (p.x + p.y + p.z > best.x + best.y + best.z) best = p;
    return best;
}

std::string error_of(const SubdivCage& cage, const SubdivOptions& o) {
    try {
        io::subdivide(cage, o, "cage 'test'");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Subdivide, CubeCountsPerLevel) {
    const size_t vertices[] = {8, 26, 98, 386}, quads[] = {6, 24, 96, 384};
    for (int level = 0; level <= 3; ++level) {
        const Mesh m = run(cube(), level);
        EXPECT_EQ(m.positions.size(), vertices[level]) << "level " << level;
        EXPECT_EQ(m.triangle_count(), 2 * quads[level]) << "level " << level;
        EXPECT_EQ(io::subdivided_face_count(cube().face_sizes, SubdivScheme::CatmullClark, level),
                  quads[level]);
    }
}

TEST(Subdivide, CornersConvergeToTheKnownLimit) {
    // Catmull-Clark's limit mask at a vertex of valence n is (n^2 v + 4 sum(edge neighbours) +
    // sum(diagonal neighbours)) / (n (n + 5)); at a cube corner (n = 3) it gives (1/2, 1/2, 1/2).
    const Vec3 limit(0.5f, 0.5f, 0.5f);
    float previous = 1e9f;
    for (int level = 1; level <= 5; ++level) {
        const float d = length(corner(run(cube(), level)) - limit);
        EXPECT_LT(d, previous) << "level " << level;
        previous = d;
        // Projected to the limit surface, the corner is there at every level.
        EXPECT_LT(length(corner(run(cube(), level, true)) - limit), 1e-5f) << "level " << level;
    }
    EXPECT_LT(previous, 0.01f);
}

TEST(Subdivide, LimitPointsLieOnTheSurfaceOfFinerLevels) {
    // Every limit point at level 2 is a point of the limit surface; level 6's refined points lie
    // within a small distance of it, so each limit point has a level-6 point very near.
    const Mesh coarse = run(cube(), 2, true), fine = run(cube(), 6);
    for (const Vec3& p : coarse.positions) {
        float nearest = 1e9f;
        for (const Vec3& q : fine.positions) nearest = std::min(nearest, length(p - q));
        EXPECT_LT(nearest, 2e-3f) << p.x << " " << p.y << " " << p.z;
    }
    // The refined (unprojected) level-2 points are farther off than the projected ones.
    const Mesh refined = run(cube(), 2);
    EXPECT_GT(length(corner(refined) - Vec3(0.5f)), length(corner(coarse) - Vec3(0.5f)) + 0.01f);
}

TEST(Subdivide, CreasesKeepEdgesSharp) {
    SubdivCage creased = cube();
    // The three edges at the corner (1, 1, 1) = vertex 7: to 3, 5 and 6.
    creased.crease_edges = {7, 3, 7, 5, 7, 6};
    creased.crease_sharpness = {10, 10, 10}; // infinitely sharp: a corner that stays put
    EXPECT_LT(length(corner(run(creased, 3, true)) - Vec3(1, 1, 1)), 1e-5f);
    // A finite sharpness: sharper than smooth, rounder than infinitely sharp.
    creased.crease_sharpness = {1, 1, 1};
    const float smooth = length(corner(run(cube(), 3, true))),
                semi = length(corner(run(creased, 3, true)));
    EXPECT_GT(semi, smooth + 0.05f);
    EXPECT_LT(semi, std::sqrt(3.0f) - 0.01f);
}

TEST(Subdivide, NormalsAreSmoothUnitAndOutward) {
    for (bool limit : {false, true}) {
        const Mesh m = run(cube(), 3, limit);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        for (size_t i = 0; i < m.positions.size(); ++i) {
            EXPECT_NEAR(length(m.normals[i]), 1.0f, 1e-4f);
            EXPECT_GT(dot(m.normals[i], normalize(m.positions[i])), 0.5f);
        }
        // Triangles wind the way the cage's faces do: outwards.
        for (size_t t = 0; t < m.triangle_count(); ++t) {
            const Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                       c = m.positions[m.indices[3 * t + 2]];
            EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0);
        }
    }
}

TEST(Subdivide, LoopRefinesTriangles) {
    // Loop: 4^level triangles per triangle; V - E + F = 2 for the closed octahedron.
    for (int level = 0; level <= 3; ++level) {
        const Mesh m = run(octahedron(), level, level > 0, SubdivScheme::Loop);
        const size_t faces = size_t(8) << (2 * level);
        EXPECT_EQ(m.triangle_count(), faces);
        EXPECT_EQ(m.positions.size(), 2 + faces / 2); // E = 3F/2, V = 2 + E - F
    }
    // Loop's limit mask at a vertex of valence n weighs it 1 - n chi and each neighbour chi,
    // chi = 1 / (3 / (8 beta) + n), beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. The
    // octahedron's vertex (1, 0, 0) has four neighbours summing to 0: its limit is
    // (1 - 4 chi, 0, 0) at every level.
    const double beta = (5.0 / 8 - std::pow(3.0 / 8 + std::cos(2 * M_PI / 4) / 4, 2)) / 4;
    const double chi = 1 / (3 / (8 * beta) + 4);
    for (int level = 1; level <= 3; ++level) {
        float x = -1;
        for (const Vec3& p : run(octahedron(), level, true, SubdivScheme::Loop).positions)
            x = std::max(x, p.x);
        EXPECT_NEAR(x, 1 - 4 * chi, 1e-5) << "level " << level;
    }
}

TEST(Subdivide, TextureCoordinatesAreRefined) {
    SubdivCage c = cube();
    for (const Vec3& p : c.positions)
        c.uvs.insert(c.uvs.end(), {0.5f + 0.5f * p.x, 0.5f + 0.5f * p.y});
    const Mesh m = run(c, 2);
    ASSERT_EQ(m.uvs.size(), 2 * m.positions.size());
    for (float v : m.uvs) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }
}

TEST(Subdivide, BoundaryRules) {
    // One quad: edge-only rounds its corners, edge-and-corner keeps them.
    SubdivCage quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.face_sizes = {4};
    quad.face_indices = {0, 1, 2, 3};
    SubdivOptions o;
    o.level = 3;
    o.limit = true;
    auto nearest_to_origin = [](const Mesh& m) {
        float d = 1e9f;
        for (const Vec3& p : m.positions) d = std::min(d, length(p));
        return d;
    };
    EXPECT_GT(nearest_to_origin(io::subdivide(quad, o)), 0.05f);
    o.boundary = io::SubdivBoundary::EdgeAndCorner;
    EXPECT_LT(nearest_to_origin(io::subdivide(quad, o)), 1e-5f);
}

TEST(Subdivide, BadCagesAreErrors) {
    SubdivOptions o;
    o.level = 2;
    auto expect_error = [&](const SubdivCage& c, const SubdivOptions& opt,
                            const std::string& what) {
        const std::string e = error_of(c, opt);
        EXPECT_NE(e.find("cage 'test'"), std::string::npos) << e;
        EXPECT_NE(e.find(what), std::string::npos) << e;
    };
    SubdivCage c = cube();
    c.positions[3].y = NAN;
    expect_error(c, o, "vertex 3 is not finite");
    c = cube();
    c.face_indices[5] = 8;
    expect_error(c, o, "names vertex 8, out of range");
    c = cube();
    c.face_indices[1] = c.face_indices[0];
    expect_error(c, o, "twice");
    c = cube();
    c.face_sizes[0] = 2, c.face_sizes[1] = 6;
    expect_error(c, o, "face 0 has 2 vertices");
    c = cube();
    c.face_indices.pop_back();
    expect_error(c, o, "vertex indices");
    c = cube();
    c.face_sizes.clear(), c.face_indices.clear();
    expect_error(c, o, "no faces");
    c = cube();
    c.crease_edges = {0, 7};
    c.crease_sharpness = {2};
    expect_error(c, o, "not an edge of the cage");
    c.crease_edges = {0, 1};
    c.crease_sharpness = {-1};
    expect_error(c, o, "sharpness");
    c = cube();
    c.uvs = {0, 0};
    expect_error(c, o, "two per vertex");

    SubdivOptions loop = o;
    loop.scheme = SubdivScheme::Loop;
    expect_error(cube(), loop, "Loop subdivision needs a cage of triangles");
    SubdivOptions deep = o;
    deep.level = 9;
    expect_error(cube(), deep, "level 9 is out of range");
    deep.level = -1;
    expect_error(cube(), deep, "out of range");
    SubdivOptions flat = o;
    flat.level = 0, flat.limit = true;
    expect_error(cube(), flat, "level 1 or more");
    // The face limit: 6 * 4 * 4^7 = 393216 faces at level 8 is fine, 100 cubes' worth is not.
    SubdivCage many;
    for (int k = 0; k < 100; ++k) {
        const SubdivCage one = cube();
        const uint32_t base = uint32_t(many.positions.size());
        for (Vec3 p : one.positions) many.positions.push_back(p + Vec3(3.0f * k, 0, 0));
        for (uint32_t i : one.face_indices) many.face_indices.push_back(base + i);
        many.face_sizes.insert(many.face_sizes.end(), one.face_sizes.begin(), one.face_sizes.end());
    }
    SubdivOptions level8 = o;
    level8.level = 8;
    expect_error(many, level8, "faces; at most");
}

} // namespace
} // namespace sheaf

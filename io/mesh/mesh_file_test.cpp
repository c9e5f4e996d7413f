// Mesh files through Assimp: OBJ, PLY (ASCII and binary) and glTF (.gltf, .glb) read back what
// was written (positions, normals, texture coordinates, node transforms), and bad files are
// errors that name the file and the problem.
#include "io/mesh/mesh_file.h"

#include "core/base/error.h"
#include "tests/support/mesh_test_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sheaf {
namespace {

using io::read_mesh_file;
using io::read_mesh_parts;

/// The index of the vertex at `p` (exactly), or -1.
int find_vertex(const Mesh& m, Vec3 p) {
    for (size_t i = 0; i < m.positions.size(); ++i)
        if (length(m.positions[i] - p) < 1e-6f) return int(i);
    return -1;
}

/// Checks the unit quad: four corners, two triangles facing +z, normals +z, (s, t) = corner.
void expect_quad(const Mesh& m, bool normals, bool uvs) {
    ASSERT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.triangle_count(), 2u);
    for (size_t t = 0; t < 2; ++t) {
        const Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                   c = m.positions[m.indices[3 * t + 2]];
        EXPECT_GT(cross(b - a, c - a).z, 0) << "triangle " << t << " turns the wrong way";
    }
    EXPECT_EQ(m.normals.empty(), !normals);
    for (const Vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    ASSERT_EQ(m.uvs.empty(), !uvs);
    if (uvs) {
        for (Vec3 corner : {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}) {
            const int v = find_vertex(m, corner);
            ASSERT_GE(v, 0);
            EXPECT_NEAR(m.uvs[2 * v], corner.x > 0 ? 1.0f : 0.0f, 1e-6f);
            EXPECT_NEAR(m.uvs[2 * v + 1], corner.y > 0 ? 1.0f : 0.0f, 1e-6f);
        }
    }
}

std::string error_of(const std::string& path) {
    try {
        read_mesh_file(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST(MeshFile, ObjRoundTrip) {
    const auto dir = test::temp_folder("obj");
    expect_quad(read_mesh_file(test::write_text(dir / "quad.obj", test::kQuadObj)), true, true);
    // Without normals and texture coordinates: none are made up.
    expect_quad(
        read_mesh_file(test::write_text(dir / "bare.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                                          "f 1 2 3\nf 1 3 4\n")),
        false, false);
}

TEST(MeshFile, PlyRoundTrip) {
    const auto dir = test::temp_folder("ply");
    expect_quad(read_mesh_file(test::write_text(dir / "quad.ply", test::kQuadPly)), true, true);
    expect_quad(read_mesh_file(test::write_binary_ply(dir / "binary.ply")), false, false);
}

TEST(MeshFile, GltfRoundTripWithNodeTransforms) {
    const auto dir = test::temp_folder("gltf");
    for (const std::string& path :
         {test::write_gltf(dir / "quad.gltf"), test::write_glb(dir / "quad.glb")}) {
        SCOPED_TRACE(path);
        const std::vector<io::MeshPart> parts = read_mesh_parts(path);
        ASSERT_EQ(parts.size(), 2u); // one mesh, placed by two nodes
        const io::MeshPart& up = parts[0].name == "up" ? parts[0] : parts[1];
        const io::MeshPart& big = parts[0].name == "up" ? parts[1] : parts[0];
        EXPECT_EQ(up.name, "up");
        EXPECT_EQ(big.name, "big");
        EXPECT_GE(find_vertex(up.mesh, Vec3(1, 3, 0)), 0) << "translation not applied";
        EXPECT_GE(find_vertex(big.mesh, Vec3(2, 2, 0)), 0) << "scale not applied";
        Mesh moved_back = up.mesh;
        for (Vec3& p : moved_back.positions) p.y -= 2;
        expect_quad(moved_back, true, true); // glTF's flipped t comes back as t up
        const Mesh merged = read_mesh_file(path);
        EXPECT_EQ(merged.positions.size(), 8u);
        EXPECT_EQ(merged.triangle_count(), 4u);
        EXPECT_EQ(merged.normals.size(), 8u);
        EXPECT_EQ(merged.uvs.size(), 16u);
    }
}

TEST(MeshFile, ExtensionsAreCaseInsensitive) {
    const auto dir = test::temp_folder("case");
    expect_quad(read_mesh_file(test::write_text(dir / "QUAD.OBJ", test::kQuadObj)), true, true);
    EXPECT_TRUE(io::is_mesh_file("a/b.GLB"));
    EXPECT_FALSE(io::is_mesh_file("a/b.stl"));
}

TEST(MeshFile, NonFiniteCoordinatesAreAnError) {
    const auto dir = test::temp_folder("nan");
    for (const char* bad : {"nan", "inf"}) {
        const std::string path =
            test::write_text(dir / (std::string(bad) + ".obj"),
                             "v 0 0 0\nv 1 0 0\nv 0 " + std::string(bad) + " 0\nf 1 2 3\n");
        const std::string e = error_of(path);
        EXPECT_NE(e.find(path), std::string::npos) << e;
        EXPECT_NE(e.find("not finite"), std::string::npos) << e;
    }
    const std::string ply = test::write_text(
        dir / "nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n");
    const std::string e = error_of(ply);
    EXPECT_NE(e.find(ply), std::string::npos) << e;
}

TEST(MeshFile, IndicesOutOfRangeAreAnError) {
    const auto dir = test::temp_folder("index");
    const std::string obj =
        test::write_text(dir / "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    std::string e = error_of(obj);
    EXPECT_NE(e.find(obj), std::string::npos) << e;
    const std::string ply = test::write_text(
        dir / "index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    e = error_of(ply);
    EXPECT_NE(e.find(ply), std::string::npos) << e;
}

TEST(MeshFile, NoFacesIsAnError) {
    const auto dir = test::temp_folder("nofaces");
    for (const char* text : {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "v 0 0 0\nv 1 0 0\nl 1 2\n", ""}) {
        const std::string path = test::write_text(dir / "empty.obj", text);
        const std::string e = error_of(path);
        EXPECT_NE(e.find(path), std::string::npos) << e;
        EXPECT_NE(e.find("no"), std::string::npos) << e;
    }
}

TEST(MeshFile, BadFilesAreErrorsNotCrashes) {
    const auto dir = test::temp_folder("bad");
    // A header that promises more elements than the file could hold.
    std::string e = error_of(test::write_text(
        dir / "huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                          "property float x\nproperty float y\nproperty float z\nend_header\n"));
    EXPECT_NE(e.find("more than the file can hold"), std::string::npos) << e;
    // A header cut short: Assimp alone would loop for ever.
    e = error_of(test::write_text(dir / "cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                                   "property float x\n"));
    EXPECT_NE(e.find("no end_header"), std::string::npos) << e;
    // A face of no vertices: Debian's Assimp asserts on it in Triangulate and aborts the
    // process (found by fuzz_ply).
    e = error_of(test::write_text(dir / "empty_face.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 2\n"
                                  "property list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0\n3 0 1 2\n"));
    EXPECT_NE(e.find("face 0 of mesh 0 has no vertices"), std::string::npos) << e;
    // A value that is not a number in an ASCII body: Assimp leaked what it had read and read
    // on (found by fuzz_ply under LeakSanitizer).
    e = error_of(test::write_text(dir / "word.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0x runtime_error\n0 1 0\n3 0 1 2\n"));
    EXPECT_NE(e.find("word.ply:11: a value of the PLY data is not a number"), std::string::npos)
        << e;
    // A header line Assimp does not know, or a format version that is not a number: it leaked.
    e = error_of(
        test::write_text(dir / "line.ply", "ply\nformat ascii 1.0\nprope x\nend_header\n"));
    EXPECT_NE(e.find("line.ply:3: not a line of a PLY header"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "version.ply", "ply\nformat ascii 1.0?\nend_header\n"));
    EXPECT_NE(e.find("version.ply:2: the PLY format line is not"), std::string::npos) << e;
    // A property without a name, or a second format line: Assimp freed what it had not
    // allocated (found by fuzz_ply under AddressSanitizer).
    e = error_of(test::write_text(dir / "prop.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float\n"
                                  "end_header\n0\n"));
    EXPECT_NE(e.find("prop.ply:4: a PLY property is"), std::string::npos) << e;
    // A NUL in a header line: Assimp read on past it and looped without end (found by
    // fuzz_ply: a timeout).
    e = error_of(test::write_text(
        dir / "nul.ply", std::string("ply\nformat ascii 1.0\ncomment x\0ver list undice\nend_header", 57)));
    EXPECT_NE(e.find("nul.ply:3: a NUL byte in the PLY header"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "twice.ply",
                                  "ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n"));
    EXPECT_NE(e.find("twice.ply:3: a PLY header has one format line"), std::string::npos) << e;
    // OBJ: a face naming a vertex that does not exist, in a second object: Assimp threw and
    // leaked the meshes it had built (found by fuzz_obj under LeakSanitizer). Indices are
    // checked first, with their place; so are the lines Assimp would count otherwise (a vertex
    // line short of numbers, which it completes from the next line; a NUL byte, where it
    // stops reading).
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    e = error_of(test::write_text(dir / "second.obj", tri + "o x\nf 24 1 2\n"));
    EXPECT_NE(e.find("second.obj:6:3: the vertex index 24 is out of range (the file has 3 "
                     "vertices)"),
              std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "back.obj", tri + "f -1 -2 -4\n"));
    EXPECT_NE(e.find("back.obj:5:9: the vertex index -4 reaches back before the first vertex"),
              std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "zero.obj", tri + "f 0 1 2\n"));
    EXPECT_NE(e.find("zero.obj:5:3: the vertex index 0 is not an index"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "uv.obj", tri + "vt 0 0\nf 1/1 2/2 3/2\n"));
    EXPECT_NE(e.find("uv.obj:6:7: the texture coordinate index 2 is out of range"),
              std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "line.obj", tri + "f 2 3\n"));
    EXPECT_NE(e.find("line.obj:5:1: a face has 3 corners or more, this one 2"), std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "point_line.obj", tri + "g a\nl 1\n"));
    EXPECT_NE(e.find("point_line.obj:6:1: a line has 2 points or more, this one 1"),
              std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "word.obj", tri + "f 1 2 x\n"));
    EXPECT_NE(e.find("word.obj:5:7: expected vertex indices"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "short.obj", "v 0 0 0\nv 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_NE(e.find("short.obj:2:1: a vertex is 3 numbers, 4 (w not 0) or 6 (a colour), not 1"),
              std::string::npos)
        << e;
    // Assimp counts no number that starts otherwise than with a digit, a sign, nan or inf.
    e = error_of(test::write_text(dir / "dot.obj", "v .5 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_NE(e.find("dot.obj:1:3: expected a number"), std::string::npos) << e;
    // A second index names a normal where no texture coordinate but a normal came before.
    e = error_of(test::write_text(dir / "asnormal.obj", tri + "vn 0 0 1\nf 1/1 2/1 3/2\n"));
    EXPECT_NE(e.find("asnormal.obj:6:11: the normal index 2 is out of range"), std::string::npos)
        << e;
    // What follows a backslash is the line before to Assimp: a vertex there is none.
    e = error_of(test::write_text(dir / "joined.obj", "g a\\\nv 0 0 0\n" + tri + "f 4 1 2\n"));
    EXPECT_NE(e.find("joined.obj:7:3: the vertex index 4 is out of range"), std::string::npos)
        << e;
    e = error_of(test::write_text(dir / "nul.obj", tri + std::string("v 0 \0 1\n", 8)));
    EXPECT_NE(e.find("nul.obj:5:5: a NUL byte"), std::string::npos) << e;
    // What Assimp reads as it is stays usable: indices relative and absolute, a normal index
    // without texture coordinates, texture indices in a file without any (ignored), comments.
    EXPECT_EQ(io::read_mesh_file(test::write_text(dir / "fine.obj",
                                                  "v 0 0 0 # a comment\nv 1 0 0 1\nv 0 1 0 "
                                                  "0.5 0.5 0.5\nvn 0 0 1\nf 1//1 -2//1 3//-1\n"
                                                  "  v 9 9 9\nvp 1 2\n"))
                  .indices.size(),
              3u);
    EXPECT_EQ(io::read_mesh_file(test::write_text(dir / "no_uv.obj", tri + "f 1/7 2/8 3/9\n"))
                  .indices.size(),
              6u);
    e = error_of(test::write_text(dir / "garbage.glb", std::string("glTF\x02\0\0\0\xff\xff", 10)));
    EXPECT_NE(e.find("garbage.glb"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "garbage.gltf", "{\"asset\": [1, 2"));
    EXPECT_NE(e.find("garbage.gltf"), std::string::npos) << e;
    std::string glb = test::write_glb(dir / "cut.glb");
    std::filesystem::resize_file(glb, 100);
    e = error_of(glb);
    EXPECT_NE(e.find("cut.glb"), std::string::npos) << e;
    e = error_of((dir / "missing.obj").string());
    EXPECT_NE(e.find("no such file"), std::string::npos) << e;
    e = error_of(test::write_text(dir / "model.stl", "solid x\nendsolid x\n"));
    EXPECT_NE(e.find("not a mesh file"), std::string::npos) << e;
}

TEST(MeshFile, PolygonCageKeepsFacesAndWeldsVertices) {
    const auto dir = test::temp_folder("cage");
    // A quad and a pentagon sharing an edge, written with separate vertices and normals.
    const std::string path =
        test::write_text(dir / "cage.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                           "v 1 0 0\nv 2 0 0\nv 2.5 0.5 0\nv 2 1 0\nv 1 1 0\n"
                                           "vn 0 0 1\n"
                                           "f 1//1 2//1 3//1 4//1\nf 5//1 6//1 7//1 8//1 9//1\n");
    const io::PolygonCage cage = io::read_polygon_cage(path);
    EXPECT_EQ(cage.positions.size(), 7u); // the shared edge's two vertices welded
    ASSERT_EQ(cage.face_sizes.size(), 2u);
    EXPECT_EQ(cage.face_sizes[0] + cage.face_sizes[1], 9u);
    EXPECT_EQ(cage.face_indices.size(), 9u);
}

} // namespace
} // namespace sheaf

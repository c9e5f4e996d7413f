// Mesh files through Assimp: OBJ, PLY and glTF 2 (.obj .ply .gltf .glb) as sheaf meshes.
// Every mesh of the file is placed by its nodes' transforms (a mesh used by two nodes appears
// twice), polygons are triangulated, points and lines dropped; positions, normals where the
// file has them and the first set of texture coordinates are kept. Bad data (non-finite
// coordinates, indices out of range, no faces) is a SceneError naming the file, never a crash.
#pragma once

#include "core/scene/scene.h"

#include <string>
#include <vector>

namespace sheaf::io {

/// One mesh of a file as placed by one node, in the file's world space.
struct MeshPart {
    std::string name; // the node's name, else the mesh's; may be empty
    Mesh mesh;
    bool has_color = false; // the file's material gives a diffuse (or base) colour
    Vec3 color{0.8f, 0.8f, 0.8f};
};

/// Reads every triangle mesh of the file. Throws SceneError "PATH: ..." for an unreadable or
/// malformed file, a mesh without faces, non-finite values, indices out of range, or more than
/// kMaxMeshFileTriangles triangles.
std::vector<MeshPart> read_mesh_parts(const std::string& path);

/// The file's meshes merged into one. Normals are kept when every part has them, texture
/// coordinates when any part has them (zero for the parts without).
Mesh read_mesh_file(const std::string& path);

/// Merges parts into one mesh, by the rules of read_mesh_file.
Mesh merge_mesh_parts(const std::vector<MeshPart>& parts);

/// A polygon cage for subdivision: the file's faces as they are (not triangulated), its meshes
/// merged and placed by their nodes, vertices welded where their positions are equal.
struct PolygonCage {
    std::vector<Vec3> positions;
    std::vector<uint32_t> face_sizes;   // vertices per face
    std::vector<uint32_t> face_indices; // the faces' vertices, concatenated
};

/// Reads a file's polygons as a cage (same formats and checks as read_mesh_parts).
PolygonCage read_polygon_cage(const std::string& path);

/// Whether the extension of `path` (case-insensitive) is one of mesh_file_extensions().
bool is_mesh_file(const std::string& path);
/// ".obj .ply .gltf .glb", for messages.
const char* mesh_file_extensions();

/// Bounds the memory a file can ask for (instancing can multiply a small file's triangles).
constexpr size_t kMaxMeshFileTriangles = size_t(1) << 25;

} // namespace sheaf::io

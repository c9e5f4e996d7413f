// A mesh camera's meshes (Scene::camera_meshes, Projection::Mesh) flattened for the ray kernel
// (core/shading/mesh_camera.h): every face in its mesh's space with what a ray leaving it
// needs, each mesh's transforms, and for distribution 3 a grid over uv space listing the first
// mesh's faces by cell, so a sample finds the face holding its (u, v) without a search.
#pragma once

#include "core/math/affine.h"

#include <cstdint>

namespace sheaf {

struct PreparedScene;
class Scene;

/// A face of a camera mesh, in the mesh's space. Degenerate faces (no area) are left out, as
/// POV-Ray leaves them out of its meshes, so the faces count as POV-Ray's do.
struct CameraFace {
    Vec3 a, b, c;     // the corners
    Vec3 n;           // the unit normal, normalize(cross(b - a, c - a)): where rays go
    Vec3 na, nb, nc;  // the corners' normals (zero when the mesh has none)
    float s[3], t[3]; // the corners' uv coordinates (zero when the mesh has none)
    uint32_t mesh;    // its mesh, in Scene::camera_meshes
};

/// A camera mesh: its faces [first, first + count) of the flattened faces, and its transforms.
struct CameraMeshRef {
    Affine to_world;
    Affine normal_to_world; // the inverse transpose of to_world's linear part
    uint32_t first = 0, count = 0;
};

/// Cells across and up the uv square of the distribution-3 grid.
constexpr uint32_t kCameraUvGrid = 32;

/// Fills p's camera faces, meshes and uv grid from scene.camera_meshes (none unless the
/// camera's projection is Mesh).
void prepare_camera_faces(const Scene& scene, PreparedScene& p);

} // namespace sheaf

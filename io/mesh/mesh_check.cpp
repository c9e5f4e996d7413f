// check_mesh: see mesh_check.h.
#include "io/mesh/mesh_check.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io {

void check_mesh(const Mesh& mesh, const std::string& what) {
    if (mesh.indices.empty()) throw SceneError(what + ": the mesh has no faces");
    if (mesh.indices.size() % 3 != 0)
        throw SceneError(what + ": " + std::to_string(mesh.indices.size()) +
                         " triangle indices are not a multiple of 3");
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (!is_finite(mesh.positions[i]))
            throw SceneError(what + ": vertex " + std::to_string(i) +
                             " is not finite (NaN or infinity)");
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
        throw SceneError(what + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                         std::to_string(mesh.positions.size()) + " vertices");
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        if (!is_finite(mesh.normals[i]))
            throw SceneError(what + ": normal " + std::to_string(i) +
                             " is not finite (NaN or infinity)");
    if (!mesh.uvs.empty() && mesh.uvs.size() != 2 * mesh.positions.size())
        throw SceneError(what + ": " + std::to_string(mesh.uvs.size() / 2) +
                         " texture coordinates for " + std::to_string(mesh.positions.size()) +
                         " vertices");
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i]))
            throw SceneError(what + ": the texture coordinate of vertex " + std::to_string(i / 2) +
                             " is not finite");
    for (size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.positions.size())
            throw SceneError(what + ": triangle " + std::to_string(i / 3) + " names vertex " +
                             std::to_string(mesh.indices[i]) + ", out of range (" +
                             std::to_string(mesh.positions.size()) + " vertices)");
}

} // namespace sheaf::io

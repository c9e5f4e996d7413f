// Checks of meshes that come from files or cages, before they reach the scene: finite
// coordinates, indices in range, at least one face. The message names where the mesh came from
// (a file, a cage) rather than a mesh number, which is what Scene::validate can say.
#pragma once

#include "core/scene/scene.h"

#include <string>

namespace sheaf::io {

/// Throws SceneError "WHAT: ..." naming the first vertex, normal, texture coordinate or index
/// that is wrong, or that the mesh has no faces.
void check_mesh(const Mesh& mesh, const std::string& what);

} // namespace sheaf::io

// A mesh file as a whole scene (`render model.obj`): one object per mesh the file places, each
// with a material of the file's diffuse colour, framed by the default camera and light.
#pragma once

#include "io/scene/scene_file.h"

#include <string>

namespace sheaf::io {

/// Reads `path` (.obj .ply .gltf .glb) into a scene. Throws SceneError naming the file.
SceneFile read_mesh_scene(const std::string& path, const SceneFileOptions& options);

} // namespace sheaf::io

// XML scene files (.xml, docs/xml-scene.md): every part of the core Scene — meshes inline or
// from mesh files, subdivision surfaces, analytic shapes and CSG, materials, image textures,
// procedural textures (pigments, normals, material switches), lights, the camera, the
// background or sky, fog and the scene's settings — read with pugixml and checked
// element by element. Errors are SceneError "FILE:LINE:COL: error: ..." naming what was found
// and what was expected; unknown elements and attributes are errors.
#pragma once

#include "io/scene/scene_file.h"

#include <string>

namespace sheaf::io {

/// Reads the scene file at `path`.
SceneFile read_xml_scene(const std::string& path, const SceneFileOptions& options = {});

/// Reads a scene from `text`; `path` names it in messages and anchors relative file names.
SceneFile parse_xml_scene(const std::string& text, const std::string& path);

} // namespace sheaf::io

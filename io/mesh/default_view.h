// A camera and a light for scenes that bring none (a bare mesh file): the camera looks at the
// centre of the meshes' bounds from the front, above and to the right, far enough that the
// bounding sphere fills the view; a white point light sits above and behind the camera's
// right shoulder.
#pragma once

#include "core/scene/scene.h"

namespace sheaf::io {

/// Sets scene.camera to frame every mesh object and adds one point light. A scene without
/// mesh objects keeps the default camera and still gets the light.
void add_default_view(Scene& scene);

} // namespace sheaf::io

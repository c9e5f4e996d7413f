// The built-in scenes, generated in code and shaped like paper 000's (section 4.2).
#pragma once

#include "core/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace sheaf {

/// "cornell", "office", "colonnade".
const std::vector<std::string>& builtin_scene_names();
/// The one `render` draws when given no scene.
const char* default_builtin_scene();
/// Throws SceneError naming the known scenes when `name` is not one of them.
Scene make_builtin_scene(std::string_view name);

} // namespace sheaf

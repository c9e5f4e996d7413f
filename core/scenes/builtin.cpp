// The built-in scenes' names and the dispatch from a name to the code that builds the scene.
#include "core/scenes/builtin.h"

#include "core/base/error.h"

namespace sheaf {

// Each is defined in its own file: builtin_cornell.cpp, builtin_office.cpp,
// builtin_colonnade.cpp.
namespace builtin_detail {
Scene make_cornell();
Scene make_office();
Scene make_colonnade();
} // namespace builtin_detail

const std::vector<std::string>& builtin_scene_names() {
    static const std::vector<std::string> names{"cornell", "office", "colonnade"};
    return names;
}

const char* default_builtin_scene() {
    return "cornell";
}

Scene make_builtin_scene(std::string_view name) {
    if (name == "cornell") return builtin_detail::make_cornell();
    if (name == "office") return builtin_detail::make_office();
    if (name == "colonnade") return builtin_detail::make_colonnade();
    std::string known;
    for (const std::string& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
    throw SceneError("unknown built-in scene '" + std::string(name) +
                     "'; built-in scenes: " + known);
}

} // namespace sheaf

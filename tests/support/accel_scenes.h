// The scenes the object-space structures are checked on (core/accel/): the built-in scenes and
// the shared test scenes (glass and mirrors, every light kind, CSG, a julia fractal, media,
// photons, procedural textures), prepared. Test code.
#pragma once

#include "core/scenes/builtin.h"
#include "tests/support/test_scenes.h"

#include <string>
#include <utility>
#include <vector>

namespace sheaf::test {

inline std::vector<std::pair<std::string, PreparedScene>> accel_scenes() {
    std::vector<std::pair<std::string, PreparedScene>> v;
    for (const std::string& name : builtin_scene_names())
        v.emplace_back(name, prepare_scene(make_builtin_scene(name)));
    v.emplace_back("glass_mirror", prepare_scene(glass_mirror_scene()));
    v.emplace_back("lights", prepare_scene(lights_scene(false)));
    v.emplace_back("csg", prepare_scene(csg_scene()));
    v.emplace_back("julia", prepare_scene(julia_scene()));
    v.emplace_back("media", prepare_scene(media_scene()));
    v.emplace_back("photons", prepare_scene(photon_scene()));
    v.emplace_back("procedural", prepare_scene(procedural_scene()));
    return v;
}

} // namespace sheaf::test

// For tests that render every sample scene: scenes/*.pov and *.xml, loaded and prepared in
// name order. On a machine without the source tree or POV-Ray's includes (the GPU kit,
// gpu/kit.sh), $SHEAF_SCENES_DIR and $SHEAF_POV_INCLUDE name copies.
#pragma once

#include "core/scene/prepared_scene.h"
#include "io/scene/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace sheaf::io {

/// fn(file name, prepared scene) for each sample scene, read at width x height; a scene that
/// does not load is a test failure.
template <class Fn>
void for_each_sample_scene(const std::string& default_dir, int width, int height, Fn fn) {
    SceneFileOptions options;
    options.image_width = width, options.image_height = height;
    const char* include_env = std::getenv("SHEAF_POV_INCLUDE");
    const std::string include =
        include_env && *include_env ? include_env : "/usr/share/povray-3.7/include";
    if (std::filesystem::exists(include)) options.include_paths.push_back(include);
    const char* dir_env = std::getenv("SHEAF_SCENES_DIR");
    const std::string dir = dir_env && *dir_env ? dir_env : default_dir;
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string ext = e.path().extension().string();
        if (ext == ".pov" || ext == ".xml") files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty()) << dir;
    for (const std::string& f : files) {
        PreparedScene scene;
        try {
            scene = prepare_scene(load_scene_file(f, options).scene);
        } catch (const std::exception& e) {
            ADD_FAILURE() << f << ": " << e.what();
            continue;
        }
        fn(std::filesystem::path(f).filename().string(), scene);
    }
}

} // namespace sheaf::io

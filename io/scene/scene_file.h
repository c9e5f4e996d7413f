// Scene files by extension: one entry point for every reader, so the C ABI, the CLI and the
// tests load "builtin:NAME", .pov and (as readers are added) other formats the same way.
#pragma once

#include "core/scene/scene.h"
#include "io/image/raster.h"
#include "io/image/texture_sampler.h"
#include "io/pov/animation.h"
#include "io/pov/limits.h"

#include <string>
#include <utility>
#include <vector>

namespace sheaf::io {

/// How a scene file is read. Readers use what applies to them.
struct SceneFileOptions {
    std::vector<std::string> include_paths; // POV-Ray #include folders, after the scene's own
    bool strict = false;                    // an unsupported feature is an error, not a warning
    int image_width = 512, image_height = 512; // the size the scene will be rendered at, for
                                               // scenes that ask (POV-Ray's image_width)
    RasterReader read_raster = nullptr;        // images a scene builds geometry from (POV-Ray's
                                               // height_field): io::read_raster, or none (an error)
    SamplerAttacher attach_sampler = nullptr;  // images of pigments the reader evaluates
                                               // (POV-Ray's pigment functions in the language):
                                               // io::attach_texture_sampler, or none (an error)
    pov::Animation animation; // the frame a POV-Ray scene is read for (its clock, frame_number)
    std::vector<std::pair<std::string, double>> declares; // POV-Ray's Declare=NAME=VALUE
    pov::PovLimits limits; // the POV-Ray reader's budgets of work and memory
};

struct SceneFile {
    Scene scene;
    /// "FILE:LINE:COL: warning: ..." lines: what was read but cannot be shown exactly.
    std::vector<std::string> warnings;
    /// What the reader used of its limits (the POV-Ray reader's; none for other formats).
    std::vector<pov::LimitUse> limits;
};

/// Reads `path`: "builtin:NAME", or a file whose extension picks the reader (.pov, .inc).
/// Throws SceneError naming the file (and the line and column where the reader knows them).
SceneFile load_scene_file(const std::string& path, const SceneFileOptions& options = {});

/// The extensions load_scene_file reads, e.g. ".pov .inc", for messages.
std::string scene_file_extensions();

} // namespace sheaf::io

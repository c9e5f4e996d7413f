// The POV-Ray 3.7 scene language reader: load_pov_scene parses a .pov file (with its
// #includes, macros, loops and declarations) into a sheaf::Scene. What the core cannot show
// is reported as a warning "FILE:LINE:COL: warning: unsupported ..." (an error when strict);
// syntax errors throw SceneError "FILE:LINE:COL: error: found 'TOKEN', expected ...".
// POV-Ray is left-handed and y-up; the scene is mirrored in z (see docs/pov.md) so that
// pictures are not mirrored.
#pragma once

#include "core/scene/scene.h"
#include "io/image/raster.h"
#include "io/image/texture_sampler.h"
#include "io/pov/animation.h"
#include "io/pov/limits.h"

#include <string>
#include <utility>
#include <vector>

namespace sheaf::io::pov {

struct PovOptions {
    std::vector<std::string> include_paths;    // searched after the including file's folder
    bool strict = false;                       // the first unsupported feature is an error
    int image_width = 512, image_height = 512; // what image_width and image_height give
    RasterReader read_raster = nullptr;        // height_field images (io::read_raster); without it,
                                               // a height field from an image is an error
    SamplerAttacher attach_sampler = nullptr;  // images of pigment functions the language
                                               // evaluates (io::attach_texture_sampler); without
                                               // it, such an image is an error
    Clock clock;                               // clock, frame_number ... (animation.h)
    std::vector<std::pair<std::string, double>> declares; // POV-Ray's Declare=NAME=VALUE: floats
                                                          // declared before the scene's first line
    PovLimits limits;
};

struct PovResult {
    sheaf::Scene scene;
    std::vector<std::string> warnings;
    double version = 3.7;     // the scene's #version (the last one), 3.7 when none
    double assumed_gamma = 1; // the gamma the colours were decoded with
    PovUsage usage;           // what the scene used of options.limits
};

/// Reads the scene at `path`. Throws SceneError on a syntax error, an #error directive, an
/// unreadable file, a limit exceeded (loops, recursion, memory), or in strict mode the first
/// unsupported feature.
PovResult load_pov_scene(const std::string& path, const PovOptions& options = {});

} // namespace sheaf::io::pov

// A rendered frame: the image, its passes and its statistics.
#pragma once

#include "core/math/vec3.h"
#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sheaf {

struct Frame {
    int width = 0, height = 0; // the image: the whole frame, or the region rendered (region.*)
    /// Where the image lies in the whole frame (full_width x full_height): its first column
    /// and row; 0, 0 and the image's size unless a region was rendered.
    int x = 0, y = 0, full_width = 0, full_height = 0;
    std::vector<float> rgba;  // scene-linear combined pass, 4 floats per pixel, top row first
    std::vector<float> depth; // camera distance of the primary hit, +inf where nothing was hit
    std::vector<Vec3> normal; // world-space shading normal of the primary hit
    std::vector<Vec3> albedo; // material colour of the primary hit
    std::vector<uint32_t> object_id; // object of the primary hit, 0xFFFFFFFF for none
    std::vector<uint32_t> tests;     // exact ray-primitive tests of the pixel's secondary rays
    Stats stats;
    /// Effective settings the frame was rendered with (key, canonical value).
    std::vector<std::pair<std::string, std::string>> settings;
    /// Where the frame was computed: "cpu" or "cuda" (empty before render_frame sets it).
    std::string backend;
    /// The same in one line, with why: "backend: cpu (no CUDA device: cudaErrorNoDevice: ...)".
    std::string backend_line;
};

/// Whether `f` holds the pass named `pass` (one of pass_names()) for every pixel: a frame
/// keeps only the passes output.passes names.
bool frame_has_pass(const Frame& f, std::string_view pass);
/// Why `f` lacks `pass`, in a sentence that names the setting: "the frame has no 'depth' pass
/// (output.passes=combined)".
std::string missing_pass(const Frame& f, std::string_view pass);

} // namespace sheaf

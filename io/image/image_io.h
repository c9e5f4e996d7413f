// Image files, the format chosen by the extension: PNG through libpng (io/image/png_write.h),
// the others through OpenImageIO (the image module, io/image/image_module.h):
//  - .png .jpg .jpeg .tif .tiff: 8 bits per channel, display-referred through OpenColorIO
//    (the frame's output.display / output.view / output.look / output.ocio_config settings);
//  - .exr: scene-linear RGBA (half or float: output.exr) plus every pass as named channels:
//    Z (depth), N.X N.Y N.Z (normal), albedo.R/G/B, object_id, tests;
//  - .hdr: float scene-linear RGB.
// The effective settings ("sheaf:settings") and the statistics as JSON ("sheaf:stats") go into
// the file's metadata where the format can hold them.
#pragma once

#include "core/frame/frame.h"
#include "io/color/color.h"

#include <string>
#include <utility>
#include <vector>

namespace sheaf {

/// Writes the frame (combined, and the passes where the format holds them) to `path`.
/// Throws RenderError naming the path for an unknown extension or a failed write.
void write_image(const Frame& frame, const std::string& path);

/// Reads back a frame that write_image wrote as OpenEXR with output.exr=float: every pass it
/// holds, its place in the whole frame (the data window), its settings and statistics (the
/// file's sheaf:settings and sheaf:stats). Throws RenderError naming the path when the file
/// cannot be read, is not such a frame, or holds half floats (not the frame's values).
Frame read_frame_image(const std::string& path);

/// Writes one pass as an 8-bit false-colour picture: depth as grey (near is bright), normal as
/// 0.5 + 0.5 n, albedo through the display transform, object ids as distinct colours, test
/// counts as a heat map (log scale). "combined" is the display-referred image.
void write_pass_image(const Frame& frame, const std::string& pass, const std::string& path);

/// Writes `channels` floats per pixel (1: grey, 2: grey+alpha, 3: RGB, 4: RGBA) to `path`.
/// 8-bit formats get the display transform when `display_referred`, else are clamped as they
/// are; float formats are written as given. `metadata` becomes string attributes.
void write_pixels(const std::string& path, int width, int height, int channels, const float* pixels,
                  bool display_referred, const io::DisplayOptions& display,
                  const std::vector<std::pair<std::string, std::string>>& metadata = {});

/// The display options a frame's settings ask for.
io::DisplayOptions display_options(const Frame& frame);

/// The sRGB transfer function (linear -> display-encoded), not clamped.
float srgb_encode(float linear);

/// Whether write_image knows the extension of `path` (case-insensitive).
bool is_supported_image_path(const std::string& path);

} // namespace sheaf

// Image files: writes a rendered frame through OpenImageIO, the format chosen by the extension.
#pragma once

#include "core/render/frame.h"

#include <string>

namespace sheaf {

/// Writes the combined pass of `frame` to `path`:
///  - .png .jpg .jpeg .tif .tiff: 8 bits per channel, display-referred (sRGB transfer function,
///    clamped to [0, 1], alpha 1);
///  - .exr: half-float scene-linear RGBA;
///  - .hdr: float scene-linear RGB.
/// The effective settings ("sheaf:settings") and the statistics as JSON ("sheaf:stats") go into
/// the file's metadata where the format can hold them.
/// Throws RenderError naming the path for an unknown extension or a failed write.
void write_image(const Frame& frame, const std::string& path);

/// The sRGB transfer function (linear -> display-encoded), not clamped.
float srgb_encode(float linear);

/// Whether write_image knows the extension of `path` (case-insensitive).
bool is_supported_image_path(const std::string& path);

} // namespace sheaf

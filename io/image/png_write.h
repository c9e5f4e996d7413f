// 8-bit PNG files written with libpng directly: PNG is the default output, and writing it
// through OpenImageIO meant loading OpenImageIO's ~250 libraries (0.4 s) for every picture.
// The other formats, and every image read, go through the image module
// (io/image/image_module_abi.h).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sheaf::io {

/// Writes `width` x `height` pixels of `channels` bytes each (1 grey, 2 grey + alpha, 3 RGB,
/// 4 RGBA), top row first, as `path`. `srgb`: the values are display-encoded sRGB (an sRGB
/// chunk), else linear (gAMA 1.0). `text`: key/value pairs as tEXt chunks (keys of 1 to 79
/// Latin-1 characters). Throws RenderError("<path>: cannot write image: ...").
void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels, bool srgb,
               const std::vector<std::pair<std::string, std::string>>& text);

} // namespace sheaf::io

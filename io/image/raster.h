// Reading an image's pixels for the scene readers (a POV-Ray height field's heights).
// The reader is passed to them as a function pointer in their options rather than called
// directly, so that a program may read scenes without reading images: libsheaf and the tests
// pass &read_raster (which loads the image module, and OpenImageIO with it, at the first image:
// io/image/image_module_abi.h); programs that carry no image module (the GPU kit's) pass
// none, and a scene asking for an image is then an error at the file's position.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sheaf::io {

/// An image's pixels as floats, row by row from the top, `channels` per pixel (at most 3).
struct Raster {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
    /// An 8-bit palette PNG: `pixels` holds its palette indices / 255 in one channel (as
    /// POV-Ray reads such files), not the colours the palette gives.
    bool indexed = false;
};

/// Reads `path` through the image module (OpenImageIO; palette PNGs through libpng, for their
/// indices).
/// Throws RenderError("cannot read ...") for an unreadable file, and for one of more than
/// `max_pixels` pixels or less than 2 x 2, before reading its pixels.
Raster read_raster(const std::string& path, size_t max_pixels);

/// What scene readers are given: read_raster, or nullptr where images are not read.
using RasterReader = Raster (*)(const std::string& path, size_t max_pixels);

} // namespace sheaf::io

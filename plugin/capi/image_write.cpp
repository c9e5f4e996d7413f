// The C ABI's general image writer: any float buffer (1-4 channels) to an image file through
// io/image's write_pixels (OpenImageIO), the format chosen by the extension.
#include "capi_internal.h"

#include "core/base/error.h"
#include "io/image/image_io.h"

using namespace sheaf::capi;

extern "C" {

SHEAF_API SheafError sheafWriteImage(const char* path, int width, int height, int channels,
                                     const float* pixels, int display_referred) {
    return barrier([&] {
        const char* p = require(path, "path");
        if (width < 1 || height < 1)
            throw InvalidArgument("image size " + std::to_string(width) + "x" +
                                  std::to_string(height) + " is not positive");
        if (channels < 1 || channels > 4)
            throw InvalidArgument("channels is " + std::to_string(channels) +
                                  "; expected 1 (gray), 2 (gray, alpha), 3 (RGB) or 4 (RGBA)");
        require(pixels, "pixels");
        try {
            // The default display of the OpenColorIO config ($OCIO, else the shipped one: sRGB).
            sheaf::write_pixels(p, width, height, channels, pixels, display_referred != 0,
                                sheaf::io::DisplayOptions{});
        } catch (const sheaf::RenderError& e) {
            throw IoError(e.what());
        }
    });
}

} // extern "C"

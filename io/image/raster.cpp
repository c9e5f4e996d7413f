#include "io/image/raster.h"

#include "core/base/error.h"
#include "io/image/image_module.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>

namespace sheaf::io {

namespace {

/// The palette indices of an 8-bit palette PNG, row by row from the top (OpenImageIO expands
/// palettes to colours, and palettes often repeat colours); empty for any other file.
std::vector<uint8_t> png_indices(const std::string& path, int& w, int& h) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    png_byte sig[8];
    if (std::fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        std::fclose(f);
        return {};
    }
    std::vector<uint8_t> out;
    png_structp png = png_create_read_struct(
        PNG_LIBPNG_VER_STRING, nullptr, [](png_structp p, png_const_charp) { png_longjmp(p, 1); },
        [](png_structp, png_const_charp) {});
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (png && info && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, f);
        png_set_sig_bytes(png, 8);
        png_read_info(png, info);
        if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE &&
            png_get_bit_depth(png, info) == 8 &&
            png_get_interlace_type(png, info) == PNG_INTERLACE_NONE) {
            w = int(png_get_image_width(png, info)), h = int(png_get_image_height(png, info));
            out.resize(size_t(w) * size_t(h));
            for (int row = 0; row < h; ++row)
                png_read_row(png, &out[size_t(row) * size_t(w)], nullptr);
        }
    } else {
        out.clear(); // libpng reported an error: OpenImageIO's message is given instead
    }
    png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr);
    std::fclose(f);
    return out;
}

} // namespace

Raster read_raster(const std::string& path, size_t max_pixels) {
    ImageReader in(path);
    const SheafImageInfo& spec = in.info();
    Raster r;
    r.width = spec.width, r.height = spec.height;
    if (r.width < 2 || r.height < 2 || spec.channels < 1 ||
        size_t(r.width) * size_t(r.height) > max_pixels)
        throw RenderError("an image of " + std::to_string(r.width) + " x " +
                          std::to_string(r.height) + " pixels, where at least 2 x 2 and at most " +
                          std::to_string(max_pixels) + " pixels are read");
    const size_t n = size_t(r.width) * size_t(r.height);
    int pw = 0, ph = 0;
    std::vector<uint8_t> indices = png_indices(path, pw, ph);
    if (!indices.empty() && pw == r.width && ph == r.height) {
        r.indexed = true;
        r.channels = 1;
        r.pixels.resize(n);
        for (size_t i = 0; i < n; ++i) r.pixels[i] = float(indices[i]) / 255.0f;
        return r;
    }
    r.channels = std::min(spec.channels, 3);
    r.pixels = in.read(r.channels);
    return r;
}

} // namespace sheaf::io

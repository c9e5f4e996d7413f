#include "io/image/png_write.h"

#include "core/base/error.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace sheaf::io {

namespace {

struct PngFailure {
    char message[512] = "";
};

void on_error(png_structp png, png_const_charp message) {
    auto* f = static_cast<PngFailure*>(png_get_error_ptr(png));
    std::snprintf(f->message, sizeof f->message, "%s", message ? message : "libpng failed");
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

/// The libpng calls, in a function of plain data only: libpng reports errors by longjmp.
bool encode(std::FILE* file, int width, int height, int channels, const uint8_t* pixels,
            bool srgb, png_text* text, int text_count, PngFailure& failure) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, on_error, on_warning);
    if (!png) {
        std::snprintf(failure.message, sizeof failure.message, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return false;
    }
    static const int kColourType[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                      PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8,
                 kColourType[channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (srgb)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    else
        png_set_gAMA(png, info, 1.0);
    if (text_count > 0) png_set_text(png, info, text, text_count);
    png_write_info(png, info);
    const size_t stride = size_t(width) * size_t(channels);
    for (int row = 0; row < height; ++row)
        png_write_row(png, pixels + size_t(row) * stride);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

} // namespace

void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels, bool srgb,
               const std::vector<std::pair<std::string, std::string>>& text) {
    const std::string where = path + ": cannot write image: ";
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 ||
        pixels.size() != size_t(width) * size_t(height) * size_t(channels))
        throw RenderError(where + "no " + std::to_string(width) + "x" + std::to_string(height) +
                          " image of " + std::to_string(channels) + " channels to write");
    std::vector<png_text> chunks;
    for (const auto& [key, value] : text) {
        if (key.empty() || key.size() > 79)
            throw RenderError(where + "the text key '" + key + "' is not 1 to 79 characters");
        png_text t{};
        t.compression = PNG_TEXT_COMPRESSION_NONE;
        t.key = const_cast<char*>(key.c_str());
        t.text = const_cast<char*>(value.c_str());
        t.text_length = value.size();
        chunks.push_back(t);
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw RenderError(where + std::strerror(errno));
    PngFailure failure;
    const bool ok = encode(file, width, height, channels, pixels.data(), srgb, chunks.data(),
                           int(chunks.size()), failure);
    const bool closed = std::fclose(file) == 0;
    if (!ok) throw RenderError(where + failure.message);
    if (!closed) throw RenderError(where + std::strerror(errno));
}

} // namespace sheaf::io

// Image files through OpenImageIO: 8-bit display-referred or float scene-linear by extension.
#include "io/image/image_io.h"

#include "core/base/error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>

namespace sheaf {

namespace {

enum class Encoding { Display8, Half, Float };

struct Format {
    const char* extension;
    Encoding encoding;
    int channels;
};

constexpr Format kFormats[] = {
    {".png", Encoding::Display8, 4},  {".jpg", Encoding::Display8, 3},
    {".jpeg", Encoding::Display8, 3}, {".tif", Encoding::Display8, 4},
    {".tiff", Encoding::Display8, 4}, {".exr", Encoding::Half, 4},
    {".hdr", Encoding::Float, 3},
};

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

const Format* find_format(const std::string& path) {
    const std::string ext = lower_extension(path);
    for (const Format& f : kFormats)
        if (ext == f.extension) return &f;
    return nullptr;
}

std::string known_extensions() {
    std::string out;
    for (const Format& f : kFormats) out += (out.empty() ? "" : ", ") + std::string(f.extension);
    return out;
}

std::string settings_text(const Frame& frame) {
    std::string out;
    for (const auto& [key, value] : frame.settings)
        out += (out.empty() ? "" : " ") + key + "=" + value;
    return out;
}

uint8_t to_display8(float linear) {
    float v = srgb_encode(linear);
    if (!(v > 0.0f)) v = 0.0f; // also NaN
    if (v > 1.0f) v = 1.0f;
    return uint8_t(std::lround(v * 255.0f));
}

} // namespace

float srgb_encode(float linear) {
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

bool is_supported_image_path(const std::string& path) {
    return find_format(path) != nullptr;
}

void write_image(const Frame& frame, const std::string& path) {
    const Format* format = find_format(path);
    if (!format) {
        const std::string ext = lower_extension(path);
        throw RenderError(path + ": unknown image format '" + ext +
                          "'; known: " + known_extensions());
    }
    const int w = frame.width, h = frame.height;
    const size_t pixels = size_t(std::max(w, 0)) * size_t(std::max(h, 0));
    if (w <= 0 || h <= 0 || frame.rgba.size() < pixels * 4)
        throw RenderError(path + ": the frame holds no image to write");

    const int nc = format->channels;
    OIIO::TypeDesc file_type = format->encoding == Encoding::Display8 ? OIIO::TypeDesc::UINT8
                               : format->encoding == Encoding::Half   ? OIIO::TypeDesc::HALF
                                                                      : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(w, h, nc, file_type);
    spec.attribute("Software", "Sheaf");
    spec.attribute("sheaf:settings", settings_text(frame));
    spec.attribute("sheaf:stats", frame.stats.to_json());
    if (format->encoding == Encoding::Display8)
        spec.attribute("oiio:ColorSpace", "sRGB");
    else
        spec.attribute("oiio:ColorSpace", "Linear");

    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw RenderError(path + ": cannot write image: " + OIIO::geterror());
    if (!out->open(path, spec))
        throw RenderError(path + ": cannot write image: " + out->geterror());

    bool ok = false;
    if (format->encoding == Encoding::Display8) {
        std::vector<uint8_t> data(pixels * size_t(nc));
        for (size_t p = 0; p < pixels; ++p) {
            for (int c = 0; c < 3; ++c) data[p * nc + c] = to_display8(frame.rgba[p * 4 + c]);
            if (nc == 4) data[p * nc + 3] = 255; // display images are opaque
        }
        ok = out->write_image(OIIO::TypeDesc::UINT8, data.data());
    } else if (nc == 4) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, frame.rgba.data());
    } else {
        // Radiance RGBE holds neither negative nor non-finite values.
        std::vector<float> data(pixels * size_t(nc));
        for (size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < nc; ++c) {
                const float v = frame.rgba[p * 4 + c];
                data[p * nc + c] = std::isfinite(v) && v > 0.0f ? v : 0.0f;
            }
        ok = out->write_image(OIIO::TypeDesc::FLOAT, data.data());
    }
    if (!ok) {
        const std::string message = out->geterror();
        out->close();
        throw RenderError(path + ": cannot write image: " + message);
    }
    if (!out->close()) throw RenderError(path + ": cannot write image: " + out->geterror());
}

} // namespace sheaf

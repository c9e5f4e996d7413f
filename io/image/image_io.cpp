// Image files by extension: 8-bit display-referred or float scene-linear; PNG through libpng,
// the others through OpenImageIO (the image module, loaded at the first such image).
#include "io/image/image_io.h"

#include "core/base/error.h"
#include "io/image/image_module.h"
#include "io/image/png_write.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>

namespace sheaf {

namespace {

enum class Encoding { Display8, Half, Float };

struct Format {
    const char* extension;
    Encoding encoding;
    int max_channels; // jpeg has no alpha; Radiance HDR holds RGB only
    bool libpng;      // written with libpng, not through the image module (OpenImageIO)
};

constexpr Format kFormats[] = {
    {".png", Encoding::Display8, 4, true},   {".jpg", Encoding::Display8, 3, false},
    {".jpeg", Encoding::Display8, 3, false}, {".tif", Encoding::Display8, 4, false},
    {".tiff", Encoding::Display8, 4, false}, {".exr", Encoding::Half, 4, false},
    {".hdr", Encoding::Float, 3, false},
};

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

const Format& format_of(const std::string& path) {
    const std::string ext = lower_extension(path);
    for (const Format& f : kFormats)
        if (ext == f.extension) return f;
    std::string known;
    for (const Format& f : kFormats)
        known += (known.empty() ? "" : ", ") + std::string(f.extension);
    throw RenderError(path + ": unknown image format '" + ext + "'; known: " + known);
}

std::string setting(const Frame& frame, const char* key) {
    for (const auto& [k, v] : frame.settings)
        if (k == key) return v;
    return {};
}

std::vector<std::pair<std::string, std::string>> frame_metadata(const Frame& frame) {
    std::string settings;
    for (const auto& [key, value] : frame.settings)
        settings += (settings.empty() ? "" : " ") + key + "=" + value;
    return {{"sheaf:settings", settings}, {"sheaf:stats", frame.stats.to_json()}};
}

/// The frame's pixels, when it holds `pass` to write.
size_t pixel_count(const Frame& frame, const std::string& path,
                   const std::string& pass = "combined") {
    const size_t pixels = size_t(std::max(frame.width, 0)) * size_t(std::max(frame.height, 0));
    if (frame.width <= 0 || frame.height <= 0)
        throw RenderError(path + ": the frame holds no image to write");
    if (!frame_has_pass(frame, pass)) throw RenderError(path + ": " + missing_pass(frame, pass));
    return pixels;
}

// The multi-channel OpenEXR: combined plus every pass, each channel named.
void write_exr(const Frame& frame, const std::string& path) {
    const size_t pixels = pixel_count(frame, path);
    const bool half = setting(frame, "output.exr") != "float";
    std::vector<std::string> names = {"R", "G", "B", "A"};
    std::vector<int> formats(4, half ? SHEAF_PIXEL_HALF : SHEAF_PIXEL_FLOAT);
    std::vector<std::function<float(size_t)>> get = {
        [&](size_t p) { return frame.rgba[4 * p]; },
        [&](size_t p) { return frame.rgba[4 * p + 1]; },
        [&](size_t p) { return frame.rgba[4 * p + 2]; },
        [&](size_t p) { return frame.rgba[4 * p + 3]; }};
    auto add = [&](const char* name, std::function<float(size_t)> f, size_t have) {
        if (have < pixels) return; // a frame without this pass
        names.push_back(name);
        formats.push_back(SHEAF_PIXEL_FLOAT);
        get.push_back(std::move(f));
    };
    add(
        "Z", [&](size_t p) { return frame.depth[p]; }, frame.depth.size());
    add(
        "N.X", [&](size_t p) { return frame.normal[p].x; }, frame.normal.size());
    add(
        "N.Y", [&](size_t p) { return frame.normal[p].y; }, frame.normal.size());
    add(
        "N.Z", [&](size_t p) { return frame.normal[p].z; }, frame.normal.size());
    add(
        "albedo.R", [&](size_t p) { return frame.albedo[p].x; }, frame.albedo.size());
    add(
        "albedo.G", [&](size_t p) { return frame.albedo[p].y; }, frame.albedo.size());
    add(
        "albedo.B", [&](size_t p) { return frame.albedo[p].z; }, frame.albedo.size());
    add(
        "object_id",
        [&](size_t p) {
            return frame.object_id[p] == 0xFFFFFFFFu ? -1.0f : float(frame.object_id[p]);
        },
        frame.object_id.size());
    add(
        "tests", [&](size_t p) { return float(frame.tests[p]); }, frame.tests.size());

    const int nc = int(names.size());
    std::vector<float> data(pixels * size_t(nc));
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < nc; ++c) data[p * nc + c] = get[size_t(c)](p);
    io::ImageToWrite im;
    im.path = path;
    im.width = frame.width, im.height = frame.height, im.channels = nc;
    if (frame.full_width > 0 && frame.full_height > 0) { // a part's place: the data window
        im.x = frame.x, im.y = frame.y;
        im.full_width = frame.full_width, im.full_height = frame.full_height;
    }
    im.channel_names = names;
    im.types = formats;
    im.alpha_channel = 3;
    im.z_channel = names.size() > 4 && names[4] == "Z" ? 4 : -1;
    im.attributes = {{"Software", "Sheaf"}, {"oiio:ColorSpace", "Linear"}, {"compression", "zip"}};
    for (const auto& kv : frame_metadata(frame)) im.attributes.push_back(kv);
    im.pixels = data.data();
    io::encode_image(im);
}

// A colour for each object id, far apart for neighbouring ids.
Vec3 id_colour(uint32_t id) {
    if (id == 0xFFFFFFFFu) return Vec3(0.0f);
    uint32_t h = id * 2654435761u;
    h ^= h >> 15;
    return Vec3(0.25f + 0.75f * float(h & 0xFF) / 255.0f,
                0.25f + 0.75f * float((h >> 8) & 0xFF) / 255.0f,
                0.25f + 0.75f * float((h >> 16) & 0xFF) / 255.0f);
}

// A perceptually ordered heat map (dark blue -> teal -> yellow -> red) of x in [0, 1].
Vec3 heat(float x) {
    static const Vec3 stops[] = {{0.05f, 0.03f, 0.25f},
                                 {0.1f, 0.45f, 0.55f},
                                 {0.55f, 0.8f, 0.3f},
                                 {0.98f, 0.85f, 0.2f},
                                 {0.85f, 0.15f, 0.1f}};
    x = std::fmin(1.0f, std::fmax(0.0f, x)) * 4.0f;
    const int i = std::min(3, int(x));
    const float f = x - float(i);
    return stops[i] * (1 - f) + stops[i + 1] * f;
}

} // namespace

float srgb_encode(float linear) {
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

bool is_supported_image_path(const std::string& path) {
    const std::string ext = lower_extension(path);
    return std::any_of(std::begin(kFormats), std::end(kFormats),
                       [&](const Format& f) { return ext == f.extension; });
}

io::DisplayOptions display_options(const Frame& frame) {
    return {setting(frame, "output.ocio_config"), setting(frame, "output.display"),
            setting(frame, "output.view"), setting(frame, "output.look")};
}

void write_pixels(const std::string& path, int w, int h, int channels, const float* pixels,
                  bool display_referred, const io::DisplayOptions& display,
                  const std::vector<std::pair<std::string, std::string>>& metadata) {
    const Format& format = format_of(path);
    if (w <= 0 || h <= 0 || channels < 1 || channels > 4 || !pixels)
        throw RenderError(path + ": nothing to write (" + std::to_string(w) + "x" +
                          std::to_string(h) + ", " + std::to_string(channels) + " channels)");
    const size_t n = size_t(w) * size_t(h);
    const bool colour_in = channels >= 3, alpha_in = channels == 2 || channels == 4;
    // RGBA working copy: grey expands to RGB.
    std::vector<float> rgba(n * 4);
    for (size_t p = 0; p < n; ++p) {
        const float* src = pixels + p * size_t(channels);
        for (int c = 0; c < 3; ++c) rgba[4 * p + c] = colour_in ? src[c] : src[0];
        rgba[4 * p + 3] = alpha_in ? src[channels - 1] : 1.0f;
    }
    const bool eight = format.encoding == Encoding::Display8;
    if (eight && display_referred) io::apply_display_transform(rgba.data(), n, display);
    // Layout in the file: grey stays grey where the format allows, alpha where it fits.
    const int colour_out = (colour_in || format.max_channels == 3) ? 3 : 1;
    const int nc = std::min(format.max_channels, colour_out + (alpha_in ? 1 : 0));
    const int type = eight                               ? SHEAF_PIXEL_UINT8
                     : format.encoding == Encoding::Half ? SHEAF_PIXEL_HALF
                                                         : SHEAF_PIXEL_FLOAT;
    // A channel's value as the file holds it: clamped where the format cannot hold more, and
    // for 8-bit files the byte's value (0..255).
    const auto value = [&](size_t p, int c) {
        float v = c < colour_out ? rgba[4 * p + c] : rgba[4 * p + 3];
        if (eight || format.encoding == Encoding::Float)
            v = std::isfinite(v) && v > 0 ? v : 0.0f;
        return eight ? std::round(std::fmin(v, 1.0f) * 255.0f) : v;
    };
    const size_t count = n * size_t(nc);
    if (format.libpng) { // no OpenImageIO to load for the default output
        std::vector<uint8_t> bytes(count);
        for (size_t i = 0; i < count; ++i) bytes[i] = uint8_t(value(i / nc, int(i % nc)));
        std::vector<std::pair<std::string, std::string>> text = {{"Software", "Sheaf"}};
        text.insert(text.end(), metadata.begin(), metadata.end());
        return io::write_png(path, w, h, nc, bytes, display_referred, text);
    }
    std::vector<float> data(count);
    for (size_t i = 0; i < count; ++i) {
        const float v = value(i / nc, int(i % nc));
        data[i] = eight ? v / 255.0f : v; // OpenImageIO converts to 8 bits exactly
    }
    io::ImageToWrite im;
    im.path = path;
    im.width = w, im.height = h, im.channels = nc;
    im.types.assign(size_t(nc), type);
    im.attributes = {{"Software", "Sheaf"},
                     {"oiio:ColorSpace", eight && display_referred ? "sRGB" : "Linear"}};
    for (const auto& kv : metadata) im.attributes.push_back(kv);
    im.pixels = data.data();
    io::encode_image(im);
}

void write_image(const Frame& frame, const std::string& path) {
    const Format& format = format_of(path);
    if (format.encoding == Encoding::Half) return write_exr(frame, path);
    const size_t pixels = pixel_count(frame, path);
    // Display images are opaque; scene-linear ones keep the alpha.
    std::vector<float> rgba(frame.rgba.begin(), frame.rgba.begin() + long(pixels * 4));
    if (format.encoding == Encoding::Display8)
        for (size_t p = 0; p < pixels; ++p) rgba[4 * p + 3] = 1.0f;
    write_pixels(path, frame.width, frame.height, 4, rgba.data(), true, display_options(frame),
                 frame_metadata(frame));
}

void write_pass_image(const Frame& frame, const std::string& pass, const std::string& path) {
    const auto& known = pass_names();
    if (std::find(known.begin(), known.end(), pass) == known.end()) {
        std::string names;
        for (const auto& s : known) names += (names.empty() ? "" : ", ") + s;
        throw RenderError("unknown pass '" + pass + "'; passes: " + names);
    }
    const size_t n = pixel_count(frame, path, pass);
    std::vector<float> rgb(n * 3);
    auto put = [&](size_t p, Vec3 c) {
        rgb[3 * p] = c.x, rgb[3 * p + 1] = c.y, rgb[3 * p + 2] = c.z;
    };
    bool display = false;
    if (pass == "combined" || pass == "albedo") {
        display = true;
        for (size_t p = 0; p < n; ++p)
            put(p, pass == "combined"
                       ? Vec3(frame.rgba[4 * p], frame.rgba[4 * p + 1], frame.rgba[4 * p + 2])
                       : frame.albedo[p]);
    } else if (pass == "depth") {
        float lo = INFINITY, hi = 0;
        for (float d : frame.depth)
            if (std::isfinite(d)) lo = std::fmin(lo, d), hi = std::fmax(hi, d);
        for (size_t p = 0; p < n; ++p) {
            const float d = frame.depth[p];
            put(p, Vec3(std::isfinite(d) && hi > lo ? 1.0f - 0.9f * (d - lo) / (hi - lo)
                                                    : (std::isfinite(d) ? 1.0f : 0.0f)));
        }
    } else if (pass == "normal") {
        // Black where nothing was hit: no object, or (a frame without ids) no normal.
        const bool ids = frame_has_pass(frame, "object_id");
        for (size_t p = 0; p < n; ++p) {
            const bool none =
                ids ? frame.object_id[p] == 0xFFFFFFFFu : frame.normal[p] == Vec3(0.0f);
            put(p, none ? Vec3(0.0f) : frame.normal[p] * 0.5f + Vec3(0.5f));
        }
    } else if (pass == "object_id") {
        for (size_t p = 0; p < n; ++p) put(p, id_colour(frame.object_id[p]));
    } else if (pass == "tests") {
        uint32_t most = 0;
        for (uint32_t t : frame.tests) most = std::max(most, t);
        const float scale = most > 0 ? 1.0f / std::log1p(float(most)) : 0.0f;
        for (size_t p = 0; p < n; ++p) put(p, heat(std::log1p(float(frame.tests[p])) * scale));
    }
    if (format_of(path).encoding != Encoding::Display8)
        throw RenderError(path +
                          ": a false-colour pass is an 8-bit picture; use .png, .jpg or .tif");
    write_pixels(path, frame.width, frame.height, 3, rgb.data(), display, display_options(frame),
                 frame_metadata(frame));
}

} // namespace sheaf

// Reading back a frame from the OpenEXR that write_image wrote (image_io.cpp, write_exr): the
// parts of a frame rendered apart (render --tile, a farm's tasks) are put together from these.
#include "core/base/error.h"
#include "core/settings/settings.h"
#include "io/image/image_io.h"
#include "io/image/image_module.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace sheaf {
namespace {

// "key=value key=value ...", as image_io.cpp writes sheaf:settings. Values may hold spaces
// (output.display="sRGB - Display"): an entry runs to the next " key=" of a known key.
std::vector<std::pair<std::string, std::string>> parse_settings(const std::string& text,
                                                                const std::string& path) {
    std::vector<size_t> starts;
    for (const SettingSpec& spec : setting_specs()) {
        const std::string needle = spec.key + "=";
        for (size_t at = text.find(needle); at != std::string::npos;
             at = text.find(needle, at + 1))
            if (at == 0 || text[at - 1] == ' ') starts.push_back(at);
    }
    std::sort(starts.begin(), starts.end());
    std::vector<std::pair<std::string, std::string>> out;
    for (size_t i = 0; i < starts.size(); ++i) {
        const size_t end = i + 1 < starts.size() ? starts[i + 1] - 1 : text.size();
        const std::string entry = text.substr(starts[i], end - starts[i]);
        const size_t eq = entry.find('=');
        out.emplace_back(entry.substr(0, eq), entry.substr(eq + 1));
    }
    if (out.empty() && !text.empty())
        throw RenderError(path + ": its sheaf:settings name no known setting");
    return out;
}

} // namespace

Frame read_frame_image(const std::string& path) {
    std::optional<io::ImageReader> opened;
    try {
        opened.emplace(path);
    } catch (const RenderError& e) {
        throw RenderError(path + ": cannot read the frame: " + e.what());
    }
    io::ImageReader& reader = *opened;
    const SheafImageInfo& info = reader.info();
    const std::optional<std::string> settings = reader.describe(-1, "sheaf:settings");
    if (!settings)
        throw RenderError(path + ": not a frame written by Sheaf (no sheaf:settings attribute)");
    // A frame is at most 16384 x 16384 (the width and height settings' range): a larger header
    // is not a Sheaf frame, and is refused before its pixels are allocated.
    constexpr int kMaxSide = 16384, kMaxChannels = 64;
    if (info.width < 1 || info.height < 1 || info.width > kMaxSide || info.height > kMaxSide ||
        info.channels < 1 || info.channels > kMaxChannels)
        throw RenderError(path + ": " + std::to_string(info.width) + "x" +
                          std::to_string(info.height) + " pixels of " +
                          std::to_string(info.channels) + " channels is not a frame Sheaf wrote "
                          "(at most 16384x16384, 64 channels)");
    if (!info.all_float)
        throw RenderError(path + ": does not hold the frame's values as 32-bit floats; write "
                                 "parts as .exr with output.exr=float to put them together "
                                 "exactly");
    std::map<std::string, int> channel;
    for (int c = 0; c < info.channels; ++c)
        if (const auto name = reader.describe(c)) channel[*name] = c;
    for (const char* rgba : {"R", "G", "B", "A"})
        if (!channel.count(rgba))
            throw RenderError(path + ": has no channel " + rgba + " (the combined pass)");
    Frame f;
    f.width = info.width, f.height = info.height;
    f.x = info.x, f.y = info.y;
    f.full_width = info.full_width, f.full_height = info.full_height;
    f.settings = parse_settings(*settings, path);
    if (const auto stats = reader.describe(-1, "sheaf:stats")) {
        try {
            f.stats = Stats::from_json(*stats);
        } catch (const std::invalid_argument& e) {
            throw RenderError(path + ": sheaf:stats: " + e.what());
        }
    }
    const int nc = info.channels;
    const std::vector<float> data = reader.read(nc);
    const size_t pixels = size_t(f.width) * size_t(f.height);
    auto at = [&](size_t p, int c) { return data[p * size_t(nc) + size_t(c)]; };
    auto has = [&](std::initializer_list<const char*> names) {
        return std::all_of(names.begin(), names.end(), [&](const char* n) { return channel.count(n) > 0; });
    };
    f.rgba.resize(4 * pixels);
    const int r = channel["R"], g = channel["G"], b = channel["B"], a = channel["A"];
    for (size_t p = 0; p < pixels; ++p)
        f.rgba[4 * p] = at(p, r), f.rgba[4 * p + 1] = at(p, g), f.rgba[4 * p + 2] = at(p, b),
                   f.rgba[4 * p + 3] = at(p, a);
    if (has({"Z"})) {
        f.depth.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) f.depth[p] = at(p, channel["Z"]);
    }
    auto vec3 = [&](std::vector<Vec3>& out, const char* x, const char* y, const char* z) {
        if (!has({x, y, z})) return;
        const int cx = channel[x], cy = channel[y], cz = channel[z];
        out.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) out[p] = Vec3(at(p, cx), at(p, cy), at(p, cz));
    };
    vec3(f.normal, "N.X", "N.Y", "N.Z");
    vec3(f.albedo, "albedo.R", "albedo.G", "albedo.B");
    auto ids = [&](std::vector<uint32_t>& out, const char* name, bool none_is_minus_one) {
        if (!has({name})) return;
        const int c = channel[name];
        out.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) {
            const float v = at(p, c);
            out[p] = none_is_minus_one && v < 0 ? 0xFFFFFFFFu : uint32_t(std::fmax(v, 0.0f));
        }
    };
    ids(f.object_id, "object_id", true);
    ids(f.tests, "tests", false);
    return f;
}

} // namespace sheaf

// The render tool's thin layer over the C ABI: errors, frame read-back, settings and scenes.
#include "capi_util.h"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace render {

namespace {
std::string g_last_message; // the last error() printed, for a farm task's failure record
} // namespace

int error(int code, const std::string& message) {
    std::cerr << "render: error: " << message << "\n";
    g_last_message = message;
    return code;
}

const std::string& last_printed_error() { return g_last_message; }

std::string last_error() {
    const char* message = nullptr;
    sheafGetLastError(&message);
    return message && *message ? message : "unknown error";
}

int render_error_code(SheafError e) {
    return e == SHEAF_ERROR_SCENE ? kScene : e == SHEAF_ERROR_INVALID_SETTING ? kUsage : kRender;
}

std::optional<std::string> frame_text(SheafFrame frame, const char* what) {
    size_t needed = 0;
    if (sheafFrameGetText(frame, what, nullptr, 0, &needed) != SHEAF_OK) return std::nullopt;
    std::string text(needed, '\0');
    if (sheafFrameGetText(frame, what, text.data(), text.size(), &needed) != SHEAF_OK)
        return std::nullopt;
    text.resize(needed - 1);
    return text;
}

std::string frame_backend(SheafFrame frame) {
    std::optional<std::string> line = frame_text(frame, "backend");
    if (!line || line->empty()) {
        double cuda = 0;
        sheafFrameGetStatByName(frame, "backend.cuda", &cuda);
        line = cuda != 0 ? "backend: cuda" : "backend: cpu";
    }
    while (!line->empty() && line->back() == '\n') line->pop_back();
    return *line;
}

std::optional<std::vector<float>> frame_pass(SheafFrame frame, const char* pass, int channels) {
    int w = 0, h = 0;
    if (sheafFrameGetSize(frame, &w, &h) != SHEAF_OK) return std::nullopt;
    std::vector<float> data(size_t(w) * size_t(h) * size_t(channels));
    if (sheafFrameGetPass(frame, pass, data.data(), data.size()) != SHEAF_OK) return std::nullopt;
    return data;
}

std::vector<std::pair<std::string, double>> frame_stats(SheafFrame frame) {
    std::vector<std::pair<std::string, double>> out;
    size_t count = 0;
    if (sheafFrameGetStatCount(frame, &count) != SHEAF_OK) return out;
    for (size_t i = 0; i < count; ++i) {
        const char* key = nullptr;
        double value = 0;
        if (sheafFrameGetStat(frame, i, &key, &value) == SHEAF_OK && key)
            out.emplace_back(key, value);
    }
    return out;
}

int apply_settings(SheafRenderer renderer, const std::string& preset, const CommonSettings& s) {
    if (!preset.empty() && sheafRendererLoadPreset(renderer, preset.c_str()) != SHEAF_OK)
        return error(kUsage, "preset '" + preset + "': " + last_error());
    if (s.width && sheafRendererSetInt(renderer, "width", *s.width) != SHEAF_OK)
        return error(kUsage, "-W: " + last_error());
    if (s.height && sheafRendererSetInt(renderer, "height", *s.height) != SHEAF_OK)
        return error(kUsage, "-H: " + last_error());
    if (s.threads && sheafRendererSetInt(renderer, "threads", *s.threads) != SHEAF_OK)
        return error(kUsage, "--threads: " + last_error());
    for (const std::string& set : s.sets) {
        const size_t eq = set.find('=');
        if (eq == std::string::npos || eq == 0)
            return error(kUsage, "--set '" + set + "': expected key=value");
        const std::string key = set.substr(0, eq), value = set.substr(eq + 1);
        if (sheafRendererSetString(renderer, key.c_str(), value.c_str()) != SHEAF_OK)
            return error(kUsage, "--set " + set + ": " + last_error());
    }
    return kOk;
}

std::string limits_used(SheafScene scene) {
    size_t count = 0;
    std::string text;
    if (sheafSceneGetLimitCount(scene, &count) != SHEAF_OK) return text;
    for (size_t i = 0; i < count; ++i) {
        const char* name = nullptr;
        double used = 0, limit = 0;
        if (sheafSceneGetLimitUse(scene, i, &name, &used, &limit) != SHEAF_OK) continue;
        char line[160];
        std::snprintf(line, sizeof line, used == std::floor(used) ? "%s%s %.15g of %.15g (%.2g%%)"
                                                                  : "%s%s %.3g of %.15g (%.2g%%)",
                      text.empty() ? "" : ", ", name, used, limit,
                      limit > 0 ? 100 * used / limit : 0.0);
        text += line;
    }
    return text;
}

std::string scene_label(const std::string& path) {
    return path.empty() ? std::string("builtin:") + sheafGetDefaultSceneName() : path;
}

int load_scene(SheafScene scene, const SceneSource& source) {
    const std::string label = scene_label(source.path);
    for (const std::string& dir : source.include_paths)
        if (sheafSceneSetLoadOption(scene, "include_path", dir.c_str()) != SHEAF_OK)
            return error(kUsage, "--include-path " + dir + ": " + last_error());
    if (sheafSceneSetLoadOption(scene, "strict", source.strict ? "1" : "0") != SHEAF_OK)
        return error(kUsage, "--strict: " + last_error());
    if (source.width)
        sheafSceneSetLoadOption(scene, "image_width", std::to_string(*source.width).c_str());
    if (source.height)
        sheafSceneSetLoadOption(scene, "image_height", std::to_string(*source.height).c_str());
    std::vector<std::pair<std::string, std::string>> animation;
    auto number = [](double x) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", x);
        return std::string(text);
    };
    if (source.initial_frame)
        animation.emplace_back("initial_frame", std::to_string(*source.initial_frame));
    if (source.final_frame)
        animation.emplace_back("final_frame", std::to_string(*source.final_frame));
    if (source.frame) animation.emplace_back("frame", std::to_string(*source.frame));
    if (source.initial_clock)
        animation.emplace_back("initial_clock", number(*source.initial_clock));
    if (source.final_clock) animation.emplace_back("final_clock", number(*source.final_clock));
    if (source.clock) animation.emplace_back("clock", number(*source.clock));
    if (source.cyclic) animation.emplace_back("cyclic_animation", *source.cyclic ? "1" : "0");
    animation.emplace_back("declare", "");
    for (const std::string& d : source.declares) animation.emplace_back("declare", d);
    for (const auto& [key, value] : animation)
        if (sheafSceneSetLoadOption(scene, key.c_str(), value.c_str()) != SHEAF_OK)
            return error(kUsage, last_error());
    for (const std::string& limit : source.limits) {
        const size_t eq = limit.find('=');
        const std::string key = "limit." + limit.substr(0, std::min(eq, limit.size()));
        const std::string value = eq == std::string::npos ? "" : limit.substr(eq + 1);
        if (eq == std::string::npos || value.empty() ||
            sheafSceneSetLoadOption(scene, key.c_str(), value.c_str()) != SHEAF_OK)
            return error(kUsage, "--limit " + limit + ": " +
                                     (eq == std::string::npos || value.empty()
                                          ? std::string("expected NAME=N, e.g. parse_steps=1000000000")
                                          : last_error()));
    }
    if (const SheafError e = sheafSceneLoadFile(scene, label.c_str()); e != SHEAF_OK)
        return error(e == SHEAF_ERROR_INVALID_ARGUMENT ? kUsage : kScene, last_error());
    size_t warnings = 0;
    sheafSceneGetWarningCount(scene, &warnings);
    for (size_t i = 0; i < warnings; ++i) {
        const char* message = nullptr;
        if (sheafSceneGetWarning(scene, i, &message) == SHEAF_OK && message)
            std::cerr << message << "\n";
    }
    if (sheafSceneCommit(scene) != SHEAF_OK) return error(kScene, label + ": " + last_error());
    return kOk;
}

bool is_setting_key(const std::string& key) {
    size_t count = 0;
    sheafGetSettingCount(&count);
    for (size_t i = 0; i < count; ++i) {
        const char* k = nullptr;
        if (sheafGetSettingInfo(i, &k, nullptr, nullptr, nullptr) == SHEAF_OK && k && key == k)
            return true;
    }
    return false;
}

std::string setting_keys() {
    std::string out;
    size_t count = 0;
    sheafGetSettingCount(&count);
    for (size_t i = 0; i < count; ++i) {
        const char* k = nullptr;
        if (sheafGetSettingInfo(i, &k, nullptr, nullptr, nullptr) == SHEAF_OK && k)
            out += (out.empty() ? "" : ", ") + std::string(k);
    }
    return out;
}

} // namespace render

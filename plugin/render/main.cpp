// render: renders a scene to an image file through the C ABI (libsheaf.so) only.
#include <sheaf/sheaf.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

// Exit codes.
constexpr int kOk = 0, kUsage = 1, kScene = 2, kRender = 3;

struct Options {
    std::string scene;
    std::string output = "render.png";
    int width = 0, height = 0;
    bool has_width = false, has_height = false;
    std::string preset;
    std::vector<std::string> sets;
    bool stats = false;
    std::string stats_json;
    bool list_settings = false;
    bool version = false;
};

int error(int code, const std::string& message) {
    std::cerr << "render: error: " << message << "\n";
    return code;
}

/// The message of the C ABI's last error on this thread.
std::string last_error() {
    const char* message = nullptr;
    sheafGetLastError(&message);
    return message && *message ? message : "unknown error";
}

/// A text of the frame through the two-call size protocol.
std::optional<std::string> frame_text(SheafFrame frame, const char* what) {
    size_t needed = 0;
    if (sheafFrameGetText(frame, what, nullptr, 0, &needed) != SHEAF_OK) return std::nullopt;
    std::string text(needed, '\0');
    if (sheafFrameGetText(frame, what, text.data(), text.size(), &needed) != SHEAF_OK)
        return std::nullopt;
    text.resize(needed - 1);
    return text;
}

void list_settings() {
    size_t count = 0;
    sheafGetSettingCount(&count);
    for (size_t i = 0; i < count; ++i) {
        const char *key, *def, *allowed, *help;
        if (sheafGetSettingInfo(i, &key, &def, &allowed, &help) != SHEAF_OK) continue;
        std::cout << key << " (default " << def << "; " << allowed << ")\n    " << help << "\n";
    }
}

/// Applies the preset, then -W/-H, then each --set in order. Returns an exit code.
int apply_settings(SheafRenderer renderer, const Options& o) {
    if (!o.preset.empty() && sheafRendererLoadPreset(renderer, o.preset.c_str()) != SHEAF_OK)
        return error(kUsage, "--preset " + o.preset + ": " + last_error());
    if (o.has_width && sheafRendererSetInt(renderer, "width", o.width) != SHEAF_OK)
        return error(kUsage, "-W: " + last_error());
    if (o.has_height && sheafRendererSetInt(renderer, "height", o.height) != SHEAF_OK)
        return error(kUsage, "-H: " + last_error());
    for (const std::string& set : o.sets) {
        const size_t eq = set.find('=');
        if (eq == std::string::npos || eq == 0)
            return error(kUsage, "--set '" + set + "': expected key=value");
        const std::string key = set.substr(0, eq), value = set.substr(eq + 1);
        if (sheafRendererSetString(renderer, key.c_str(), value.c_str()) != SHEAF_OK)
            return error(kUsage, "--set " + set + ": " + last_error());
    }
    return kOk;
}

int load_scene(SheafScene scene, const Options& o) {
    const std::string path =
        o.scene.empty() ? std::string("builtin:") + sheafGetDefaultSceneName() : o.scene;
    if (sheafSceneLoadFile(scene, path.c_str()) != SHEAF_OK) return error(kScene, last_error());
    if (sheafSceneCommit(scene) != SHEAF_OK) return error(kScene, path + ": " + last_error());
    return kOk;
}

int render_and_write(SheafRenderer renderer, SheafScene scene, const Options& o) {
    SheafFrame frame = nullptr;
    const auto start = std::chrono::steady_clock::now();
    const SheafError rendered = sheafRender(renderer, scene, &frame);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (rendered != SHEAF_OK) {
        const int code = rendered == SHEAF_ERROR_SCENE             ? kScene
                         : rendered == SHEAF_ERROR_INVALID_SETTING ? kUsage
                                                                   : kRender;
        return error(code, last_error());
    }
    int result = kOk;
    int w = 0, h = 0;
    sheafFrameGetSize(frame, &w, &h);
    if (sheafFrameSaveImage(frame, o.output.c_str()) != SHEAF_OK) {
        result = error(kRender, last_error());
    } else {
        char line[64];
        std::snprintf(line, sizeof line, "%dx%d, %.1f ms", w, h, ms);
        std::cout << "wrote " << o.output << " (" << line << ")\n";
    }
    if (result == kOk && o.stats) {
        if (auto table = frame_text(frame, "stats.table"))
            std::cout << *table;
        else
            result = error(kRender, "--stats: " + last_error());
    }
    if (result == kOk && !o.stats_json.empty()) {
        std::optional<std::string> json = frame_text(frame, "stats.json");
        std::ofstream out(o.stats_json);
        if (!json)
            result = error(kRender, "--stats-json: " + last_error());
        else if (!(out << *json << "\n"))
            result = error(kRender, "--stats-json " + o.stats_json + ": cannot write the file");
    }
    sheafFrameRelease(frame);
    return result;
}

int run(const Options& o) {
    if (o.version) {
        std::cout << "render (Sheaf) " << sheafGetVersionString() << "\n";
        return kOk;
    }
    if (o.list_settings) {
        list_settings();
        return kOk;
    }
    SheafRenderer renderer = nullptr;
    SheafScene scene = nullptr;
    if (sheafRendererNew(&renderer) != SHEAF_OK || sheafSceneNew(&scene) != SHEAF_OK) {
        if (renderer) sheafRendererRelease(renderer);
        return error(kRender, last_error());
    }
    int result = apply_settings(renderer, o);
    if (result == kOk) result = load_scene(scene, o);
    if (result == kOk) result = render_and_write(renderer, scene, o);
    sheafSceneRelease(scene);
    sheafRendererRelease(renderer);
    return result;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"render: renders a scene with the Sheaf engine and writes an image."};
    app.footer(R"(Settings apply in this order: --preset, then -W/-H, then each --set in order.
Exit codes: 0 ok, 1 usage or settings, 2 scene, 3 render or image write.

Examples:
  render                                         the default built-in scene to render.png
  render builtin:cornell -W 640 -H 480 -o cornell.exr
  render builtin:office --preset rah --stats     the Roger et al. hierarchy, with statistics
  render --set accel=brute --set trace.depth=2 --stats-json stats.json
  render --list-settings                         every key, its default and what it allows)");
    app.add_option("scene", o.scene,
                   "builtin:NAME or a scene file (default: the built-in " +
                       std::string(sheafGetDefaultSceneName()) + " scene)");
    app.add_option("-o,--output", o.output,
                   "image file; the extension picks the format: .png .jpg .tif .exr .hdr")
        ->capture_default_str();
    CLI::Option* width =
        app.add_option("-W,--width", o.width, "image width in pixels (setting width)");
    CLI::Option* height =
        app.add_option("-H,--height", o.height, "image height in pixels (setting height)");
    app.add_option("--preset", o.preset, "a preset name (brute, rah, crsh, ...) or .xml file");
    app.add_option("--set", o.sets, "a setting, key=value; repeatable (see --list-settings)")
        ->allow_extra_args(false)
        ->type_name("KEY=VALUE");
    app.add_flag("--stats", o.stats, "print the frame statistics as a table");
    app.add_option("--stats-json", o.stats_json, "write the frame statistics as JSON to FILE")
        ->type_name("FILE");
    app.add_flag("--list-settings", o.list_settings, "list every setting and exit");
    app.add_flag("--version", o.version, "print the version and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return error(kUsage, std::string(e.what()) + " (see render --help)");
    }
    o.has_width = width->count() > 0;
    o.has_height = height->count() > 0;
    return run(o);
}

// The C ABI's renderers: the explicit settings a host sets, presets, the progress callback.
#include "capi_internal.h"
#include "text_out.h"

#include "io/presets/preset.h"

#include <charconv>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>

using namespace sheaf::capi;

namespace {

/// The directory of libsheaf.so itself, "" when unknown.
std::string library_dir() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&sheafRendererLoadPreset), &info) || !info.dli_fname)
        return {};
    std::error_code ec;
    std::filesystem::path lib = std::filesystem::canonical(info.dli_fname, ec);
    if (ec) lib = info.dli_fname;
    return lib.parent_path().string();
}

/// Where presets are looked for: $SHEAF_PRESET_PATH, the installed share directory beside the
/// library, and the source tree (for the build tree).
std::vector<std::string> preset_dirs() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("SHEAF_PRESET_PATH")) {
        std::string_view rest = env;
        while (true) {
            const size_t colon = rest.find(':');
            const std::string_view dir = rest.substr(0, colon);
            if (!dir.empty()) dirs.emplace_back(dir);
            if (colon == std::string_view::npos) break;
            rest.remove_prefix(colon + 1);
        }
    }
    const std::string lib = library_dir();
    if (!lib.empty()) {
        const auto add = [&](const std::string& dir) {
            const std::string d = std::filesystem::path(dir).lexically_normal().string();
            if (std::find(dirs.begin(), dirs.end(), d) == dirs.end()) dirs.push_back(d);
        };
#ifdef SHEAF_LIB_TO_PRESETS
        add(lib + "/" SHEAF_LIB_TO_PRESETS);
#endif
        add(lib + "/../share/sheaf/presets");
    }
#ifdef SHEAF_SOURCE_PRESET_DIR
    dirs.emplace_back(SHEAF_SOURCE_PRESET_DIR);
#endif
    return dirs;
}

SheafRendererT& renderer_of(SheafRenderer r) {
    return *require(r, "renderer");
}

void set_setting(SheafRenderer r, const char* key, const std::string& value) {
    SheafRendererT& renderer = renderer_of(r);
    renderer.settings.set(require(key, "key"), value);
}

} // namespace

extern "C" {

SHEAF_API SheafError sheafRendererNew(SheafRenderer* out) {
    return barrier([&] {
        require(out, "out");
        *out = nullptr;
        *out = new SheafRendererT;
    });
}

SHEAF_API SheafError sheafRendererRetain(SheafRenderer renderer) {
    return barrier([&] { sheaf_retain(require(renderer, "renderer")); });
}

SHEAF_API SheafError sheafRendererRelease(SheafRenderer renderer) {
    return barrier([&] { sheaf_release(require(renderer, "renderer")); });
}

SHEAF_API SheafError sheafRendererSetString(SheafRenderer renderer, const char* key,
                                            const char* value) {
    return barrier([&] { set_setting(renderer, key, require(value, "value")); });
}

SHEAF_API SheafError sheafRendererSetInt(SheafRenderer renderer, const char* key, long long value) {
    return barrier([&] { set_setting(renderer, key, std::to_string(value)); });
}

SHEAF_API SheafError sheafRendererSetFloat(SheafRenderer renderer, const char* key, double value) {
    return barrier([&] {
        char text[64];
        // Shortest text that reads back as the same double: 3.0 becomes "3", fit for int keys.
        const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
        set_setting(renderer, key, ec == std::errc() ? std::string(text, end) : "nan");
    });
}

SHEAF_API SheafError sheafRendererSetBool(SheafRenderer renderer, const char* key, int value) {
    return barrier([&] { set_setting(renderer, key, value ? "true" : "false"); });
}

SHEAF_API SheafError sheafRendererUnset(SheafRenderer renderer, const char* key) {
    return barrier([&] { renderer_of(renderer).settings.unset(require(key, "key")); });
}

SHEAF_API SheafError sheafRendererGetString(SheafRenderer renderer, const char* key, char* buf,
                                            size_t size, size_t* needed) {
    return barrier([&] {
        const std::string value = renderer_of(renderer).settings.get(require(key, "key"));
        copy_text(value, buf, size, needed);
    });
}

SHEAF_API SheafError sheafRendererGetEffective(SheafRenderer renderer, SheafScene scene,
                                               const char* key, char* buf, size_t size,
                                               size_t* needed) {
    return barrier([&] {
        const SheafRendererT& r = renderer_of(renderer);
        const std::string k = require(key, "key");
        const std::shared_ptr<const sheaf::PreparedScene> prepared =
            require(scene, "scene")->commit();
        if (!sheaf::find_setting(k)) r.settings.get(k); // throws naming the unknown key
        for (const auto& [name, value] :
             sheaf::RenderSettings::effective(r.settings, prepared->settings))
            if (name == k) return copy_text(value, buf, size, needed);
    });
}

SHEAF_API SheafError sheafRendererLoadPreset(SheafRenderer renderer, const char* name_or_path) {
    return barrier([&] {
        SheafRendererT& r = renderer_of(renderer);
        const std::string path =
            sheaf::find_preset(require(name_or_path, "name_or_path"), preset_dirs());
        const sheaf::Preset preset = sheaf::load_preset(path);
        sheaf::Settings settings = r.settings; // all or nothing
        for (const auto& [key, value] : preset.values) settings.set(key, value);
        r.settings = std::move(settings);
    });
}

SHEAF_API SheafError sheafGetPresetList(char* buf, size_t size, size_t* needed) {
    return barrier([&] {
        const std::vector<std::string> dirs = preset_dirs();
        std::string text;
        for (const std::string& name : sheaf::list_presets(dirs)) {
            std::string description;
            try {
                description = sheaf::load_preset(sheaf::find_preset(name, dirs)).description;
            } catch (const std::exception& e) {
                description = std::string("(unreadable: ") + e.what() + ")";
            }
            for (char& c : description)
                if (c == '\n' || c == '\t') c = ' ';
            text += name + "\t" + description + "\n";
        }
        copy_text(text, buf, size, needed);
    });
}

SHEAF_API SheafError sheafRendererSetProgressCallback(SheafRenderer renderer,
                                                      SheafProgressCallback callback, void* user) {
    return barrier([&] {
        SheafRendererT& r = renderer_of(renderer);
        r.progress = callback;
        r.progress_user = user;
    });
}

} // extern "C"

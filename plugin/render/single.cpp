// The plain render and the settings listing.
#include "single.h"

#include "progress.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace render {

namespace {

int write_outputs(SheafFrame frame, const Options& o, double ms) {
    int w = 0, h = 0;
    sheafFrameGetSize(frame, &w, &h);
    if (sheafFrameSaveImage(frame, o.output.c_str()) != SHEAF_OK)
        return error(kRender, last_error());
    if (!o.quiet) {
        char line[64];
        std::snprintf(line, sizeof line, "%dx%d, %.1f ms", w, h, ms);
        std::cout << "wrote " << o.output << " (" << line << ")\n";
    }
    if (o.stats) {
        auto table = frame_text(frame, "stats.table");
        if (!table) return error(kRender, "--stats: " + last_error());
        std::cout << *table;
    }
    if (!o.stats_json.empty()) {
        std::optional<std::string> json = frame_text(frame, "stats.json");
        if (!json) return error(kRender, "--stats-json: " + last_error());
        std::ofstream out(o.stats_json);
        if (!(out << *json << "\n"))
            return error(kRender, "--stats-json " + o.stats_json + ": cannot write the file");
    }
    return kOk;
}

} // namespace

void list_settings() {
    size_t count = 0;
    sheafGetSettingCount(&count);
    for (size_t i = 0; i < count; ++i) {
        const char *key, *def, *allowed, *help;
        if (sheafGetSettingInfo(i, &key, &def, &allowed, &help) != SHEAF_OK) continue;
        std::cout << key << " (default " << def << "; " << allowed << ")\n    " << help << "\n";
    }
}

int run_check(const Options& o) {
    SheafScene raw_scene = nullptr;
    if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
    Scene scene(raw_scene);
    if (int rc = load_scene(raw_scene, scene_source(o))) return rc;
    size_t warnings = 0;
    sheafSceneGetWarningCount(raw_scene, &warnings);
    std::cout << scene_label(o.scene) << ": usable, " << warnings
              << (warnings == 1 ? " warning\n" : " warnings\n");
    return kOk;
}

int run_single(const Options& o) {
    SheafRenderer raw_renderer = nullptr;
    SheafScene raw_scene = nullptr;
    if (sheafRendererNew(&raw_renderer) != SHEAF_OK) return error(kRender, last_error());
    Renderer renderer(raw_renderer);
    if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
    Scene scene(raw_scene);
    if (int rc = apply_settings(raw_renderer, o.preset, o.settings)) return rc;
    if (int rc = load_scene(raw_scene, scene_source(o))) return rc;

    Progress progress(Progress::wanted(o.quiet), 1);
    progress.start_run(raw_renderer, 0, scene_label(o.scene));
    SheafFrame raw_frame = nullptr;
    const auto start = std::chrono::steady_clock::now();
    const SheafError rendered = sheafRender(raw_renderer, raw_scene, &raw_frame);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    progress.finish_run(raw_renderer);
    if (rendered != SHEAF_OK) return error(render_error_code(rendered), last_error());
    Frame frame(raw_frame);
    if (!o.quiet) std::cerr << frame_backend(frame.get()) << "\n";
    return write_outputs(frame.get(), o, ms);
}

} // namespace render

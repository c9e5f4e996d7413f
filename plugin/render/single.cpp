// The plain render and the settings listing.
#include "single.h"

#include "progress.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace render {

namespace {

/// Milliseconds since `start`.
double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/// `scene_ms`: reading and committing the scene; `ms`: rendering the frame.
int write_outputs(SheafFrame frame, const Options& o, const std::string& output,
                  const std::string& stats_json, double scene_ms, double ms) {
    int w = 0, h = 0;
    sheafFrameGetSize(frame, &w, &h);
    if (int rc = save_image(frame, output)) return rc;
    if (!o.quiet) {
        char line[96];
        std::snprintf(line, sizeof line, "%dx%d, scene %.1f ms, frame %.1f ms", w, h, scene_ms, ms);
        std::cout << "wrote " << output << " (" << line << ")\n";
    }
    return write_stats(frame, o.stats, stats_json);
}

} // namespace

std::string numbered(const std::string& file, int frame, int last) {
    const size_t slash = file.find_last_of('/');
    size_t dot = file.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) dot = file.size();
    std::string n = std::to_string(frame);
    const size_t digits = std::to_string(last).size();
    if (frame >= 0 && n.size() < digits) n.insert(0, digits - n.size(), '0');
    return file.substr(0, dot) + n + file.substr(dot);
}

std::string partial_name(const std::string& file) {
    const size_t slash = file.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : file.substr(0, slash + 1);
    const std::string base = file.substr(dir.size());
    const size_t dot = base.find_last_of('.');
    const std::string ext = dot == std::string::npos ? "" : base.substr(dot);
    return dir + "." + base + ".partial-" + std::to_string(getpid()) + ext;
}

int save_image(SheafFrame frame, const std::string& output) {
    // Written under a temporary name, then renamed: a file of that name is always whole.
    const std::string partial = partial_name(output);
    if (sheafFrameSaveImage(frame, partial.c_str()) != SHEAF_OK) {
        std::remove(partial.c_str());
        // The message names the temporary file; say the one asked for.
        std::string shown = last_error();
        for (size_t at; (at = shown.find(partial)) != std::string::npos;)
            shown.replace(at, partial.size(), output);
        return error(kRender, shown);
    }
    if (std::rename(partial.c_str(), output.c_str()) != 0) {
        std::remove(partial.c_str());
        return error(kRender, output + ": cannot write the file (rename failed)");
    }
    return kOk;
}

int write_stats(SheafFrame frame, bool table, const std::string& stats_json) {
    if (table) {
        const std::optional<std::string> text = frame_text(frame, "stats.table");
        if (!text) return error(kRender, "--stats: " + last_error());
        std::cout << *text;
    }
    if (!stats_json.empty()) {
        const std::optional<std::string> json = frame_text(frame, "stats.json");
        if (!json) return error(kRender, "--stats-json: " + last_error());
        std::ofstream out(stats_json);
        if (!(out << *json << "\n"))
            return error(kRender, "--stats-json " + stats_json + ": cannot write the file");
    }
    return kOk;
}

int name_digits_frame(const Options& o) {
    return o.final_frame.value_or(1) + (o.cyclic.value_or(false) ? 1 : 0);
}

namespace {

/// The frames to read: the sequence's (cut to the subset), or one still (no frame number).
std::vector<std::optional<int>> frames(const Options& o) {
    if (!o.sequence()) return {std::nullopt};
    std::vector<std::optional<int>> out;
    for (int f : o.frame_numbers()) out.push_back(f);
    return out;
}

} // namespace

int apply_region(SheafRenderer renderer, SheafScene scene, const RegionRequest& region) {
    if (!region.any()) return kOk;
    int size[2] = {0, 0};
    const char* keys[2] = {"width", "height"};
    for (int i = 0; i < 2; ++i) {
        char text[32] = "";
        if (sheafRendererGetEffective(renderer, scene, keys[i], text, sizeof text, nullptr) !=
            SHEAF_OK)
            return error(kScene, last_error());
        size[i] = std::atoi(text);
    }
    PixelRect p;
    try {
        p = resolve_region(region, size[0], size[1]);
    } catch (const RegionError& e) {
        return error(kUsage, e.what());
    }
    const std::pair<const char*, int> values[] = {{"region.x", p.x},
                                                  {"region.y", p.y},
                                                  {"region.width", p.width},
                                                  {"region.height", p.height}};
    for (const auto& [key, value] : values)
        if (sheafRendererSetInt(renderer, key, value) != SHEAF_OK)
            return error(kUsage, last_error());
    return kOk;
}

int keep_written_passes(SheafRenderer renderer, SheafScene scene, const std::string& output) {
    // An OpenEXR file holds every pass; the other formats hold the picture alone, so the frame
    // need not keep the rest (output.passes at its default: all).
    std::string ext = std::filesystem::path(output).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".exr") return kOk;
    char passes[256] = "";
    if (sheafRendererGetEffective(renderer, scene, "output.passes", passes, sizeof passes,
                                  nullptr) != SHEAF_OK)
        return error(kScene, last_error());
    if (std::string(passes) != "all") return kOk; // as the scene or the user asked
    if (sheafRendererSetString(renderer, "output.passes", "combined") != SHEAF_OK)
        return error(kRender, last_error());
    return kOk;
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

int run_check(const Options& o) {
    // Every frame of a sequence is read: a scene may fail only at some clock values.
    for (const std::optional<int>& f : frames(o)) {
        SheafScene raw_scene = nullptr;
        if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
        Scene scene(raw_scene);
        if (int rc = load_scene(raw_scene, scene_source(o, f))) return rc;
        size_t warnings = 0;
        sheafSceneGetWarningCount(raw_scene, &warnings);
        std::cout << scene_label(o.scene);
        if (f) std::cout << " (frame " << *f << ")";
        std::cout << ": usable, " << warnings << (warnings == 1 ? " warning\n" : " warnings\n");
        if (const std::string used = limits_used(raw_scene); !used.empty())
            std::cout << "  limits used: " << used << "\n";
    }
    return kOk;
}

int run_single(const Options& o) {
    SheafRenderer raw_renderer = nullptr;
    if (sheafRendererNew(&raw_renderer) != SHEAF_OK) return error(kRender, last_error());
    Renderer renderer(raw_renderer);
    if (int rc = apply_settings(raw_renderer, o.preset, o.settings)) return rc;

    const std::vector<std::optional<int>> frame_list = frames(o);
    Progress progress(Progress::wanted(o.quiet), int(frame_list.size()));
    for (size_t i = 0; i < frame_list.size(); ++i) {
        const std::optional<int>& f = frame_list[i];
        // Each frame reads the scene again: its clock may change anything in it.
        SheafScene raw_scene = nullptr;
        if (sheafSceneNew(&raw_scene) != SHEAF_OK) return error(kRender, last_error());
        Scene scene(raw_scene);
        const auto load_start = std::chrono::steady_clock::now();
        if (int rc = load_scene(raw_scene, scene_source(o, f))) return rc;
        const double scene_ms = ms_since(load_start);

        if (int rc = apply_region(raw_renderer, raw_scene, o.region)) return rc;
        if (int rc = keep_written_passes(raw_renderer, raw_scene, o.output)) return rc;
        std::string label = scene_label(o.scene);
        if (f) label += " frame " + std::to_string(*f);
        progress.start_run(raw_renderer, int(i), label);
        SheafFrame raw_frame = nullptr;
        const auto start = std::chrono::steady_clock::now();
        const SheafError rendered = sheafRender(raw_renderer, raw_scene, &raw_frame);
        const double ms = ms_since(start);
        progress.finish_run(raw_renderer);
        if (rendered != SHEAF_OK) return error(render_error_code(rendered), last_error());
        Frame frame(raw_frame);
        if (!o.quiet && i == 0) std::cerr << frame_backend(frame.get()) << "\n";
        const int digits_of = name_digits_frame(o);
        const std::string output = f ? numbered(o.output, *f, digits_of) : o.output;
        const std::string stats_json =
            f && !o.stats_json.empty() ? numbered(o.stats_json, *f, digits_of) : o.stats_json;
        if (int rc = write_outputs(frame.get(), o, output, stats_json, scene_ms, ms)) return rc;
    }
    return kOk;
}

} // namespace render

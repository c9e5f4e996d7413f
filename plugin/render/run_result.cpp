// Rendering one configuration and reading its frame back into a RunResult.
#include "run_result.h"

namespace render {

bool RunResult::has(const std::string& key) const {
    for (const auto& [k, v] : stats)
        if (k == key) return true;
    return false;
}

double RunResult::stat(const std::string& key) const {
    for (const auto& [k, v] : stats)
        if (k == key) return v;
    return 0.0;
}

double RunResult::share() const {
    const double brute = stat("tests.brute_force");
    return brute > 0 ? stat("tests.total") / brute : 0.0;
}

std::vector<std::pair<std::string, std::string>> RunResult::settings_list() const {
    std::vector<std::pair<std::string, std::string>> out;
    size_t start = 0;
    while (start < settings.size()) {
        size_t end = settings.find('\n', start);
        if (end == std::string::npos) end = settings.size();
        const std::string line = settings.substr(start, end - start);
        const size_t eq = line.find('=');
        if (eq != std::string::npos) out.emplace_back(line.substr(0, eq), line.substr(eq + 1));
        start = end + 1;
    }
    return out;
}

std::string backend_summary(const std::vector<RunResult>& results) {
    if (results.empty()) return "backend: none";
    bool same = true;
    for (const RunResult& r : results) same = same && r.backend == results.front().backend;
    if (same) return results.front().backend;
    const std::string prefix = "backend: ";
    std::string line = prefix;
    for (const RunResult& r : results) {
        const bool plain = r.backend.compare(0, prefix.size(), prefix) == 0;
        line += (line.size() > prefix.size() ? "; " : "") + r.name + ": " +
                (plain ? r.backend.substr(prefix.size()) : r.backend);
    }
    return line;
}

int render_into(SheafRenderer renderer, SheafScene scene, bool keep_images, RunResult& out,
                const std::string& image_path) {
    SheafFrame raw = nullptr;
    const SheafError e = sheafRender(renderer, scene, &raw);
    if (e != SHEAF_OK) return error(render_error_code(e), out.name + ": " + last_error());
    Frame frame(raw);
    sheafFrameGetSize(frame.get(), &out.width, &out.height);
    out.stats = frame_stats(frame.get());
    auto settings = frame_text(frame.get(), "settings");
    if (!settings) return error(kRender, out.name + ": settings: " + last_error());
    out.settings = *settings;
    out.backend = frame_backend(frame.get());
    if (!image_path.empty() && sheafFrameSaveImage(frame.get(), image_path.c_str()) != SHEAF_OK)
        return error(kRender, last_error());
    if (keep_images) {
        auto rgba = frame_pass(frame.get(), "combined", 4);
        auto tests = frame_pass(frame.get(), "tests", 1);
        if (!rgba || !tests) return error(kRender, out.name + ": passes: " + last_error());
        out.rgba = std::move(*rgba);
        out.tests = std::move(*tests);
    }
    return kOk;
}

} // namespace render

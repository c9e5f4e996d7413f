// Prints, for each built-in scene, the intersection tests of crsh and rah as a share of
// brute force (paper 000, Table 4), their ratio, and the time per phase (Table 5).
// Usage: sheaf_scene_table [--size N] [--frames K] [scene ...]
// Times are the median of K frames on this machine; counts do not depend on K.
#include "core/backend/backend.h"
#include "core/scenes/builtin.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace sheaf;

namespace {

struct Paper {
    double crsh_share, crsh_over_rah;
};
const std::map<std::string, Paper> kPaper = {
    {"cornell", {0.0883, 0.74}}, {"office", {0.0186, 0.36}}, {"colonnade", {0.0238, 0.64}}};

Frame run(const PreparedScene& scene, const char* preset, int size, int frames) {
    Settings s;
    s.set("width", std::to_string(size));
    s.set("height", std::to_string(size));
    s.set("backend", "cpu");
    s.set("cull.distance", "false"); // the paper's unbounded cones, as presets/rah.xml, crsh.xml
    s.set("cull.cluster", "0");      // whole objects, as the paper culls
    if (std::strcmp(preset, "rah") == 0) {
        s.set("accel", "rah"), s.set("cull.objects", "false"), s.set("hash.mode", "none"),
            s.set("sort.mode", "none");
    } else {
        s.set("accel", "crsh"), s.set("hash.mode", "crsh"), s.set("sort.mode", "csd"),
            s.set("cull.objects", "true");
    }
    const RenderSettings rs = RenderSettings::resolve(s, scene.settings);
    std::vector<Frame> runs;
    for (int i = 0; i < frames; ++i) runs.push_back(render_frame(scene, rs));
    // Median frame time; its statistics (counts are identical across runs).
    std::sort(runs.begin(), runs.end(), [](const Frame& a, const Frame& b) {
        return a.stats.get("time_ms.frame") < b.stats.get("time_ms.frame");
    });
    return std::move(runs[runs.size() / 2]);
}

} // namespace

int main(int argc, char** argv) {
    int size = 512, frames = 3;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
            size = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else
            scenes.push_back(argv[i]);
    }
    if (scenes.empty()) scenes = builtin_scene_names();

    std::printf("## Intersection tests at %dx%d (hierarchy depth 2, arity 8)\n\n", size, size);
    std::printf("| scene | triangles | objects | shadow rays | reflection rays | brute force | rah "
                "| rah %% | crsh | crsh %% "
                "| crsh/rah | paper crsh %% | paper crsh/rah |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::vector<std::pair<std::string, std::pair<Frame, Frame>>> all;
    for (const std::string& name : scenes) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        Frame rah = run(scene, "rah", size, frames);
        Frame crsh = run(scene, "crsh", size, frames);
        const double brute = crsh.stats.get("tests.brute_force");
        const double tr = rah.stats.get("tests.total"), tc = crsh.stats.get("tests.total");
        const Paper p = kPaper.count(name) ? kPaper.at(name) : Paper{0, 0};
        std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %.4g | %.4g | %.2f%% | %.4g | %.2f%% | "
                    "%.2f | %.2f%% | %.2f |\n",
                    name.c_str(), crsh.stats.get("scene.primitives"),
                    crsh.stats.get("scene.objects"), crsh.stats.get("rays.shadow"),
                    crsh.stats.get("rays.reflection"), brute, tr, 100 * tr / brute, tc,
                    100 * tc / brute, tc / tr, 100 * p.crsh_share, p.crsh_over_rah);
        all.emplace_back(name, std::make_pair(std::move(rah), std::move(crsh)));
    }

    std::printf("\n## Time per phase (ms, median of %d frames; share of the frame)\n\n", frames);
    const char* phases[] = {"raster",      "gbuffer",     "ray_creation",  "hashing",
                            "compression", "sorting",     "decompression", "hierarchy",
                            "traversal",   "final_tests", "shading",       "frame"};
    std::printf("| phase |");
    for (auto& [name, f] : all) std::printf(" %s rah | %s crsh |", name.c_str(), name.c_str());
    std::printf("\n|---|");
    for (size_t i = 0; i < all.size(); ++i) std::printf("---:|---:|");
    std::printf("\n");
    for (const char* ph : phases) {
        std::printf("| %s |", ph);
        const std::string k = std::string("time_ms.") + ph;
        for (auto& [name, f] : all)
            for (const Frame* fr : {&f.first, &f.second})
                std::printf(" %.1f (%.0f%%) |", fr->stats.get(k),
                            100 * fr->stats.get(k) / fr->stats.get("time_ms.frame"));
        std::printf("\n");
    }
    std::printf("| peak memory (MiB) |");
    for (auto& [name, f] : all)
        for (const Frame* fr : {&f.first, &f.second})
            std::printf(" %.1f |", fr->stats.get("memory.peak_bytes") / 1048576.0);
    std::printf("\n");
    return 0;
}

// Paper 003's study (its Table 1): ambient occlusion rays under each ray order, the time to
// reorder them and the time to render them, with radix and bitonic sorting, on each backend.
//
// Usage: sheaf_ao_study [--size N] [--samples S] [--frames K] [--backends cpu,cuda]
//                       [--sorts radix,bitonic] [--set KEY=VALUE ...] [scene ...]
// Defaults: 1024 x 1024, 16 AO rays per pixel (about 17M rays on the built-in scenes), one
// frame, the CPU and, when a CUDA device is usable, the GPU; every built-in scene.
//
// Each scene is rendered with its lights removed and no bounces, so the frame is the primary
// visibility plus the AO rays alone (as the paper's figures are). AO rays reach a tenth of
// the scene's bounding radius. "reorder" is hashing + compression + sorting + decompression;
// "render" is the rest of the frame. Counts are exact; times are one run (or the median of K).
// --set gives other settings (hierarchy.depth=4, say); the study sets the size, accel, order,
// sort, AO, trace.depth and backend itself, and keeps only the image (output.passes=combined:
// the depth, normal, albedo, id and test passes are neither resolved nor read back) unless
// --set names the passes.
#include "bench_args.h"
#include "core/backend/backend.h"
#include "core/base/error.h"
#include "core/scenes/builtin.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace sheaf;

namespace {

struct Order {
    const char* label; // as the paper's rows
    const char* hash;
    const char* sort; // "" for static orders (no sort setting)
};

const Order kOrders[] = {
    {"static 1D", "static1d", ""},        {"static 3D", "static3d", ""},
    {"dynamic 32-bit", "hash32", "full"}, {"dynamic 192-bit", "hash192", "full"},
    {"c.s.d. 32-bit", "hash32", "csd"},
};

// The scene without its lights: primary visibility and AO only.
PreparedScene ao_only(const std::string& name) {
    PreparedScene p = prepare_scene(make_builtin_scene(name));
    p.lights.clear();
    return p;
}

float bounding_radius(const PreparedScene& p) {
    float r = 0;
    for (const Sphere& s : p.object_sphere)
        if (std::isfinite(s.radius)) r = std::max(r, length(s.center) + s.radius);
    return r > 0 ? r : 1.0f;
}

struct Result {
    bool ok = false;
    std::string error;
    double render_ms = 0, reorder_ms = 0, ao_tests = 0, ao_brute = 0, ao_rays = 0;
};

Result run(const PreparedScene& scene, const Order& o, const std::string& sort_algorithm,
           const std::string& backend, int size, int samples, int frames, const Settings& sets) {
    Settings s = sets;
    s.set("width", std::to_string(size));
    s.set("height", std::to_string(size));
    s.set("accel", "crsh");
    s.set("hash.mode", o.hash);
    if (*o.sort) s.set("sort.mode", o.sort);
    s.set("sort.algorithm", sort_algorithm);
    s.set("ao.samples", std::to_string(samples));
    s.set("ao.distance", std::to_string(0.1f * bounding_radius(scene)));
    s.set("trace.depth", "0");
    s.set("backend", backend);
    // The study renders the AO image: the other passes are not read back (unless --set asks).
    if (!sets.has("output.passes")) s.set("output.passes", "combined");
    Result r;
    try {
        const RenderSettings rs = RenderSettings::resolve(s, scene.settings);
        std::vector<Frame> runs;
        for (int i = 0; i < frames; ++i) runs.push_back(render_frame(scene, rs));
        std::sort(runs.begin(), runs.end(), [](const Frame& a, const Frame& b) {
            return a.stats.get("time_ms.frame") < b.stats.get("time_ms.frame");
        });
        const Stats& st = runs[runs.size() / 2].stats;
        r.reorder_ms = st.get("time_ms.hashing") + st.get("time_ms.compression") +
                       st.get("time_ms.sorting") + st.get("time_ms.decompression");
        r.render_ms = st.get("time_ms.frame") - r.reorder_ms;
        r.ao_tests = st.get("tests.ao.total");
        r.ao_brute = st.get("tests.ao.brute_force");
        r.ao_rays = st.get("rays.ao");
        r.ok = true;
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    return r;
}

} // namespace

int main(int argc, char** argv) {
    int size = 1024, samples = 16, frames = 1;
    std::vector<std::string> backends = {"cpu", "cuda"}, sorts = {"radix", "bitonic"}, scenes;
    Settings sets;
    std::string set_text; // the --set arguments, for the header
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--size")
            size = std::max(8, std::atoi(next().c_str()));
        else if (a == "--samples")
            samples = std::max(1, std::atoi(next().c_str()));
        else if (a == "--frames")
            frames = std::max(1, std::atoi(next().c_str()));
        else if (a == "--backends")
            backends = bench::split_list(next());
        else if (a == "--sorts")
            sorts = bench::split_list(next());
        else if (a == "--set") {
            std::string error;
            if (!bench::add_setting(sets, next(), error)) {
                std::fprintf(stderr, "sheaf_ao_study: %s\n", error.c_str());
                return 2;
            }
            set_text += " " + std::string(argv[i]);
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: sheaf_ao_study [--size N] [--samples S] [--frames K] "
                        "[--backends cpu,cuda] [--sorts radix,bitonic] [--set KEY=VALUE ...] "
                        "[scene ...]\n");
            return 0;
        } else
            scenes.push_back(a);
    }
    if (scenes.empty()) scenes = builtin_scene_names();

    std::printf("## Paper 003, Table 1: AO at %dx%d, %d rays per pixel\n\n", size, size, samples);
    std::printf("Reorder = hashing + compression + sorting + decompression; render = the rest "
                "of the frame (primary visibility, the AO rays and the image read back; other "
                "passes only when output.passes is set). Tests: AO ray-primitive tests as a "
                "share of brute force.\n");
    if (!set_text.empty()) std::printf("\nSettings given:%s\n", set_text.c_str());
    for (const std::string& backend : backends) {
        std::vector<PreparedScene> prepared;
        for (const std::string& n : scenes) prepared.push_back(ao_only(n));
        std::printf("\n### backend=%s\n\n| order | sort |", backend.c_str());
        for (const std::string& n : scenes)
            std::printf(" %s render ms | %s reorder ms | %s tests |", n.c_str(), n.c_str(),
                        n.c_str());
        std::printf("\n|---|---|");
        for (size_t i = 0; i < scenes.size(); ++i) std::printf("---:|---:|---:|");
        std::printf("\n");
        bool unavailable = false;
        for (const Order& o : kOrders) {
            // Static orders sort nothing the algorithm would change... except static 3D, whose
            // fixed permutation is applied by a sort: it is shown with each algorithm.
            const bool sorted = *o.sort || std::strcmp(o.hash, "static3d") == 0;
            for (const std::string& algorithm : sorted ? sorts : std::vector<std::string>{"-"}) {
                std::printf("| %s | %s |", o.label, algorithm.c_str());
                for (size_t k = 0; k < scenes.size(); ++k) {
                    const Result r = run(prepared[k], o, algorithm == "-" ? "radix" : algorithm,
                                         backend, size, samples, frames, sets);
                    if (!r.ok) {
                        std::printf(" unavailable | | |");
                        if (!unavailable) { // the library's message may name the backend
                            const bool named = r.error.rfind("backend=", 0) == 0;
                            const std::string what =
                                named ? r.error : "backend=" + backend + ": " + r.error;
                            std::fprintf(stderr, "%s\n", what.c_str());
                        }
                        unavailable = true;
                        continue;
                    }
                    std::printf(" %.0f | %.0f | %.2f%% |", r.render_ms, r.reorder_ms,
                                100.0 * r.ao_tests / std::max(1.0, r.ao_brute));
                }
                std::printf("\n");
                std::fflush(stdout);
                if (unavailable) break;
            }
            if (unavailable) break;
        }
    }
    return 0;
}

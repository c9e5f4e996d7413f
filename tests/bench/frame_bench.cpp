// Frame benchmark per backend: the built-in scenes at 512x512 and 1024x1024 with the default
// settings (accel=bvh), the time per phase, the frame time and rays per second, on the CPU and, when
// a CUDA device is usable, the GPU of the same machine.
//
// Usage: sheaf_frame_bench [--sizes 512,1024] [--frames K] [--backends cpu,cuda]
//                          [--set KEY=VALUE ...] [scene ...]
// A backend is a value of the setting `backend`, or `wavefront-cpu`: the CUDA module's pipeline
// (core/frame/wavefront_tracer.h) under the CPU policy, to weigh it against the CPU backend's.
// Times are the median of K frames (default 3), and the first frame's apart: on the CUDA
// backend the frames after the first find the scene on the device (device.scene_kept), so a
// first frame marked "copied" adds the scene's copy ("kept": an earlier size left it there). Rays
// per second counts every ray the frame traced: primary (one per sample) and secondary (shadow,
// reflection, refraction, AO).
#include "bench_args.h"
#include "core/backend/backend.h"
#include "core/frame/render_frame.h"
#include "core/scenes/builtin.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace sheaf;

namespace {

const char* const kPhases[] = {"raster",      "gbuffer",     "ray_creation",  "hashing",
                               "compression", "sorting",     "decompression", "hierarchy",
                               "traversal",   "final_tests", "shading"};

} // namespace

int main(int argc, char** argv) {
    std::vector<int> sizes = {512, 1024};
    int frames = 3;
    std::vector<std::string> backends = {"cpu", "cuda"}, scenes;
    Settings sets; // --set; each run sets its size and backend over these
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--sizes") {
            sizes.clear();
            for (const std::string& s : bench::split_list(next()))
                sizes.push_back(std::max(8, std::stoi(s)));
        } else if (a == "--frames") {
            frames = std::max(1, std::stoi(next()));
        } else if (a == "--backends") {
            backends = bench::split_list(next());
        } else if (a == "--set") {
            std::string error;
            if (!bench::add_setting(sets, next(), error)) {
                std::fprintf(stderr, "sheaf_frame_bench: %s\n", error.c_str());
                return 2;
            }
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: sheaf_frame_bench [--sizes 512,1024] [--frames K] "
                        "[--backends cpu,cuda] [--set KEY=VALUE ...] [scene ...]\n");
            return 0;
        } else {
            scenes.push_back(a);
        }
    }
    if (scenes.empty()) scenes = builtin_scene_names();

    std::printf("## Frames per backend (median of %d; ms; share of the frame)\n\n", frames);
    std::printf("| scene | size | backend | frame ms | first frame ms | rays | Mrays/s |");
    for (const char* p : kPhases) std::printf(" %s |", p);
    std::printf(" launches | host waits |");
    std::printf("\n|---|---:|---|---:|---:|---:|---:|");
    for (size_t i = 0; i < std::size(kPhases) + 2; ++i) std::printf("---:|");
    std::printf("\n");
    for (const std::string& name : scenes) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (int size : sizes)
            for (const std::string& backend : backends) {
                Settings s = sets;
                s.set("width", std::to_string(size));
                s.set("height", std::to_string(size));
                const bool wavefront = backend == "wavefront-cpu";
                std::vector<Frame> runs;
                try {
                    s.set("backend", wavefront ? "cpu" : backend);
                    const RenderSettings rs = RenderSettings::resolve(s, scene.settings);
                    for (int f = 0; f < frames; ++f)
                        runs.push_back(wavefront ? render_frame_wavefront_cpu(scene, rs)
                                                 : render_frame(scene, rs));
                } catch (const std::exception& e) {
                    std::printf("| %s | %d | %s | unavailable: %s |\n", name.c_str(), size,
                                backend.c_str(), e.what());
                    continue;
                }
                // Whether the first frame copied the scene or found it kept (an earlier size).
                const Stats& first = runs.front().stats;
                char first_ms[64];
                std::snprintf(first_ms, sizeof first_ms, "%.2f%s", first.get("time_ms.frame"),
                              !first.has("device.scene_kept")  ? ""
                              : first.get("device.scene_kept") ? " (kept)"
                                                               : " (copied)");
                std::sort(runs.begin(), runs.end(), [](const Frame& a, const Frame& b) {
                    return a.stats.get("time_ms.frame") < b.stats.get("time_ms.frame");
                });
                const Stats& st = runs[runs.size() / 2].stats;
                const double ms = st.get("time_ms.frame");
                const double rays = st.get("rays.primary") + st.get("rays.secondary");
                std::printf("| %s | %d | %s | %.2f | %s | %.0f | %.2f |", name.c_str(), size,
                            backend.c_str(), ms, first_ms, rays, rays / (ms * 1e3));
                for (const char* p : kPhases) {
                    const double t = st.get(std::string("time_ms.") + p);
                    std::printf(" %.2f (%.0f%%) |", t, ms > 0 ? 100 * t / ms : 0.0);
                }
                // The wavefront pipeline's fixed costs on a GPU (none for the CPU backend).
                if (st.has("device.launches"))
                    std::printf(" %.0f | %.0f |", st.get("device.launches"),
                                st.get("device.host_waits"));
                else
                    std::printf(" - | - |");
                std::printf("\n");
                std::fflush(stdout);
            }
    }
    return 0;
}

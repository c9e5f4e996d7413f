// Frame digests: every built-in scene (under several accel, hash and sampling settings), every
// test scene of the pipeline and every sample scene (scenes/*.pov, *.xml) rendered small on the
// CPU backend, each frame reduced to one line of 64-bit digests: its image, each pass, and its
// statistics (every counted key and value, by key; times, memory and device counters left
// out, they are measured rather than computed). The committed list (digests.txt) is what the
// frames were when it was written; the test `frame_digests` renders them again and compares, so
// a change that was meant to keep every picture and every count proves it did.
//
// Usage: sheaf_frame_digests [--scenes DIR] [--only SUBSTRING] [--stats]
// Prints "name | settings | rgba depth normal albedo object tests | stats" per frame; --stats
// also prints each frame's statistics (to see what a differing digest changed).
#include "core/backend/backend.h"
#include "core/scenes/builtin.h"
#include "io/image/raster.h"
#include "io/image/texture_sampler.h"
#include "io/scene/scene_file.h"
#include "tests/support/test_scenes.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

using namespace sheaf;

namespace {

// FNV-1a over bytes: stable across runs and builds, enough to tell frames apart.
uint64_t fnv(const void* data, size_t bytes, uint64_t h = 1469598103934665603ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}
template <class V> uint64_t digest(const V& v) {
    return fnv(v.data(), v.size() * sizeof(v[0]));
}

bool measured(const std::string& k) {
    return k.rfind("time_ms.", 0) == 0 || k.rfind("memory.", 0) == 0 ||
           k.rfind("device.", 0) == 0 || k.rfind("backend.", 0) == 0;
}

struct Options {
    std::string scenes_dir, only;
    bool stats = false;
};

void emit(const Options& o, const std::string& name, const PreparedScene& scene,
          const test::SettingList& kv, int w, int h) {
    const std::string label = test::label(name, kv);
    if (!o.only.empty() && label.find(o.only) == std::string::npos) return;
    test::SettingList all = kv;
    all.emplace_back("backend", "cpu");
    Frame f;
    try {
        f = render_frame(scene, test::settings_for(scene, all, w, h));
    } catch (const std::exception& e) {
        std::printf("%s | error: %s\n", label.c_str(), e.what());
        return;
    }
    // By key: a key first counted in a later band (band.samples) comes later in the list.
    std::vector<std::pair<std::string, double>> counted;
    for (const auto& e : f.stats.entries())
        if (!measured(e.first)) counted.push_back(e);
    std::sort(counted.begin(), counted.end());
    uint64_t stats = 1469598103934665603ull;
    for (const auto& [k, v] : counted) {
        stats = fnv(k.data(), k.size(), stats);
        stats = fnv(&v, sizeof v, stats);
    }
    std::printf("%s | %dx%d | %016" PRIx64 " %016" PRIx64 " %016" PRIx64 " %016" PRIx64
                " %016" PRIx64 " %016" PRIx64 " | %016" PRIx64 "\n",
                label.c_str(), w, h, digest(f.rgba), digest(f.depth), digest(f.normal),
                digest(f.albedo), digest(f.object_id), digest(f.tests), stats);
    if (o.stats)
        for (const auto& [k, v] : counted) std::printf("    %s = %.17g\n", k.c_str(), v);
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    o.scenes_dir = SHEAF_SCENES_DIR;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--scenes" && i + 1 < argc) {
            o.scenes_dir = argv[++i];
        } else if (a == "--only" && i + 1 < argc) {
            o.only = argv[++i];
        } else if (a == "--stats") {
            o.stats = true;
        } else {
            std::fprintf(stderr,
                         "usage: sheaf_frame_digests [--scenes DIR] [--only TEXT] [--stats]\n");
            return 2;
        }
    }
    // The default accel (bvh), then the ray hierarchies with their own settings, over the BVH,
    // and the strips.
    const std::vector<test::SettingList> builtin_variants = {
        {},
        {{"accel", "brute"}},
        {{"accel", "crsh"}},
        {{"accel", "rah"}, {"cull.objects", "false"}},
        {{"accel", "crsh"}, {"hash.mode", "hash192"}, {"ao.samples", "2"}},
        {{"accel", "crsh"}, {"hash.mode", "static3d"}, {"sort.algorithm", "bitonic"}},
        {{"accel", "crsh"}, {"aa.samples", "2"}, {"traversal.batch", "4096"}},
        {{"accel", "crsh"},
         {"cull.cluster", "0"},
         {"hierarchy.depth", "3"},
         {"hierarchy.arity", "4"}},
        {{"accel", "crsh-bvh"}},
        {{"accel", "rah-bvh"}, {"traversal.batch", "4096"}},
        {{"accel", "strips"}},
        {{"output.passes", "combined"}},
    };
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (const test::SettingList& kv : builtin_variants) emit(o, name, scene, kv, 64, 48);
    }
    const std::vector<std::pair<std::string, Scene>> cases = {
        {"glass_mirror", test::glass_mirror_scene()},
        {"lights", test::lights_scene(false)},
        {"lights_ortho", test::lights_scene(true)},
        {"csg", test::csg_scene()},
        {"julia", test::julia_scene()},
        {"media", test::media_scene(false)},
        {"media_inside", test::media_scene(true)},
        {"scattering", test::scattering_scene()},
        {"photons", test::photon_scene()},
        {"atmosphere", test::atmosphere_scene()},
        {"rainbow", test::rainbow_scene()},
        {"procedural", test::procedural_scene()},
    };
    for (const auto& [name, built] : cases) {
        const PreparedScene scene = prepare_scene(built);
        for (const test::SettingList& kv :
             {test::SettingList{}, test::SettingList{{"accel", "brute"}},
              test::SettingList{{"accel", "crsh"}},
              test::SettingList{{"accel", "crsh"}, {"ao.samples", "3"}, {"hash.mode", "hash32"}}})
            emit(o, name, scene, kv, 48, 36);
    }

    io::SceneFileOptions options;
    options.image_width = 64, options.image_height = 48;
    options.read_raster = &io::read_raster;
    options.attach_sampler = &io::attach_texture_sampler;
    if (std::filesystem::exists("/usr/share/povray-3.7/include"))
        options.include_paths.push_back("/usr/share/povray-3.7/include");
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(o.scenes_dir)) {
        const std::string ext = e.path().extension().string();
        if (ext == ".pov" || ext == ".xml" || ext == ".obj") files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    for (const std::string& path : files) {
        const std::string name = std::filesystem::path(path).filename().string();
        try {
            PreparedScene scene = prepare_scene(io::load_scene_file(path, options).scene);
            io::attach_texture_sampler(scene);
            emit(o, name, scene, {}, 64, 48);
        } catch (const std::exception& e) {
            std::printf("%s | error: %s\n", name.c_str(), e.what());
        }
    }
    return 0;
}

// Runs saved fuzz inputs (files, or every file in the folders given) through the checks the
// fuzzers make, each as the format of its extension (.capi: a host's C ABI calls; .accel:
// lattice meshes under every accel; .farm: a farm job's folder): the regression test of what
// fuzzing found, built with any compiler.
#include "tests/fuzz/capi_input.h"
#include "tests/fuzz/farm_input.h"
#include "tests/fuzz/scene_input.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const fs::path p = argv[i];
        if (fs::is_directory(p)) {
            for (const auto& entry : fs::directory_iterator(p))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
        } else {
            inputs.push_back(p);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    if (inputs.empty()) {
        std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...  (no inputs found)\n", argv[0]);
        return 2;
    }
    for (const fs::path& p : inputs) {
        const std::string ext = p.extension().string();
        if (ext != ".pov" && ext != ".xml" && ext != ".obj" && ext != ".ply" && ext != ".capi" &&
            ext != ".accel" && ext != ".farm") {
            std::fprintf(stderr,
                         "%s: the extension says no format (.pov .xml .obj .ply .capi .accel "
                         ".farm)\n",
                         p.c_str());
            return 2;
        }
        std::ifstream in(p, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), {}};
        std::printf("%s (%zu bytes)\n", p.filename().c_str(), bytes.size());
        std::fflush(stdout);
        const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
        if (ext == ".capi")
            sheaf::fuzz::run_capi_input(data, bytes.size(), stdout);
        else if (ext == ".farm")
            sheaf::fuzz::run_farm_input(data, bytes.size(), stdout);
        else if (ext == ".accel")
            sheaf::fuzz::run_capi_input(data, bytes.size(), stdout, sheaf::fuzz::CapiMode::Accels);
        else
            sheaf::fuzz::run_scene_input(data, bytes.size(), ext.c_str(), stdout);
    }
    std::printf("%zu inputs, no broken promise\n", inputs.size());
    return 0;
}

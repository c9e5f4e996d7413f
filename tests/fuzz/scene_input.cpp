#include "tests/fuzz/scene_input.h"

#include "tests/fuzz/promises.h"

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <unistd.h>

namespace sheaf::fuzz {
namespace {

/// A folder of this process's own for the input file (fuzzers run several processes at
/// once), removed when the process ends.
const std::string& work_dir() {
    struct Dir {
        std::filesystem::path path;
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Dir dir{std::filesystem::temp_directory_path() /
                         ("sheaf-fuzz-" + std::to_string(getpid()))};
    static const std::string name = [] {
        std::error_code ec;
        std::filesystem::create_directories(dir.path, ec);
        if (ec) broken("cannot create " + dir.path.string() + ": " + ec.message());
        return dir.path.string();
    }();
    return name;
}

/// Whether `message` starts "FILE:LINE:COL: ": an error in a file the scene includes names
/// that file.
bool names_a_place(const std::string& message) {
    static const std::regex place(R"(^[^:\s]+:[0-9]+:[0-9]+: )");
    return std::regex_search(message, place);
}

} // namespace

int run_scene_input(const uint8_t* data, size_t size, const char* ext, std::FILE* log) {
    const std::string path = work_dir() + "/input" + ext;
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        if (size && std::fwrite(data, 1, size, f) != size) broken("cannot write " + path);
        std::fclose(f);
    } else {
        broken("cannot write " + path);
    }
    SheafScene scene = nullptr;
    if (sheafSceneNew(&scene) != SHEAF_OK) broken("sheafSceneNew failed");
    SheafError e = sheafSceneLoadFile(scene, path.c_str());
    if (e != SHEAF_OK) {
        std::string message = failure("sheafSceneLoadFile", e);
        if (e != SHEAF_ERROR_SCENE && e != SHEAF_ERROR_OUT_OF_MEMORY)
            broken("a bad scene file gave error " + std::to_string(e) + ": " + message);
        if (message.find("input") == std::string::npos && !names_a_place(message))
            broken("the error names neither the file nor a FILE:LINE:COL: " + message);
        if (log) std::fprintf(log, "  load error %d: %s\n", int(e), message.c_str());
    } else if ((e = sheafSceneCommit(scene)) != SHEAF_OK) {
        const std::string message = failure("sheafSceneCommit", e);
        if (log) std::fprintf(log, "  commit error %d: %s\n", int(e), message.c_str());
    } else {
        render_small(scene, log);
    }
    sheafSceneRelease(scene);
    return 0;
}

} // namespace sheaf::fuzz

#include "tests/fuzz/scene_input.h"

#include "sheaf/sheaf.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>
#include <string>
#include <unistd.h>
#include <vector>

namespace sheaf::fuzz {
namespace {

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "sheaf fuzz: broken promise: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

/// The last error's message, and a broken promise when a failed call left none.
std::string failure(const char* call, SheafError code) {
    const char* message = nullptr;
    SheafError last = sheafGetLastError(&message);
    if (last != code)
        broken(std::string(call) + " returned " + std::to_string(code) +
               " but sheafGetLastError says " + std::to_string(last));
    if (!message || !*message) broken(std::string(call) + " failed without a message");
    return message;
}

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

void render_small(SheafScene scene, std::FILE* log) {
    SheafRenderer renderer = nullptr;
    if (sheafRendererNew(&renderer) != SHEAF_OK) broken("sheafRendererNew failed");
    // Small and single-threaded: a fuzzer runs many inputs a second. backend=cpu: the input
    // is what is under test, not the machine.
    const int width = 24, height = 16;
    if (sheafRendererSetInt(renderer, "width", width) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "height", height) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "threads", 1) != SHEAF_OK ||
        sheafRendererSetString(renderer, "backend", "cpu") != SHEAF_OK)
        broken("a documented setting was refused");
    SheafFrame frame = nullptr;
    SheafError e = sheafRender(renderer, scene, &frame);
    if (e != SHEAF_OK) {
        const std::string message = failure("sheafRender", e);
        if (log) std::fprintf(log, "  render error %d: %s\n", int(e), message.c_str());
    } else {
        int w = 0, h = 0;
        if (sheafFrameGetSize(frame, &w, &h) != SHEAF_OK || w != width || h != height)
            broken("the frame is not the size asked for");
        std::vector<float> rgba(size_t(w) * h * 4);
        if (sheafFrameGetPass(frame, "combined", rgba.data(), rgba.size()) != SHEAF_OK)
            broken("the combined pass cannot be read");
        for (size_t i = 0; i < rgba.size(); ++i)
            if (!std::isfinite(rgba[i]))
                broken("pixel " + std::to_string(i / 4) + " channel " + std::to_string(i % 4) +
                       " is " + std::to_string(rgba[i]));
        if (log) std::fprintf(log, "  rendered %dx%d\n", w, h);
        sheafFrameRelease(frame);
    }
    sheafRendererRelease(renderer);
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

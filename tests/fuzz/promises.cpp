#include "tests/fuzz/promises.h"

#include <cmath>
#include <cstdlib>
#include <vector>

namespace sheaf::fuzz {

void broken(const std::string& what) {
    std::fflush(stdout);
    std::fprintf(stderr, "sheaf fuzz: broken promise: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

std::string failure(const char* call, SheafError code) {
    const char* message = nullptr;
    SheafError last = sheafGetLastError(&message);
    if (last != code)
        broken(std::string(call) + " returned " + std::to_string(code) +
               " but sheafGetLastError says " + std::to_string(last));
    if (!message || !*message) broken(std::string(call) + " failed without a message");
    if (code == SHEAF_ERROR_UNKNOWN)
        broken(std::string(call) +
               " failed with SHEAF_ERROR_UNKNOWN (an exception the C ABI "
               "did not expect): " +
               message);
    return message;
}

void render_small(SheafScene scene, std::FILE* log, SheafRenderer renderer) {
    if (renderer) {
        if (sheafRendererRetain(renderer) != SHEAF_OK) broken("sheafRendererRetain failed");
    } else if (sheafRendererNew(&renderer) != SHEAF_OK) {
        broken("sheafRendererNew failed");
    }
    // Small and single-threaded: a fuzzer runs many inputs a second. backend=cpu: the input
    // is what is under test, not the machine. The whole frame: the size is checked.
    const int width = 24, height = 16;
    if (sheafRendererSetInt(renderer, "width", width) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "height", height) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "threads", 1) != SHEAF_OK ||
        sheafRendererSetString(renderer, "backend", "cpu") != SHEAF_OK)
        broken("a documented setting was refused");
    for (const char* key : {"region.x", "region.y", "region.width", "region.height"})
        if (sheafRendererUnset(renderer, key) != SHEAF_OK) broken("cannot unset a setting");
    SheafFrame frame = nullptr;
    SheafError e = sheafRender(renderer, scene, &frame);
    if (e != SHEAF_OK) {
        const std::string message = failure("sheafRender", e);
        if (frame) broken("a failed sheafRender returned a frame");
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

} // namespace sheaf::fuzz

#include "tests/fuzz/promises.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
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

namespace {

constexpr int kWidth = 24, kHeight = 16;

struct Rendered {
    bool ok = false;
    int x = 0, y = 0, width = 0, height = 0; // where the image lies in the whole frame
    std::vector<float> rgba;
};

// One render with the renderer as it is set, and the checks every frame gets.
Rendered render_once(SheafRenderer renderer, SheafScene scene, std::FILE* log) {
    Rendered r;
    SheafFrame frame = nullptr;
    SheafError e = sheafRender(renderer, scene, &frame);
    if (e != SHEAF_OK) {
        const std::string message = failure("sheafRender", e);
        if (frame) broken("a failed sheafRender returned a frame");
        if (log) std::fprintf(log, "  render error %d: %s\n", int(e), message.c_str());
        return r;
    }
    int full_width = 0, full_height = 0;
    if (sheafFrameGetSize(frame, &r.width, &r.height) != SHEAF_OK ||
        sheafFrameGetRegion(frame, &r.x, &r.y, &full_width, &full_height) != SHEAF_OK)
        broken("a frame's size cannot be read");
    if (full_width != kWidth || full_height != kHeight || r.width < 1 || r.height < 1 || r.x < 0 ||
        r.y < 0 || r.x + r.width > kWidth || r.y + r.height > kHeight)
        broken("the frame is not the size asked for: " + std::to_string(r.width) + "x" +
               std::to_string(r.height) + " at " + std::to_string(r.x) + "," + std::to_string(r.y) +
               " of " + std::to_string(full_width) + "x" + std::to_string(full_height));
    r.rgba.resize(size_t(r.width) * r.height * 4);
    if (sheafFrameGetPass(frame, "combined", r.rgba.data(), r.rgba.size()) != SHEAF_OK)
        broken("the combined pass cannot be read");
    for (size_t i = 0; i < r.rgba.size(); ++i)
        if (!std::isfinite(r.rgba[i]))
            broken("pixel " + std::to_string(i / 4) + " channel " + std::to_string(i % 4) + " is " +
                   std::to_string(r.rgba[i]));
    if (log) {
        double sum = 0;
        for (size_t i = 0; i < r.rgba.size(); ++i) sum += i % 4 == 3 ? 0 : r.rgba[i];
        std::fprintf(log, "  rendered %dx%d at %d,%d, mean %.4f\n", r.width, r.height, r.x, r.y,
                     sum / double(r.rgba.size() / 4 * 3));
    }
    sheafFrameRelease(frame);
    r.ok = true;
    return r;
}

} // namespace

std::vector<float> render_small(SheafScene scene, std::FILE* log, SheafRenderer renderer) {
    if (renderer) {
        if (sheafRendererRetain(renderer) != SHEAF_OK) broken("sheafRendererRetain failed");
    } else if (sheafRendererNew(&renderer) != SHEAF_OK) {
        broken("sheafRendererNew failed");
    }
    // Small and single-threaded: a fuzzer runs many inputs a second. backend=cpu: the input
    // is what is under test, not the machine.
    if (sheafRendererSetInt(renderer, "width", kWidth) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "height", kHeight) != SHEAF_OK ||
        sheafRendererSetInt(renderer, "threads", 1) != SHEAF_OK ||
        sheafRendererSetString(renderer, "backend", "cpu") != SHEAF_OK)
        broken("a documented setting was refused");
    Rendered part = render_once(renderer, scene, log);
    // The whole frame from here on (0: to the edge), over a scene file's own region too.
    for (const char* key : {"region.x", "region.y", "region.width", "region.height"})
        if (sheafRendererSetInt(renderer, key, 0) != SHEAF_OK) broken("cannot set a region");
    if (part.ok && (part.width != kWidth || part.height != kHeight)) {
        const Rendered whole = render_once(renderer, scene, log);
        if (!whole.ok) broken("a region rendered but the whole frame did not");
        if (whole.width != kWidth || whole.height != kHeight)
            broken("region.* set to 0 did not render the whole frame");
        for (int j = 0; j < part.height; ++j)
            for (int i = 0; i < part.width; ++i) {
                const float* a = &part.rgba[(size_t(j) * part.width + i) * 4];
                const float* b = &whole.rgba[(size_t(j + part.y) * kWidth + i + part.x) * 4];
                if (std::memcmp(a, b, 4 * sizeof(float)) != 0)
                    broken("pixel " + std::to_string(i + part.x) + "," +
                           std::to_string(j + part.y) +
                           " of a region differs from the whole "
                           "frame's: " +
                           std::to_string(a[0]) + " against " + std::to_string(b[0]));
            }
        part = whole;
    }
    sheafRendererRelease(renderer);
    return part.rgba;
}

} // namespace sheaf::fuzz

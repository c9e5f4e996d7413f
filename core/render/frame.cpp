#include "core/render/frame.h"

namespace sheaf {

bool frame_has_pass(const Frame& f, std::string_view pass) {
    const size_t pixels = size_t(f.width > 0 ? f.width : 0) * size_t(f.height > 0 ? f.height : 0);
    if (pixels == 0) return false;
    if (pass == "combined") return f.rgba.size() >= 4 * pixels;
    if (pass == "depth") return f.depth.size() >= pixels;
    if (pass == "normal") return f.normal.size() >= pixels;
    if (pass == "albedo") return f.albedo.size() >= pixels;
    if (pass == "object_id") return f.object_id.size() >= pixels;
    if (pass == "tests") return f.tests.size() >= pixels;
    return false;
}

std::string missing_pass(const Frame& f, std::string_view pass) {
    std::string out = "the frame has no '" + std::string(pass) + "' pass";
    for (const auto& [key, value] : f.settings)
        if (key == "output.passes") return out + " (output.passes=" + value + ")";
    return out;
}

} // namespace sheaf

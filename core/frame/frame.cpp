#include "core/frame/frame.h"

#include <algorithm>
#include <iterator>

namespace sheaf {

bool frame_has_pass(const Frame& f, std::string_view pass) {
    const size_t pixels = size_t(f.width > 0 ? f.width : 0) * size_t(f.height > 0 ? f.height : 0);
    const std::vector<std::string>& names = pass_names();
    const auto it = std::find(names.begin(), names.end(), pass);
    if (pixels == 0 || it == names.end()) return false;
    // Elements held, in pass_names() order (combined: 4 floats a pixel).
    const size_t held[] = {f.rgba.size() / 4, f.depth.size(),     f.normal.size(),
                           f.albedo.size(),   f.object_id.size(), f.tests.size()};
    static_assert(std::size(held) == 6, "one entry per pass");
    return held[it - names.begin()] >= pixels;
}

std::string missing_pass(const Frame& f, std::string_view pass) {
    std::string out = "the frame has no '" + std::string(pass) + "' pass";
    for (const auto& [key, value] : f.settings)
        if (key == "output.passes") return out + " (output.passes=" + value + ")";
    return out;
}

} // namespace sheaf

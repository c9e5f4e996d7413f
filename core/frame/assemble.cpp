#include "core/frame/assemble.h"

#include "core/base/error.h"

#include <algorithm>
#include <string>

namespace sheaf {
namespace {

bool is_region_key(const std::string& key) { return key.rfind("region.", 0) == 0; }

std::vector<std::pair<std::string, std::string>> whole_settings(const Frame& f) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& kv : f.settings)
        if (!is_region_key(kv.first)) out.push_back(kv);
    return out;
}

std::string where(const Frame& f) {
    return std::to_string(f.width) + "x" + std::to_string(f.height) + " at (" +
           std::to_string(f.x) + ", " + std::to_string(f.y) + ")";
}

// Copies `per` values a pixel of a part's pass into the whole's, row by row.
template <class T>
void paste(const std::vector<T>& from, std::vector<T>& to, const Frame& part, int whole_width,
           size_t per) {
    for (int y = 0; y < part.height; ++y)
        std::copy_n(from.begin() + ptrdiff_t(size_t(y) * size_t(part.width) * per),
                    size_t(part.width) * per,
                    to.begin() + ptrdiff_t((size_t(part.y + y) * size_t(whole_width) +
                                            size_t(part.x)) * per));
}

} // namespace

Frame assemble_frame(const std::vector<const Frame*>& parts) {
    if (parts.empty()) throw RenderError("no parts to put together");
    const Frame& first = *parts.front();
    Frame out;
    out.width = first.full_width > 0 ? first.full_width : first.width;
    out.height = first.full_height > 0 ? first.full_height : first.height;
    out.full_width = out.width, out.full_height = out.height;
    out.settings = whole_settings(first);
    out.backend = first.backend, out.backend_line = first.backend_line;
    const size_t pixels = size_t(out.width) * size_t(out.height);
    auto sized = [&](const auto& pass, size_t n) { return pass.empty() ? size_t(0) : n; };
    out.rgba.resize(sized(first.rgba, 4 * pixels));
    out.depth.resize(sized(first.depth, pixels));
    out.normal.resize(sized(first.normal, pixels));
    out.albedo.resize(sized(first.albedo, pixels));
    out.object_id.resize(sized(first.object_id, pixels));
    out.tests.resize(sized(first.tests, pixels));
    std::vector<uint32_t> owner(pixels, 0); // 1 + the part that covers each pixel
    for (size_t k = 0; k < parts.size(); ++k) {
        const Frame& p = *parts[k];
        const std::string name = "part " + std::to_string(k + 1) + " (" + where(p) + ")";
        const int fw = p.full_width > 0 ? p.full_width : p.width;
        const int fh = p.full_height > 0 ? p.full_height : p.height;
        if (fw != out.width || fh != out.height)
            throw RenderError(name + " is of a " + std::to_string(fw) + "x" + std::to_string(fh) +
                              " frame, part 1 of a " + std::to_string(out.width) + "x" +
                              std::to_string(out.height) + " one");
        if (p.width <= 0 || p.height <= 0 || p.x < 0 || p.y < 0 || p.x + p.width > out.width ||
            p.y + p.height > out.height)
            throw RenderError(name + " does not lie within the " + std::to_string(out.width) +
                              "x" + std::to_string(out.height) + " frame");
        const size_t n = size_t(p.width) * size_t(p.height);
        auto same_passes = [&](const auto& a, const auto& b, size_t per) {
            return a.empty() == b.empty() && (a.empty() || a.size() == n * per);
        };
        if (!same_passes(p.rgba, first.rgba, 4) || !same_passes(p.depth, first.depth, 1) ||
            !same_passes(p.normal, first.normal, 1) || !same_passes(p.albedo, first.albedo, 1) ||
            !same_passes(p.object_id, first.object_id, 1) || !same_passes(p.tests, first.tests, 1))
            throw RenderError(name + " keeps other passes than part 1 (output.passes)");
        const auto settings = whole_settings(p);
        if (settings != out.settings) {
            std::string diff;
            for (const auto& kv : settings)
                if (std::find(out.settings.begin(), out.settings.end(), kv) == out.settings.end()) {
                    diff = kv.first + "=" + kv.second;
                    break;
                }
            throw RenderError(name + " was rendered with other settings than part 1" +
                              (diff.empty() ? std::string() : " (" + diff + ")"));
        }
        for (int y = p.y; y < p.y + p.height; ++y)
            for (int x = p.x; x < p.x + p.width; ++x) {
                uint32_t& o = owner[size_t(y) * size_t(out.width) + size_t(x)];
                if (o != 0)
                    throw RenderError(name + " overlaps part " + std::to_string(o) + " at pixel (" +
                                      std::to_string(x) + ", " + std::to_string(y) + ")");
                o = uint32_t(k + 1);
            }
        paste(p.rgba, out.rgba, p, out.width, 4);
        paste(p.depth, out.depth, p, out.width, 1);
        paste(p.normal, out.normal, p, out.width, 1);
        paste(p.albedo, out.albedo, p, out.width, 1);
        paste(p.object_id, out.object_id, p, out.width, 1);
        paste(p.tests, out.tests, p, out.width, 1);
        for (const auto& [key, v] : p.stats.entries()) {
            if (key.rfind("frame.", 0) == 0 || key.rfind("scene.", 0) == 0) {
                if (k == 0) out.stats.set(key, v);
            } else if (key.rfind("memory.", 0) == 0) {
                out.stats.set(key, std::max(out.stats.get(key), v));
            } else {
                out.stats.add(key, v);
            }
        }
    }
    const auto hole = std::find(owner.begin(), owner.end(), 0u);
    if (hole != owner.end()) {
        const size_t i = size_t(hole - owner.begin());
        throw RenderError("the parts leave pixel (" + std::to_string(i % size_t(out.width)) +
                          ", " + std::to_string(i / size_t(out.width)) + ") of the " +
                          std::to_string(out.width) + "x" + std::to_string(out.height) +
                          " frame uncovered");
    }
    out.stats.set("frame.width", out.width);
    out.stats.set("frame.height", out.height);
    out.stats.set("frame.parts", double(parts.size()));
    if (out.stats.has("tests.share_of_brute_force")) {
        const double brute = out.stats.get("tests.brute_force");
        out.stats.set("tests.share_of_brute_force",
                      brute > 0 ? out.stats.get("tests.total") / brute : 0.0);
    }
    return out;
}

} // namespace sheaf

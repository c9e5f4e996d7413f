#include "merge.h"

#include "single.h"

#include <iostream>

namespace render {

int run_merge(const Options& o) {
    std::vector<Frame> parts;
    std::vector<SheafFrame> raw;
    for (const std::string& path : o.merge) {
        SheafFrame f = nullptr;
        if (sheafFrameLoadImage(path.c_str(), &f) != SHEAF_OK) return error(kRender, last_error());
        parts.emplace_back(f);
        raw.push_back(f);
    }
    SheafFrame whole_raw = nullptr;
    if (sheafFrameAssemble(raw.data(), raw.size(), &whole_raw) != SHEAF_OK)
        return error(kRender, "--merge: " + last_error());
    Frame whole(whole_raw);
    if (int rc = save_image(whole.get(), o.output)) return rc;
    if (!o.quiet) {
        int w = 0, h = 0;
        sheafFrameGetSize(whole.get(), &w, &h);
        std::cout << "wrote " << o.output << " (" << w << "x" << h << ", " << parts.size()
                  << (parts.size() == 1 ? " part)\n" : " parts)\n");
    }
    return write_stats(whole.get(), o.stats, o.stats_json);
}

} // namespace render

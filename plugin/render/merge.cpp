#include "merge.h"

#include "single.h"

#include <cstdio>
#include <fstream>
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
    if (o.stats) {
        auto table = frame_text(whole.get(), "stats.table");
        if (!table) return error(kRender, "--stats: " + last_error());
        std::cout << *table;
    }
    if (!o.stats_json.empty()) {
        const std::optional<std::string> json = frame_text(whole.get(), "stats.json");
        std::ofstream out(o.stats_json);
        if (!json || !(out << *json << "\n"))
            return error(kRender, "--stats-json " + o.stats_json + ": cannot write the file");
    }
    return kOk;
}

} // namespace render

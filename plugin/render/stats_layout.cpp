// The rows and columns of the papers' tables, found from the statistic keys themselves.
#include "stats_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace render {

namespace {

constexpr const char* kTypes[] = {"shadow",  "reflection", "refraction", "ao",
                                  "diffuse", "camera",     "photon"};

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

} // namespace

std::vector<std::string> traced_types(const std::vector<RunResult>& results) {
    std::vector<std::string> out;
    for (const char* type : kTypes)
        for (const RunResult& r : results)
            if (r.stat(std::string("rays.") + type) > 0) {
                out.push_back(type);
                break;
            }
    return out;
}

std::vector<std::string> level_rows(const std::vector<RunResult>& results,
                                    const std::string& type) {
    const std::string prefix = "tests." + type + ".";
    bool objects = false, nodes = false, final_row = false;
    int top = 0;
    for (const RunResult& r : results)
        for (const auto& [key, value] : r.stats) {
            if (!starts_with(key, prefix)) continue;
            const std::string rest = key.substr(prefix.size());
            if (starts_with(rest, "objects.")) objects = true;
            if (starts_with(rest, "final.")) final_row = true;
            if (starts_with(rest, "nodes.")) nodes = true;
            if (starts_with(rest, "level")) top = std::max(top, std::atoi(rest.c_str() + 5));
        }
    std::vector<std::string> rows;
    if (objects) rows.push_back("objects");
    for (int k = top; k >= 1; --k) rows.push_back("level" + std::to_string(k));
    if (nodes) rows.push_back("nodes");
    if (final_row) rows.push_back("final");
    return rows;
}

std::string row_label(const std::string& row) {
    if (row == "nodes") return "bvh nodes";
    return starts_with(row, "level") ? "level " + row.substr(5) : row;
}

std::vector<std::string> phases(const std::vector<RunResult>& results) {
    std::vector<std::string> out;
    for (const RunResult& r : results)
        for (const auto& [key, value] : r.stats)
            if (starts_with(key, "time_ms.") && key != "time_ms.frame") {
                const std::string phase = key.substr(8);
                if (std::find(out.begin(), out.end(), phase) == out.end()) out.push_back(phase);
            }
    return out;
}

std::string with_commas(double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", std::round(value));
    std::string digits = buf, out;
    const bool negative = !digits.empty() && digits[0] == '-';
    if (negative) digits.erase(0, 1);
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return negative ? "-" + out : out;
}

std::string percent(double share) {
    return fixed(share * 100.0, 2) + "%";
}

std::string fixed(double value, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    return buf;
}

} // namespace render

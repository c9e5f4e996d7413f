// Writing the results of a comparison or sweep as JSON and CSV.
#include "results_files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace render {

namespace {

constexpr const char* kTotals[] = {"tests.total", "tests.brute_force", "share", "time_ms.frame"};

double total_value(const RunResult& r, const std::string& key) {
    return key == "share" ? r.share() : r.stat(key);
}

std::string csv_number(double v) {
    return std::isfinite(v) ? json_number(v) : std::string();
}

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[64];
    if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string results_json(const ResultsMeta& meta, const std::vector<RunResult>& results) {
    std::string out = "{\n";
    out += "  \"mode\": " + json_string(meta.mode) + ",\n";
    out += "  \"scene\": " + json_string(meta.scene) + ",\n";
    out += "  \"command\": " + json_string(meta.command) + ",\n";
    out += "  \"version\": " + json_string(meta.version) + ",\n";
    if (meta.images_identical)
        out += std::string("  \"images_identical\": ") +
               (*meta.images_identical ? "true" : "false") + ",\n";
    if (meta.best && !results.empty())
        out +=
            "  \"best\": {\"fewest_tests\": " + json_string(results[meta.best->fewest_tests].name) +
            ", \"fastest\": " + json_string(results[meta.best->fastest].name) + "},\n";
    out += "  \"entries\": [";
    for (size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        out +=
            std::string(i ? "," : "") + "\n    {\n      \"name\": " + json_string(r.name) + ",\n";
        if (!r.grid.empty()) {
            out += "      \"grid\": {";
            for (size_t g = 0; g < r.grid.size(); ++g)
                out += std::string(g ? ", " : "") + json_string(r.grid[g].first) + ": " +
                       json_string(r.grid[g].second);
            out += "},\n";
        }
        out += "      \"totals\": {";
        for (size_t t = 0; t < std::size(kTotals); ++t)
            out += std::string(t ? ", " : "") + json_string(kTotals[t]) + ": " +
                   json_number(total_value(r, kTotals[t]));
        out += "},\n      \"settings\": {";
        const auto settings = r.settings_list();
        for (size_t s = 0; s < settings.size(); ++s)
            out += std::string(s ? ", " : "") + json_string(settings[s].first) + ": " +
                   json_string(settings[s].second);
        out += "},\n      \"stats\": {";
        for (size_t s = 0; s < r.stats.size(); ++s)
            out += std::string(s ? "," : "") + "\n        " + json_string(r.stats[s].first) + ": " +
                   json_number(r.stats[s].second);
        out += "\n      }\n    }";
    }
    out += "\n  ]\n}\n";
    return out;
}

std::string results_csv(const std::vector<RunResult>& results) {
    std::vector<std::string> grid_keys, stat_keys;
    for (const RunResult& r : results) {
        for (const auto& [key, value] : r.grid)
            if (std::find(grid_keys.begin(), grid_keys.end(), key) == grid_keys.end())
                grid_keys.push_back(key);
        for (const auto& [key, value] : r.stats)
            if (std::find(std::begin(kTotals), std::end(kTotals), key) == std::end(kTotals) &&
                std::find(stat_keys.begin(), stat_keys.end(), key) == stat_keys.end())
                stat_keys.push_back(key);
    }
    std::string out = "name";
    // Appended piece by piece: "," + csv_cell(k) trips GCC 12's -Wrestrict false positive.
    for (const std::string& k : grid_keys) out.append(",").append(csv_cell(k));
    for (const char* k : kTotals) out.append(",").append(k);
    for (const std::string& k : stat_keys) out.append(",").append(csv_cell(k));
    out += "\n";
    for (const RunResult& r : results) {
        out += csv_cell(r.name);
        for (const std::string& k : grid_keys) {
            std::string value;
            for (const auto& [key, v] : r.grid)
                if (key == k) value = v;
            out.append(",").append(csv_cell(value));
        }
        for (const char* k : kTotals) out.append(",").append(csv_number(total_value(r, k)));
        for (const std::string& k : stat_keys)
            out.append(",").append(r.has(k) ? csv_number(r.stat(k)) : std::string());
        out += "\n";
    }
    return out;
}

bool write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    return static_cast<bool>(out << text) && static_cast<bool>(out.flush());
}

} // namespace render

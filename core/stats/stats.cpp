#include "core/stats/stats.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <cstdlib>

namespace sheaf {

void Stats::set(std::string_view key, double value) {
    auto it = index_.find(std::string(key));
    if (it != index_.end()) {
        entries_[it->second].second = value;
        return;
    }
    index_.emplace(std::string(key), entries_.size());
    entries_.emplace_back(std::string(key), value);
}

void Stats::add(std::string_view key, double value) {
    set(key, get(key) + value);
}

double Stats::get(std::string_view key) const {
    auto it = index_.find(std::string(key));
    return it == index_.end() ? 0.0 : entries_[it->second].second;
}

bool Stats::has(std::string_view key) const {
    return index_.count(std::string(key)) != 0;
}

namespace {

std::string number(double v) {
    char buf[64];
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else if (std::isfinite(v))
        std::snprintf(buf, sizeof buf, "%.9g", v);
    else
        std::snprintf(buf, sizeof buf, "null");
    return buf;
}

std::string grouped(double v) {
    std::string s = number(v);
    if (s.find_first_of(".e") != std::string::npos || s == "null") return s;
    std::string out;
    int n = 0;
    for (auto it = s.rbegin(); it != s.rend(); ++it) {
        if (n && n % 3 == 0 && *it != '-') out.push_back(',');
        out.push_back(*it);
        ++n;
    }
    return {out.rbegin(), out.rend()};
}

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out.push_back('\\');
        out.push_back(c);
    }
    return out;
}

} // namespace

std::string Stats::to_json() const {
    std::ostringstream os;
    os << "{\n";
    for (size_t i = 0; i < entries_.size(); ++i)
        os << "  \"" << escape(entries_[i].first) << "\": " << number(entries_[i].second)
           << (i + 1 < entries_.size() ? ",\n" : "\n");
    os << "}\n";
    return os.str();
}

Stats Stats::from_json(std::string_view json) {
    Stats out;
    size_t i = 0;
    auto skip = [&] {
        while (i < json.size() && std::isspace(static_cast<unsigned char>(json[i]))) ++i;
    };
    auto fail = [&](const char* what) {
        throw std::invalid_argument(std::string("statistics JSON: ") + what + " at offset " +
                                    std::to_string(i));
    };
    skip();
    if (i >= json.size() || json[i++] != '{') fail("expected '{'");
    for (skip(); i < json.size() && json[i] != '}'; skip()) {
        if (json[i++] != '"') fail("expected a key");
        std::string key;
        while (i < json.size() && json[i] != '"') {
            if (json[i] == '\\' && i + 1 < json.size()) ++i;
            key.push_back(json[i++]);
        }
        if (i++ >= json.size()) fail("unterminated key");
        skip();
        if (i >= json.size() || json[i++] != ':') fail("expected ':'");
        skip();
        const size_t end = json.find_first_of(",}", i);
        if (end == std::string_view::npos) fail("unterminated object");
        std::string text(json.substr(i, end - i));
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
        double v = std::nan("");
        if (text != "null") {
            char* stop = nullptr;
            v = std::strtod(text.c_str(), &stop);
            if (text.empty() || *stop != '\0') fail("expected a number");
        }
        out.set(key, v);
        i = end;
        if (json[i] == ',') ++i;
    }
    if (i >= json.size()) fail("expected '}'");
    return out;
}

std::string Stats::to_table() const {
    std::ostringstream os;
    char line[256];
    auto row = [&](const std::string& label, double a) {
        std::snprintf(line, sizeof line, "  %-28s %18s\n", label.c_str(), grouped(a).c_str());
        os << line;
    };

    os << "Rays\n";
    std::vector<std::string> types;
    for (auto& [k, v] : entries_) {
        if (k.rfind("rays.", 0) != 0) continue;
        const std::string type = k.substr(5);
        row(type, v);
        if (v > 0 && type != "primary" && type != "secondary") types.push_back(type);
    }

    for (const std::string& t : types) {
        const std::string p = "tests." + t + ".";
        // The ray hierarchy's top nodes (rah, crsh); a BVH has none.
        const std::string top = "hierarchy." + t + ".top_nodes";
        if (has(top))
            std::snprintf(line, sizeof line, "\nIntersection tests: %s (%s rays, %s top nodes)\n",
                          t.c_str(), grouped(get("rays." + t)).c_str(), grouped(get(top)).c_str());
        else
            std::snprintf(line, sizeof line, "\nIntersection tests: %s (%s rays)\n", t.c_str(),
                          grouped(get("rays." + t)).c_str());
        os << line;
        std::snprintf(line, sizeof line, "  %-12s %18s %18s %18s\n", "", "tests", "hits", "misses");
        os << line;
        auto level_row = [&](const std::string& label, const std::string& key) {
            if (!has(p + key + ".tests")) return;
            std::snprintf(line, sizeof line, "  %-12s %18s %18s %18s\n", label.c_str(),
                          grouped(get(p + key + ".tests")).c_str(),
                          grouped(get(p + key + ".hits")).c_str(),
                          grouped(get(p + key + ".misses")).c_str());
            os << line;
        };
        level_row("objects", "objects");
        for (int k = 16; k >= 1; --k)
            level_row("level " + std::to_string(k), "level" + std::to_string(k));
        level_row("nodes", "nodes"); // the BVH's boxes, or the strips' boxes and planes
        level_row("final", "final");
        const double total = get(p + "total"), brute = get(p + "brute_force");
        std::snprintf(line, sizeof line, "  %-12s %18s   %.2f%% of brute force (%s)\n", "total",
                      grouped(total).c_str(), brute > 0 ? 100.0 * total / brute : 0.0,
                      grouped(brute).c_str());
        os << line;
    }

    const double total = get("tests.total"), brute = get("tests.brute_force");
    os << "\nTotals (hierarchy levels or structure nodes + final tests; object-sphere tests on "
          "their "
          "own row)\n";
    row("tests.total", total);
    row("tests.objects", get("tests.objects"));
    row("tests.brute_force", brute);
    std::snprintf(line, sizeof line, "  %-28s %17.2f%%\n", "share of brute force",
                  brute > 0 ? 100.0 * total / brute : 0.0);
    os << line;

    const double frame = get("time_ms.frame");
    os << "\nTime per phase                       ms     share\n";
    for (auto& [k, v] : entries_) {
        if (k.rfind("time_ms.", 0) != 0) continue;
        std::snprintf(line, sizeof line, "  %-24s %12.3f %8.2f%%\n", k.substr(8).c_str(), v,
                      frame > 0 ? 100.0 * v / frame : 0.0);
        os << line;
    }
    os << "\nMemory\n";
    for (auto& [k, v] : entries_)
        if (k.rfind("memory.", 0) == 0) row(k.substr(7), v);
    return os.str();
}

} // namespace sheaf

// The comparison and sweep tables as text.
#include "tables.h"

#include "stats_layout.h"
#include "text_table.h"

namespace render {

namespace {

std::string count_or_dash(const RunResult& r, const std::string& key) {
    return r.has(key) ? with_commas(r.stat(key)) : "-";
}

} // namespace

std::string type_tables(const std::vector<RunResult>& results) {
    std::string out;
    for (const std::string& type : traced_types(results)) {
        std::string rays;
        for (const RunResult& r : results)
            rays += (rays.empty() ? "" : ", ") + r.name + " " + with_commas(r.stat("rays." + type));
        out += "Intersection tests: " + type + " (rays: " + rays + ")\n";
        TextTable t;
        t.header.push_back("");
        for (const RunResult& r : results) {
            t.groups.emplace_back(r.name, 3);
            t.header.insert(t.header.end(), {"tests", "hits", "misses"});
        }
        const std::string prefix = "tests." + type + ".";
        for (const std::string& row : level_rows(results, type)) {
            std::vector<std::string> cells{row_label(row)};
            for (const RunResult& r : results)
                for (const char* what : {".tests", ".hits", ".misses"})
                    cells.push_back(count_or_dash(r, prefix + row + what));
            t.rows.push_back(cells);
        }
        std::vector<std::string> total{"total"}, brute{"brute force"}, share{"share"};
        for (const RunResult& r : results) {
            const double b = r.stat(prefix + "brute_force");
            total.insert(total.end(), {count_or_dash(r, prefix + "total"), "", ""});
            brute.insert(brute.end(), {with_commas(b), "", ""});
            share.insert(share.end(),
                         {b > 0 ? percent(r.stat(prefix + "total") / b) : "-", "", ""});
        }
        t.rows.insert(t.rows.end(), {total, brute, share});
        out += t.str() + "\n";
    }
    return out;
}

std::string totals_table(const std::vector<RunResult>& results) {
    if (results.empty()) return "";
    TextTable t;
    const double first = results.front().stat("tests.total");
    t.header = {"",
                "tests.total",
                "tests.brute_force",
                "share of brute force",
                "vs " + results.front().name,
                "frame ms"};
    for (const RunResult& r : results)
        t.rows.push_back({r.name, with_commas(r.stat("tests.total")),
                          with_commas(r.stat("tests.brute_force")), percent(r.share()),
                          first > 0 ? fixed(r.stat("tests.total") / first, 3) + "x" : "-",
                          fixed(r.stat("time_ms.frame"), 1)});
    return "Totals (levels or bvh nodes + final tests; object-sphere tests not counted, as in the "
           "paper)\n" +
           t.str() + "\n";
}

std::string phase_table(const std::vector<RunResult>& results) {
    TextTable t;
    t.header.push_back("");
    for (const RunResult& r : results) {
        t.groups.emplace_back(r.name, 2);
        t.header.insert(t.header.end(), {"ms", "share"});
    }
    std::vector<std::string> names = phases(results);
    names.push_back("frame");
    for (const std::string& phase : names) {
        std::vector<std::string> cells{phase};
        for (const RunResult& r : results) {
            const double frame = r.stat("time_ms.frame"), ms = r.stat("time_ms." + phase);
            cells.push_back(fixed(ms, 3));
            cells.push_back(frame > 0 ? percent(ms / frame) : "-");
        }
        t.rows.push_back(cells);
    }
    return "Time per phase\n" + t.str() + "\n";
}

Best find_best(const std::vector<RunResult>& results) {
    Best best;
    for (size_t i = 1; i < results.size(); ++i) {
        if (results[i].stat("tests.total") < results[best.fewest_tests].stat("tests.total"))
            best.fewest_tests = i;
        if (results[i].stat("time_ms.frame") < results[best.fastest].stat("time_ms.frame"))
            best.fastest = i;
    }
    return best;
}

std::string sweep_table(const std::vector<RunResult>& results, const Best& best) {
    if (results.empty()) return "";
    TextTable t;
    for (const auto& [key, value] : results.front().grid) t.header.push_back(key);
    t.header.insert(t.header.end(), {"tests.total", "share of brute force", "frame ms", ""});
    for (size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        std::vector<std::string> cells;
        for (const auto& [key, value] : r.grid) cells.push_back(value);
        std::string mark;
        if (i == best.fewest_tests) mark += "fewest tests";
        if (i == best.fastest) mark += std::string(mark.empty() ? "" : ", ") + "fastest";
        cells.insert(cells.end(), {with_commas(r.stat("tests.total")), percent(r.share()),
                                   fixed(r.stat("time_ms.frame"), 1), mark});
        t.rows.push_back(cells);
    }
    // The first column is left-aligned; keep every axis right-aligned by starting with "".
    for (auto& row : t.rows) row.insert(row.begin(), "");
    t.header.insert(t.header.begin(), "");
    return "Sweep (" + std::to_string(results.size()) + " settings)\n" + t.str() + "\n";
}

std::string best_lines(const std::vector<RunResult>& results, const Best& best) {
    if (results.empty()) return "";
    const RunResult& f = results[best.fewest_tests];
    const RunResult& s = results[best.fastest];
    return "fewest tests: " + f.name + " (" + with_commas(f.stat("tests.total")) + " tests, " +
           percent(f.share()) + " of brute force)\nfastest frame: " + s.name + " (" +
           fixed(s.stat("time_ms.frame"), 1) + " ms)\n";
}

} // namespace render

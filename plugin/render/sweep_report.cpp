// The sweep report page. The last axis runs along x; every combination of the other axes is
// one line.
#include "sweep_report.h"

#include "html_page.h"
#include "stats_layout.h"
#include "svg_chart.h"

namespace render {

namespace {

/// One chart over the grid of `key` ("share" for the share of brute force).
std::string grid_chart(const std::vector<Axis>& axes, const std::vector<RunResult>& results,
                       const std::string& title, const std::string& y_label, const std::string& key,
                       size_t best, bool log_y) {
    const Axis& x = axes.back();
    const size_t per_line = x.values.size();
    std::vector<Series> series;
    for (size_t i = 0; i < results.size(); ++i) {
        if (i % per_line == 0) {
            std::string name;
            for (size_t a = 0; a + 1 < axes.size(); ++a)
                name += (name.empty() ? "" : " ") + results[i].grid[a].first + "=" +
                        results[i].grid[a].second;
            series.push_back({name.empty() ? y_label : name, {}});
        }
        series.back().values.push_back(results[i].stat(key));
    }
    ChartOptions o;
    o.title = title;
    o.y_label = y_label;
    o.x_label = x.key;
    o.log_y = log_y;
    o.width = 600;
    o.height = 340;
    o.highlight.emplace_back(best / per_line, best % per_line);
    return line_chart(x.values, series, o);
}

/// Whether the values of `key` span more than two decades (then the chart is logarithmic).
bool wide_range(const std::vector<RunResult>& results, const std::string& key) {
    double lo = 0, hi = 0;
    for (const RunResult& r : results) {
        const double v = r.stat(key);
        if (v <= 0) continue;
        lo = lo == 0 ? v : std::min(lo, v);
        hi = std::max(hi, v);
    }
    return lo > 0 && hi / lo > 100;
}

} // namespace

std::string sweep_html(const ResultsMeta& meta, const std::vector<Axis>& axes,
                       const std::vector<RunResult>& results, const Best& best) {
    std::string title = "Sheaf parameter sweep:";
    for (const Axis& a : axes) title += " " + a.key;
    std::string out = page_begin(title, meta);
    if (results.empty() || axes.empty()) return out + page_end();
    const RunResult& few = results[best.fewest_tests];
    const RunResult& fast = results[best.fastest];
    out += "<div class=\"verdict ok\">Fewest tests: " + escape_xml(few.name) + " (" +
           with_commas(few.stat("tests.total")) + " tests, " + percent(few.share()) +
           " of brute force)<br>Fastest frame: " + escape_xml(fast.name) + " (" +
           fixed(fast.stat("time_ms.frame"), 1) + " ms)</div>\n";
    out += "<h2>Charts</h2>\n<div class=\"charts\">\n";
    out += grid_chart(axes, results, "Total tests", "tests.total", "tests.total", best.fewest_tests,
                      wide_range(results, "tests.total"));
    out += grid_chart(axes, results, "Frame time", "ms", "time_ms.frame", best.fastest,
                      wide_range(results, "time_ms.frame"));
    out += "</div>\n<p class=\"meta\">Ringed: the best point of each chart.</p>\n";

    std::vector<std::vector<std::string>> rows(1);
    for (const Axis& a : axes) rows[0].push_back(a.key);
    rows[0].insert(rows[0].end(), {"tests.total", "share of brute force", "frame ms", "best"});
    std::vector<std::string> classes{""};
    for (size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        std::vector<std::string> row;
        for (const auto& [key, value] : r.grid) row.push_back(value);
        std::string mark;
        if (i == best.fewest_tests) mark = "fewest tests";
        if (i == best.fastest) mark += std::string(mark.empty() ? "" : ", ") + "fastest";
        row.insert(row.end(), {with_commas(r.stat("tests.total")), percent(r.share()),
                               fixed(r.stat("time_ms.frame"), 1), mark});
        rows.push_back(row);
        classes.push_back(mark.empty() ? "" : "best");
    }
    out += "<h2>Grid</h2>\n" + html_table(rows, classes);
    std::vector<RunResult> shown{few};
    if (best.fastest != best.fewest_tests) shown.push_back(fast);
    out += "<h2>Settings of the best</h2>\n" + html_settings_table(shown);
    return out + page_end();
}

} // namespace render

// The comparison report page.
#include "compare_report.h"

#include "html_page.h"
#include "images.h"
#include "stats_layout.h"
#include "svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace render {

namespace {

std::string verdict(const std::vector<RunResult>& results,
                    const std::vector<std::string>& differences) {
    std::string bad;
    for (const std::string& d : differences)
        if (!d.empty()) bad += "<li>" + escape_xml(d) + "</li>";
    if (bad.empty())
        return "<p class=\"verdict ok\">All " + std::to_string(results.size()) +
               " images are identical to " + escape_xml(results.front().name) +
               "&rsquo;s, pixel for pixel: the accel modes are exact.</p>\n";
    return "<div class=\"verdict bad\">Images differ from " + escape_xml(results.front().name) +
           "&rsquo;s:<ul>" + bad + "</ul></div>\n";
}

std::string totals(const std::vector<RunResult>& results) {
    const double first = results.front().stat("tests.total");
    std::vector<std::vector<std::string>> rows{{"preset", "tests.total", "tests.brute_force",
                                                "share of brute force",
                                                "vs " + results.front().name, "frame ms"}};
    for (const RunResult& r : results)
        rows.push_back({r.name, with_commas(r.stat("tests.total")),
                        with_commas(r.stat("tests.brute_force")), percent(r.share()),
                        first > 0 ? fixed(r.stat("tests.total") / first, 3) + "x" : "-",
                        fixed(r.stat("time_ms.frame"), 1)});
    return "<h2>Totals</h2>\n<p class=\"meta\">Levels plus final tests; the object-sphere tests "
           "are not counted, as in the paper.</p>\n" +
           html_table(rows);
}

std::string figure(const std::string& src, const std::string& caption,
                   const std::string& cls = "") {
    return "<figure" + (cls.empty() ? "" : " class=\"" + cls + "\"") + "><img src=\"" +
           escape_xml(src) + "\" alt=\"" + escape_xml(caption) + "\"><figcaption>" +
           escape_xml(caption) + "</figcaption></figure>\n";
}

std::string gallery(const std::vector<RunResult>& results,
                    const std::vector<std::string>& differences, const CompareImages& im) {
    const size_t n = results.size();
    std::string out = "<h2>Images</h2>\n<div class=\"grid\" style=\"grid-template-columns: 110px "
                      "repeat(" +
                      std::to_string(n) + ", minmax(0, 320px))\">\n<div></div>\n";
    for (const RunResult& r : results)
        out += "<div class=\"rowlabel\">" + escape_xml(r.name) + "</div>\n";
    out += "<div class=\"rowlabel\">image</div>\n";
    for (size_t i = 0; i < n; ++i)
        out += figure(im.image[i], results[i].name + ", " + std::to_string(results[i].width) + "x" +
                                       std::to_string(results[i].height));
    char gain[32];
    std::snprintf(gain, sizeof gain, "%g", double(im.gain));
    out += "<div class=\"rowlabel\">difference from " + escape_xml(results[0].name) + " (&times;" +
           gain + ")</div>\n";
    for (size_t i = 0; i < n; ++i) {
        if (i == 0)
            out += "<figure><figcaption>the reference</figcaption></figure>\n";
        else
            out += differences[i].empty() ? figure(im.difference[i], "identical (black)", "small")
                                          : figure(im.difference[i], differences[i]);
    }
    out += "<div class=\"rowlabel\">tests per pixel</div>\n";
    for (size_t i = 0; i < n; ++i) {
        double total = 0, peak = 0;
        for (float t : results[i].tests) {
            total += t;
            peak = std::max(peak, double(t));
        }
        out += figure(im.heat[i],
                      "max " + with_commas(peak) + " per pixel, " + with_commas(total) + " in all");
    }
    out += "</div>\n<p class=\"meta\">Heat maps share one log scale of the exact "
           "ray&ndash;primitive tests per pixel (all secondary rays of the pixel; black: none): " +
           with_commas(im.min_tests) +
           " <span class=\"scale\" style=\"background: "
           "linear-gradient(to right";
    for (int s = 0; s <= 8; ++s) out += ", " + heat_colour(0.08 + 0.92 * s / 8.0);
    out += ")\"></span> " + with_commas(im.max_tests) + "</p>\n";
    return out;
}

std::string charts(const std::vector<RunResult>& results) {
    std::string out = "<h2>Charts</h2>\n<div class=\"charts\">\n";
    for (const std::string& type : traced_types(results)) {
        const std::vector<std::string> rows = level_rows(results, type);
        std::vector<std::string> categories;
        for (const std::string& row : rows) categories.push_back(row_label(row));
        std::vector<Series> series;
        for (const RunResult& r : results) {
            Series s{r.name, {}};
            for (const std::string& row : rows) {
                const std::string key = "tests." + type + "." + row + ".tests";
                s.values.push_back(r.has(key) ? r.stat(key) : NAN);
            }
            series.push_back(s);
        }
        ChartOptions o;
        o.title = "Tests per level: " + type + " rays";
        o.y_label = "tests";
        o.log_y = true;
        o.width = 600;
        out += bar_chart(categories, series, o);
    }
    std::vector<std::string> names = phases(results);
    std::vector<Series> series;
    for (const RunResult& r : results) {
        Series s{r.name, {}};
        for (const std::string& p : names) s.values.push_back(r.stat("time_ms." + p));
        series.push_back(s);
    }
    ChartOptions o;
    o.title = "Time per phase";
    o.y_label = "ms";
    o.log_y = true;
    o.width = 1212;
    o.height = 340;
    out += bar_chart(names, series, o);
    return out + "</div>\n";
}

std::string phase_table_html(const std::vector<RunResult>& results) {
    std::vector<std::vector<std::string>> rows{{"phase"}};
    for (const RunResult& r : results) {
        rows[0].push_back(r.name + " ms");
        rows[0].push_back(r.name + " share");
    }
    std::vector<std::string> names = phases(results);
    names.push_back("frame");
    for (const std::string& p : names) {
        std::vector<std::string> row{p};
        for (const RunResult& r : results) {
            const double ms = r.stat("time_ms." + p), frame = r.stat("time_ms.frame");
            row.push_back(fixed(ms, 3));
            row.push_back(frame > 0 ? percent(ms / frame) : "-");
        }
        rows.push_back(row);
    }
    std::vector<std::string> classes(rows.size());
    classes.back() = "sum";
    return "<h2>Time per phase</h2>\n" + html_table(rows, classes);
}

} // namespace

std::string compare_html(const ResultsMeta& meta, const std::vector<RunResult>& results,
                         const std::vector<std::string>& differences, const CompareImages& images) {
    std::string names;
    for (const RunResult& r : results) names += (names.empty() ? "" : ", ") + r.name;
    std::string out = page_begin("Sheaf preset comparison: " + names, meta);
    if (results.empty()) return out + page_end();
    out += verdict(results, differences);
    out += totals(results);
    out += gallery(results, differences, images);
    out += charts(results);
    out += "<h2>Intersection tests per ray type and level</h2>\n" + html_type_tables(results);
    out += phase_table_html(results);
    out += "<h2>Settings</h2>\n<p class=\"meta\">The effective settings of each frame; values "
           "that differ are marked.</p>\n" +
           html_settings_table(results);
    return out + page_end();
}

} // namespace render

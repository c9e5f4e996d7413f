// The report's page frame, style sheet and statistic tables.
#include "html_page.h"

#include "stats_layout.h"
#include "svg_chart.h"

#include <algorithm>
#include <map>

namespace render {

namespace {

const char* const kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; margin: 24px auto;
       max-width: 1240px; padding: 0 16px; color: #222; background: #fafafa; }
h1 { font-size: 24px; margin-bottom: 4px; }
h2 { font-size: 19px; margin-top: 32px; border-bottom: 1px solid #ddd; padding-bottom: 4px; }
h3 { font-size: 15px; margin: 18px 0 6px; }
.meta { color: #666; font-size: 13px; }
.meta code { background: #eee; padding: 1px 4px; border-radius: 3px; }
.verdict { padding: 10px 14px; border-radius: 6px; margin: 16px 0; font-weight: 600; }
.verdict.ok { background: #e3f4e1; border: 1px solid #9ccf96; }
.verdict.bad { background: #fbe3e3; border: 1px solid #e39a9a; }
table { border-collapse: collapse; margin: 6px 0 14px; font-size: 13px; background: #fff; }
th, td { border: 1px solid #ddd; padding: 3px 8px; text-align: right; white-space: nowrap; }
th { background: #f0f0f0; }
td:first-child, th:first-child { text-align: left; }
tr.best td { background: #fff4cc; font-weight: 600; }
tr.sum td { border-top: 2px solid #999; }
td.differs { background: #ffe7c2; font-weight: 600; }
.grid { display: grid; gap: 12px; align-items: start; }
figure { margin: 0; background: #fff; border: 1px solid #ddd; padding: 6px; border-radius: 4px; }
figure img { width: 100%; image-rendering: pixelated; display: block; }
figure.small img { width: 30%; }
figcaption { font-size: 12px; color: #444; margin-top: 4px; }
.rowlabel { font-size: 13px; font-weight: 600; align-self: center; }
.charts { display: flex; flex-wrap: wrap; gap: 12px; }
svg.chart { background: #fff; border: 1px solid #ddd; border-radius: 4px; }
.scale { height: 12px; width: 240px; display: inline-block; vertical-align: middle;
         border: 1px solid #ccc; }
)";

std::string cell_tag(size_t row, const std::string& text) {
    const char* tag = row == 0 ? "th" : "td";
    return std::string("<") + tag + ">" + escape_xml(text) + "</" + tag + ">";
}

} // namespace

std::string page_begin(const std::string& title, const ResultsMeta& meta) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           escape_xml(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
           escape_xml(title) + "</h1>\n<p class=\"meta\">Scene <code>" + escape_xml(meta.scene) +
           "</code> &middot; Sheaf " + escape_xml(meta.version) + " &middot; <code>" +
           escape_xml(meta.command) + "</code></p>\n";
}

std::string page_end() {
    return "<p class=\"meta\">Written by the Sheaf render tool. Counts are exact; times are one "
           "measurement each.</p>\n</body>\n</html>\n";
}

std::string html_table(const std::vector<std::vector<std::string>>& rows,
                       const std::vector<std::string>& classes) {
    std::string out = "<table>\n";
    for (size_t r = 0; r < rows.size(); ++r) {
        const std::string cls =
            r < classes.size() && !classes[r].empty() ? " class=\"" + classes[r] + "\"" : "";
        out += "<tr" + cls + ">";
        for (const std::string& cell : rows[r]) out += cell_tag(r, cell);
        out += "</tr>\n";
    }
    return out + "</table>\n";
}

std::string html_type_tables(const std::vector<RunResult>& results) {
    std::string out;
    for (const std::string& type : traced_types(results)) {
        const std::string prefix = "tests." + type + ".";
        out += "<h3>" + escape_xml(type) + " rays</h3>\n<table>\n<tr><th rowspan=\"2\">level</th>";
        for (const RunResult& r : results)
            out += "<th colspan=\"3\">" + escape_xml(r.name) + " (" +
                   with_commas(r.stat("rays." + type)) + " rays)</th>";
        out += "</tr>\n<tr>";
        for (size_t i = 0; i < results.size(); ++i)
            out += "<th>tests</th><th>hits</th><th>misses</th>";
        out += "</tr>\n";
        for (const std::string& row : level_rows(results, type)) {
            out += "<tr><td>" + escape_xml(row_label(row)) + "</td>";
            for (const RunResult& r : results)
                for (const char* what : {".tests", ".hits", ".misses"}) {
                    const std::string key = prefix + row + what;
                    out += "<td>" + (r.has(key) ? with_commas(r.stat(key)) : "&ndash;") + "</td>";
                }
            out += "</tr>\n";
        }
        out += "<tr class=\"sum\"><td>total</td>";
        for (const RunResult& r : results) {
            const double b = r.stat(prefix + "brute_force");
            out += "<td>" + with_commas(r.stat(prefix + "total")) + "</td><td colspan=\"2\">" +
                   (b > 0 ? percent(r.stat(prefix + "total") / b) : "&ndash;") + " of " +
                   with_commas(b) + "</td>";
        }
        out += "</tr>\n</table>\n";
    }
    return out;
}

std::string html_settings_table(const std::vector<RunResult>& results) {
    std::vector<std::string> keys;
    std::vector<std::map<std::string, std::string>> values;
    for (const RunResult& r : results) {
        values.emplace_back();
        for (const auto& [k, v] : r.settings_list()) {
            if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
            values.back()[k] = v;
        }
    }
    std::string out = "<table>\n<tr><th>setting</th>";
    for (const RunResult& r : results) out += "<th>" + escape_xml(r.name) + "</th>";
    out += "</tr>\n";
    for (const std::string& k : keys) {
        bool same = true;
        for (const auto& v : values)
            same = same && v.count(k) && values[0].count(k) && v.at(k) == values[0].at(k);
        out += "<tr><td>" + escape_xml(k) + "</td>";
        for (const auto& v : values) {
            const auto it = v.find(k);
            out += std::string(same ? "<td>" : "<td class=\"differs\">") +
                   (it == v.end() ? "&ndash;" : escape_xml(it->second)) + "</td>";
        }
        out += "</tr>\n";
    }
    return out + "</table>\n";
}

} // namespace render

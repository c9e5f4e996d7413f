// Inline SVG charts for the HTML report: grouped bar charts (tests per level, time per phase)
// and line charts (a sweep's totals over its grid). Plain SVG text, no scripts or fonts.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace render {

struct Series {
    std::string name;
    std::vector<double> values; ///< one per category or x position; NaN for none
};

struct ChartOptions {
    std::string title, y_label, x_label;
    bool log_y = false; ///< decades on the y axis; values <= 0 are not drawn
    int width = 640, height = 320;
    /// Points to ring in a line chart: (series, index).
    std::vector<std::pair<size_t, size_t>> highlight;
};

/// Bars grouped by category, one colour per series, each with a <title> of its exact value.
std::string bar_chart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                      const ChartOptions& options);

/// One polyline per series over evenly spaced x positions labelled `x_labels`.
std::string line_chart(const std::vector<std::string>& x_labels, const std::vector<Series>& series,
                       const ChartOptions& options);

/// The colour of series i, "#rrggbb".
std::string series_colour(size_t i);

/// Escapes &, <, >, " and ' for HTML and SVG text and attributes.
std::string escape_xml(const std::string& s);

/// A short number for axis labels: 950, 1.2k, 34M, 5G, 0.25.
std::string short_number(double v);

} // namespace render

// Inline SVG bar and line charts: axes with round ticks (linear or decades), a legend, values
// in <title> elements for hovering.
#include "svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace render {

namespace {

constexpr const char* kPalette[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2",
                                    "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};

struct Frame {
    double left = 72, right = 16, top = 34, bottom = 64;
    double width, height;
    double plot_w() const { return width - left - right; }
    double plot_h() const { return height - top - bottom; }
};

/// Maps values to the plot's y pixels, with the ticks to draw.
struct YAxis {
    bool log = false;
    double lo = 0, hi = 1;
    std::vector<double> ticks;

    YAxis(const std::vector<Series>& series, bool log_y) : log(log_y) {
        double mn = INFINITY, mx = -INFINITY;
        for (const Series& s : series)
            for (double v : s.values) {
                if (!std::isfinite(v) || (log && v <= 0)) continue;
                mn = std::min(mn, v);
                mx = std::max(mx, v);
            }
        if (!std::isfinite(mx)) mn = mx = log ? 1 : 0;
        if (log) {
            hi = std::ceil(std::log10(mx));
            // At most six decades: smaller values sit on the axis.
            lo = std::max(std::floor(std::log10(mn)), hi - 6);
            hi = std::max(lo + 1, hi);
            for (double d = lo; d <= hi + 1e-9; ++d) ticks.push_back(std::pow(10.0, d));
        } else {
            lo = 0;
            const double top = mx > 0 ? mx : 1;
            const double raw = top / 5, mag = std::pow(10.0, std::floor(std::log10(raw)));
            const double step = raw / mag <= 1   ? mag
                                : raw / mag <= 2 ? 2 * mag
                                : raw / mag <= 5 ? 5 * mag
                                                 : 10 * mag;
            hi = std::ceil(top / step) * step;
            for (double t = 0; t <= hi + step * 1e-6; t += step) ticks.push_back(t);
        }
    }
    /// 0 at the bottom of the plot, 1 at the top.
    double unit(double v) const {
        if (log) return (std::log10(v) - lo) / (hi - lo);
        return (v - lo) / (hi - lo);
    }
    bool drawable(double v) const { return std::isfinite(v) && (!log || v > 0); }
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string exact(double v) {
    char buf[64];
    if (v == std::floor(v) && std::fabs(v) < 1e15)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string open_svg(const Frame& f, const ChartOptions& o) {
    std::string out = "<svg class=\"chart\" width=\"" + num(f.width) + "\" height=\"" +
                      num(f.height) + "\" viewBox=\"0 0 " + num(f.width) + " " + num(f.height) +
                      "\" font-family=\"sans-serif\" font-size=\"11\" role=\"img\">\n";
    out += "<title>" + escape_xml(o.title) + "</title>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    out += "<text x=\"" + num(f.width / 2) +
           "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" +
           escape_xml(o.title) + "</text>\n";
    return out;
}

std::string y_axis(const Frame& f, const YAxis& y, const ChartOptions& o) {
    std::string out;
    for (double t : y.ticks) {
        const double py = f.top + f.plot_h() * (1 - y.unit(t));
        out += "<line x1=\"" + num(f.left) + "\" x2=\"" + num(f.left + f.plot_w()) + "\" y1=\"" +
               num(py) + "\" y2=\"" + num(py) + "\" stroke=\"#e0e0e0\"/>\n";
        out += "<text x=\"" + num(f.left - 6) + "\" y=\"" + num(py + 4) +
               "\" text-anchor=\"end\">" + escape_xml(short_number(t)) + "</text>\n";
    }
    out += "<line x1=\"" + num(f.left) + "\" x2=\"" + num(f.left) + "\" y1=\"" + num(f.top) +
           "\" y2=\"" + num(f.top + f.plot_h()) + "\" stroke=\"#333\"/>\n";
    out += "<line x1=\"" + num(f.left) + "\" x2=\"" + num(f.left + f.plot_w()) + "\" y1=\"" +
           num(f.top + f.plot_h()) + "\" y2=\"" + num(f.top + f.plot_h()) +
           "\" stroke=\"#333\"/>\n";
    const std::string label = o.y_label + (y.log ? " (log scale)" : "");
    out += "<text transform=\"translate(14," + num(f.top + f.plot_h() / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escape_xml(label) + "</text>\n";
    return out;
}

std::string legend(const Frame& f, const std::vector<Series>& series) {
    std::string out;
    double x = f.left;
    const double y = f.height - 14;
    for (size_t i = 0; i < series.size(); ++i) {
        out += "<rect x=\"" + num(x) + "\" y=\"" + num(y - 9) +
               "\" width=\"10\" height=\"10\" fill=\"" + series_colour(i) + "\"/>\n";
        out += "<text x=\"" + num(x + 14) + "\" y=\"" + num(y) + "\">" +
               escape_xml(series[i].name) + "</text>\n";
        x += 24 + 6.5 * double(series[i].name.size());
    }
    return out;
}

} // namespace

std::string series_colour(size_t i) {
    return kPalette[i % std::size(kPalette)];
}

std::string escape_xml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string short_number(double v) {
    const double a = std::fabs(v);
    char buf[32];
    const char* suffix = "";
    double shown = v;
    if (a >= 1e9) {
        shown = v / 1e9;
        suffix = "G";
    } else if (a >= 1e6) {
        shown = v / 1e6;
        suffix = "M";
    } else if (a >= 1e3) {
        shown = v / 1e3;
        suffix = "k";
    }
    std::snprintf(buf, sizeof buf, "%.3g%s", shown, suffix);
    return buf;
}

std::string bar_chart(const std::vector<std::string>& categories, const std::vector<Series>& series,
                      const ChartOptions& o) {
    Frame f;
    f.width = o.width;
    f.height = o.height;
    const YAxis y(series, o.log_y);
    std::string out = open_svg(f, o) + y_axis(f, y, o);
    const double group = f.plot_w() / double(std::max<size_t>(categories.size(), 1));
    const double bar = group * 0.8 / double(std::max<size_t>(series.size(), 1));
    for (size_t c = 0; c < categories.size(); ++c) {
        const double gx = f.left + group * double(c);
        out += "<text x=\"" + num(gx + group / 2) + "\" y=\"" + num(f.top + f.plot_h() + 16) +
               "\" text-anchor=\"middle\">" + escape_xml(categories[c]) + "</text>\n";
        for (size_t s = 0; s < series.size(); ++s) {
            const double v = c < series[s].values.size() ? series[s].values[c] : NAN;
            if (!y.drawable(v)) continue;
            const double u = std::clamp(y.unit(v), 0.0, 1.0);
            const double h = f.plot_h() * u, x = gx + group * 0.1 + bar * double(s);
            out += "<rect x=\"" + num(x) + "\" y=\"" + num(f.top + f.plot_h() - h) + "\" width=\"" +
                   num(std::max(bar - 1, 1.0)) + "\" height=\"" + num(h) + "\" fill=\"" +
                   series_colour(s) + "\"><title>" +
                   escape_xml(series[s].name + ", " + categories[c] + ": " + exact(v)) +
                   "</title></rect>\n";
        }
    }
    out += legend(f, series) + "</svg>\n";
    return out;
}

std::string line_chart(const std::vector<std::string>& x_labels, const std::vector<Series>& series,
                       const ChartOptions& o) {
    Frame f;
    f.width = o.width;
    f.height = o.height;
    const YAxis y(series, o.log_y);
    std::string out = open_svg(f, o) + y_axis(f, y, o);
    const size_t n = std::max<size_t>(x_labels.size(), 1);
    auto px = [&](size_t i) {
        return n == 1 ? f.left + f.plot_w() / 2
                      : f.left + 20 + (f.plot_w() - 40) * double(i) / double(n - 1);
    };
    auto py = [&](double v) { return f.top + f.plot_h() * (1 - std::clamp(y.unit(v), 0.0, 1.0)); };
    for (size_t i = 0; i < x_labels.size(); ++i)
        out += "<text x=\"" + num(px(i)) + "\" y=\"" + num(f.top + f.plot_h() + 16) +
               "\" text-anchor=\"middle\">" + escape_xml(x_labels[i]) + "</text>\n";
    if (!o.x_label.empty())
        out += "<text x=\"" + num(f.left + f.plot_w() / 2) + "\" y=\"" +
               num(f.top + f.plot_h() + 32) + "\" text-anchor=\"middle\">" + escape_xml(o.x_label) +
               "</text>\n";
    for (size_t s = 0; s < series.size(); ++s) {
        std::string points;
        for (size_t i = 0; i < series[s].values.size() && i < x_labels.size(); ++i)
            if (y.drawable(series[s].values[i]))
                points += num(px(i)) + "," + num(py(series[s].values[i])) + " ";
        out += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + series_colour(s) +
               "\" points=\"" + points + "\"/>\n";
        for (size_t i = 0; i < series[s].values.size() && i < x_labels.size(); ++i) {
            const double v = series[s].values[i];
            if (!y.drawable(v)) continue;
            out += "<circle cx=\"" + num(px(i)) + "\" cy=\"" + num(py(v)) + "\" r=\"3.5\" fill=\"" +
                   series_colour(s) + "\"><title>" +
                   escape_xml(series[s].name + ", " + x_labels[i] + ": " + exact(v)) +
                   "</title></circle>\n";
        }
    }
    for (const auto& [s, i] : o.highlight)
        if (s < series.size() && i < series[s].values.size() && y.drawable(series[s].values[i]))
            out += "<circle cx=\"" + num(px(i)) + "\" cy=\"" + num(py(series[s].values[i])) +
                   "\" r=\"8\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>\n";
    out += legend(f, series) + "</svg>\n";
    return out;
}

} // namespace render

// Parsing the sweep's axes and expanding their product.
#include "grid.h"

#include <cerrno>
#include <cstdlib>

namespace render {

namespace {

/// An integer, the whole text; false when it is not one.
bool parse_int(const std::string& s, long long& out) {
    if (s.empty()) return false;
    errno = 0;
    char* end = nullptr;
    out = std::strtoll(s.c_str(), &end, 10);
    return errno == 0 && end && *end == '\0';
}

} // namespace

Axis parse_axis(const std::string& spec) {
    const size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0)
        throw GridError("--sweep '" + spec + "': expected KEY=A..B or KEY=V1,V2,...");
    Axis axis{spec.substr(0, eq), {}};
    const std::string values = spec.substr(eq + 1);
    const size_t dots = values.find("..");
    if (dots != std::string::npos) {
        long long a = 0, b = 0;
        if (!parse_int(values.substr(0, dots), a) || !parse_int(values.substr(dots + 2), b))
            throw GridError("--sweep '" + spec + "': a range is two integers, A..B");
        if (b < a)
            throw GridError("--sweep '" + spec + "': the range " + std::to_string(a) + ".." +
                            std::to_string(b) + " is empty");
        if (b - a >= static_cast<long long>(kMaxGridPoints))
            throw GridError("--sweep '" + spec + "': the range has more than " +
                            std::to_string(kMaxGridPoints) + " values");
        for (long long v = a; v <= b; ++v) axis.values.push_back(std::to_string(v));
        return axis;
    }
    size_t start = 0;
    while (true) {
        const size_t comma = values.find(',', start);
        const std::string v =
            values.substr(start, comma == std::string::npos ? comma : comma - start);
        if (v.empty()) throw GridError("--sweep '" + spec + "': an empty value");
        axis.values.push_back(v);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return axis;
}

std::vector<std::vector<std::pair<std::string, std::string>>>
grid_points(const std::vector<Axis>& axes) {
    size_t count = 1;
    for (size_t i = 0; i < axes.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
            if (axes[j].key == axes[i].key)
                throw GridError("--sweep: the key '" + axes[i].key + "' is given twice");
        count *= axes[i].values.size();
        if (count > kMaxGridPoints)
            throw GridError("--sweep: the grid has more than " + std::to_string(kMaxGridPoints) +
                            " points");
    }
    std::vector<std::vector<std::pair<std::string, std::string>>> points;
    if (axes.empty()) return points;
    for (size_t n = 0; n < count; ++n) {
        std::vector<std::pair<std::string, std::string>> point(axes.size());
        size_t rest = n;
        for (size_t i = axes.size(); i-- > 0;) {
            point[i] = {axes[i].key, axes[i].values[rest % axes[i].values.size()]};
            rest /= axes[i].values.size();
        }
        points.push_back(point);
    }
    return points;
}

} // namespace render

// The sweep's grid: axes written KEY=A..B (integers, inclusive) or KEY=V1,V2,..., and the
// points of their product, the first axis outermost.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace render {

/// A malformed axis; the message names it.
struct GridError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Axis {
    std::string key;
    std::vector<std::string> values;
};

/// The most points a sweep may have.
constexpr size_t kMaxGridPoints = 4096;

/// Parses one axis. Throws GridError for a missing '=', an empty value, or a bad range.
Axis parse_axis(const std::string& spec);

/// Every point: one (key, value) per axis. Throws GridError when a key repeats or there are
/// more than kMaxGridPoints points.
std::vector<std::vector<std::pair<std::string, std::string>>>
grid_points(const std::vector<Axis>& axes);

} // namespace render

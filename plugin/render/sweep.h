// render --sweep KEY=VALUES...: the scene rendered once per point of the grid (on top of the
// --preset, -W/-H/--threads and --set), the totals tabulated, the best setting named, and with
// --report DIR line charts over the grid and the results files.
#pragma once

#include "grid.h"
#include "options.h"
#include "run_result.h"

namespace render {

/// Runs the sweep; returns the exit code.
int run_sweep(const Options& o);

/// The axes of o.sweep; throws GridError on a malformed one.
std::vector<Axis> sweep_axes(const Options& o);

/// A grid point's name: "key=value key=value".
std::string point_name(const std::vector<std::pair<std::string, std::string>>& point);

/// The sweep's tables on stdout and, with o.report, its report folder: what run_sweep prints
/// and writes once every point has rendered (a farm's merge calls it with the points' results).
int report_sweep(const Options& o, const std::vector<Axis>& axes,
                 const std::vector<RunResult>& results);

} // namespace render

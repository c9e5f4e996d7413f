// The sweep's HTML report: the best setting named, line charts of total tests and frame time
// over the grid, the table of grid points, and the settings of the best.
#pragma once

#include "grid.h"
#include "results_files.h"
#include "run_result.h"
#include "tables.h"

#include <string>
#include <vector>

namespace render {

std::string sweep_html(const ResultsMeta& meta, const std::vector<Axis>& axes,
                       const std::vector<RunResult>& results, const Best& best);

} // namespace render

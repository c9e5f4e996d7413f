// The papers' tables as text for several results side by side: per ray type and level
// tests/hits/misses, totals with the share of brute force, time per phase; and the sweep's
// table of grid points with the best named.
#pragma once

#include "run_result.h"

#include <string>
#include <vector>

namespace render {

/// Per ray type, the rows of level_rows() plus total, brute force and share, three columns
/// (tests, hits, misses) per result.
std::string type_tables(const std::vector<RunResult>& results);

/// One row per result: tests.total, tests.brute_force, share, the ratio to the first result's
/// total, frame time.
std::string totals_table(const std::vector<RunResult>& results);

/// One row per phase: ms and share of the frame per result.
std::string phase_table(const std::vector<RunResult>& results);

/// The indices of the results with the fewest tests.total and the shortest time_ms.frame
/// (the first on ties).
struct Best {
    size_t fewest_tests = 0, fastest = 0;
};
Best find_best(const std::vector<RunResult>& results);

/// One row per grid point: the axis values, tests.total, share, frame time, marks for the best.
std::string sweep_table(const std::vector<RunResult>& results, const Best& best);

/// "fewest tests: NAME (N tests, S of brute force)" and "fastest frame: NAME (T ms)" lines.
std::string best_lines(const std::vector<RunResult>& results, const Best& best);

} // namespace render

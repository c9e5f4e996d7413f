// results.json and results.csv: one entry per preset or grid point with its totals
// (tests.total, tests.brute_force, share, time_ms.frame), settings and every statistic.
#pragma once

#include "run_result.h"
#include "tables.h"

#include <optional>
#include <string>
#include <vector>

namespace render {

struct ResultsMeta {
    std::string mode; ///< "compare" or "sweep"
    std::string scene, command, version;
    std::optional<bool> images_identical; ///< compare
    std::optional<Best> best;             ///< sweep
};

/// A number as JSON: integers exactly, others with 9 significant digits, null when not finite.
std::string json_number(double v);
/// A string as a JSON string literal, quotes included.
std::string json_string(const std::string& s);

/// The JSON document: the meta fields and "entries": [{name, grid, totals, settings, stats}].
std::string results_json(const ResultsMeta& meta, const std::vector<RunResult>& results);

/// The CSV: a header, then one line per result: name, the grid axes, tests.total,
/// tests.brute_force, share, time_ms.frame, then every other statistic.
std::string results_csv(const std::vector<RunResult>& results);

/// Writes `text` to `path`; returns false when it cannot.
bool write_file(const std::string& path, const std::string& text);

} // namespace render

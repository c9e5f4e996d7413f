// The comparison's HTML report: verdict, totals, the images side by side with difference
// images and test-count heat maps, bar charts of tests per level and time per phase, the
// papers' tables and each preset's settings.
#pragma once

#include "results_files.h"
#include "run_result.h"

#include <string>
#include <vector>

namespace render {

struct CompareImages {
    /// Paths relative to the report, one per result; difference[0] is empty (the reference).
    std::vector<std::string> image, difference, heat;
    double min_tests = 0, max_tests = 0; ///< the heat maps' common scale (min above zero)
    float gain = 1;                      ///< the difference images' amplification
};

/// The page. `differences` holds, per result, "" when its image equals the first's, else the
/// description of how it differs.
std::string compare_html(const ResultsMeta& meta, const std::vector<RunResult>& results,
                         const std::vector<std::string>& differences, const CompareImages& images);

} // namespace render

// Image checks and the report's derived images: the exact comparison of two renders, the
// amplified difference image, and the heat map of per-pixel test counts.
#pragma once

#include "run_result.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace render {

struct ImageDiff {
    bool size_differs = false;
    size_t count = 0;                       ///< pixels whose combined RGBA differs at all
    double max_diff = 0.0;                  ///< the largest absolute channel difference
    std::vector<std::pair<int, int>> first; ///< (x, y) of the first differing pixels, top row 0
};

/// Compares the combined passes of `a` and `b` bit for bit, keeping up to `keep` coordinates.
ImageDiff compare_images(const RunResult& a, const RunResult& b, size_t keep = 5);

/// "N pixels differ (max difference D) at (x,y) (x,y) ..." or "image sizes differ".
std::string describe(const ImageDiff& d, const RunResult& a, const RunResult& b);

/// RGB display values: black where the pixels agree; elsewhere red, the largest channel
/// difference times `gain`, at least 0.25 so every differing pixel shows.
std::vector<float> difference_image(const RunResult& a, const RunResult& b, float gain);

/// RGB display values: the tests pass on a log scale from min_tests (the smallest count above
/// zero) to max_tests, through an inferno-like colour map: black for no tests, dark purple for
/// min_tests, pale yellow for max_tests.
std::vector<float> heat_map(const std::vector<float>& tests, double min_tests, double max_tests);

/// The colour of `v` in 0..1 on the heat map's colour map, as "#rrggbb".
std::string heat_colour(double v);

} // namespace render

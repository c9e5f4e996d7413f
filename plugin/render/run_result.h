// One render of a comparison or sweep: its name, effective settings, statistics and (when kept)
// its image and per-pixel test counts, read back through the C ABI.
#pragma once

#include "capi_util.h"

#include <string>
#include <utility>
#include <vector>

namespace render {

struct RunResult {
    std::string name;                                      ///< preset, or the grid point
    std::vector<std::pair<std::string, std::string>> grid; ///< sweep axes: key, value
    std::string settings; ///< the frame's effective settings, "key=value" lines
    std::string backend;  ///< where it was computed and why: "backend: cpu (no CUDA device: ...)"
    std::vector<std::pair<std::string, double>> stats;
    int width = 0, height = 0;
    std::vector<float> rgba;  ///< "combined", 4 floats per pixel (compare only)
    std::vector<float> tests; ///< "tests", 1 float per pixel (compare only)

    bool has(const std::string& key) const;
    /// The statistic, 0 when the frame has none of that name.
    double stat(const std::string& key) const;
    /// tests.total / tests.brute_force (0 when there is no brute-force count).
    double share() const;
    /// The settings as (key, value) pairs.
    std::vector<std::pair<std::string, std::string>> settings_list() const;
};

/// Where a set of runs was computed, in one line: the common line ("backend: cpu (reason)") when
/// every run says the same, else each run's name with its own ("backend: a: cuda (...); b: cpu (...)").
std::string backend_summary(const std::vector<RunResult>& results);

/// Renders `scene` with `renderer` into `out` (its name and grid are left as they are); with
/// `keep_images` the combined and tests passes are kept; with an `image_path` the frame is saved
/// there (sheafFrameSaveImage). Prints the error and returns its exit code on failure.
int render_into(SheafRenderer renderer, SheafScene scene, bool keep_images, RunResult& out,
                const std::string& image_path = "");

} // namespace render

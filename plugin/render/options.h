// The render tool's command line: every option, its help text with examples, and the parse
// (POV-Ray switches are translated first, pov_switches.h).
#pragma once

#include "capi_util.h"
#include "region.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace render {

struct Options {
    std::string scene; ///< the positional scene, or +I/--input
    std::string output = "render.png";
    bool has_output = false;
    std::string preset;
    CommonSettings settings;
    bool stats = false;
    std::string stats_json;
    bool list_settings = false;
    bool version = false;
    bool quiet = false;
    std::vector<std::string> compare;       ///< preset names, in order
    std::vector<std::string> sweep;         ///< KEY=VALUES axes, in order
    std::string report;                     ///< --report DIR
    std::vector<std::string> include_paths; ///< --include-path, +L: folders for #include
    bool strict = false;                    ///< --strict: unsupported features are errors
    bool check = false;                     ///< --check: load the scene, report, do not render
    std::string command_line;               ///< as typed, for the report
    /// POV-Ray animation (+KFI +KFF +KI +KF +KC, +SF +EF, +K) and Declare=.
    std::optional<int> initial_frame, final_frame, subset_start, subset_end;
    std::optional<double> initial_clock, final_clock, clock;
    std::optional<bool> cyclic;
    std::vector<std::string> declares;
    std::vector<std::string> limits; // NAME=N
    RegionRequest region;            ///< +SR +ER +SC +EC, --tile: a part of the image
    int frame_step = 1;              ///< --frame-step: every Nth frame of the subset
    std::vector<std::string> merge;  ///< --merge: parts to put together into -o
    /// A farm job (farm.h): --farm SCHEDULER plans and submits it into farm_dir; --farm-task,
    /// --farm-merge and --farm-status run its steps.
    std::string farm, farm_dir, farm_tiles, farm_sbatch;
    bool farm_print = false, farm_merge = false, farm_status = false, farm_wait = false;
    int farm_throttle = 0, farm_chunk = 1;
    std::optional<int> farm_task;

    /// Whether the frames differ (POV-Ray renders a sequence when final_frame != initial_frame).
    bool sequence() const { return initial_frame.value_or(1) != final_frame.value_or(1); }
    /// The frames to render: the sequence cut to --subset-start/end-frame.
    int first_frame() const {
        return std::max(initial_frame.value_or(1),
                        subset_start.value_or(initial_frame.value_or(1)));
    }
    int last_frame() const {
        return std::min(final_frame.value_or(1), subset_end.value_or(final_frame.value_or(1)));
    }
    /// The frame numbers to render, in order: first_frame() to last_frame() by frame_step.
    std::vector<int> frame_numbers() const {
        std::vector<int> out;
        for (int f = first_frame(); f <= last_frame(); f += frame_step) out.push_back(f);
        return out;
    }
};

/// The scene argument with the options that say how to read it.
/// The scene argument with the options that say how to read it; `frame` is the frame of a
/// sequence to read.
inline SceneSource scene_source(const Options& o, std::optional<int> frame = std::nullopt) {
    SceneSource s;
    s.path = o.scene;
    s.include_paths = o.include_paths;
    s.strict = o.strict;
    s.width = o.settings.width;
    s.height = o.settings.height;
    s.initial_frame = o.initial_frame;
    s.final_frame = o.final_frame;
    s.frame = frame;
    s.initial_clock = o.initial_clock;
    s.final_clock = o.final_clock;
    s.clock = o.clock;
    s.cyclic = o.cyclic;
    s.declares = o.declares;
    s.limits = o.limits;
    return s;
}

/// Parses the command line into `o`. Returns an exit code when the program should stop now
/// (--help printed: 0; a usage error, already printed: 1), nothing to go on.
std::optional<int> parse_options(int argc, char** argv, Options& o);

} // namespace render

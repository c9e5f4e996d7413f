// The render tool's command line: every option, its help text with examples, and the parse
// (POV-Ray switches are translated first, pov_switches.h).
#pragma once

#include "capi_util.h"

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
};

/// The scene argument with the options that say how to read it.
inline SceneSource scene_source(const Options& o) {
    return {o.scene, o.include_paths, o.strict, o.settings.width, o.settings.height};
}

/// Parses the command line into `o`. Returns an exit code when the program should stop now
/// (--help printed: 0; a usage error, already printed: 1), nothing to go on.
std::optional<int> parse_options(int argc, char** argv, Options& o);

} // namespace render

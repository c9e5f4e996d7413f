// The POV-Ray reader's budgets of work and memory (PovLimits) and what a scene used of them
// (PovUsage), apart from the reader so that the scene-file options and the C ABI can name them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sheaf::io::pov {

/// The reader's budgets of work and memory. A scene that goes past one is an error at the place
/// where it did (never a hang, nor memory without bound); one that means to go further raises
/// it (the load options limit.*, render --limit). The defaults and what POV-Ray's example
/// scenes use of each are in docs/pov.md, "Limits".
struct PovLimits {
    /// Tokens read (macro and loop bodies each time they run) and function terms evaluated.
    uint64_t parse_steps = 400'000'000;
    /// Objects parsed, temporaries and declarations included.
    uint64_t objects = 200'000;
    /// Live arrays and strings, and objects placed or held by a CSG, in bytes.
    uint64_t data_bytes = uint64_t(128) << 20;
    /// Runs of #while and #for loop bodies, all loops together: loops within loops stop here
    /// long before parse_steps (a run of a small body is a dozen steps).
    uint64_t loop_iterations = 4'000'000;
    /// Macro calls. Each costs the reader far more than the few parse steps of its name and
    /// arguments, so a macro that calls itself twice runs out of these long before parse_steps.
    uint64_t macro_calls = 5'000'000;
    /// Terms of functions evaluated while the scene is read (`#declare v = f(...)`, height
    /// fields of a function); they also count as parse steps. A term is cheaper than a token,
    /// so this budget is the smaller.
    uint64_t function_terms = 50'000'000;
};

/// What a scene used of each budget of PovLimits: the total steps and objects, the peak of
/// the data, the total loop runs, macro calls and function terms.
struct PovUsage {
    uint64_t parse_steps = 0, objects = 0, data_bytes = 0, loop_iterations = 0;
    uint64_t macro_calls = 0, function_terms = 0;
};

/// One limit as hosts see it (the load option limit.NAME): its name, the amount used and the
/// limit, data in MiB.
struct LimitUse {
    std::string name;
    double used = 0, limit = 0;
};
std::vector<LimitUse> limit_uses(const PovUsage& used, const PovLimits& limits);

/// Sets limit `name` (parse_steps, objects, data_mib, loop_iterations, macro_calls,
/// function_terms) to `value`; false when
/// the name is unknown or the value outside 1..2^50.
bool set_limit(PovLimits& limits, const std::string& name, uint64_t value);
/// Sets limit `name` back to its default; false when the name is unknown.
bool reset_limit(PovLimits& limits, const std::string& name);

} // namespace sheaf::io::pov

// The reader's limits by name (see limits.h).
#include "io/pov/limits.h"

namespace sheaf::io::pov {

namespace {
constexpr double kMiB = 1 << 20;
} // namespace

std::vector<LimitUse> limit_uses(const PovUsage& used, const PovLimits& limits) {
    return {{"parse_steps", double(used.parse_steps), double(limits.parse_steps)},
            {"objects", double(used.objects), double(limits.objects)},
            {"data_mib", double(used.data_bytes) / kMiB, double(limits.data_bytes) / kMiB},
            {"loop_iterations", double(used.loop_iterations), double(limits.loop_iterations)},
            {"macro_calls", double(used.macro_calls), double(limits.macro_calls)},
            {"function_terms", double(used.function_terms), double(limits.function_terms)}};
}

bool set_limit(PovLimits& limits, const std::string& name, uint64_t value) {
    if (value < 1 || value > (uint64_t(1) << 50)) return false;
    if (name == "parse_steps")
        limits.parse_steps = value;
    else if (name == "objects")
        limits.objects = value;
    else if (name == "data_mib")
        limits.data_bytes = value << 20 >> 20 == value ? value << 20 : UINT64_MAX;
    else if (name == "loop_iterations")
        limits.loop_iterations = value;
    else if (name == "macro_calls")
        limits.macro_calls = value;
    else if (name == "function_terms")
        limits.function_terms = value;
    else
        return false;
    return true;
}

bool reset_limit(PovLimits& limits, const std::string& name) {
    const PovLimits defaults;
    if (name == "parse_steps")
        limits.parse_steps = defaults.parse_steps;
    else if (name == "objects")
        limits.objects = defaults.objects;
    else if (name == "data_mib")
        limits.data_bytes = defaults.data_bytes;
    else if (name == "loop_iterations")
        limits.loop_iterations = defaults.loop_iterations;
    else if (name == "macro_calls")
        limits.macro_calls = defaults.macro_calls;
    else if (name == "function_terms")
        limits.function_terms = defaults.function_terms;
    else
        return false;
    return true;
}

} // namespace sheaf::io::pov

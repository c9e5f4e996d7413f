// The shape of the papers' tables over several results: which ray types were traced, which
// rows (object spheres, levels top to bottom, final tests) each has, and the timed phases.
// Also the number formats the text and HTML tables share.
#pragma once

#include "run_result.h"

#include <string>
#include <vector>

namespace render {

/// The ray types any result traced (rays.<type> > 0), in the order shadow, reflection,
/// refraction, ao.
std::vector<std::string> traced_types(const std::vector<RunResult>& results);

/// The rows of a ray type's table any result has: "objects", "level<k>" from the highest k down,
/// "nodes" (accel=bvh's box tests), "final". The stat keys are tests.<type>.<row>.tests|hits|misses.
std::vector<std::string> level_rows(const std::vector<RunResult>& results, const std::string& type);

/// "level2" -> "level 2", "nodes" -> "bvh nodes"; others unchanged.
std::string row_label(const std::string& row);

/// The phases timed (time_ms.<phase>, without "frame"), in the frame's order.
std::vector<std::string> phases(const std::vector<RunResult>& results);

/// 1234567 -> "1,234,567" (rounded to an integer).
std::string with_commas(double value);
/// 0.1234 -> "12.34%".
std::string percent(double share);
/// A number with `decimals` digits after the point.
std::string fixed(double value, int decimals);

} // namespace render

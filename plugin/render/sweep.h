// render --sweep KEY=VALUES...: the scene rendered once per point of the grid (on top of the
// --preset, -W/-H/--threads and --set), the totals tabulated, the best setting named, and with
// --report DIR line charts over the grid and the results files.
#pragma once

#include "options.h"

namespace render {

/// Runs the sweep; returns the exit code.
int run_sweep(const Options& o);

} // namespace render

// render --compare P1,P2,...: one scene, one renderer per preset, the images checked identical,
// the papers' tables side by side, and with --report DIR the HTML report and results files.
#pragma once

#include "options.h"

namespace render {

/// Runs the comparison; returns the exit code (3 when any image differs from the first).
int run_compare(const Options& o);

} // namespace render

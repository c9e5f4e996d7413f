// The plain render: one scene, one renderer, one image file, optional statistics.
#pragma once

#include "options.h"

namespace render {

/// Renders o.scene with o.preset and the common settings to o.output; returns the exit code.
int run_single(const Options& o);

/// --check: loads and builds the scene without rendering, prints its warnings and a verdict;
/// 0 when the scene is usable.
int run_check(const Options& o);

/// Prints every setting, its default, what it allows and its help.
void list_settings();

} // namespace render

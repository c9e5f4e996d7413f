// render --merge: the parts of a frame (tiles, rows or columns rendered apart, written as
// OpenEXR with output.exr=float) put back together into the whole frame, exactly.
#pragma once

#include "options.h"

namespace render {

/// Reads o.merge, assembles them and writes o.output (and --stats / --stats-json: the parts'
/// statistics summed). Returns the exit code.
int run_merge(const Options& o);

} // namespace render

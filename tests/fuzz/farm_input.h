// One fuzz input as a farm job's folder (docs/farm.md): job.txt, the plan `render --farm`
// writes, and the state records tasks leave in state/, as a hostile or damaged shared folder
// holds them. The input's text is job.txt up to the first line "--- NAME"; each such line
// starts the record state/NAME (NAME: letters, digits, '.', '-' and '_').
//
// What is checked, as `render --farm-status` and `--farm-task` read the folder: a job that
// does not read fails with a FarmError naming job.txt (any other exception would end render
// through std::terminate); one that reads writes back to the same text, and its status and
// each task's command line (parsed as render parses it, not run) come out without a crash,
// a hang or runaway memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace sheaf::fuzz {

/// Runs one input in a fresh folder under the system's temporary folder, removed after.
/// Returns 0; aborts with a message when a promise is broken. With `log`, writes the outcome.
int run_farm_input(const uint8_t* data, size_t size, std::FILE* log = nullptr);

} // namespace sheaf::fuzz

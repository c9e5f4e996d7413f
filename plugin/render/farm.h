// Work beyond one machine: a render, an animation, a tiled frame or a sweep cut into tasks
// that any scheduler can run, each an ordinary `render` command, and a merge.
//
// The job lives in one shared folder (--farm-dir): job.txt lists the tasks (each a render
// command line and the files it writes), state/ records what each task did. Three commands
// drive it, the same under every scheduler:
//   render --farm-dir DIR --farm-task I   runs task I (from 1); skips it when its outputs are
//                                         complete (their sizes and hashes as recorded)
//   render --farm-dir DIR --farm-merge    puts the tiles together (or the sweep's results)
//                                         once every task is complete
//   render --farm-dir DIR --farm-status   tasks done, running, failed and waiting; time left
// `render --farm slurm ...` plans the job and submits it as a Slurm job array plus a merge job
// (farm_slurm.cpp); docs/farm.md says how other schedulers drive the same commands.
#pragma once

#include "options.h"

namespace render {

/// --farm SCHEDULER: plans the job into o.farm_dir and submits it (or prints the scripts).
int run_farm_submit(const Options& o);
/// --farm-task I
int run_farm_task(const Options& o);
/// --farm-merge
int run_farm_merge(const Options& o);
/// --farm-status [--farm-wait]; `jobs`: the scheduler's job ids to watch, so that a job that
/// ends without completing its tasks (cancelled, every task failed) ends the wait.
int run_farm_status(const Options& o, const std::vector<std::string>& jobs = {});

} // namespace render

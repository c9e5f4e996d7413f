// The Slurm side of a farm job, kept thin: two batch scripts that call the task CLI
// (render --farm-task, --farm-merge) and their submission as a job array plus a merge job
// that waits for it (afterok). Other schedulers drive the same CLI (docs/farm.md).
#pragma once

#include "farm_job.h"

#include <string>
#include <vector>

namespace render {

struct SlurmPlan {
    std::string task_script, merge_script; ///< the scripts' text
    std::string array;                     ///< --array: the waiting tasks, "1-4,7%8"
    std::vector<std::string> sbatch_extra; ///< --farm-sbatch's words, for both jobs
};

/// The scripts and the array for the job's tasks in `waiting` (their indices), calling the
/// render program at `program`; `throttle` > 0 caps the tasks running at once.
SlurmPlan slurm_plan(const FarmJob& job, const std::vector<int>& waiting,
                     const std::string& program, int throttle, const std::string& sbatch_extra);

/// "1-4,7": indices as Slurm's --array ranges.
std::string array_ranges(const std::vector<int>& indices);

/// Writes the scripts into DIR/slurm/ and submits them: the array (when any task waits), then
/// the merge after it (when the job has one and it is not done). Prints what it submitted;
/// returns the exit code (sbatch's errors are printed).
int slurm_submit(const FarmJob& job, const SlurmPlan& plan, bool merge_needed, bool quiet,
                 std::vector<std::string>& job_ids);

/// Whether any of the Slurm jobs is still queued or running (squeue lists it).
bool slurm_jobs_active(const std::vector<std::string>& job_ids);

/// The scripts and the commands that would submit them, on stdout.
void slurm_print(const FarmJob& job, const SlurmPlan& plan, bool merge_needed);

} // namespace render

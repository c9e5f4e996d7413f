// A farm job on disk (see farm.h): the plan (job.txt: its kind, the tasks' render command lines
// and outputs) and each task's state (state/: done with its outputs' sizes and hashes, failed
// with the reason, running with where and since when).
#pragma once

#include "options.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace render {

struct FarmError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct FarmTask {
    int index = 0;                    ///< from 1: Slurm's array index, Kubernetes' index + 1
    std::vector<std::string> args;    ///< the render command line, without the program
    std::vector<std::string> outputs; ///< the files it writes
    std::vector<std::pair<std::string, std::string>> point; ///< a sweep's grid point
};

struct FarmJob {
    std::string dir;    ///< absolute
    std::string kind;   ///< "still", "frames", "tiles" or "sweep"
    std::string output; ///< tiles: the whole frame; still: the image
    std::string report; ///< sweep: the report folder, or empty
    std::vector<std::string> sweep; ///< sweep: the axes, as --sweep took them
    std::string label;  ///< the scene, as shown
    std::vector<FarmTask> tasks;

    const FarmTask& task(int index) const; ///< throws FarmError when there is none
    bool has_merge() const { return kind == "tiles" || kind == "sweep"; }
};

/// The job `o` asks for in `dir` (absolute paths throughout, so tasks may run anywhere the
/// folder is shared): the frames of an animation in chunks of o.farm_chunk, o.farm_tiles
/// tiles of a still, the points of a sweep, or the one still. Throws FarmError.
FarmJob plan_job(const Options& o, const std::string& dir);

/// job.txt's text, and the job it describes (throws FarmError naming the line).
std::string job_text(const FarmJob& job);
FarmJob read_job(const std::string& dir);

/// Writes job.txt, or checks that the folder already holds the same job (a resubmission);
/// throws FarmError when it holds another.
void write_or_check_job(const FarmJob& job);

/// What a task's state records say.
enum class TaskState { Waiting, Running, Done, Failed };
struct TaskStatus {
    TaskState state = TaskState::Waiting;
    double seconds = 0;  ///< Done: how long it took
    std::string reason;  ///< Failed: the error; Running: where
};

/// The state the records of `who` (task_who(I), or "merge") say. Done only when every output
/// is there with the size and hash recorded when it finished.
TaskStatus status_of(const FarmJob& job, const std::string& who);
/// The task's state. Done only when every output is there with the size and hash recorded
/// when the task finished (a file changed or cut short since makes it Waiting again).
TaskStatus task_status(const FarmJob& job, int index);
/// The merge: done when its record and output check out ("merge" in state/).
TaskStatus merge_status(const FarmJob& job);

/// Records, under state/ (written under a temporary name, then renamed).
void mark_running(const FarmJob& job, const std::string& who);
void mark_done(const FarmJob& job, const std::string& who, const std::vector<std::string>& outputs,
               double seconds);
void mark_failed(const FarmJob& job, const std::string& who, const std::string& reason);
void clear_marks(const FarmJob& job, const std::string& who);

/// "task-3" for task 3, "merge" for the merge: the names of the records.
std::string task_who(int index);

/// An absolute path: `path` against the current folder.
std::string absolute(const std::string& path);

} // namespace render

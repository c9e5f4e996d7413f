#include "farm.h"

#include "farm_job.h"
#include "farm_slurm.h"
#include "merge.h"
#include "single.h"
#include "sweep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace render {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// This program's path, for the scripts: /proc/self/exe, else argv[0] made absolute.
std::string program_path() {
    char buf[4096];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n > 0) return std::string(buf, size_t(n));
    return absolute("render");
}

// Parses a task's command line as render would and runs it.
int run_args(const std::vector<std::string>& args, Options& parsed) {
    std::vector<std::string> argv_text = {"render"};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (std::optional<int> done = parse_options(int(argv_text.size()), argv.data(), parsed))
        return *done == kOk ? kUsage : *done;
    return run_single(parsed);
}

struct Counts {
    int done = 0, running = 0, failed = 0, waiting = 0;
    double done_seconds = 0;
    std::vector<std::string> failures; // "task 3: reason"
};

Counts count_tasks(const FarmJob& job) {
    Counts c;
    for (const FarmTask& t : job.tasks) {
        const TaskStatus s = task_status(job, t.index);
        switch (s.state) {
        case TaskState::Done:
            ++c.done;
            c.done_seconds += s.seconds;
            break;
        case TaskState::Running: ++c.running; break;
        case TaskState::Failed:
            ++c.failed;
            c.failures.push_back("task " + std::to_string(t.index) + ": " + s.reason);
            break;
        case TaskState::Waiting: ++c.waiting; break;
        }
    }
    return c;
}

std::string duration_text(double s) {
    char buf[32];
    if (s < 90) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 5400) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
    else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
}

// One line: "16 tasks: 10 done, 2 running, 0 failed, 4 waiting; merge waiting; about 12 s left".
// The time left: the tasks not done at the mean time of those done, spread over the tasks
// running now (at least one).
std::string status_line(const FarmJob& job, const Counts& c, const TaskStatus& merge) {
    std::ostringstream s;
    s << job.tasks.size() << (job.tasks.size() == 1 ? " task: " : " tasks: ") << c.done
      << " done, " << c.running << " running, " << c.failed << " failed, " << c.waiting
      << " waiting";
    if (job.has_merge())
        s << "; merge "
          << (merge.state == TaskState::Done      ? "done"
              : merge.state == TaskState::Running ? "running"
              : merge.state == TaskState::Failed  ? "failed"
                                                  : "waiting");
    const int left = c.running + c.waiting;
    if (c.done > 0 && left > 0)
        s << "; about " << duration_text(c.done_seconds / c.done * left / std::max(1, c.running))
          << " left";
    return s.str();
}

bool finished(const FarmJob& job, const Counts& c, const TaskStatus& merge) {
    return c.done == int(job.tasks.size()) &&
           (!job.has_merge() || merge.state == TaskState::Done);
}

} // namespace

int run_farm_task(const Options& o) {
    const auto start = std::chrono::steady_clock::now();
    FarmJob job;
    try {
        job = read_job(o.farm_dir);
        const FarmTask& task = job.task(*o.farm_task);
        const std::string who = task_who(task.index);
        if (task_status(job, task.index).state == TaskState::Done) {
            if (!o.quiet)
                std::cout << "task " << task.index << ": complete already, skipped\n";
            return kOk;
        }
        clear_marks(job, who);
        mark_running(job, who);
        Options parsed;
        const int rc = run_args(task.args, parsed);
        if (rc != kOk) {
            mark_failed(job, who, last_printed_error());
            return rc;
        }
        mark_done(job, who, task.outputs, seconds_since(start));
        if (!o.quiet)
            std::cout << "task " << task.index << ": done in " << duration_text(seconds_since(start))
                      << "\n";
        return kOk;
    } catch (const FarmError& e) {
        return error(kUsage, e.what());
    }
}

int run_farm_merge(const Options& o) {
    const auto start = std::chrono::steady_clock::now();
    FarmJob job;
    try {
        job = read_job(o.farm_dir);
        const Counts c = count_tasks(job);
        if (c.done != int(job.tasks.size())) {
            std::string missing;
            for (const FarmTask& t : job.tasks)
                if (task_status(job, t.index).state != TaskState::Done)
                    missing += (missing.empty() ? "" : ", ") + std::to_string(t.index);
            return error(kRender, "--farm-merge: tasks " + missing + " of " + job.dir +
                                      " are not complete");
        }
        if (!job.has_merge()) {
            if (!o.quiet) std::cout << "all " << job.tasks.size() << " tasks complete\n";
            return kOk;
        }
        clear_marks(job, "merge");
        mark_running(job, "merge");
        int rc = kOk;
        std::vector<std::string> outputs;
        if (job.kind == "tiles") {
            Options m;
            m.quiet = o.quiet;
            m.output = job.output;
            for (const FarmTask& t : job.tasks) m.merge.push_back(t.outputs.front());
            rc = run_merge(m);
            outputs = {job.output};
        } else { // sweep: each point's frame read back, reported as a one-machine sweep would
            Options s;
            s.quiet = o.quiet;
            s.sweep = job.sweep;
            s.report = job.report;
            s.scene = job.label;
            s.command_line = "render --farm-merge " + job.dir;
            std::vector<RunResult> results;
            for (const FarmTask& t : job.tasks) {
                RunResult r;
                r.grid = t.point;
                r.name = point_name(t.point);
                SheafFrame raw = nullptr;
                if (sheafFrameLoadImage(t.outputs.front().c_str(), &raw) != SHEAF_OK) {
                    rc = error(kRender, last_error());
                    break;
                }
                Frame frame(raw);
                sheafFrameGetSize(frame.get(), &r.width, &r.height);
                r.stats = frame_stats(frame.get());
                r.settings = frame_text(frame.get(), "settings").value_or("");
                r.backend = frame_backend(frame.get());
                results.push_back(std::move(r));
            }
            if (rc == kOk) rc = report_sweep(s, sweep_axes(s), results);
            if (!job.report.empty()) outputs = {job.report + "/results.json"};
        }
        if (rc != kOk) {
            mark_failed(job, "merge", last_printed_error());
            return rc;
        }
        if (outputs.empty()) outputs = {job.dir + "/job.txt"};
        mark_done(job, "merge", outputs, seconds_since(start));
        return kOk;
    } catch (const FarmError& e) {
        return error(kRender, e.what());
    } catch (const GridError& e) {
        return error(kRender, e.what());
    }
}

int run_farm_status(const Options& o, const std::vector<std::string>& jobs) {
    try {
        const FarmJob job = read_job(o.farm_dir);
        std::string last;
        for (;;) {
            const Counts c = count_tasks(job);
            const TaskStatus merge = merge_status(job);
            const std::string line = status_line(job, c, merge);
            if (line != last) std::cout << line << std::endl;
            last = line;
            if (c.failed > 0 || merge.state == TaskState::Failed) {
                for (const std::string& f : c.failures) std::cerr << "render: " << f;
                if (merge.state == TaskState::Failed) std::cerr << "render: merge: " << merge.reason;
                if (o.farm_wait) return kRender;
            }
            if (!o.farm_wait) return kOk;
            if (finished(job, c, merge)) return kOk;
            if (!jobs.empty() && !slurm_jobs_active(jobs)) {
                // The scheduler is done with the job: one last look, then say what is missing.
                const Counts after = count_tasks(job);
                if (finished(job, after, merge_status(job))) continue;
                return error(kRender, "the Slurm jobs ended with " +
                                          std::to_string(int(job.tasks.size()) - after.done) +
                                          " tasks not complete: see " + job.dir + "/logs");
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        }
    } catch (const FarmError& e) {
        return error(kUsage, e.what());
    }
}

int run_farm_submit(const Options& o) {
    if (o.farm != "slurm" && o.farm != "none")
        return error(kUsage, "--farm " + o.farm + ": the schedulers known are: slurm, and none "
                                                  "(the plan and its commands, for any other "
                                                  "scheduler: docs/farm.md)");
    try {
        const FarmJob job = plan_job(o, o.farm_dir);
        write_or_check_job(job);
        std::vector<int> waiting;
        for (const FarmTask& t : job.tasks) {
            const TaskState s = task_status(job, t.index).state;
            if (s != TaskState::Done) waiting.push_back(t.index);
        }
        const bool merge_needed = job.has_merge() && merge_status(job).state != TaskState::Done;
        if (waiting.empty() && !merge_needed) {
            if (!o.quiet)
                std::cout << "nothing to do: all " << job.tasks.size() << " tasks of " << job.dir
                          << (job.has_merge() ? " and the merge" : "")
                          << " are complete\n";
            return kOk;
        }
        if (o.farm == "none") { // the commands, one a line, for another scheduler to run
            const std::string render = program_path();
            for (int i : waiting)
                std::cout << render << " --farm-dir " << job.dir << " --farm-task " << i << "\n";
            if (merge_needed)
                std::cout << render << " --farm-dir " << job.dir << " --farm-merge\n";
            return kOk;
        }
        const SlurmPlan plan =
            slurm_plan(job, waiting, program_path(), o.farm_throttle, o.farm_sbatch);
        if (o.farm_print) {
            slurm_print(job, plan, merge_needed);
            return kOk;
        }
        std::vector<std::string> ids;
        if (int rc = slurm_submit(job, plan, merge_needed, o.quiet, ids)) return rc;
        if (!o.quiet)
            std::cout << "progress: render --farm-dir " << job.dir << " --farm-status [--farm-wait]\n";
        if (!o.farm_wait) return kOk;
        return run_farm_status(o, ids);
    } catch (const FarmError& e) {
        return error(kUsage, e.what());
    }
}

} // namespace render

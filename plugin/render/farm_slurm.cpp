#include "farm_slurm.h"

#include "capi_util.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>

namespace render {
namespace {

// A word for the shell, in single quotes.
std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out.append("'\\''");
        else out.push_back(c);
    }
    out.push_back('\'');
    return out;
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// Runs the shell command, returns its exit status and stdout (stderr passes through).
int run_command(const std::string& command, std::string& out) {
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return 127;
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string sbatch_command(const SlurmPlan& plan, const std::vector<std::string>& extra,
                           const std::string& script) {
    std::string c = "sbatch --parsable";
    for (const std::string& w : plan.sbatch_extra) c.append(" ").append(quote(w));
    for (const std::string& w : extra) c.append(" ").append(quote(w));
    return c.append(" ").append(quote(script));
}

} // namespace

std::string array_ranges(const std::vector<int>& indices) {
    std::string out;
    for (size_t i = 0; i < indices.size();) {
        size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        if (!out.empty()) out.push_back(',');
        out.append(std::to_string(indices[i]));
        if (j > i) out.append("-").append(std::to_string(indices[j]));
        i = j + 1;
    }
    return out;
}

SlurmPlan slurm_plan(const FarmJob& job, const std::vector<int>& waiting,
                     const std::string& program, int throttle, const std::string& sbatch_extra) {
    SlurmPlan p;
    p.array = array_ranges(waiting);
    if (throttle > 0 && !p.array.empty()) p.array.append("%").append(std::to_string(throttle));
    p.sbatch_extra = words(sbatch_extra);
    const std::string dir = quote(job.dir), render = quote(program);
    std::ostringstream t;
    t << "#!/bin/bash\n"
      << "#SBATCH --job-name=sheaf-" << job.kind << "\n"
      << "#SBATCH --output=" << job.dir << "/logs/task-%a.log\n"
      << "#SBATCH --open-mode=append\n"
      << "#SBATCH --requeue\n"
      << "# One task of the Sheaf farm job in " << job.dir << ".\n"
      << "# render --farm-task skips a task whose outputs are complete. A task that dies (a\n"
      << "# signal: killed, out of memory) is requeued, at most 3 times; one that fails for a\n"
      << "# reason in the scene or settings cancels the array, so the merge never runs.\n"
      << render << " --farm-dir " << dir << " --farm-task \"$SLURM_ARRAY_TASK_ID\"\n"
      << "rc=$?\n"
      << "if [ \"$rc\" -ge 128 ] && [ \"${SLURM_RESTART_COUNT:-0}\" -lt 3 ]; then\n"
      << "    echo \"sheaf farm: task $SLURM_ARRAY_TASK_ID died (exit $rc); requeued\" >&2\n"
      << "    scontrol requeue \"${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}\" && sleep 600\n"
      << "elif [ \"$rc\" -ne 0 ]; then\n"
      << "    echo \"sheaf farm: task $SLURM_ARRAY_TASK_ID failed (exit $rc); cancelling job "
         "$SLURM_ARRAY_JOB_ID\" >&2\n"
      << "    scancel \"$SLURM_ARRAY_JOB_ID\"\n"
      << "fi\n"
      << "exit \"$rc\"\n";
    p.task_script = t.str();
    std::ostringstream m;
    m << "#!/bin/bash\n"
      << "#SBATCH --job-name=sheaf-merge\n"
      << "#SBATCH --output=" << job.dir << "/logs/merge.log\n"
      << "#SBATCH --open-mode=append\n"
      << "# The merge of the Sheaf farm job in " << job.dir << ", after every task.\n"
      << render << " --farm-dir " << dir << " --farm-merge\n";
    p.merge_script = m.str();
    return p;
}

bool slurm_jobs_active(const std::vector<std::string>& job_ids) {
    if (job_ids.empty()) return false;
    std::string list;
    for (const std::string& id : job_ids) list.append(list.empty() ? "" : ",").append(id);
    std::string out;
    if (run_command("squeue -h -o %i -j " + quote(list) + " 2>/dev/null", out) != 0) return true;
    return out.find_first_not_of(" \n") != std::string::npos;
}

int slurm_submit(const FarmJob& job, const SlurmPlan& plan, bool merge_needed, bool quiet,
                 std::vector<std::string>& job_ids) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(job.dir + "/slurm", ec);
    const std::string task_path = job.dir + "/slurm/task.sbatch";
    const std::string merge_path = job.dir + "/slurm/merge.sbatch";
    for (const auto& [path, text] : {std::pair{task_path, plan.task_script},
                                     std::pair{merge_path, plan.merge_script}}) {
        std::ofstream out(path);
        if (!(out << text)) return error(kRender, path + ": cannot write the script");
        chmod(path.c_str(), 0755);
    }
    std::string array_id;
    if (!plan.array.empty()) {
        std::string out;
        const std::string cmd = sbatch_command(plan, {"--array=" + plan.array}, task_path);
        if (run_command(cmd, out) != 0 || out.empty())
            return error(kRender, "sbatch refused the job array (" + cmd + "): " + out);
        array_id = out.substr(0, out.find_first_of(";\n"));
        job_ids.push_back(array_id);
        if (!quiet)
            std::cout << "submitted job " << array_id << ": tasks " << plan.array << " of "
                      << job.tasks.size() << "\n";
    }
    if (merge_needed) {
        std::vector<std::string> extra;
        if (!array_id.empty())
            extra = {"--dependency=afterok:" + array_id, "--kill-on-invalid-dep=yes"};
        std::string out;
        const std::string cmd = sbatch_command(plan, extra, merge_path);
        if (run_command(cmd, out) != 0 || out.empty())
            return error(kRender, "sbatch refused the merge job (" + cmd + "): " + out);
        job_ids.push_back(out.substr(0, out.find_first_of(";\n")));
        if (!quiet)
            std::cout << "submitted merge job " << job_ids.back()
                      << (array_id.empty() ? "" : " (after job " + array_id + ")") << "\n";
    }
    return kOk;
}

void slurm_print(const FarmJob& job, const SlurmPlan& plan, bool merge_needed) {
    const std::string task_path = job.dir + "/slurm/task.sbatch";
    const std::string merge_path = job.dir + "/slurm/merge.sbatch";
    std::cout << "# " << task_path << "\n" << plan.task_script << "\n";
    if (merge_needed) std::cout << "# " << merge_path << "\n" << plan.merge_script << "\n";
    std::cout << "# Submit:\n";
    if (!plan.array.empty())
        std::cout << "ARRAY=$(" << sbatch_command(plan, {"--array=" + plan.array}, task_path)
                  << ")\n";
    if (merge_needed) {
        std::string c = sbatch_command(plan, {}, merge_path);
        if (!plan.array.empty())
            c.insert(std::string("sbatch --parsable").size(),
                     " --dependency=afterok:\"$ARRAY\" --kill-on-invalid-dep=yes");
        std::cout << c << "\n";
    }
}

} // namespace render

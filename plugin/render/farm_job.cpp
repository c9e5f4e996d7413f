#include "farm_job.h"

#include "grid.h"
#include "region.h"
#include "single.h"
#include "sweep.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace render {
namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "sheaf-farm 1";

bool is_builtin(const std::string& scene) { return scene.rfind("builtin:", 0) == 0; }

// The render command line every task of `o` shares: the scene and how to read it, the
// settings, the animation's clock; paths made absolute.
std::vector<std::string> base_args(const Options& o) {
    std::vector<std::string> a;
    if (!o.scene.empty()) a.push_back(is_builtin(o.scene) ? o.scene : absolute(o.scene));
    if (o.settings.width) a.insert(a.end(), {"-W", std::to_string(*o.settings.width)});
    if (o.settings.height) a.insert(a.end(), {"-H", std::to_string(*o.settings.height)});
    if (o.settings.threads) a.insert(a.end(), {"--threads", std::to_string(*o.settings.threads)});
    if (!o.preset.empty()) {
        const bool is_file = o.preset.find('/') != std::string::npos ||
                             (o.preset.size() > 4 &&
                              o.preset.compare(o.preset.size() - 4, 4, ".xml") == 0);
        a.insert(a.end(), {"--preset", is_file ? absolute(o.preset) : o.preset});
    }
    for (const std::string& s : o.settings.sets) a.insert(a.end(), {"--set", s});
    for (const std::string& p : o.include_paths) a.insert(a.end(), {"--include-path", absolute(p)});
    if (o.strict) a.push_back("--strict");
    for (const std::string& d : o.declares) a.insert(a.end(), {"--declare", d});
    for (const std::string& l : o.limits) a.insert(a.end(), {"--limit", l});
    auto num = [](double v) {
        std::ostringstream s;
        s.precision(17);
        s << v;
        return s.str();
    };
    if (o.initial_frame) a.insert(a.end(), {"--initial-frame", std::to_string(*o.initial_frame)});
    if (o.final_frame) a.insert(a.end(), {"--final-frame", std::to_string(*o.final_frame)});
    if (o.initial_clock) a.insert(a.end(), {"--initial-clock", num(*o.initial_clock)});
    if (o.final_clock) a.insert(a.end(), {"--final-clock", num(*o.final_clock)});
    if (o.clock) a.insert(a.end(), {"--clock", num(*o.clock)});
    if (o.cyclic) a.push_back(*o.cyclic ? "--cyclic-animation" : "--no-cyclic-animation");
    a.push_back("-q");
    return a;
}

// Only a regular file has a hash: a device or a pipe named in a record could be read without
// end (or block opening).
std::string file_hash(const std::string& path, uintmax_t& size) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return {};
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    uint64_t h = 1469598103934665603ull; // FNV-1a, 64 bits
    char buf[1 << 16];
    size = 0;
    while (in) {
        in.read(buf, sizeof buf);
        const std::streamsize n = in.gcount();
        for (std::streamsize i = 0; i < n; ++i) {
            h ^= static_cast<unsigned char>(buf[i]);
            h *= 1099511628211ull;
        }
        size += uintmax_t(n);
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::string record_path(const FarmJob& job, const std::string& who, const char* what) {
    return job.dir + "/state/" + who + "." + what;
}

void write_atomically(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp-" + std::to_string(getpid());
    {
        std::ofstream out(tmp);
        if (!(out << text) || !(out.flush()))
            throw FarmError(path + ": cannot write the file");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw FarmError(path + ": cannot write the file (rename failed)");
    }
}

// The text of job.txt or a record, or nothing when there is no such file. Throws FarmError
// when it is not a regular file or outgrows what a job writes (a device, a pipe, or a damaged
// folder would otherwise be read without end).
std::optional<std::string> read_text(const std::string& path) {
    constexpr uintmax_t kMostBytes = uintmax_t(64) << 20;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) return std::nullopt;
    if (!fs::is_regular_file(status))
        throw FarmError(path + ": not a regular file (a farm job writes only files)");
    if (fs::file_size(path, ec) > kMostBytes)
        throw FarmError(path + ": over 64 MiB, more than a farm job writes");
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void check_word(const std::string& word, const std::string& what) {
    if (word.find('\n') != std::string::npos || word.find('\t') != std::string::npos)
        throw FarmError(what + " '" + word + "' holds a newline or a tab, which a farm job "
                                             "cannot carry");
}

// The status a done record gives, after checking the files it names.
TaskStatus done_status(const std::string& record) {
    TaskStatus s;
    std::istringstream in(record);
    std::string word;
    bool any = false;
    while (in >> word) {
        if (word == "seconds") {
            in >> s.seconds;
        } else if (word == "file") {
            uintmax_t size = 0, actual = 0;
            std::string hash, path;
            in >> size >> hash;
            std::getline(in >> std::ws, path);
            // The size first: a file that has changed is not read.
            std::error_code ec;
            if (fs::file_size(path, ec) != size || ec) return {};
            if (file_hash(path, actual) != hash || actual != size) return {};
            any = true;
        }
    }
    if (!any) return {};
    s.state = TaskState::Done;
    return s;
}

} // namespace

std::string absolute(const std::string& path) {
    if (path.empty()) return path;
    std::error_code ec;
    const fs::path p = fs::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
}

std::string task_who(int index) { return "task-" + std::to_string(index); }

const FarmTask& FarmJob::task(int index) const {
    for (const FarmTask& t : tasks)
        if (t.index == index) return t;
    throw FarmError("the job in " + dir + " has no task " + std::to_string(index) + " (tasks 1.." +
                    std::to_string(tasks.size()) + ")");
}

FarmJob plan_job(const Options& o, const std::string& dir) {
    FarmJob job;
    job.dir = absolute(dir);
    job.label = scene_label(o.scene);
    const std::vector<std::string> base = base_args(o);
    const std::string parts = job.dir + "/parts";
    auto add = [&](std::vector<std::string> extra, std::vector<std::string> outputs) {
        FarmTask t;
        t.index = int(job.tasks.size()) + 1;
        t.args = base;
        t.args.insert(t.args.end(), extra.begin(), extra.end());
        t.outputs = std::move(outputs);
        job.tasks.push_back(std::move(t));
        return &job.tasks.back();
    };
    if (o.region.any())
        throw FarmError("--farm renders whole frames (or --farm-tiles of them); leave out --tile "
                        "and +SR/+ER/+SC/+EC");
    if (!o.sweep.empty()) {
        if (o.sequence()) throw FarmError("--sweep renders one frame; give --clock instead");
        if (!o.farm_tiles.empty()) throw FarmError("--farm-tiles and --sweep: give one");
        job.kind = "sweep";
        job.report = absolute(o.report);
        job.sweep = o.sweep;
        std::vector<std::vector<std::pair<std::string, std::string>>> points;
        try {
            points = grid_points(sweep_axes(o));
        } catch (const GridError& e) {
            throw FarmError(e.what());
        }
        for (const auto& point : points) {
            std::vector<std::string> extra;
            for (const auto& [k, v] : point) extra.insert(extra.end(), {"--set", k + "=" + v});
            const std::string out = parts + "/point-" + std::to_string(job.tasks.size() + 1) + ".exr";
            extra.insert(extra.end(), {"--set", "output.exr=float", "-o", out});
            add(extra, {out})->point = point;
        }
    } else if (o.sequence()) {
        if (!o.farm_tiles.empty())
            throw FarmError("--farm-tiles cuts one frame; an animation is cut into frames "
                            "(--farm-chunk)");
        job.kind = "frames";
        job.output = absolute(o.output);
        const std::vector<int> frames = o.frame_numbers();
        const size_t chunk = size_t(std::max(1, o.farm_chunk));
        for (size_t i = 0; i < frames.size(); i += chunk) {
            const size_t end = std::min(frames.size(), i + chunk);
            std::vector<std::string> outs;
            for (size_t k = i; k < end; ++k)
                outs.push_back(numbered(job.output, frames[k], name_digits_frame(o)));
            add({"--subset-start-frame", std::to_string(frames[i]), "--subset-end-frame",
                 std::to_string(frames[end - 1]), "--frame-step", std::to_string(o.frame_step),
                 "-o", job.output},
                outs);
        }
    } else if (!o.farm_tiles.empty()) {
        job.kind = "tiles";
        job.output = absolute(o.output);
        int columns = 0, rows = 0;
        try {
            tile_grid(o.farm_tiles, columns, rows);
        } catch (const RegionError& e) {
            throw FarmError(std::string("--farm-tiles: ") + e.what());
        }
        const std::string grid = std::to_string(columns) + "x" + std::to_string(rows);
        for (int i = 1; i <= columns * rows; ++i) {
            const std::string out = parts + "/tile-" + std::to_string(i) + ".exr";
            add({"--tile", std::to_string(i) + "/" + grid, "--set", "output.exr=float", "-o", out},
                {out});
        }
    } else {
        job.kind = "still";
        job.output = absolute(o.output);
        add({"-o", job.output}, {job.output});
    }
    for (const FarmTask& t : job.tasks)
        for (const std::string& a : t.args) check_word(a, "the argument");
    return job;
}

std::string job_text(const FarmJob& job) {
    std::ostringstream s;
    s << kMagic << "\n";
    s << "kind " << job.kind << "\n";
    s << "label " << job.label << "\n";
    if (!job.output.empty()) s << "output " << job.output << "\n";
    if (!job.report.empty()) s << "report " << job.report << "\n";
    for (const std::string& axis : job.sweep) s << "sweep " << axis << "\n";
    for (const FarmTask& t : job.tasks) {
        s << "task " << t.index << "\n";
        for (const std::string& a : t.args) s << "arg " << a << "\n";
        for (const std::string& f : t.outputs) s << "out " << f << "\n";
        for (const auto& [k, v] : t.point) s << "point " << k << "=" << v << "\n";
    }
    return s.str();
}

FarmJob read_job(const std::string& dir) {
    FarmJob job;
    job.dir = absolute(dir);
    const std::string path = job.dir + "/job.txt";
    const std::optional<std::string> text = read_text(path);
    if (!text) throw FarmError(path + ": no farm job here (render --farm writes it)");
    std::istringstream in(*text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = path + ":" + std::to_string(number);
        if (number == 1) {
            if (line != kMagic) throw FarmError(where + ": expected '" + kMagic + "'");
            continue;
        }
        const size_t space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
        if (key == "kind") job.kind = value;
        else if (key == "label") job.label = value;
        else if (key == "output") job.output = value;
        else if (key == "report") job.report = value;
        else if (key == "sweep") job.sweep.push_back(value);
        else if (key == "task") {
            FarmTask t;
            t.index = std::atoi(value.c_str());
            if (t.index != int(job.tasks.size()) + 1)
                throw FarmError(where + ": expected task " + std::to_string(job.tasks.size() + 1));
            job.tasks.push_back(t);
        } else if (job.tasks.empty()) {
            throw FarmError(where + ": '" + key + "' before the first task");
        } else if (key == "arg") job.tasks.back().args.push_back(value);
        else if (key == "out") job.tasks.back().outputs.push_back(value);
        else if (key == "point") {
            const size_t eq = value.find('=');
            job.tasks.back().point.emplace_back(value.substr(0, eq),
                                                eq == std::string::npos ? "" : value.substr(eq + 1));
        } else throw FarmError(where + ": unknown entry '" + key + "'");
    }
    if (job.kind != "still" && job.kind != "frames" && job.kind != "tiles" && job.kind != "sweep")
        throw FarmError(path + ": unknown kind '" + job.kind + "'");
    if (job.tasks.empty()) throw FarmError(path + ": no tasks");
    return job;
}

void write_or_check_job(const FarmJob& job) {
    std::error_code ec;
    for (const char* sub : {"", "/state", "/parts", "/logs"}) {
        fs::create_directories(job.dir + sub, ec);
        if (ec) throw FarmError(job.dir + sub + ": cannot create the folder: " + ec.message());
    }
    // The folders of the outputs: tasks on other machines write there.
    std::vector<std::string> outputs = {job.output, job.report.empty() ? "" : job.report + "/x"};
    for (const FarmTask& t : job.tasks) outputs.insert(outputs.end(), t.outputs.begin(), t.outputs.end());
    for (const std::string& f : outputs) {
        if (f.empty()) continue;
        const fs::path parent = fs::path(f).parent_path();
        fs::create_directories(parent, ec);
        if (ec) throw FarmError(parent.string() + ": cannot create the folder: " + ec.message());
    }
    const std::string path = job.dir + "/job.txt", text = job_text(job);
    if (const std::optional<std::string> old = read_text(path)) {
        if (*old != text)
            throw FarmError(job.dir + " holds another job (its job.txt differs): give another "
                                      "--farm-dir, or remove that one");
        return;
    }
    write_atomically(path, text);
}

TaskStatus status_of(const FarmJob& job, const std::string& who) {
    if (const auto done = read_text(record_path(job, who, "done")))
        if (TaskStatus s = done_status(*done); s.state == TaskState::Done) return s;
    if (const auto failed = read_text(record_path(job, who, "failed")))
        return {TaskState::Failed, 0, *failed};
    if (const auto running = read_text(record_path(job, who, "running")))
        return {TaskState::Running, 0, *running};
    return {};
}

TaskStatus task_status(const FarmJob& job, int index) { return status_of(job, task_who(index)); }

TaskStatus merge_status(const FarmJob& job) { return status_of(job, "merge"); }

void mark_running(const FarmJob& job, const std::string& who) {
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    write_atomically(record_path(job, who, "running"),
                     std::string(host) + " pid " + std::to_string(getpid()) + "\n");
}

void mark_done(const FarmJob& job, const std::string& who, const std::vector<std::string>& outputs,
               double seconds) {
    std::ostringstream s;
    s << "seconds " << seconds << "\n";
    for (const std::string& f : outputs) {
        uintmax_t size = 0;
        const std::string hash = file_hash(f, size);
        if (hash.empty()) throw FarmError(f + ": the task's output is missing");
        s << "file " << size << " " << hash << " " << f << "\n";
    }
    write_atomically(record_path(job, who, "done"), s.str());
    std::remove(record_path(job, who, "running").c_str());
    std::remove(record_path(job, who, "failed").c_str());
}

void mark_failed(const FarmJob& job, const std::string& who, const std::string& reason) {
    write_atomically(record_path(job, who, "failed"), reason.empty() ? "failed\n" : reason + "\n");
    std::remove(record_path(job, who, "running").c_str());
}

void clear_marks(const FarmJob& job, const std::string& who) {
    for (const char* what : {"done", "failed", "running"})
        std::remove(record_path(job, who, what).c_str());
}

} // namespace render

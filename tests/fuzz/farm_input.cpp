#include "tests/fuzz/farm_input.h"

#include "plugin/render/farm.h"
#include "plugin/render/farm_job.h"
#include "plugin/render/options.h"
#include "tests/fuzz/promises.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace sheaf::fuzz {
namespace {

bool record_name(const std::string& name) {
    if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_')
            return false;
    return true;
}

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) broken("cannot write " + path.string());
}

// A fresh folder, removed with what the input left in it.
struct Scratch {
    fs::path dir;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "sheaf-fuzz-farm-XXXXXX").string();
        if (!mkdtemp(pattern.data())) broken("cannot make a scratch folder");
        dir = pattern;
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

// read_job, with only a FarmError naming job.txt allowed to come out of it.
bool read(const fs::path& dir, render::FarmJob& job, std::FILE* log) {
    try {
        job = render::read_job(dir.string());
        return true;
    } catch (const render::FarmError& e) {
        const std::string what = e.what();
        if (what.find("job.txt") == std::string::npos)
            broken("a farm job's error names no file: " + what);
        if (log) std::fprintf(log, "  error: %s\n", what.c_str());
        return false;
    } catch (const std::exception& e) {
        broken(std::string("read_job threw what render does not catch: ") + e.what());
    }
}

} // namespace

int run_farm_input(const uint8_t* data, size_t size, std::FILE* log) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    Scratch scratch;
    const fs::path state = scratch.dir / "state";
    fs::create_directories(state);
    // job.txt, then the records.
    size_t at = text.find("\n--- ");
    write_file(scratch.dir / "job.txt", text.substr(0, at == std::string::npos ? at : at + 1));
    while (at != std::string::npos) {
        const size_t name_at = at + 5, line_end = text.find('\n', name_at);
        const std::string name = text.substr(name_at, line_end - name_at);
        const size_t next =
            line_end == std::string::npos ? line_end : text.find("\n--- ", line_end);
        if (record_name(name) && line_end != std::string::npos)
            write_file(state / name,
                       text.substr(line_end + 1,
                                   next == std::string::npos ? next : next + 1 - line_end - 1));
        at = next;
    }

    render::FarmJob job;
    if (!read(scratch.dir, job, log)) return 0;
    if (log) std::fprintf(log, "  a %s job of %zu tasks\n", job.kind.c_str(), job.tasks.size());

    // What it reads writes back as the same text (render --farm checks a resubmission so).
    const std::string again = render::job_text(job);
    Scratch copy;
    write_file(copy.dir / "job.txt", again);
    render::FarmJob reread;
    if (!read(copy.dir, reread, log)) broken("a job read from job.txt does not read back");
    if (render::job_text(reread) != again) broken("a job read back writes another job.txt");

    // The status, as render --farm-status prints it, and each task's state.
    render::Options o;
    o.farm_dir = scratch.dir.string();
    o.farm_status = true;
    try {
        render::run_farm_status(o);
        for (const render::FarmTask& t : job.tasks) render::task_status(job, t.index);
        render::merge_status(job);
    } catch (const std::exception& e) {
        broken(std::string("a farm job's status threw: ") + e.what());
    }

    // The first tasks' command lines, parsed as render --farm-task parses them.
    for (size_t i = 0; i < job.tasks.size() && i < 4; ++i) {
        std::vector<std::string> words = {"render"};
        words.insert(words.end(), job.tasks[i].args.begin(), job.tasks[i].args.end());
        std::vector<char*> argv;
        for (std::string& w : words) argv.push_back(w.data());
        argv.push_back(nullptr);
        render::Options parsed;
        try {
            const std::optional<int> done =
                render::parse_options(int(words.size()), argv.data(), parsed);
            if (log) std::fprintf(log, "  task %zu: %s\n", i + 1, done ? "refused" : "parsed");
        } catch (const std::exception& e) {
            broken(std::string("a task's command line threw: ") + e.what());
        }
    }
    return 0;
}

} // namespace sheaf::fuzz

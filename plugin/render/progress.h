// A progress bar with an estimate of the time left, drawn on stderr only when stderr is a
// terminal, fed by the C ABI's progress callback (sheafRendererSetProgressCallback).
#pragma once

#include <sheaf/sheaf.h>

#include <chrono>
#include <string>

namespace render {

class Progress {
  public:
    /// `enabled` false (quiet, or stderr not a terminal) draws nothing at all. `runs` is how
    /// many renders the bar covers (several for --compare and --sweep).
    Progress(bool enabled, int runs);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Whether the bar is drawn: not quiet and stderr is a terminal.
    static bool wanted(bool quiet);

    /// Starts render number `index` (from 0), labelled `label`, and installs the callback on
    /// `renderer` (removed again by finish_run).
    void start_run(SheafRenderer renderer, int index, const std::string& label);
    void finish_run(SheafRenderer renderer);

  private:
    static int callback(void* user, float done);
    void draw(float done, bool force);
    void clear();

    bool enabled_;
    int runs_, index_ = 0;
    std::string label_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    bool drawn_ = false;
};

} // namespace render

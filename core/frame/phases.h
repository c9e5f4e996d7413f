// The frame's phase times (time_ms.<phase>) on the executing side: each phase's spans are
// summed by an Exec::Stopwatch and read when the frame ends, so timing a phase costs the host
// no wait while the frame runs (on a GPU each wait drains the device's queue of work).
#pragma once

#include "core/stats/stats.h"

#include <deque>
#include <string>
#include <utility>

namespace sheaf::wavefront {

template <class Exec> class PhaseClock {
  public:
    explicit PhaseClock(Exec& ex) : ex_(ex) {}

    /// A span of `phase` begins; spans of one phase do not nest.
    void start(const char* phase) { watch(phase).start(); }
    void stop(const char* phase) { watch(phase).stop(); }

    /// Waits once for the executing side, then adds each phase's total to `stats`.
    void add_to(Stats& stats) {
        if (watches_.empty()) return;
        ex_.synchronize();
        for (const auto& [phase, w] : watches_) stats.add("time_ms." + phase, w.total_ms());
    }

  private:
    typename Exec::Stopwatch& watch(const char* phase) {
        for (auto& [name, w] : watches_)
            if (name == phase) return w;
        watches_.emplace_back(phase, ex_.stopwatch());
        return watches_.back().second;
    }

    Exec& ex_;
    std::deque<std::pair<std::string, typename Exec::Stopwatch>> watches_;
};

} // namespace sheaf::wavefront

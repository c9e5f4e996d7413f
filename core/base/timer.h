// Wall-clock timing of pipeline phases into the frame statistics.
#pragma once

#include "core/stats/stats.h"

#include <chrono>
#include <string>

namespace sheaf {

class PhaseTimer {
  public:
    PhaseTimer(Stats& stats, std::string key)
        : stats_(stats), key_(std::move(key)), start_(clock::now()) {}
    ~PhaseTimer() { stop(); }
    void stop() {
        if (done_) return;
        done_ = true;
        stats_.add(key_, std::chrono::duration<double, std::milli>(clock::now() - start_).count());
    }

  private:
    using clock = std::chrono::steady_clock;
    Stats& stats_;
    std::string key_;
    clock::time_point start_;
    bool done_ = false;
};

} // namespace sheaf

// The launch seam: every data-parallel stage goes through parallel_for, which runs on oneTBB
// here and maps one-to-one onto a CUDA kernel launch in the GPU module.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace sheaf {

/// Calls fn(i) for every i in [0, n). `name` names the stage (for profiling and the GPU's
/// kernel names); the order of calls is unspecified, so fn must not depend on it.
template <class Fn> void parallel_for(const char* name, size_t n, Fn&& fn, size_t grain = 256) {
    (void)name;
    if (n == 0) return;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
}

/// Calls fn(begin, end) on disjoint sub-ranges covering [0, n), for stages that keep
/// per-range state (local output buffers, counters).
template <class Fn>
void parallel_for_range(const char* name, size_t n, Fn&& fn, size_t grain = 256) {
    (void)name;
    if (n == 0) return;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain),
                      [&](const tbb::blocked_range<size_t>& r) { fn(r.begin(), r.end()); });
}

} // namespace sheaf

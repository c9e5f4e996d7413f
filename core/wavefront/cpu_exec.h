// The CPU execution policy of the wavefront pipeline: launches are oneTBB parallel loops,
// memory is host memory, scans and reductions run here, sort_pairs is the CPU's stable LSD
// radix sort. The pipeline compiled against it runs in libsheaf, so the unit tests check the
// device pipeline's logic, stage by stage, against the CPU renderer on any machine.
#pragma once

#include "core/base/memory.h"
#include "core/base/parallel.h"
#include "core/sort/radix_sort.h"

#include <tbb/parallel_reduce.h>
#include <tbb/parallel_scan.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <new>

namespace sheaf::wavefront {

class CpuExec {
  public:
    static constexpr const char* kName = "cpu";

    void* allocate(size_t bytes) {
        memory_.add(int64_t(bytes));
        return ::operator new(bytes);
    }
    void deallocate(void* p, size_t bytes) {
        memory_.sub(int64_t(bytes));
        ::operator delete(p);
    }
    void copy_to_device(void* dst, const void* src, size_t bytes) {
        ++waits_;
        std::memcpy(dst, src, bytes);
    }
    void copy_to_host(void* dst, const void* src, size_t bytes) {
        ++waits_;
        std::memcpy(dst, src, bytes);
    }
    void copy_on_device(void* dst, const void* src, size_t bytes) { std::memmove(dst, src, bytes); }

    /// fn(i) for every i in [0, n), in any order.
    template <class Fn> void launch(const char* name, size_t n, const Fn& fn) {
        if (n == 0) return;
        ++launches_;
        parallel_for(name, n, fn, 1024);
    }

    /// data[i] = sum of data[0..i) in place; returns the total.
    uint32_t exclusive_scan(uint32_t* data, size_t n) {
        if (n == 0) return 0;
        ++launches_, ++waits_;
        return tbb::parallel_scan(
            tbb::blocked_range<size_t>(0, n, 1 << 16), uint32_t(0),
            [data](const tbb::blocked_range<size_t>& r, uint32_t sum, bool final) {
                for (size_t i = r.begin(); i != r.end(); ++i) {
                    const uint32_t t = data[i];
                    if (final) data[i] = sum;
                    sum += t;
                }
                return sum;
            },
            [](uint32_t a, uint32_t b) { return a + b; });
    }

    /// op over map(i) for i in [0, n), from init. op must be associative and commutative and
    /// exact (integer sums, minima, maxima), so the result does not depend on the grouping.
    template <class T, class Map, class Op>
    T transform_reduce(const char* name, size_t n, T init, const Map& map, const Op& op) {
        (void)name;
        if (n == 0) return init;
        ++launches_, ++waits_;
        return tbb::parallel_reduce(
            tbb::blocked_range<size_t>(0, n, 4096), init,
            [&](const tbb::blocked_range<size_t>& r, T acc) {
                for (size_t i = r.begin(); i != r.end(); ++i) acc = op(acc, map(i));
                return acc;
            },
            op);
    }

    /// Sorts values by keys (n * words words, word 0 least significant), stably.
    void sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n) {
        if (n < 2) return;
        ++launches_;
        radix_sort_pairs(keys, words, values, n);
    }

    /// Wall time of a phase.
    class Timer {
      public:
        explicit Timer(uint64_t* waits) : waits_(waits) {}
        double stop_ms() const {
            ++*waits_;
            return std::chrono::duration<double, std::milli>(clock::now() - start_).count();
        }

      private:
        using clock = std::chrono::steady_clock;
        uint64_t* waits_;
        clock::time_point start_ = clock::now();
    };
    Timer timer() { return Timer(&waits_); }

    int64_t peak_bytes() const { return memory_.peak(); }
    /// Device work started (launches, scans, reductions, sorts) and host waits for the device
    /// (copies, scan totals, reductions, timers): what a frame costs a GPU beyond its kernels.
    /// Counted alike by both policies, so the CPU policy shows what the GPU will do.
    uint64_t launches() const { return launches_; }
    uint64_t host_waits() const { return waits_; }

  private:
    MemoryTracker memory_;
    uint64_t launches_ = 0, waits_ = 0;
};

} // namespace sheaf::wavefront

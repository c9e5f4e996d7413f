// The CPU execution policy of the wavefront pipeline: launches are oneTBB parallel loops,
// memory is host memory, scans and reductions run here, sort_pairs is the CPU's stable LSD
// radix sort. The pipeline compiled against it runs in libsheaf, so the unit tests check the
// device pipeline's logic, stage by stage, against the CPU backend on any machine.
#pragma once

#include "core/base/memory.h"
#include "core/base/parallel.h"
#include "core/frame/compact.h"
#include "core/rsh/test_count.h"
#include "core/settings/settings.h"
#include "core/sort/radix_sort.h"

#include <tbb/parallel_reduce.h>
#include <tbb/parallel_scan.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <new>

namespace sheaf::wavefront {

class CpuExec {
  public:
    static constexpr const char* kName = "cpu";
    /// Launches run on this machine's cores over host memory.
    static constexpr bool kHostMemory = true;

    /// `shared`: a tracker to count into (the frame's, under its limit), else its own.
    explicit CpuExec(MemoryTracker* shared = nullptr) : memory_(shared ? shared : &own_) {}
    CpuExec(const CpuExec&) = delete;
    CpuExec& operator=(const CpuExec&) = delete;

    void* allocate(size_t bytes) {
        memory_->add(int64_t(bytes));
        return ::operator new(bytes);
    }
    void deallocate(void* p, size_t bytes) {
        memory_->sub(int64_t(bytes));
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

    /// Compaction without a scan or a wait: for every i in [0, min(count(), max)), e = fn(i)
    /// (a Compacted); e.tests and e.hits are added into *sums, and emit(i, e.what, slot) is
    /// called with the first of e.outputs consecutive slots taken from *counter. count() runs
    /// on the executing side and reads what earlier work left there, so the host needs no wait
    /// to size the launch; max bounds it. Slots go to elements in no particular order.
    template <class Count, class Fn, class Emit>
    void launch_compact(const char* name, size_t max, const Count& count, uint32_t* counter,
                        TestCount* sums, const Fn& fn, const Emit& emit) {
        if (max == 0) return;
        ++launches_;
        const size_t n = std::min(max, size_t(count()));
        std::atomic_ref<uint32_t> next(*counter);
        tally_ranges(name, n, sums, [&](size_t b, size_t e, TestCount& sum) {
            // Pieces of a range: counted, then one reservation for the piece's outputs.
            constexpr size_t kPiece = 256;
            Compacted c[kPiece];
            for (size_t p = b; p < e; p += kPiece) {
                const size_t m = std::min(kPiece, e - p);
                uint32_t outputs = 0;
                for (size_t k = 0; k < m; ++k) {
                    c[k] = fn(p + k);
                    sum.tests += c[k].tests, sum.hits += c[k].hits, outputs += c[k].outputs;
                }
                if (!outputs) continue;
                uint32_t slot = next.fetch_add(outputs, std::memory_order_relaxed);
                for (size_t k = 0; k < m; ++k)
                    if (c[k].outputs) emit(p + k, c[k].what, slot), slot += c[k].outputs;
            }
        });
    }

    /// For every i in [0, min(count(), max)), fn(i) (a TestCount) added into *sums: a launch
    /// whose counts the host reads later, sized without a wait as launch_compact is.
    template <class Count, class Fn>
    void launch_tally(const char* name, size_t max, const Count& count, TestCount* sums,
                      const Fn& fn) {
        if (max == 0) return;
        ++launches_;
        tally_ranges(name, std::min(max, size_t(count())), sums,
                     [&](size_t b, size_t e, TestCount& sum) {
                         for (size_t i = b; i < e; ++i) {
                             const TestCount c = fn(i);
                             sum.tests += c.tests, sum.hits += c.hits;
                         }
                     });
    }

    /// data[i] = sum of data[0..i) in place; returns the total (T: uint32_t or uint64_t).
    template <class T> T exclusive_scan(T* data, size_t n) {
        if (n == 0) return 0;
        ++waits_;
        return scan(data, n);
    }
    /// The same scan when the host does not need the total: no wait.
    template <class T> void exclusive_scan_async(T* data, size_t n) {
        if (n > 0) scan(data, n);
    }

    /// op over map(i) for i in [0, n), from init. op must be associative and commutative and
    /// exact (integer sums, minima, maxima), so the result does not depend on the grouping.
    template <class T, class Map, class Op>
    T transform_reduce(const char* name, size_t n, T init, const Map& map, const Op& op) {
        (void)name;
        if (n == 0) return init;
        ++launches_, ++waits_;
        return reduce(n, init, map, op);
    }

    /// *acc = op(*acc, op over map(i) for i in [0, n)), acc on the executing side: a
    /// reduction the host reads later, with others, or that later launches read, so it costs
    /// no wait. `identity`: op(identity, x) == x. Two launches, as on the GPU (the reduction,
    /// then the step into *acc).
    template <class T, class Map, class Op>
    void reduce_into(const char* name, size_t n, T* acc, T identity, const Map& map,
                     const Op& op) {
        (void)name;
        if (n == 0) return;
        launches_ += 2;
        *acc = op(*acc, reduce(n, identity, map, op));
    }

    /// Sorts values by keys (n * words words, word 0 least significant), stably.
    void sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n) {
        if (n < 2) return;
        ++launches_;
        radix_sort_pairs(keys, words, values, n);
    }

    /// Waits for the work issued so far (here it is done already): one host wait.
    void synchronize() { ++waits_; }

    /// Time summed over several spans of work (start, stop, start, stop ...), read by
    /// total_ms() after synchronize(): no wait of its own.
    class Stopwatch {
      public:
        void start() { start_ = clock::now(); }
        void stop() {
            ms_ += std::chrono::duration<double, std::milli>(clock::now() - start_).count();
        }
        double total_ms() const { return ms_; }

      private:
        using clock = std::chrono::steady_clock;
        clock::time_point start_;
        double ms_ = 0;
    };
    Stopwatch stopwatch() { return Stopwatch(); }

    int64_t peak_bytes() const { return memory_->peak(); }
    /// What the buffers hold, counted (and, with a limit, refused) as they are allocated.
    MemoryTracker& memory() { return *memory_; }
    /// traversal.batch when the setting is 0: the CPU's.
    size_t auto_batch_pairs() const { return kCpuBatchPairs; }
    /// Device work started (launches, scans, reductions, sorts) and host waits for the device
    /// (copies, scan totals, reductions read at once, synchronize): what a frame costs a GPU
    /// beyond its kernels.
    /// Counted alike by both policies, so the CPU policy shows what the GPU will do.
    uint64_t launches() const { return launches_; }
    uint64_t host_waits() const { return waits_; }

  private:
    // body(b, e, sum) over ranges [b, e) of [0, n) on every core, each adding into its own
    // sum; the sums go into *sums once per range.
    template <class Body>
    static void tally_ranges(const char* name, size_t n, TestCount* sums, const Body& body) {
        std::atomic_ref<uint64_t> tests(sums->tests), hits(sums->hits);
        parallel_for_range(
            name, n,
            [&](size_t b, size_t e) {
                TestCount sum;
                body(b, e, sum);
                tests.fetch_add(sum.tests, std::memory_order_relaxed);
                hits.fetch_add(sum.hits, std::memory_order_relaxed);
            },
            1024);
    }

    template <class T> T scan(T* data, size_t n) {
        ++launches_;
        return tbb::parallel_scan(
            tbb::blocked_range<size_t>(0, n, 1 << 16), T(0),
            [data](const tbb::blocked_range<size_t>& r, T sum, bool final) {
                for (size_t i = r.begin(); i != r.end(); ++i) {
                    const T t = data[i];
                    if (final) data[i] = sum;
                    sum += t;
                }
                return sum;
            },
            [](T a, T b) { return a + b; });
    }

    template <class T, class Map, class Op>
    static T reduce(size_t n, T init, const Map& map, const Op& op) {
        return tbb::parallel_reduce(
            tbb::blocked_range<size_t>(0, n, 4096), init,
            [&](const tbb::blocked_range<size_t>& r, T acc) {
                for (size_t i = r.begin(); i != r.end(); ++i) acc = op(acc, map(i));
                return acc;
            },
            op);
    }

    MemoryTracker own_;
    MemoryTracker* memory_;
    uint64_t launches_ = 0, waits_ = 0;
};

} // namespace sheaf::wavefront

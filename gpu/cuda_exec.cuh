// The CUDA execution policy of the frame pipeline (core/frame): launches are
// grid-stride kernels over the pipeline's __host__ __device__ lambdas, memory is stream-ordered
// device memory, scans, radix sorts and reductions kept on the device are CUB's, reductions
// read at once Thrust's, phase times CUDA events.
// Every call names what failed when the runtime reports an error.
#pragma once

#include "core/base/error.h"
#include "core/base/memory.h"
#include "core/frame/compact.h"
#include "core/rsh/test_count.h"
#include "core/settings/settings.h"
#include "gpu/pinned_staging.cuh"

#include <cub/block/block_reduce.cuh>
#include <cub/block/block_scan.cuh>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>
#include <cuda_runtime.h>
#include <nvtx3/nvToolsExt.h>
#include <thrust/execution_policy.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

namespace sheaf::gpu {

inline void check(cudaError_t e, const char* what) {
    if (e != cudaSuccess)
        throw RenderError(std::string("CUDA ") + what + ": " + cudaGetErrorName(e) + ": " +
                          cudaGetErrorString(e));
}

template <class Fn> __global__ void launch_kernel(size_t n, Fn fn) {
    for (size_t i = size_t(blockIdx.x) * blockDim.x + threadIdx.x; i < n;
         i += size_t(blockDim.x) * gridDim.x)
        fn(i);
}

/// Adds each thread's tests and hits over the block (CUB), then into *sums: one atomic each
/// a block.
template <class Reduce>
__device__ void block_add(typename Reduce::TempStorage& tmp, unsigned long long tests,
                          unsigned long long hits, TestCount* sums) {
    const unsigned long long t = Reduce(tmp).Sum(tests);
    __syncthreads();
    const unsigned long long h = Reduce(tmp).Sum(hits);
    if (threadIdx.x != 0) return;
    if (t) atomicAdd(reinterpret_cast<unsigned long long*>(&sums->tests), t);
    if (h) atomicAdd(reinterpret_cast<unsigned long long*>(&sums->hits), h);
}

/// launch_compact's kernel: the blocks stride over the elements, 256 at a time; per round, a
/// block scan of the elements' outputs places them after one atomic on the counter for the
/// whole block. The count is read on the device.
template <class Count, class Fn, class Emit>
__global__ void compact_kernel(size_t max, Count count, uint32_t* counter, TestCount* sums,
                               Fn fn, Emit emit) {
    using Scan = cub::BlockScan<uint32_t, 256>;
    using Reduce = cub::BlockReduce<unsigned long long, 256>;
    __shared__ union {
        typename Scan::TempStorage scan;
        typename Reduce::TempStorage reduce;
    } tmp;
    __shared__ uint32_t base;
    const size_t c = count(), n = c < max ? c : max;
    unsigned long long tests = 0, hits = 0;
    for (size_t b = size_t(blockIdx.x) * blockDim.x; b < n; b += size_t(blockDim.x) * gridDim.x) {
        const size_t i = b + threadIdx.x;
        wavefront::Compacted e;
        if (i < n) e = fn(i);
        tests += e.tests, hits += e.hits;
        uint32_t slot = 0, outputs = 0;
        Scan(tmp.scan).ExclusiveSum(e.outputs, slot, outputs);
        if (threadIdx.x == 0 && outputs) base = atomicAdd(counter, outputs);
        __syncthreads();
        if (e.outputs) emit(i, e.what, base + slot);
        __syncthreads(); // base and the scan's storage serve the next round
    }
    block_add<Reduce>(tmp.reduce, tests, hits, sums);
}

/// launch_tally's kernel: each thread adds its elements' counts, then the block's go into
/// *sums at once.
template <class Count, class Fn>
__global__ void tally_kernel(size_t max, Count count, TestCount* sums, Fn fn) {
    using Reduce = cub::BlockReduce<unsigned long long, 256>;
    __shared__ typename Reduce::TempStorage tmp;
    const size_t c = count(), n = c < max ? c : max;
    unsigned long long tests = 0, hits = 0;
    for (size_t i = size_t(blockIdx.x) * blockDim.x + threadIdx.x; i < n;
         i += size_t(blockDim.x) * gridDim.x) {
        const TestCount e = fn(i);
        tests += e.tests, hits += e.hits;
    }
    block_add<Reduce>(tmp, tests, hits, sums);
}

/// One thread's step of reduce_into: *acc = op(*acc, *part).
template <class T, class Op> struct AddInto {
    T* acc;
    const T* part;
    Op op;
    __device__ void operator()(size_t) const { *acc = op(*acc, *part); }
};

class CudaExec {
  public:
    static constexpr const char* kName = "cuda";
    static constexpr bool kHostMemory = false;

    /// Renders on `device`; `stack_bytes`: the per-thread stack the recursive CSG and pigment
    /// code needs. An exec may render many frames, one at a time (begin_frame).
    CudaExec(int device, size_t stack_bytes) : born_(std::chrono::steady_clock::now()) {
        const char* sync = std::getenv("SHEAF_CUDA_SYNC");
        sync_launches_ = sync && *sync && *sync != '0';
        const char* profile = std::getenv("SHEAF_CUDA_PROFILE");
        profile_ = profile && *profile && *profile != '0';
        check(cudaSetDevice(device), "cudaSetDevice");
        device_ = device;
        pool_ = device_pool(device);
        size_t free = 0;
        check(cudaMemGetInfo(&free, &device_bytes_), "cudaMemGetInfo");
        int sms = 0;
        check(cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, device),
              "cudaDeviceGetAttribute(multiprocessors)");
        resident_blocks_ = size_t(std::max(sms, 1)) * 8; // 2,048 threads a multiprocessor
        raise_stack_limit(stack_bytes);
        check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "cudaStreamCreate");
        setup_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                              born_)
                        .count();
    }
    ~CudaExec() {
        end_frame();
        if (temp_) cudaFreeAsync(temp_, stream_);
        if (scan_ends_) cudaFreeAsync(scan_ends_, stream_);
        cudaStreamSynchronize(stream_);
        cudaStreamDestroy(stream_);
    }
    CudaExec(const CudaExec&) = delete;
    CudaExec& operator=(const CudaExec&) = delete;

    /// The start of a later frame on this exec: its counts and memory peak start again (from
    /// what the exec still holds: a kept scene, CUB's scratch), its stack need is raised to.
    void begin_frame(size_t stack_bytes) {
        born_ = std::chrono::steady_clock::now();
        check(cudaSetDevice(device_), "cudaSetDevice");
        raise_stack_limit(stack_bytes);
        launches_ = waits_ = 0;
        memory_.restart_peak();
        for (const Mark& m : marks_) cudaEventDestroy(m.event); // a failed frame's
        marks_.clear();
        depth_ = 0;
        setup_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                              born_)
                        .count();
    }
    /// The end of a frame: SHEAF_CUDA_PROFILE's table of it, when asked for.
    void end_frame() {
        if (profile_ && !marks_.empty()) print_profile();
        marks_.clear();
    }
    int device() const { return device_; }

    void* allocate(size_t bytes) {
        void* p = pool_allocate(bytes);
        memory_.add(int64_t(bytes));
        return p;
    }
    /// Called from destructors, so it cannot throw: a failed free is reported by the next
    /// launch or copy to the host under its own name, not left for cudaGetLastError.
    void deallocate(void* p, size_t bytes) {
        memory_.sub(int64_t(bytes));
        if (const cudaError_t e = cudaFreeAsync(p, stream_); e != cudaSuccess) {
            cudaGetLastError();
            if (free_error_ == cudaSuccess) free_error_ = e;
        }
    }
    // Host <-> device copies wait for the copy: the host side may be a temporary. Large ones
    // go through the process's page-locked staging (gpu/pinned_staging.cuh) when it is free.
    void copy_to_device(void* dst, const void* src, size_t bytes) {
        ++waits_;
        const Span span(*this, "copy to device");
        cudaError_t e = cudaSuccess;
        if (staged_copy(dst, src, bytes, cudaMemcpyHostToDevice, stream_, e))
            return check(e, "copy to device");
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyHostToDevice, stream_), "copy to device");
        check(cudaStreamSynchronize(stream_), "copy to device");
    }
    void copy_to_host(void* dst, const void* src, size_t bytes) {
        ++waits_;
        check_frees();
        const Span span(*this, "copy to host");
        cudaError_t e = cudaSuccess;
        if (staged_copy(dst, src, bytes, cudaMemcpyDeviceToHost, stream_, e))
            return check(e, "copy to host");
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToHost, stream_), "copy to host");
        check(cudaStreamSynchronize(stream_), "copy to host");
    }
    void copy_on_device(void* dst, const void* src, size_t bytes) {
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToDevice, stream_), "device copy");
    }

    /// fn(i) for every i in [0, n): a grid-stride kernel of 256-thread blocks.
    template <class Fn> void launch(const char* name, size_t n, const Fn& fn) {
        if (n == 0) return;
        ++launches_;
        check_frees();
        const size_t blocks = std::min<size_t>((n + 255) / 256, size_t(1) << 20);
        const Span span(*this, name);
        launch_kernel<<<unsigned(blocks), 256, 0, stream_>>>(n, fn);
        check(cudaGetLastError(), name);
        // SHEAF_CUDA_SYNC=1: wait for every launch, so a fault names the launch that made it.
        if (sync_launches_) check(cudaStreamSynchronize(stream_), name);
    }

    /// Compaction without a scan or a wait (core/frame/cpu_exec.h): 256-thread blocks, at
    /// most one resident wave of them whatever max is, the count read on the device; one
    /// atomic on the counter per block and round, one per block for each sum.
    template <class Count, class Fn, class Emit>
    void launch_compact(const char* name, size_t max, const Count& count, uint32_t* counter,
                        TestCount* sums, const Fn& fn, const Emit& emit) {
        if (max == 0) return;
        ++launches_;
        check_frees();
        const Span span(*this, name);
        compact_kernel<<<unsigned(counted_blocks(max)), 256, 0, stream_>>>(max, count, counter,
                                                                           sums, fn, emit);
        check(cudaGetLastError(), name);
        if (sync_launches_) check(cudaStreamSynchronize(stream_), name);
    }
    /// fn(i) for every i in [0, min(count(), max)) added into *sums, sized as launch_compact.
    template <class Count, class Fn>
    void launch_tally(const char* name, size_t max, const Count& count, TestCount* sums,
                      const Fn& fn) {
        if (max == 0) return;
        ++launches_;
        check_frees();
        const Span span(*this, name);
        tally_kernel<<<unsigned(counted_blocks(max)), 256, 0, stream_>>>(max, count, sums, fn);
        check(cudaGetLastError(), name);
        if (sync_launches_) check(cudaStreamSynchronize(stream_), name);
    }

    /// data[i] = sum of data[0..i) in place (CUB); returns the total (T: uint32_t or
    /// uint64_t). The last element before and after the scan are copied aside on the device,
    /// so the host waits once.
    template <class T> T exclusive_scan(T* data, size_t n) {
        static_assert(sizeof(T) <= sizeof(uint64_t), "a scanned element fits a scan end slot");
        if (n == 0) return 0;
        ++launches_;
        if (!scan_ends_) scan_ends_ = static_cast<uint64_t*>(pool_allocate(2 * sizeof(uint64_t)));
        T* ends = reinterpret_cast<T*>(scan_ends_);
        const Span span(*this, "scan (waited)");
        copy_on_device(ends, data + n - 1, sizeof(T));
        scan_on_stream(data, n);
        copy_on_device(ends + 1, data + n - 1, sizeof(T));
        T e[2] = {0, 0};
        copy_to_host(e, ends, sizeof e);
        return T(e[0] + e[1]);
    }

    /// op over map(i) for i in [0, n), from init (Thrust; waits for the result).
    template <class T, class Map, class Op>
    T transform_reduce(const char* name, size_t n, T init, const Map& map, const Op& op) {
        if (n == 0) return init;
        ++launches_, ++waits_;
        const Span span(*this, name);
        const T r = thrust::transform_reduce(thrust::cuda::par.on(stream_),
                                             thrust::counting_iterator<size_t>(0),
                                             thrust::counting_iterator<size_t>(n), map, init, op);
        check(cudaGetLastError(), name);
        return r;
    }

    /// The same scan when the host does not need the total: no wait.
    template <class T> void exclusive_scan_async(T* data, size_t n) {
        if (n == 0) return;
        ++launches_;
        check_frees();
        const Span span(*this, "scan");
        scan_on_stream(data, n);
    }

    /// *acc = op(*acc, op over map(i) for i in [0, n)), acc in device memory, without a wait:
    /// CUB's reduction (from `identity`) into a slot after its scratch space, then one thread
    /// steps *acc by the slot.
    template <class T, class Map, class Op>
    void reduce_into(const char* name, size_t n, T* acc, T identity, const Map& map,
                     const Op& op) {
        if (n == 0) return;
        ++launches_;
        check_frees();
        const thrust::counting_iterator<size_t> first(0);
        size_t bytes = 0;
        check(cub::DeviceReduce::TransformReduce(nullptr, bytes, first, static_cast<T*>(nullptr), n,
                                                 op, map, identity, stream_),
              name);
        const size_t at = (bytes + 255) / 256 * 256;
        const Span span(*this, name);
        char* scratch = static_cast<char*>(temp(at + sizeof(T)));
        T* part = reinterpret_cast<T*>(scratch + at);
        check(cub::DeviceReduce::TransformReduce(scratch, bytes, first, part, n, op, map, identity,
                                                 stream_),
              name);
        check(cudaGetLastError(), name);
        launch(name, 1, AddInto<T, Op>{acc, part, op});
    }

    /// Sorts values by keys (n * words words, word 0 least significant), stably: CUB's
    /// radix sort on 32-bit keys for one word; for more, an LSD sort of positions by each
    /// pair of words as 64-bit keys (each pass stable), then a gather of keys and values.
    void sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n);
    /// One stable radix sort of (k, v) on the low `bits` bits of k, the alternates as scratch;
    /// returns whether the result is in the alternates (n < 2^31).
    bool radix_pass64(uint64_t* k, uint64_t* k_alt, uint32_t* v, uint32_t* v_alt, size_t n,
                      int bits);

    /// Waits for the work issued so far on the stream: one host wait.
    void synchronize() {
        ++waits_;
        check_frees();
        check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
    }

    /// Device time summed over several spans of work (start, stop, start, stop ...): events
    /// recorded on the stream, read by total_ms() after synchronize(), with no wait of its own.
    class Stopwatch {
      public:
        explicit Stopwatch(cudaStream_t s) : stream_(s) {}
        ~Stopwatch() {
            for (cudaEvent_t e : events_) cudaEventDestroy(e);
        }
        Stopwatch(Stopwatch&& o) noexcept : stream_(o.stream_), events_(std::move(o.events_)) {
            o.events_.clear();
        }
        Stopwatch(const Stopwatch&) = delete;
        void start() { record(); }
        void stop() { record(); }
        double total_ms() const {
            double sum = 0;
            for (size_t i = 0; i + 1 < events_.size(); i += 2) {
                float ms = 0;
                check(cudaEventElapsedTime(&ms, events_[i], events_[i + 1]),
                      "cudaEventElapsedTime");
                sum += ms;
            }
            return sum;
        }

      private:
        void record() {
            // Room first (geometric growth), so a failed push cannot leak the event.
            if (events_.size() == events_.capacity())
                events_.reserve(std::max<size_t>(16, 2 * events_.size()));
            cudaEvent_t e = nullptr;
            check(cudaEventCreate(&e), "cudaEventCreate");
            events_.push_back(e);
            check(cudaEventRecord(e, stream_), "cudaEventRecord");
        }
        cudaStream_t stream_;
        std::vector<cudaEvent_t> events_;
    };
    Stopwatch stopwatch() { return Stopwatch(stream_); }

    int64_t peak_bytes() const { return memory_.peak(); }
    /// traversal.batch when the setting is 0: sized to the device's memory.
    size_t auto_batch_pairs() const { return device_batch_pairs(device_bytes_); }
    /// Whether SHEAF_CUDA_PROFILE asked for the per-span table.
    bool profiling() const { return profile_; }
    /// Device work started and host waits for the device, counted as the CPU policy does.
    uint64_t launches() const { return launches_; }
    uint64_t host_waits() const { return waits_; }
    cudaStream_t stream() const { return stream_; }

    /// Blocks of a launch of at most max elements whose count is read on the device: enough
    /// for max, at most what the device holds at once (the blocks then stride).
    size_t counted_blocks(size_t max) const {
        return std::min<size_t>((max + 255) / 256, resident_blocks_);
    }

    /// Scratch space for CUB, grown as needed (ordered on the stream).
    void* temp(size_t bytes) {
        if (bytes > temp_bytes_) {
            if (temp_) check(cudaFreeAsync(temp_, stream_), "cudaFreeAsync");
            temp_ = nullptr;
            temp_ = pool_allocate(bytes);
            memory_.add(int64_t(bytes) - int64_t(temp_bytes_));
            temp_bytes_ = bytes;
        }
        return temp_;
    }

    /// SHEAF_CUDA_PROFILE=1: device time per named piece of work, from events around each,
    /// printed to stderr when the exec ends (a diagnostic; the events cost host time).
    class Span {
      public:
        // Only the outermost span is timed (a sort's launches are the sort's).
        // An NVTX range of the same name, for Nsight Compute's --nvtx-include.
        Span(CudaExec& ex, const char* name) : ex_(ex.profile_ ? &ex : nullptr) {
            if (ex_ && ex_->depth_++ == 0) {
                nvtxRangePushA(name);
                ex_->profile_mark(name);
            }
        }
        ~Span() {
            if (ex_ && --ex_->depth_ == 0) {
                ex_->profile_mark(nullptr);
                nvtxRangePop();
            }
        }
        Span(const Span&) = delete;

      private:
        CudaExec* ex_;
    };

  private:
    /// Stream-ordered device memory from the module's pool on this device (device_pool). When
    /// the device is full, the pool's unused reservation is given back and the allocation
    /// tried once more.
    void* pool_allocate(size_t bytes) {
        void* p = nullptr;
        cudaError_t e = cudaMallocFromPoolAsync(&p, bytes, pool_, stream_);
        if (e == cudaErrorMemoryAllocation) {
            cudaGetLastError();
            check(cudaStreamSynchronize(stream_), "cudaMallocFromPoolAsync");
            check(cudaMemPoolTrimTo(pool_, 0), "cudaMemPoolTrimTo");
            e = cudaMallocFromPoolAsync(&p, bytes, pool_, stream_);
        }
        check(e, "cudaMallocFromPoolAsync");
        return p;
    }

    /// The module's memory pool on `device`, made at its first use and kept for the process.
    /// Its release threshold is an eighth of the device's memory: memory a frame frees stays
    /// reserved for the next allocations and the next frame, instead of going back to the
    /// driver at every host wait, as the default pool's threshold of 0 does (each later
    /// allocation then maps fresh memory). A pool of its own, so the process's default pool,
    /// which a host application may use, keeps its settings.
    static cudaMemPool_t device_pool(int device) {
        static std::mutex m;
        static std::vector<std::pair<int, cudaMemPool_t>> pools;
        std::lock_guard<std::mutex> lock(m);
        for (const auto& [d, pool] : pools)
            if (d == device) return pool;
        cudaMemPoolProps props{};
        props.allocType = cudaMemAllocationTypePinned;
        props.handleTypes = cudaMemHandleTypeNone;
        props.location.type = cudaMemLocationTypeDevice;
        props.location.id = device;
        cudaMemPool_t pool = nullptr;
        check(cudaMemPoolCreate(&pool, &props), "cudaMemPoolCreate");
        size_t free = 0, total = 0;
        check(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
        uint64_t threshold = total / 8;
        check(cudaMemPoolSetAttribute(pool, cudaMemPoolAttrReleaseThreshold, &threshold),
              "cudaMemPoolSetAttribute(release threshold)");
        pools.emplace_back(device, pool);
        return pool;
    }

    void profile_mark(const char* name) {
        cudaEvent_t e = nullptr;
        if (cudaEventCreate(&e) != cudaSuccess) return;
        cudaEventRecord(e, stream_);
        marks_.push_back({name, e, std::chrono::steady_clock::now()});
    }
    void print_profile() {
        if (cudaStreamSynchronize(stream_) != cudaSuccess) return;
        struct Row {
            std::string name;
            double ms = 0, host_ms = 0;
            int count = 0;
        };
        std::vector<Row> rows;
        double total = 0;
        for (size_t i = 0; i + 1 < marks_.size(); ++i) {
            if (!marks_[i].name || marks_[i + 1].name) continue;
            float ms = 0;
            cudaEventElapsedTime(&ms, marks_[i].event, marks_[i + 1].event);
            auto it = std::find_if(rows.begin(), rows.end(),
                                   [&](const Row& r) { return r.name == marks_[i].name; });
            if (it == rows.end()) it = rows.insert(rows.end(), Row{marks_[i].name});
            it->ms += ms, ++it->count, total += ms;
            it->host_ms +=
                std::chrono::duration<double, std::milli>(marks_[i + 1].at - marks_[i].at).count();
        }
        for (const auto& m : marks_) cudaEventDestroy(m.event);
        std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.ms > b.ms; });
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - born_)
                .count();
        std::fprintf(stderr,
                     "profile: %.3f ms of device work in %zu spans; %.3f ms on the host from "
                     "the exec's start (%.3f ms to set it up)\n",
                     total, marks_.size() / 2, wall, setup_ms_);
        for (const Row& r : rows)
            std::fprintf(stderr, "profile: %9.3f ms (host %9.3f ms) %5d x  %s\n", r.ms,
                         r.host_ms, r.count, r.name.c_str());
    }
    struct Mark {
        const char* name; // null: the end of the span before
        cudaEvent_t event;
        std::chrono::steady_clock::time_point at;
    };
    bool profile_ = false;
    int depth_ = 0;
    std::vector<Mark> marks_;
    std::chrono::steady_clock::time_point born_;
    double setup_ms_ = 0;

    template <class T> void scan_on_stream(T* data, size_t n) {
        size_t bytes = 0;
        check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, data, data, n, stream_),
              "cub::DeviceScan::ExclusiveSum");
        check(cub::DeviceScan::ExclusiveSum(temp(bytes), bytes, data, data, n, stream_),
              "cub::DeviceScan::ExclusiveSum");
    }

    void check_frees() {
        if (free_error_ == cudaSuccess) return;
        const cudaError_t e = free_error_;
        free_error_ = cudaSuccess;
        check(e, "cudaFreeAsync");
    }

    /// The per-thread stack limit is the device's, shared by every render in the process, and
    /// the device reserves it for every resident thread (a 96 KiB limit is about 26 GiB on an
    /// H100). It is only raised, so no render loses the stack it was launched with, and it
    /// stays raised for the next frame: setting it reallocates that reservation, which cost
    /// 2.3 ms of a 16 ms frame on an H200 when every frame raised it and put it back.
    static void raise_stack_limit(size_t bytes) {
        static std::mutex m;
        std::lock_guard<std::mutex> lock(m);
        size_t current = 0;
        check(cudaDeviceGetLimit(&current, cudaLimitStackSize), "cudaDeviceGetLimit(stack)");
        if (bytes > current)
            check(cudaDeviceSetLimit(cudaLimitStackSize, bytes), "cudaDeviceSetLimit(stack)");
    }

    cudaStream_t stream_ = nullptr;
    int device_ = 0;
    size_t device_bytes_ = 0; // the device's memory, free or not
    size_t resident_blocks_ = 1024; // 256-thread blocks the device holds at once
    cudaMemPool_t pool_ = nullptr;
    bool sync_launches_ = false;
    void* temp_ = nullptr;
    size_t temp_bytes_ = 0;
    uint64_t* scan_ends_ = nullptr; // the scanned array's last element before and after
    MemoryTracker memory_;
    uint64_t launches_ = 0, waits_ = 0;
    cudaError_t free_error_ = cudaSuccess;
};

/// CudaExec::radix_pass64 as sort_pairs_by_word_pairs's 64-bit sort: a named type at namespace
/// scope, as nvcc requires of the template arguments of a function holding extended lambdas.
struct RadixPass64 {
    CudaExec* ex;
    bool operator()(uint64_t* k, uint64_t* k_alt, uint32_t* v, uint32_t* v_alt, size_t n,
                    int bits) const {
        return ex->radix_pass64(k, k_alt, v, v_alt, n, bits);
    }
};

} // namespace sheaf::gpu

// The CUDA execution policy of the wavefront pipeline (core/wavefront): launches are
// grid-stride kernels over the pipeline's __host__ __device__ lambdas, memory is stream-ordered
// device memory, scans, radix sorts and reductions kept on the device are CUB's, reductions
// read at once Thrust's, phase times CUDA events.
// Every call names what failed when the runtime reports an error.
#pragma once

#include "core/base/error.h"
#include "core/base/memory.h"

#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>
#include <cuda_runtime.h>
#include <thrust/execution_policy.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <cstdint>
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

    /// Renders on `device`; `stack_bytes`: the per-thread stack the recursive CSG and pigment
    /// code needs.
    CudaExec(int device, size_t stack_bytes) {
        const char* sync = std::getenv("SHEAF_CUDA_SYNC");
        sync_launches_ = sync && *sync && *sync != '0';
        check(cudaSetDevice(device), "cudaSetDevice");
        stack_.acquire(stack_bytes);
        if (const cudaError_t e = cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking);
            e != cudaSuccess) {
            stack_.release();
            check(e, "cudaStreamCreate");
        }
    }
    ~CudaExec() {
        if (temp_) cudaFreeAsync(temp_, stream_);
        if (scan_ends_) cudaFreeAsync(scan_ends_, stream_);
        cudaStreamSynchronize(stream_);
        cudaStreamDestroy(stream_);
        stack_.release();
    }
    CudaExec(const CudaExec&) = delete;
    CudaExec& operator=(const CudaExec&) = delete;

    void* allocate(size_t bytes) {
        void* p = nullptr;
        check(cudaMallocAsync(&p, bytes, stream_), "cudaMallocAsync");
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
    // Host <-> device copies wait for the copy: the host side may be a temporary.
    void copy_to_device(void* dst, const void* src, size_t bytes) {
        ++waits_;
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyHostToDevice, stream_), "copy to device");
        check(cudaStreamSynchronize(stream_), "copy to device");
    }
    void copy_to_host(void* dst, const void* src, size_t bytes) {
        ++waits_;
        check_frees();
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
        launch_kernel<<<unsigned(blocks), 256, 0, stream_>>>(n, fn);
        check(cudaGetLastError(), name);
        // SHEAF_CUDA_SYNC=1: wait for every launch, so a fault names the launch that made it.
        if (sync_launches_) check(cudaStreamSynchronize(stream_), name);
    }

    /// data[i] = sum of data[0..i) in place (CUB); returns the total (T: uint32_t or
    /// uint64_t). The last element before and after the scan are copied aside on the device,
    /// so the host waits once.
    template <class T> T exclusive_scan(T* data, size_t n) {
        static_assert(sizeof(T) <= sizeof(uint64_t), "a scanned element fits a scan end slot");
        if (n == 0) return 0;
        ++launches_;
        if (!scan_ends_) {
            check(cudaMallocAsync(reinterpret_cast<void**>(&scan_ends_), 2 * sizeof(uint64_t),
                                  stream_),
                  "cudaMallocAsync");
        }
        T* ends = reinterpret_cast<T*>(scan_ends_);
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
    /// Device work started and host waits for the device, counted as the CPU policy does.
    uint64_t launches() const { return launches_; }
    uint64_t host_waits() const { return waits_; }
    cudaStream_t stream() const { return stream_; }

    /// Scratch space for CUB, grown as needed (ordered on the stream).
    void* temp(size_t bytes) {
        if (bytes > temp_bytes_) {
            if (temp_) check(cudaFreeAsync(temp_, stream_), "cudaFreeAsync");
            temp_ = nullptr;
            check(cudaMallocAsync(&temp_, bytes, stream_), "cudaMallocAsync");
            memory_.add(int64_t(bytes) - int64_t(temp_bytes_));
            temp_bytes_ = bytes;
        }
        return temp_;
    }

  private:
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
    /// H100). While renders run it is only raised, so none loses the stack it was launched
    /// with; when the last one ends, the limit the process had before is put back.
    class StackLimit {
      public:
        void acquire(size_t bytes) {
            std::lock_guard<std::mutex> lock(state().m);
            State& st = state();
            size_t current = 0;
            check(cudaDeviceGetLimit(&current, cudaLimitStackSize), "cudaDeviceGetLimit(stack)");
            if (st.active == 0) st.before = current;
            if (bytes > current)
                check(cudaDeviceSetLimit(cudaLimitStackSize, bytes), "cudaDeviceSetLimit(stack)");
            ++st.active;
            held_ = true;
        }
        void release() {
            if (!held_) return;
            held_ = false;
            std::lock_guard<std::mutex> lock(state().m);
            State& st = state();
            if (--st.active == 0) cudaDeviceSetLimit(cudaLimitStackSize, st.before);
        }

      private:
        struct State {
            std::mutex m;
            int active = 0;
            size_t before = 0;
        };
        static State& state() {
            static State s;
            return s;
        }
        bool held_ = false;
    };

    StackLimit stack_;
    cudaStream_t stream_ = nullptr;
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

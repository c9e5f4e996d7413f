// The CUDA execution policy of the wavefront pipeline (core/wavefront): launches are
// grid-stride kernels over the pipeline's __host__ __device__ lambdas, memory is stream-ordered
// device memory, scans and radix sorts are CUB's, reductions Thrust's, timers CUDA events.
// Every call names what failed when the runtime reports an error.
#pragma once

#include "core/base/error.h"
#include "core/base/memory.h"

#include <cub/device/device_radix_sort.cuh>
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

class CudaExec {
  public:
    static constexpr const char* kName = "cuda";

    /// Renders on `device`; `stack_bytes`: the per-thread stack the recursive CSG and pigment
    /// code needs.
    CudaExec(int device, size_t stack_bytes) {
        const char* sync = std::getenv("SHEAF_CUDA_SYNC");
        sync_launches_ = sync && *sync && *sync != '0';
        check(cudaSetDevice(device), "cudaSetDevice");
        raise_stack_limit(stack_bytes);
        check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "cudaStreamCreate");
    }
    ~CudaExec() {
        if (temp_) cudaFreeAsync(temp_, stream_);
        cudaStreamSynchronize(stream_);
        cudaStreamDestroy(stream_);
    }
    CudaExec(const CudaExec&) = delete;
    CudaExec& operator=(const CudaExec&) = delete;

    void* allocate(size_t bytes) {
        void* p = nullptr;
        check(cudaMallocAsync(&p, bytes, stream_), "cudaMallocAsync");
        memory_.add(int64_t(bytes));
        return p;
    }
    void deallocate(void* p, size_t bytes) {
        cudaFreeAsync(p, stream_);
        memory_.sub(int64_t(bytes));
    }
    // Host <-> device copies wait for the copy: the host side may be a temporary.
    void copy_to_device(void* dst, const void* src, size_t bytes) {
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyHostToDevice, stream_), "copy to device");
        check(cudaStreamSynchronize(stream_), "copy to device");
    }
    void copy_to_host(void* dst, const void* src, size_t bytes) {
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToHost, stream_), "copy to host");
        check(cudaStreamSynchronize(stream_), "copy to host");
    }
    void copy_on_device(void* dst, const void* src, size_t bytes) {
        check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToDevice, stream_), "device copy");
    }

    /// fn(i) for every i in [0, n): a grid-stride kernel of 256-thread blocks.
    template <class Fn> void launch(const char* name, size_t n, const Fn& fn) {
        if (n == 0) return;
        const size_t blocks = std::min<size_t>((n + 255) / 256, size_t(1) << 20);
        launch_kernel<<<unsigned(blocks), 256, 0, stream_>>>(n, fn);
        check(cudaGetLastError(), name);
        // SHEAF_CUDA_SYNC=1: wait for every launch, so a fault names the launch that made it.
        if (sync_launches_) check(cudaStreamSynchronize(stream_), name);
    }

    /// data[i] = sum of data[0..i) in place (CUB); returns the total.
    uint32_t exclusive_scan(uint32_t* data, size_t n) {
        if (n == 0) return 0;
        uint32_t last_in = 0, last_out = 0;
        copy_to_host(&last_in, data + n - 1, sizeof last_in);
        size_t bytes = 0;
        check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, data, data, n, stream_),
              "cub::DeviceScan::ExclusiveSum");
        check(cub::DeviceScan::ExclusiveSum(temp(bytes), bytes, data, data, n, stream_),
              "cub::DeviceScan::ExclusiveSum");
        copy_to_host(&last_out, data + n - 1, sizeof last_out);
        return last_out + last_in;
    }

    /// op over map(i) for i in [0, n), from init (Thrust; waits for the result).
    template <class T, class Map, class Op>
    T transform_reduce(const char* name, size_t n, T init, const Map& map, const Op& op) {
        if (n == 0) return init;
        const T r = thrust::transform_reduce(thrust::cuda::par.on(stream_),
                                             thrust::counting_iterator<size_t>(0),
                                             thrust::counting_iterator<size_t>(n), map, init, op);
        check(cudaGetLastError(), name);
        return r;
    }

    /// Sorts values by keys (n * words words, word 0 least significant), stably: CUB's
    /// radix sort on 32-bit keys for one word; for more, an LSD sort of positions by each
    /// pair of words as 64-bit keys (each pass stable), then a gather of keys and values.
    void sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n);

    /// Device time of a phase: CUDA events around it on the stream.
    class Timer {
      public:
        explicit Timer(cudaStream_t s) : stream_(s) {
            cudaEventCreate(&start_);
            cudaEventCreate(&stop_);
            cudaEventRecord(start_, stream_);
        }
        ~Timer() {
            cudaEventDestroy(start_);
            cudaEventDestroy(stop_);
        }
        Timer(Timer&& o) noexcept : stream_(o.stream_), start_(o.start_), stop_(o.stop_) {
            o.start_ = o.stop_ = nullptr;
        }
        Timer(const Timer&) = delete;
        double stop_ms() const {
            float ms = 0;
            check(cudaEventRecord(stop_, stream_), "cudaEventRecord");
            check(cudaEventSynchronize(stop_), "cudaEventSynchronize");
            check(cudaEventElapsedTime(&ms, start_, stop_), "cudaEventElapsedTime");
            return ms;
        }

      private:
        cudaStream_t stream_;
        cudaEvent_t start_ = nullptr, stop_ = nullptr;
    };
    Timer timer() { return Timer(stream_); }

    int64_t peak_bytes() const { return memory_.peak(); }
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
    /// The stack limit is the device's, shared by every render in the process: only ever
    /// raised, so a render on another thread never loses the stack it was launched with.
    static void raise_stack_limit(size_t bytes) {
        static std::mutex m;
        std::lock_guard<std::mutex> lock(m);
        size_t current = 0;
        check(cudaDeviceGetLimit(&current, cudaLimitStackSize), "cudaDeviceGetLimit(stack)");
        if (bytes > current)
            check(cudaDeviceSetLimit(cudaLimitStackSize, bytes), "cudaDeviceSetLimit(stack)");
    }

    cudaStream_t stream_ = nullptr;
    bool sync_launches_ = false;
    void* temp_ = nullptr;
    size_t temp_bytes_ = 0;
    MemoryTracker memory_;
};

} // namespace sheaf::gpu

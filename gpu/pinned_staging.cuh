// Page-locked host memory for the large copies between the host and the device. A copy from
// or to pageable memory runs through the driver's own small staging buffers: the frame's
// passes (13 MiB at 512², 52 MiB at 1024²) came back from an H200 at about 2.4 GB/s that way.
// From page-locked memory a copy is one DMA at the bus's rate, and the host's side of it is a
// memcpy on every core (parallel_copy). The buffer is the process's, kept between frames
// (page-locking is slow: it is not done per frame), grown to the largest piece asked for, and
// used by one copy at a time: a copy that finds it busy, or a process refused page-locked
// memory, copies the pageable way. SHEAF_CUDA_PINNED=0 turns it off, to measure the difference.
#pragma once

#include "core/base/memory.h"

#include <cuda_runtime.h>

#include <atomic>
#include <cstdlib>
#include <mutex>

namespace sheaf::gpu {

class PinnedStaging {
  public:
    /// Copies under this go the pageable way: the memcpy through the staging would cost more
    /// than the DMA saves.
    static constexpr size_t kMinBytes = size_t(1) << 20;
    /// The largest buffer: longer copies go through it in pieces.
    static constexpr size_t kMaxBytes = size_t(64) << 20;

    /// The process's staging. Never freed: at exit the driver may be gone before it.
    static PinnedStaging& instance() {
        static PinnedStaging* s = new PinnedStaging;
        return *s;
    }

    /// Holds the buffer, at least `bytes` (at most kMaxBytes) long, until release(); null when
    /// it is busy, off or refused.
    void* acquire(size_t bytes) {
        if (!enabled_ || !mutex_.try_lock()) return nullptr;
        bytes = bytes < kMaxBytes ? bytes : kMaxBytes;
        if (capacity_ < bytes) {
            if (p_) cudaFreeHost(p_);
            p_ = nullptr, capacity_ = 0;
            const size_t want = (bytes + kMinBytes - 1) / kMinBytes * kMinBytes;
            if (cudaHostAlloc(&p_, want, cudaHostAllocPortable) != cudaSuccess) {
                cudaGetLastError(); // not sticky: the copy goes the pageable way
                p_ = nullptr;
                enabled_ = false; // and so will every later one
                mutex_.unlock();
                return nullptr;
            }
            capacity_ = want;
        }
        return p_;
    }
    size_t capacity() const { return capacity_; }
    void release() { mutex_.unlock(); }

  private:
    PinnedStaging() {
        const char* env = std::getenv("SHEAF_CUDA_PINNED");
        enabled_ = !(env && env[0] == '0');
    }
    std::mutex mutex_;
    std::atomic<bool> enabled_{true};
    void* p_ = nullptr;
    size_t capacity_ = 0;
};

/// Copies `bytes` between host memory and the device on `stream` through the process's
/// staging, in pieces, waiting for each. False (nothing copied) when the staging is not to be
/// had: the caller copies the pageable way.
inline bool staged_copy(void* dst, const void* src, size_t bytes, cudaMemcpyKind kind,
                        cudaStream_t stream, cudaError_t& error) {
    if (bytes < PinnedStaging::kMinBytes) return false;
    PinnedStaging& staging = PinnedStaging::instance();
    char* const buffer = static_cast<char*>(staging.acquire(bytes));
    if (!buffer) return false;
    struct Release {
        PinnedStaging& s;
        ~Release() { s.release(); }
    } release{staging};
    const size_t piece = staging.capacity();
    char* const d = static_cast<char*>(dst);
    const char* const s = static_cast<const char*>(src);
    error = cudaSuccess;
    for (size_t at = 0; at < bytes && error == cudaSuccess; at += piece) {
        const size_t n = bytes - at < piece ? bytes - at : piece;
        if (kind == cudaMemcpyHostToDevice) {
            parallel_copy(buffer, s + at, n);
            error = cudaMemcpyAsync(d + at, buffer, n, kind, stream);
            if (error == cudaSuccess) error = cudaStreamSynchronize(stream);
        } else {
            error = cudaMemcpyAsync(buffer, s + at, n, kind, stream);
            if (error == cudaSuccess) error = cudaStreamSynchronize(stream);
            if (error == cudaSuccess) parallel_copy(d + at, buffer, n);
        }
    }
    return true;
}

} // namespace sheaf::gpu

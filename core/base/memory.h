// Accounting of the pipeline's buffers, so a frame can report its peak memory.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sheaf {

/// The memory this process could still take without the system running out: Linux's
/// MemAvailable, or less where the process's control group has a lower limit. 0 when unknown.
int64_t available_memory_bytes();

/// Readies fresh memory [p, p + bytes) that is about to be filled: asks for transparent huge
/// pages where the system grants them on request, and touches every page from all cores. A
/// frame's passes are tens of MiB of fresh memory, and faulting it in 4 KiB pages on one
/// core cost more than the copy that fills it. Ranges under 1 MiB are left alone.
void prefault_host_pages(void* p, size_t bytes);

/// memcpy of [src, src + bytes) to dst from all cores, in pieces of 256 KiB (one memcpy under
/// 1 MiB): one core cannot fill host memory at the rate a device copy reaches it.
void parallel_copy(void* dst, const void* src, size_t bytes);

class MemoryTracker {
  public:
    /// Buffers beyond `bytes` in all are refused (OutOfMemory) before they are allocated;
    /// 0: no limit. `available` is what the message reports the machine had.
    void set_limit(int64_t bytes, int64_t available) { limit_ = bytes, available_ = available; }

    void add(int64_t bytes) {
        const int64_t now = current_.fetch_add(bytes, std::memory_order_relaxed) + bytes;
        if (limit_ > 0 && bytes > 0 && now > limit_) {
            current_.fetch_sub(bytes, std::memory_order_relaxed);
            refuse(bytes, now);
        }
        int64_t p = peak_.load(std::memory_order_relaxed);
        while (now > p && !peak_.compare_exchange_weak(p, now, std::memory_order_relaxed)) {
        }
    }
    void sub(int64_t bytes) { current_.fetch_sub(bytes, std::memory_order_relaxed); }
    int64_t current() const { return current_.load(); }
    int64_t peak() const { return peak_.load(); }
    /// The peak starts again from what is held now (a new frame on memory kept from the last).
    void restart_peak() { peak_.store(current_.load()); }

  private:
    [[noreturn]] void refuse(int64_t bytes, int64_t total) const;
    std::atomic<int64_t> current_{0}, peak_{0};
    int64_t limit_ = 0, available_ = 0;
};

/// A std::allocator that reports to a tracker (none: untracked).
template <class T> struct TrackedAllocator {
    using value_type = T;
    MemoryTracker* tracker = nullptr;

    TrackedAllocator() = default;
    explicit TrackedAllocator(MemoryTracker* t) : tracker(t) {}
    template <class U> TrackedAllocator(const TrackedAllocator<U>& o) : tracker(o.tracker) {}

    T* allocate(size_t n) {
        if (tracker) tracker->add(int64_t(n * sizeof(T))); // may refuse: before allocating
        try {
            return std::allocator<T>().allocate(n);
        } catch (...) {
            if (tracker) tracker->sub(int64_t(n * sizeof(T)));
            throw;
        }
    }
    void deallocate(T* p, size_t n) {
        if (tracker) tracker->sub(int64_t(n * sizeof(T)));
        std::allocator<T>().deallocate(p, n);
    }
    template <class U> bool operator==(const TrackedAllocator<U>& o) const {
        return tracker == o.tracker;
    }
};

template <class T> using TrackedVector = std::vector<T, TrackedAllocator<T>>;

template <class T> TrackedVector<T> tracked_vector(MemoryTracker& m, size_t n = 0) {
    TrackedVector<T> v{TrackedAllocator<T>(&m)};
    v.resize(n);
    return v;
}

} // namespace sheaf

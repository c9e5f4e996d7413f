// Portable atomics for per-element code that both backends run: std::atomic_ref on the host,
// CUDA's atomics on the device. Relaxed ordering everywhere: results (minimum hits, flags,
// sums) do not depend on the order of the updates, only on the set of them.
#pragma once

#include "core/base/device.h"

#include <cstdint>
#if !SHEAF_DEVICE_PASS
#include <atomic>
#endif

namespace sheaf {

/// *p = min(*p, v).
SHEAF_HD_INLINE void atomic_min_u64(uint64_t* p, uint64_t v) {
#if SHEAF_DEVICE_PASS
    atomicMin(reinterpret_cast<unsigned long long*>(p), static_cast<unsigned long long>(v));
#else
    std::atomic_ref<uint64_t> slot(*p);
    uint64_t cur = slot.load(std::memory_order_relaxed);
    while (v < cur && !slot.compare_exchange_weak(cur, v, std::memory_order_relaxed)) {
    }
#endif
}

/// *p += v.
SHEAF_HD_INLINE void atomic_add_u64(uint64_t* p, uint64_t v) {
#if SHEAF_DEVICE_PASS
    atomicAdd(reinterpret_cast<unsigned long long*>(p), static_cast<unsigned long long>(v));
#else
    std::atomic_ref<uint64_t>(*p).fetch_add(v, std::memory_order_relaxed);
#endif
}

/// *p += v.
SHEAF_HD_INLINE void atomic_add_u32(uint32_t* p, uint32_t v) {
#if SHEAF_DEVICE_PASS
    atomicAdd(reinterpret_cast<unsigned int*>(p), static_cast<unsigned int>(v));
#else
    std::atomic_ref<uint32_t>(*p).fetch_add(v, std::memory_order_relaxed);
#endif
}

/// *p = 1, from any number of threads at once (every writer stores the same value).
SHEAF_HD_INLINE void store_flag(uint8_t* p) {
#if SHEAF_DEVICE_PASS
    *reinterpret_cast<volatile uint8_t*>(p) = 1;
#else
    std::atomic_ref<uint8_t>(*p).store(1, std::memory_order_relaxed);
#endif
}

} // namespace sheaf

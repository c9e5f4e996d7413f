#include "core/base/memory.h"

#include "core/base/error.h"
#include "core/base/parallel.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace sheaf {
namespace {

/// A number from a one-line file such as /sys/fs/cgroup/memory.max; -1 when absent or "max".
int64_t read_number(const char* path) {
    std::ifstream in(path);
    std::string word;
    if (!(in >> word) || word.empty() || word.find_first_not_of("0123456789") != std::string::npos)
        return -1;
    return std::stoll(word);
}

std::string mib(int64_t bytes) {
    return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB";
}

} // namespace

int64_t available_memory_bytes() {
    int64_t available = -1;
    std::ifstream meminfo("/proc/meminfo");
    std::string key, unit;
    int64_t value = 0;
    while (meminfo >> key >> value) {
        std::getline(meminfo, unit);
        if (key == "MemAvailable:") {
            available = value * 1024;
            break;
        }
    }
    // A control group (a container, a systemd slice) may allow less than the machine has.
    const int64_t max = read_number("/sys/fs/cgroup/memory.max");
    const int64_t current = read_number("/sys/fs/cgroup/memory.current");
    if (max > 0 && current >= 0) {
        const int64_t left = std::max<int64_t>(0, max - current);
        available = available < 0 ? left : std::min(available, left);
    }
    return std::max<int64_t>(available, 0);
}

void MemoryTracker::refuse(int64_t bytes, int64_t total) const {
    throw OutOfMemory("the frame needs more memory than this machine has available: its buffers "
                      "would reach " + mib(total) + " with the next " + mib(bytes) + " (" +
                      mib(available_) + " were available when it started); a smaller size, "
                      "fewer aa.samples or ao.samples, or a smaller traversal.batch need less");
}

void prefault_host_pages(void* p, size_t bytes) {
    constexpr uintptr_t kHuge = uintptr_t(2) << 20;
    if (!p || bytes < (size_t(1) << 20)) return;
#ifdef __linux__
    const uintptr_t begin = reinterpret_cast<uintptr_t>(p);
    const uintptr_t a = (begin + kHuge - 1) & ~(kHuge - 1), e = (begin + bytes) & ~(kHuge - 1);
    if (e > a) madvise(reinterpret_cast<void*>(a), e - a, MADV_HUGEPAGE); // a hint
#endif
    // Pieces of 256 KiB, one byte written per 4 KiB page: the faults are taken on every core,
    // and the caller's fill is then the one pass over the bytes.
    constexpr size_t kPiece = size_t(256) << 10, kPage = size_t(4) << 10;
    const size_t pieces = (bytes + kPiece - 1) / kPiece;
    char* const base = static_cast<char*>(p);
    parallel_for(
        "prefault", pieces,
        [&](size_t i) {
            const size_t end = std::min(bytes, (i + 1) * kPiece);
            for (size_t at = i * kPiece; at < end; at += kPage) base[at] = 0;
        },
        1);
}

void parallel_copy(void* dst, const void* src, size_t bytes) {
    constexpr size_t kPiece = size_t(256) << 10;
    if (bytes < (size_t(1) << 20)) {
        if (bytes) std::memcpy(dst, src, bytes);
        return;
    }
    char* const d = static_cast<char*>(dst);
    const char* const s = static_cast<const char*>(src);
    parallel_for(
        "copy", (bytes + kPiece - 1) / kPiece,
        [&](size_t i) {
            const size_t at = i * kPiece;
            std::memcpy(d + at, s + at, std::min(kPiece, bytes - at));
        },
        1);
}

} // namespace sheaf

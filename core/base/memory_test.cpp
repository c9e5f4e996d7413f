// The frame's memory accounting, and its limit: a buffer past the limit is refused before it
// is allocated.
#include "core/base/memory.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace sheaf {
namespace {

TEST(MemoryTracker, CountsAndPeaks) {
    MemoryTracker m;
    {
        auto a = tracked_vector<uint32_t>(m, 100);
        auto b = tracked_vector<uint8_t>(m, 50);
        EXPECT_EQ(m.current(), 450);
    }
    EXPECT_EQ(m.current(), 0);
    EXPECT_EQ(m.peak(), 450);
}

TEST(MemoryTracker, ALimitRefusesBeforeAllocating) {
    MemoryTracker m;
    m.set_limit(1000, 5000);
    auto kept = tracked_vector<uint8_t>(m, 600);
    try {
        auto refused = tracked_vector<uint8_t>(m, 600);
        FAIL() << "600 + 600 bytes passed a limit of 1000";
    } catch (const OutOfMemory& e) {
        EXPECT_NE(std::string(e.what()).find("1 MiB were available"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(m.current(), 600); // what was refused is not counted
    EXPECT_EQ(m.peak(), 600);
    auto fits = tracked_vector<uint8_t>(m, 400);
    EXPECT_EQ(m.current(), 1000);
}

TEST(MemoryTracker, TheAvailableMemoryIsKnownOnLinux) {
    EXPECT_GT(available_memory_bytes(), 0);
}

TEST(ParallelCopy, CopiesEveryByteOfLargeAndSmallRanges) {
    // 5 MiB + 3 bytes: pieces of 256 KiB and a short last one; then sizes below the 1 MiB
    // threshold, and nothing.
    for (size_t n : {(size_t(5) << 20) + 3, size_t(1) << 20, size_t(4097), size_t(1), size_t(0)}) {
        std::vector<uint8_t> src(n), dst(n + 8, 0xAB);
        for (size_t i = 0; i < n; ++i) src[i] = uint8_t(i * 131 + (i >> 12));
        parallel_copy(dst.data() + 4, src.data(), n);
        EXPECT_TRUE(std::equal(src.begin(), src.end(), dst.begin() + 4)) << n << " bytes";
        for (size_t i : {size_t(0), size_t(3), n + 4, n + 7})
            EXPECT_EQ(dst[i], 0xAB) << "byte " << i << " outside the range, " << n << " bytes";
    }
}

} // namespace
} // namespace sheaf

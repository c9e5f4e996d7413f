#include "core/base/content_hash.h"

#include <gtest/gtest.h>

#include <numeric>

namespace sheaf {
namespace {

Digest of(const std::vector<std::vector<uint8_t>>& arrays) {
    ContentHasher h;
    for (const auto& a : arrays) h.add(a);
    return h.digest();
}

TEST(ContentHash, SameArraysSameDigest) {
    std::vector<uint8_t> big(3 << 20);
    std::iota(big.begin(), big.end(), uint8_t(7));
    EXPECT_EQ(of({{1, 2, 3}, big}), of({{1, 2, 3}, big}));
    EXPECT_NE(of({{1, 2, 3}, big}), Digest{});
}

TEST(ContentHash, OneBitAnywhereChangesIt) {
    std::vector<uint8_t> big(1 << 20, 0x5a);
    const Digest before = of({big});
    for (size_t at : {size_t(0), size_t(4095), big.size() - 1}) {
        std::vector<uint8_t> changed = big;
        changed[at] ^= 1;
        EXPECT_NE(of({changed}), before) << "byte " << at;
    }
}

TEST(ContentHash, LargeArraysHashedInPiecesStillSeeEveryByte) {
    // Past 16 MiB an array is hashed in 4 MiB pieces on every core.
    std::vector<uint8_t> big((40 << 20) + 123);
    for (size_t i = 0; i < big.size(); ++i) big[i] = uint8_t(i * 2654435761u >> 24);
    const Digest before = of({big});
    EXPECT_EQ(of({big}), before);
    for (size_t at : {size_t(0), size_t(4 << 20) - 1, size_t(4 << 20), big.size() - 1}) {
        std::vector<uint8_t> changed = big;
        changed[at] ^= 0x80;
        EXPECT_NE(of({changed}), before) << "byte " << at;
    }
    big.pop_back();
    EXPECT_NE(of({big}), before) << "one byte shorter";
}

TEST(ContentHash, BoundariesAndEmptyArraysCount) {
    EXPECT_NE(of({{1, 2}, {3}}), of({{1}, {2, 3}}));
    EXPECT_NE(of({{1, 2, 3}}), of({{1, 2, 3}, {}}));
    EXPECT_NE(of({{}, {1}}), of({{1}, {}}));
    ContentHasher a, b;
    a.add_value(1), b.add_value(2);
    EXPECT_NE(a.digest(), b.digest());
}

} // namespace
} // namespace sheaf

// Radix sort and ray ordering (order.h, under the CPU policy): permutations, stability, and
// full == csd, radix == bitonic.
#include "core/frame/order.h"

#include "core/frame/cpu_exec.h"
#include "tests/support/bitonic_sort.h"
#include "core/sort/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace sheaf {
namespace {

struct OrderResult {
    std::vector<uint32_t> perm;
    size_t chunks = 0;
};

/// order_rays on the CPU policy, its phase times added to `stats`.
OrderResult order_rays(const std::vector<uint32_t>& keys, int words, size_t n, SortMode mode,
                       Stats& stats, SortAlgorithm algorithm = SortAlgorithm::Radix) {
    wavefront::CpuExec ex;
    wavefront::DeviceBuffer<uint32_t, wavefront::CpuExec> k(ex, keys.size());
    k.upload(keys.data(), keys.size());
    wavefront::PhaseClock<wavefront::CpuExec> clock(ex);
    const auto order = wavefront::order_rays(ex, k.data(), words, n, mode, clock, algorithm);
    clock.add_to(stats);
    return {order.perm.download(), order.chunks};
}

bool is_permutation_of_n(const std::vector<uint32_t>& p) {
    std::vector<char> seen(p.size(), 0);
    for (uint32_t v : p) {
        if (v >= p.size() || seen[v]) return false;
        seen[v] = 1;
    }
    return true;
}

// Keys with long runs of equal adjacent values, as coherent rays produce.
std::vector<uint32_t> runny_keys(size_t n, int words, uint32_t seed) {
    std::mt19937 g(seed);
    std::vector<uint32_t> k(n * words);
    for (size_t i = 0; i < n;) {
        const size_t run = 1 + g() % 9;
        std::vector<uint32_t> key(words);
        for (auto& w : key) w = g() % 4 == 0 ? 0 : g();
        for (size_t r = 0; r < run && i < n; ++r, ++i)
            for (int w = 0; w < words; ++w) k[i * words + w] = key[w];
    }
    return k;
}

bool key_less(const std::vector<uint32_t>& k, int words, uint32_t a, uint32_t b) {
    for (int w = words - 1; w >= 0; --w)
        if (k[a * words + w] != k[b * words + w]) return k[a * words + w] < k[b * words + w];
    return false;
}

class Sorting : public ::testing::TestWithParam<int> {};

TEST_P(Sorting, RadixSortMatchesStableSort) {
    const int words = GetParam();
    for (size_t n : {size_t(0), size_t(1), size_t(7), size_t(1000), size_t(100000)}) {
        std::vector<uint32_t> keys = runny_keys(n, words, 42 + uint32_t(n));
        std::vector<uint32_t> ref(n);
        std::iota(ref.begin(), ref.end(), 0u);
        std::stable_sort(ref.begin(), ref.end(),
                         [&](uint32_t a, uint32_t b) { return key_less(keys, words, a, b); });
        std::vector<uint32_t> k = keys, v(n);
        std::iota(v.begin(), v.end(), 0u);
        radix_sort_pairs(k, words, v);
        EXPECT_EQ(v, ref) << "n=" << n;
        for (size_t i = 0; i < n; ++i)
            for (int w = 0; w < words; ++w) ASSERT_EQ(k[i * words + w], keys[v[i] * words + w]);
    }
}

TEST_P(Sorting, FullAndCsdGiveTheSameSortedPermutation) {
    const int words = GetParam();
    const size_t n = 50000;
    const std::vector<uint32_t> keys = runny_keys(n, words, 7);
    Stats st;
    const OrderResult none = order_rays(keys, words, n, SortMode::None, st);
    const OrderResult full = order_rays(keys, words, n, SortMode::Full, st);
    const OrderResult csd = order_rays(keys, words, n, SortMode::Csd, st);
    ASSERT_TRUE(is_permutation_of_n(none.perm));
    ASSERT_TRUE(is_permutation_of_n(full.perm));
    ASSERT_TRUE(is_permutation_of_n(csd.perm));
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(none.perm[i], i);
    EXPECT_EQ(full.perm, csd.perm);
    for (size_t i = 1; i < n; ++i)
        ASSERT_FALSE(key_less(keys, words, csd.perm[i], csd.perm[i - 1]));
    // Compression found the runs: fewer chunks than rays, at least one per distinct run start.
    EXPECT_LT(csd.chunks, n);
    EXPECT_GT(csd.chunks, n / 10);
    EXPECT_TRUE(st.has("time_ms.compression"));
    EXPECT_TRUE(st.has("time_ms.decompression"));
}

TEST_P(Sorting, BitonicSortGivesTheStablePermutation) {
    const int words = GetParam();
    for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(7), size_t(1000), size_t(33333)}) {
        const std::vector<uint32_t> keys = runny_keys(n, words, 11 + uint32_t(n));
        std::vector<uint32_t> rk = keys, rv(n), bk = keys, bv(n);
        std::iota(rv.begin(), rv.end(), 0u);
        std::iota(bv.begin(), bv.end(), 0u);
        radix_sort_pairs(rk, words, rv);
        bitonic_sort_pairs(bk, words, bv);
        EXPECT_EQ(bv, rv) << "n=" << n;
        EXPECT_EQ(bk, rk) << "n=" << n;
    }
    // Through order_rays: both algorithms, full and csd, the same permutation.
    const size_t n = 20000;
    const std::vector<uint32_t> keys = runny_keys(n, words, 3);
    Stats st;
    const OrderResult radix = order_rays(keys, words, n, SortMode::Csd, st, SortAlgorithm::Radix);
    EXPECT_EQ(order_rays(keys, words, n, SortMode::Csd, st, SortAlgorithm::Bitonic).perm,
              radix.perm);
    EXPECT_EQ(order_rays(keys, words, n, SortMode::Full, st, SortAlgorithm::Bitonic).perm,
              radix.perm);
}

INSTANTIATE_TEST_SUITE_P(KeyWords, Sorting, ::testing::Values(1, 6));

TEST(Sorting, ConstantKeysKeepTheirOrder) {
    std::vector<uint32_t> keys(1000, 5u), v(1000);
    std::iota(v.begin(), v.end(), 0u);
    radix_sort_pairs(keys, 1, v);
    for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], i);
}

} // namespace
} // namespace sheaf

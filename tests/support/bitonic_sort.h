// The host reference of the bitonic sort the tracer runs as launches (core/frame/steps.h;
// paper 003 compares bitonic and radix sorting): pairs with multi-word keys, O(n log^2 n)
// compare-exchanges in log^2 n parallel stages over a power-of-two padding of the input. Ties
// are broken by the value (the ray's index), so the result is the permutation the stable
// radix sort gives.
#pragma once

#include "core/base/parallel.h"

#include <cstdint>
#include <vector>

namespace sheaf {

/// Sorts `values` (n entries, distinct) by `keys` (n * words entries, element i's key at
/// keys[i * words ...], word 0 least significant), then by value. Both arrays are permuted.
inline void bitonic_sort_pairs(std::vector<uint32_t>& keys, int words,
                               std::vector<uint32_t>& values) {
    const size_t n = values.size();
    if (n < 2) return;
    size_t m = 1;
    while (m < n) m <<= 1;
    // Sort positions into the input; padding entries (index >= n) compare greater than all.
    std::vector<uint32_t> order(m);
    for (size_t i = 0; i < m; ++i) order[i] = uint32_t(i);
    auto less = [&](uint32_t a, uint32_t b) {
        if (a >= n || b >= n) return a < b && a < n; // padding last
        for (int w = words - 1; w >= 0; --w) {
            const uint32_t ka = keys[size_t(a) * words + w], kb = keys[size_t(b) * words + w];
            if (ka != kb) return ka < kb;
        }
        return values[a] < values[b];
    };
    for (size_t k = 2; k <= m; k <<= 1)
        for (size_t j = k >> 1; j > 0; j >>= 1)
            parallel_for(
                "sort.bitonic", m / 2,
                [&](size_t t) {
                    // The t-th compare-exchange of this stage: i and its partner i ^ j.
                    const size_t i = ((t / j) * 2 * j) + (t % j), p = i + j;
                    const bool up = (i & k) == 0;
                    if (less(order[p], order[i]) == up) std::swap(order[i], order[p]);
                },
                4096);
    std::vector<uint32_t> k2(keys.size()), v2(n);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t src = order[i];
        v2[i] = values[src];
        for (int w = 0; w < words; ++w) k2[i * words + w] = keys[size_t(src) * words + w];
    }
    keys.swap(k2);
    values.swap(v2);
}

} // namespace sheaf

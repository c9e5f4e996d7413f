// A parallel, stable LSD radix sort of (key, value) pairs with multi-word keys, and the
// scans it is built on. The CUDA module puts CUB's DeviceRadixSort and DeviceScan behind the
// same signatures.
#pragma once

#include "core/base/parallel.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sheaf {

/// out[i] = sum of in[0..i); returns the total. in and out may be the same vector.
template <class T> T exclusive_scan_inplace(std::vector<T>& v) {
    T sum = 0;
    for (T& x : v) {
        const T t = x;
        x = sum;
        sum += t;
    }
    return sum;
}

/// Sorts `values` (n entries) by `keys` (n * words entries; element i's key is
/// keys[i * words ... i * words + words), word 0 least significant), stably, on all bits.
/// Both arrays are permuted. Passes whose 8-bit digit is the same for every key are skipped.
inline void radix_sort_pairs(uint32_t* keys_in, int words, uint32_t* values_in, size_t n) {
    if (n < 2) return;
    const size_t blocks = std::min<size_t>(64, n / 8192 + 1);
    const size_t per = (n + blocks - 1) / blocks;
    std::vector<uint32_t> keys_tmp(n * size_t(words)), values_tmp(n);
    uint32_t *keys = keys_in, *values = values_in;
    uint32_t *keys2 = keys_tmp.data(), *values2 = values_tmp.data();
    std::vector<size_t> hist(blocks * 256);

    for (int pass = 0; pass < 4 * words; ++pass) {
        const int w = pass / 4, shift = (pass % 4) * 8;
        auto digit = [&](size_t i) { return (keys[i * words + w] >> shift) & 0xFFu; };
        std::fill(hist.begin(), hist.end(), 0);
        parallel_for(
            "sort.histogram", blocks,
            [&](size_t b) {
                size_t* h = &hist[b * 256];
                for (size_t i = b * per, e = std::min(n, (b + 1) * per); i < e; ++i) ++h[digit(i)];
            },
            1);
        // A digit every key shares leaves the order as it is.
        bool constant = false;
        for (int d = 0; d < 256 && !constant; ++d) {
            size_t c = 0;
            for (size_t b = 0; b < blocks; ++b) c += hist[b * 256 + d];
            constant = c == n;
        }
        if (constant) continue;
        // Offsets in digit-major, block-minor order keep the sort stable.
        size_t sum = 0;
        for (int d = 0; d < 256; ++d)
            for (size_t b = 0; b < blocks; ++b) {
                const size_t c = hist[b * 256 + d];
                hist[b * 256 + d] = sum;
                sum += c;
            }
        parallel_for(
            "sort.scatter", blocks,
            [&](size_t b) {
                size_t* h = &hist[b * 256];
                for (size_t i = b * per, e = std::min(n, (b + 1) * per); i < e; ++i) {
                    const size_t dst = h[digit(i)]++;
                    for (int k = 0; k < words; ++k) keys2[dst * words + k] = keys[i * words + k];
                    values2[dst] = values[i];
                }
            },
            1);
        std::swap(keys, keys2);
        std::swap(values, values2);
    }
    if (keys != keys_in) { // an odd number of passes ran: the result is in the scratch arrays
        std::copy(keys, keys + n * size_t(words), keys_in);
        std::copy(values, values + n, values_in);
    }
}

inline void radix_sort_pairs(std::vector<uint32_t>& keys, int words,
                             std::vector<uint32_t>& values) {
    radix_sort_pairs(keys.data(), words, values.data(), values.size());
}

} // namespace sheaf

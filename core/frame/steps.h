// Data-parallel building blocks of the wavefront pipeline, written once against the exec seam
// (launch, exclusive_scan[_async], transform_reduce, reduce_into, sort_pairs): filling,
// counting and scanning, accumulation into samples in a fixed order, the stable bitonic
// sort of paper 003, and multi-word keys sorted by a 64-bit radix sort (the CUDA policy's).
#pragma once

#include "core/base/device.h"
#include "core/frame/buffer.h"
#include "core/math/vec3.h"

#include <cstddef>
#include <cstdint>

namespace sheaf::wavefront {

template <class Exec, class T> void fill(Exec& ex, T* p, size_t n, T value) {
    ex.launch("fill", n, [=] SHEAF_HD_LAMBDA(size_t i) { p[i] = value; });
}

template <class Exec> void iota(Exec& ex, uint32_t* p, size_t n) {
    ex.launch("iota", n, [=] SHEAF_HD_LAMBDA(size_t i) { p[i] = uint32_t(i); });
}

/// offsets[i] = count(i), then scanned in place; returns the total. Count, scan, fill: the
/// order of what a fill writes is the order of i, whatever the thread schedule.
template <class Exec, class Count>
uint32_t count_and_scan(Exec& ex, const char* name, size_t n, uint32_t* offsets, Count count) {
    ex.launch(name, n, [=] SHEAF_HD_LAMBDA(size_t i) { offsets[i] = count(i); });
    return ex.exclusive_scan(offsets, n);
}

/// Adds items [0, n) to samples: item i goes to sample `sample(i)` when `value(i, v)` gives
/// it a contribution v. Per sample, items add in item order, so the sums are bitwise the same
/// on every policy: on a device, a stable sort of the items by sample, one thread per sample
/// adding its run in order, the number of runs staying on the executing side (threads past it
/// return) so the host does not wait; on host memory, one thread adding them all in order.
template <class Exec, class Sample, class Value>
void accumulate_in_order(Exec& ex, size_t n, Vec3* radiance, Sample sample, Value value) {
    if (n == 0) return;
    if constexpr (Exec::kHostMemory) {
        // On host memory, the contributions in parallel, then added on one thread in item
        // order: the same sums, without sorting the items.
        constexpr uint32_t kNone = ~0u;
        DeviceBuffer<Vec3, Exec> values(ex, n);
        DeviceBuffer<uint32_t, Exec> to(ex, n);
        Vec3* v = values.data();
        uint32_t* t = to.data();
        ex.launch("accumulate.values", n,
                  [=](size_t i) { t[i] = value(i, v[i]) ? uint32_t(sample(i)) : kNone; });
        for (size_t i = 0; i < n; ++i)
            if (t[i] != kNone) radiance[t[i]] += v[i];
        return;
    }
    DeviceBuffer<uint32_t, Exec> keys(ex, n), items(ex, n), heads(ex, n), starts(ex, n + 2);
    uint32_t* k = keys.data();
    uint32_t* it = items.data();
    uint32_t* h = heads.data();
    uint32_t* st = starts.data();  // st[r]: the first item of run r, then n
    uint32_t* runs = st + (n + 1); // the number of runs
    ex.launch("accumulate.keys", n, [=] SHEAF_HD_LAMBDA(size_t i) {
        k[i] = sample(i);
        it[i] = uint32_t(i);
    });
    ex.sort_pairs(k, 1, it, n);
    ex.launch("accumulate.heads", n,
              [=] SHEAF_HD_LAMBDA(size_t j) { h[j] = j == 0 || k[j] != k[j - 1] ? 1u : 0u; });
    ex.exclusive_scan_async(h, n);
    ex.launch("accumulate.starts", n, [=] SHEAF_HD_LAMBDA(size_t j) {
        const bool head = j == 0 || k[j] != k[j - 1];
        if (head) st[h[j]] = uint32_t(j);
        if (j + 1 == n) {
            const uint32_t count = h[j] + (head ? 1u : 0u);
            st[count] = uint32_t(n);
            *runs = count;
        }
    });
    ex.launch("accumulate.add", n, [=] SHEAF_HD_LAMBDA(size_t r) {
        if (r >= *runs) return;
        const uint32_t b = st[r], e = st[r + 1];
        Vec3 acc = radiance[k[b]];
        for (uint32_t j = b; j < e; ++j) {
            Vec3 v;
            if (value(size_t(it[j]), v)) acc += v;
        }
        radiance[k[b]] = acc;
    });
}

/// Lexicographic order of multi-word keys (word 0 least significant), ties by value; entries
/// at n and beyond (the power-of-two padding) after everything.
struct BitonicLess {
    const uint32_t* keys;
    int words;
    const uint32_t* values;
    size_t n;
    SHEAF_HD bool operator()(uint32_t a, uint32_t b) const {
        if (a >= n || b >= n) return a < b && a < n; // padding last
        for (int w = words - 1; w >= 0; --w) {
            const uint32_t ka = keys[size_t(a) * words + w], kb = keys[size_t(b) * words + w];
            if (ka != kb) return ka < kb;
        }
        return values[a] < values[b];
    }
};

/// The bitonic network of tests/support/bitonic_sort.h as launches: log^2 n stages of n / 2
/// compare-exchanges; ties broken by value, so the permutation is the stable radix sort's.
template <class Exec>
void bitonic_sort_pairs(Exec& ex, uint32_t* keys, int words, uint32_t* values, size_t n) {
    if (n < 2) return;
    size_t m = 1;
    while (m < n) m <<= 1;
    DeviceBuffer<uint32_t, Exec> order_buf(ex, m);
    uint32_t* order = order_buf.data();
    iota(ex, order, m);
    const BitonicLess less{keys, words, values, n};
    for (size_t k = 2; k <= m; k <<= 1)
        for (size_t j = k >> 1; j > 0; j >>= 1)
            ex.launch("sort.bitonic", m / 2, [=] SHEAF_HD_LAMBDA(size_t t) {
                // The t-th compare-exchange of this stage: i and its partner i ^ j.
                const size_t i = ((t / j) * 2 * j) + (t % j), p = i + j;
                const bool up = (i & k) == 0;
                if (less(order[p], order[i]) == up) {
                    const uint32_t tmp = order[i];
                    order[i] = order[p];
                    order[p] = tmp;
                }
            });
    DeviceBuffer<uint32_t, Exec> k2(ex, n * size_t(words)), v2(ex, n);
    uint32_t* kk = k2.data();
    uint32_t* vv = v2.data();
    ex.launch("sort.bitonic_gather", n, [=] SHEAF_HD_LAMBDA(size_t i) {
        const uint32_t src = order[i];
        vv[i] = values[src];
        for (int w = 0; w < words; ++w) kk[i * words + w] = keys[size_t(src) * words + w];
    });
    ex.copy_on_device(keys, kk, n * size_t(words) * sizeof(uint32_t));
    ex.copy_on_device(values, vv, n * sizeof(uint32_t));
}

/// Sorts values by keys of `words` words (word 0 least significant) stably, given a stable
/// sort of 64-bit keys with 32-bit values: positions sorted by each pair of words as one
/// 64-bit key, least significant pair first (each pass stable, so the result is the
/// lexicographic order with ties by position), then keys and values gathered.
/// sort64(k, k_alt, v, v_alt, n, bits) sorts (k, v) on the low `bits` bits of k, using the
/// alternate buffers as scratch, and returns whether the result is in the alternates (as CUB's
/// DoubleBuffer leaves it).
template <class Exec, class Sort64>
void sort_pairs_by_word_pairs(Exec& ex, uint32_t* keys, int words, uint32_t* values, size_t n,
                              const Sort64& sort64) {
    if (n < 2) return;
    DeviceBuffer<uint32_t, Exec> pos_a(ex, n), pos_b(ex, n);
    DeviceBuffer<uint64_t, Exec> k_a(ex, n), k_b(ex, n);
    uint32_t* pos = pos_a.data();
    uint32_t* pos_other = pos_b.data();
    iota(ex, pos, n);
    for (int w = 0; w < words; w += 2) {
        const bool pair = w + 1 < words;
        uint64_t* k = k_a.data();
        const uint32_t* cur = pos;
        ex.launch("sort.pack", n, [=] SHEAF_HD_LAMBDA(size_t j) {
            const uint32_t* key = keys + size_t(cur[j]) * words;
            k[j] = (pair ? uint64_t(key[w + 1]) << 32 : 0) | key[w];
        });
        if (sort64(k_a.data(), k_b.data(), pos, pos_other, n, pair ? 64 : 32)) {
            uint32_t* t = pos;
            pos = pos_other;
            pos_other = t;
        }
    }
    DeviceBuffer<uint32_t, Exec> k_out(ex, n * size_t(words)), v_out(ex, n);
    uint32_t* ko = k_out.data();
    uint32_t* vo = v_out.data();
    const uint32_t* order = pos;
    ex.launch("sort.gather", n, [=] SHEAF_HD_LAMBDA(size_t j) {
        const size_t src = order[j];
        vo[j] = values[src];
        for (int w = 0; w < words; ++w) ko[j * words + w] = keys[src * words + w];
    });
    ex.copy_on_device(keys, ko, n * size_t(words) * sizeof(uint32_t));
    ex.copy_on_device(values, vo, n * sizeof(uint32_t));
}

} // namespace sheaf::wavefront

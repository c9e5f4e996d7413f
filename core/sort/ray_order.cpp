#include "core/sort/ray_order.h"

#include "core/base/parallel.h"
#include "core/base/timer.h"
#include "core/sort/bitonic_sort.h"
#include "core/sort/radix_sort.h"

#include <numeric>

namespace sheaf {

namespace {

void sort_pairs(std::vector<uint32_t>& keys, int words, std::vector<uint32_t>& values,
                SortAlgorithm algorithm) {
    if (algorithm == SortAlgorithm::Bitonic)
        bitonic_sort_pairs(keys, words, values);
    else
        radix_sort_pairs(keys, words, values);
}

} // namespace

OrderResult order_rays(const std::vector<uint32_t>& keys, int words, size_t n, SortMode mode,
                       Stats& stats, SortAlgorithm algorithm) {
    OrderResult r;
    if (mode == SortMode::None || n == 0) {
        r.perm.resize(n);
        std::iota(r.perm.begin(), r.perm.end(), 0u);
        return r;
    }
    if (mode == SortMode::Full) {
        PhaseTimer t(stats, "time_ms.sorting");
        std::vector<uint32_t> k = keys;
        r.perm.resize(n);
        std::iota(r.perm.begin(), r.perm.end(), 0u);
        sort_pairs(k, words, r.perm, algorithm);
        r.chunks = n;
        return r;
    }

    // Compression: a head flag where the key differs from its predecessor, a scan of the
    // flags, then one chunk (key, base, size) per run.
    std::vector<uint32_t> chunk_keys, chunk_ids, chunk_base, chunk_size;
    {
        PhaseTimer t(stats, "time_ms.compression");
        std::vector<uint32_t> head(n);
        parallel_for(
            "csd.flags", n,
            [&](size_t i) {
                bool differs = i == 0;
                for (int w = 0; w < words && !differs; ++w)
                    differs = keys[i * words + w] != keys[(i - 1) * words + w];
                head[i] = differs ? 1u : 0u;
            },
            4096);
        const uint32_t chunks = exclusive_scan_inplace(head); // head[i]: chunks before i
        r.chunks = chunks;
        chunk_keys.resize(size_t(chunks) * words);
        chunk_base.resize(chunks);
        chunk_size.resize(chunks);
        parallel_for(
            "csd.chunks", n,
            [&](size_t i) {
                // The flag of ray i is the step of the exclusive scan at i: 1 where a chunk starts.
                const uint32_t next = i + 1 < n ? head[i + 1] : chunks;
                if (next != head[i]) {
                    const uint32_t c = head[i];
                    chunk_base[c] = uint32_t(i);
                    for (int w = 0; w < words; ++w)
                        chunk_keys[size_t(c) * words + w] = keys[i * words + w];
                }
            },
            4096);
        parallel_for(
            "csd.sizes", chunks,
            [&](size_t c) {
                const uint32_t end = c + 1 < chunks ? chunk_base[c + 1] : uint32_t(n);
                chunk_size[c] = end - chunk_base[c];
            },
            4096);
        chunk_ids.resize(chunks);
        std::iota(chunk_ids.begin(), chunk_ids.end(), 0u);
    }
    {
        PhaseTimer t(stats, "time_ms.sorting");
        sort_pairs(chunk_keys, words, chunk_ids, algorithm);
    }
    {
        // Decompression: the sizes in sorted order, scanned, give each chunk's place.
        PhaseTimer t(stats, "time_ms.decompression");
        std::vector<uint32_t> offset(chunk_ids.size());
        for (size_t j = 0; j < chunk_ids.size(); ++j) offset[j] = chunk_size[chunk_ids[j]];
        exclusive_scan_inplace(offset);
        r.perm.resize(n);
        parallel_for(
            "csd.expand", chunk_ids.size(),
            [&](size_t j) {
                const uint32_t c = chunk_ids[j], base = chunk_base[c], size = chunk_size[c];
                for (uint32_t k = 0; k < size; ++k) r.perm[offset[j] + k] = base + k;
            },
            1024);
    }
    return r;
}

} // namespace sheaf

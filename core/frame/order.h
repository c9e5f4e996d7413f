// The order rays enter the hierarchy in (sort.mode), on the executing side: unsorted, every
// ray sorted by its key, or compress-sort-decompress (paper 000 sections 3.3.3-3.3.5) as
// flags, scans, a sort of the chunks and an expansion. Sorts are stable (ties by ray index),
// so full and csd, radix and bitonic, give the same permutation.
#pragma once

#include "core/frame/phases.h"
#include "core/frame/steps.h"
#include "core/settings/settings.h"

namespace sheaf::wavefront {

template <class Exec> struct DeviceOrder {
    DeviceBuffer<uint32_t, Exec> perm; // perm[j]: the ray at sorted position j
    size_t chunks = 0;                 // csd: runs of equal adjacent keys; full: n; none: 0
};

template <class Exec>
void sort_pairs(Exec& ex, uint32_t* keys, int words, uint32_t* values, size_t n,
                SortAlgorithm algorithm) {
    if (algorithm == SortAlgorithm::Bitonic)
        bitonic_sort_pairs(ex, keys, words, values, n);
    else
        ex.sort_pairs(keys, words, values, n);
}

/// keys: n * words words (word 0 least significant). Times the phases compression, sorting
/// and decompression.
template <class Exec>
DeviceOrder<Exec> order_rays(Exec& ex, const uint32_t* keys, int words, size_t n, SortMode mode,
                             PhaseClock<Exec>& clock, SortAlgorithm algorithm) {
    DeviceOrder<Exec> r;
    r.perm = DeviceBuffer<uint32_t, Exec>(ex, n);
    uint32_t* perm = r.perm.data();
    if (mode == SortMode::None || n == 0) {
        iota(ex, perm, n);
        return r;
    }
    if (mode == SortMode::Full) {
        clock.start("sorting");
        DeviceBuffer<uint32_t, Exec> k(ex, n * size_t(words));
        ex.copy_on_device(k.data(), keys, n * size_t(words) * sizeof(uint32_t));
        iota(ex, perm, n);
        sort_pairs(ex, k.data(), words, perm, n, algorithm);
        r.chunks = n;
        clock.stop("sorting");
        return r;
    }

    // Compression: a head flag where the key differs from its predecessor, a scan of the
    // flags, then one chunk (key, base, size) per run.
    clock.start("compression");
    DeviceBuffer<uint32_t, Exec> head_buf(ex, n);
    uint32_t* head = head_buf.data();
    ex.launch("csd.flags", n, [=] SHEAF_HD_LAMBDA(size_t i) {
        bool differs = i == 0;
        for (int w = 0; w < words && !differs; ++w)
            differs = keys[i * words + w] != keys[(i - 1) * words + w];
        head[i] = differs ? 1u : 0u;
    });
    const uint32_t chunks = ex.exclusive_scan(head, n); // head[i]: chunks before i
    r.chunks = chunks;
    DeviceBuffer<uint32_t, Exec> keys_buf(ex, size_t(chunks) * words), base_buf(ex, chunks),
        size_buf(ex, chunks), ids_buf(ex, chunks);
    uint32_t* chunk_keys = keys_buf.data();
    uint32_t* chunk_base = base_buf.data();
    uint32_t* chunk_size = size_buf.data();
    uint32_t* chunk_ids = ids_buf.data();
    ex.launch("csd.chunks", n, [=] SHEAF_HD_LAMBDA(size_t i) {
        // The flag of ray i is the step of the exclusive scan at i: 1 where a chunk starts.
        const uint32_t next = i + 1 < n ? head[i + 1] : chunks;
        if (next != head[i]) {
            const uint32_t c = head[i];
            chunk_base[c] = uint32_t(i);
            for (int w = 0; w < words; ++w) chunk_keys[size_t(c) * words + w] = keys[i * words + w];
        }
    });
    ex.launch("csd.sizes", chunks, [=] SHEAF_HD_LAMBDA(size_t c) {
        const uint32_t end = c + 1 < chunks ? chunk_base[c + 1] : uint32_t(n);
        chunk_size[c] = end - chunk_base[c];
    });
    iota(ex, chunk_ids, chunks);
    clock.stop("compression");

    clock.start("sorting");
    sort_pairs(ex, chunk_keys, words, chunk_ids, chunks, algorithm);
    clock.stop("sorting");

    // Decompression: the sizes in sorted order, scanned, give each chunk's place.
    clock.start("decompression");
    DeviceBuffer<uint32_t, Exec> offset_buf(ex, chunks);
    uint32_t* offset = offset_buf.data();
    ex.launch("csd.sorted_sizes", chunks,
              [=] SHEAF_HD_LAMBDA(size_t j) { offset[j] = chunk_size[chunk_ids[j]]; });
    ex.exclusive_scan_async(offset, chunks); // the total is n: no wait for it
    ex.launch("csd.expand", chunks, [=] SHEAF_HD_LAMBDA(size_t j) {
        const uint32_t c = chunk_ids[j], base = chunk_base[c], size = chunk_size[c];
        for (uint32_t k = 0; k < size; ++k) perm[offset[j] + k] = base + k;
    });
    clock.stop("decompression");
    return r;
}

} // namespace sheaf::wavefront

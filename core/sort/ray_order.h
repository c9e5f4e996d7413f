// The order rays enter the hierarchy in (sort.mode): unsorted, every ray sorted by its key,
// or compress-sort-decompress (paper 000 sections 3.3.3-3.3.5). Sorting is stable (the bitonic
// sort breaks ties by index), so `full` and `csd`, radix and bitonic, give the same
// permutation; `csd` sorts one entry per run of equal adjacent keys.
#pragma once

#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sheaf {

struct OrderResult {
    std::vector<uint32_t> perm; // perm[j]: the ray at sorted position j
    size_t chunks = 0;          // csd: runs of equal adjacent keys; full: n; none: 0
};

/// keys: n * words entries, word 0 least significant. Adds time_ms.compression,
/// time_ms.sorting and time_ms.decompression to `stats`.
OrderResult order_rays(const std::vector<uint32_t>& keys, int words, size_t n, SortMode mode,
                       Stats& stats, SortAlgorithm algorithm = SortAlgorithm::Radix);

} // namespace sheaf

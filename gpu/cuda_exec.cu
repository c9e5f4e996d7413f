// CudaExec's multi-word radix sort.
#include "gpu/cuda_exec.cuh"

#include "core/base/device.h"
#include "core/wavefront/buffer.h"

namespace sheaf::gpu {

void CudaExec::sort_pairs(uint32_t* keys, int words, uint32_t* values, size_t n) {
    using wavefront::DeviceBuffer;
    if (n < 2) return;
    if (n > size_t(INT32_MAX)) throw RenderError("CUDA sort: more than 2^31 keys");
    // One sort is one piece of device work in the counts, as in the CPU policy.
    struct CountOnce {
        uint64_t& launches;
        uint64_t before;
        ~CountOnce() { launches = before + 1; }
    } count_once{launches_, launches_};
    const int items = int(n);
    if (words == 1) {
        DeviceBuffer<uint32_t, CudaExec> k_alt(*this, n), v_alt(*this, n);
        cub::DoubleBuffer<uint32_t> dk(keys, k_alt.data()), dv(values, v_alt.data());
        size_t bytes = 0;
        check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, dk, dv, items, 0, 32, stream_),
              "cub::DeviceRadixSort::SortPairs");
        check(cub::DeviceRadixSort::SortPairs(temp(bytes), bytes, dk, dv, items, 0, 32, stream_),
              "cub::DeviceRadixSort::SortPairs");
        if (dk.Current() != keys) copy_on_device(keys, dk.Current(), n * sizeof(uint32_t));
        if (dv.Current() != values) copy_on_device(values, dv.Current(), n * sizeof(uint32_t));
        return;
    }
    // Positions sorted by each pair of words, least significant pair first: every pass is a
    // stable radix sort, so the result is the lexicographic order with ties by position.
    DeviceBuffer<uint32_t, CudaExec> pos_a(*this, n), pos_b(*this, n);
    DeviceBuffer<uint64_t, CudaExec> k_a(*this, n), k_b(*this, n);
    uint32_t* pos = pos_a.data();
    uint32_t* pos_other = pos_b.data();
    launch("sort.iota", n, [=] SHEAF_HD_LAMBDA(size_t i) { pos[i] = uint32_t(i); });
    for (int w = 0; w < words; w += 2) {
        const bool pair = w + 1 < words;
        uint64_t* k = k_a.data();
        const uint32_t* cur = pos;
        launch("sort.pack", n, [=] SHEAF_HD_LAMBDA(size_t j) {
            const uint32_t* key = keys + size_t(cur[j]) * words;
            k[j] = (pair ? uint64_t(key[w + 1]) << 32 : 0) | key[w];
        });
        cub::DoubleBuffer<uint64_t> dk(k_a.data(), k_b.data());
        cub::DoubleBuffer<uint32_t> dp(pos, pos_other);
        const int bits = pair ? 64 : 32;
        size_t bytes = 0;
        check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, dk, dp, items, 0, bits, stream_),
              "cub::DeviceRadixSort::SortPairs");
        check(cub::DeviceRadixSort::SortPairs(temp(bytes), bytes, dk, dp, items, 0, bits, stream_),
              "cub::DeviceRadixSort::SortPairs");
        if (dp.Current() != pos) {
            pos_other = pos;
            pos = dp.Current();
        }
    }
    DeviceBuffer<uint32_t, CudaExec> k_out(*this, n * size_t(words)), v_out(*this, n);
    uint32_t* ko = k_out.data();
    uint32_t* vo = v_out.data();
    const uint32_t* order = pos;
    launch("sort.gather", n, [=] SHEAF_HD_LAMBDA(size_t j) {
        const size_t src = order[j];
        vo[j] = values[src];
        for (int w = 0; w < words; ++w) ko[j * words + w] = keys[src * words + w];
    });
    copy_on_device(keys, ko, n * size_t(words) * sizeof(uint32_t));
    copy_on_device(values, vo, n * sizeof(uint32_t));
}

} // namespace sheaf::gpu

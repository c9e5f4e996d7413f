// CudaExec's multi-word radix sort.
#include "gpu/cuda_exec.cuh"

#include "core/base/device.h"
#include "core/frame/buffer.h"
#include "core/frame/steps.h"

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
    const Span span(*this, words == 1 ? "sort (1 word)" : "sort (word pairs)");
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
    // More words: positions sorted by each pair of words as 64-bit keys (core/frame/steps.h).
    wavefront::sort_pairs_by_word_pairs(*this, keys, words, values, n, RadixPass64{this});
}

bool CudaExec::radix_pass64(uint64_t* k, uint64_t* k_alt, uint32_t* v, uint32_t* v_alt, size_t n,
                            int bits) {
    cub::DoubleBuffer<uint64_t> dk(k, k_alt);
    cub::DoubleBuffer<uint32_t> dv(v, v_alt);
    size_t bytes = 0;
    check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, dk, dv, int(n), 0, bits, stream_),
          "cub::DeviceRadixSort::SortPairs");
    check(cub::DeviceRadixSort::SortPairs(temp(bytes), bytes, dk, dv, int(n), 0, bits, stream_),
          "cub::DeviceRadixSort::SortPairs");
    return dv.Current() != v;
}

} // namespace sheaf::gpu

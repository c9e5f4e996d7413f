// The part of a frame's sample grid a render computes (region.*): samples keep the index they
// have in the whole grid (what seeds their random numbers and names them in ray batches), and
// the frame's per-sample buffers hold only the window's, row by row.
#pragma once

#include "core/base/device.h"

#include <cstddef>
#include <cstdint>

namespace sheaf {

struct SampleWindow {
    int grid_width = 0;         // samples per row of the whole frame
    int x = 0, y = 0;           // the window's first column and row in the whole grid
    int width = 0, height = 0;  // its size in samples

    /// The window of a frame `frame_width` pixels wide with aa x aa samples per pixel, over
    /// the pixels (px, py, pw, ph).
    static SampleWindow of_pixels(int frame_width, int aa, int px, int py, int pw, int ph) {
        return {frame_width * aa, px * aa, py * aa, pw * aa, ph * aa};
    }
    SHEAF_HD_INLINE size_t count() const { return size_t(width) * size_t(height); }
    /// Column and row in the whole grid of the window's sample j.
    SHEAF_HD_INLINE int column(size_t j) const { return x + int(j % size_t(width)); }
    SHEAF_HD_INLINE int row(size_t j) const { return y + int(j / size_t(width)); }
    /// The whole grid's index of the window's sample j.
    SHEAF_HD_INLINE uint32_t global(size_t j) const {
        return uint32_t(size_t(row(j)) * size_t(grid_width) + size_t(column(j)));
    }
    /// The window's index of the whole grid's sample g (which lies in the window).
    SHEAF_HD_INLINE uint32_t local(uint32_t g) const {
        // A window of whole rows (the whole frame, a strip): no division on this hot path.
        if (width == grid_width) return g - uint32_t(y) * uint32_t(width);
        return uint32_t(size_t(g / uint32_t(grid_width) - uint32_t(y)) * size_t(width) +
                        (g % uint32_t(grid_width) - uint32_t(x)));
    }
    /// The window's index of the grid's (column, row), which lie in the window.
    SHEAF_HD_INLINE size_t at(int column, int row) const {
        return size_t(row - y) * size_t(width) + size_t(column - x);
    }
};

} // namespace sheaf

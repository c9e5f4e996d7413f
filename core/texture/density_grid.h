// POV-Ray's density_file pattern: a voxel grid over the unit cube, read at a pattern-space
// point with the nearest voxel, trilinear or tricubic interpolation; 0 outside the cube.
// Host and device.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/pattern.h"

#include <cstddef>

namespace sheaf {

namespace density_detail {

// The voxel at (x, y, z), the indices wrapping around the grid (as POV-Ray's neighbours do at
// the cube's far faces).
SHEAF_HD_INLINE float voxel(const DensityGrid& g, const float* v, int x, int y, int z) {
    auto wrap = [](int i, uint32_t n) {
        const int r = i % int(n);
        return r < 0 ? r + int(n) : r;
    };
    return v[g.first + (size_t(wrap(z, g.nz)) * g.ny + size_t(wrap(y, g.ny))) * g.nx +
             size_t(wrap(x, g.nx))];
}

// Catmull-Rom weights of the four voxels around fraction t.
SHEAF_HD_INLINE void cubic_weights(float t, float w[4]) {
    const float t2 = t * t, t3 = t2 * t;
    w[0] = 0.5f * (-t3 + 2 * t2 - t);
    w[1] = 0.5f * (3 * t3 - 5 * t2 + 2);
    w[2] = 0.5f * (-3 * t3 + 4 * t2 + t);
    w[3] = 0.5f * (t3 - t2);
}

} // namespace density_detail

/// The grid's value at pattern-space point p (0 outside [0, 1)^3), in [0, 1].
SHEAF_HD_INLINE float density_value(const DensityGrid& g, const float* voxels, Vec3 p) {
    using density_detail::voxel;
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0.0f;
    const float fx = p.x * float(g.nx), fy = p.y * float(g.ny), fz = p.z * float(g.nz);
    const int x = int(fx), y = int(fy), z = int(fz); // fx >= 0: truncation is the floor
    if (g.interpolation == 0) return voxel(g, voxels, x, y, z);
    const float tx = fx - float(x), ty = fy - float(y), tz = fz - float(z);
    if (g.interpolation == 1) {
        float sum = 0;
        for (int k = 0; k < 8; ++k) {
            const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
            sum += (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz) *
                   voxel(g, voxels, x + dx, y + dy, z + dz);
        }
        return sum;
    }
    float wx[4], wy[4], wz[4];
    density_detail::cubic_weights(tx, wx);
    density_detail::cubic_weights(ty, wy);
    density_detail::cubic_weights(tz, wz);
    float sum = 0;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                sum += wx[i] * wy[j] * wz[k] * voxel(g, voxels, x + i - 1, y + j - 1, z + k - 1);
    return hdm::fminf(1.0f, hdm::fmaxf(0.0f, sum));
}

} // namespace sheaf

// Hashes of lattice points for deterministic jitter (photon rings, rainbows, media steps,
// black holes' copies): the same point gives the same value on both backends. The patterns'
// noise is POV-Ray's (pov_noise.h).
#pragma once

#include "core/math/hd_math.h"
#include "core/math/vec3.h"

#include <cstdint>

namespace sheaf {

/// A well-mixed 32-bit hash of a lattice point and a salt.
SHEAF_HD_INLINE uint32_t lattice_hash(int x, int y, int z, uint32_t salt = 0) {
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^ uint32_t(z) * 0xcb1ab31fu ^
                 salt * 0x9e3779b9u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

/// A value in [0, 1) from a hash.
SHEAF_HD_INLINE float hash_unit(uint32_t h) {
    return float(h >> 8) * (1.0f / 16777216.0f);
}

} // namespace sheaf

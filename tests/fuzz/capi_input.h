// One fuzz input as a host's program: the bytes choose a sequence of C ABI calls that build a
// scene and set a renderer (materials, meshes, objects, lights, cameras, textures,
// subdivision cages, load options, settings), with the values a careless or hostile host
// might pass: NaN and infinite floats, out-of-range ids, enums and flags, NULL pointers with
// counts, settings out of their range. Then the scene is committed and rendered small.
// Every failed call must return an error code with a message (promises.h); crashes,
// sanitizer reports, hangs and runaway memory are the fuzzer's own findings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace sheaf::fuzz {

/// What the calls aim at.
enum class CapiMode {
    Calls,  ///< fuzz_capi: any calls, and a small render or two
    Accels, ///< fuzz_bvh: a camera and a light, then mostly meshes of up to 256 triangles on a
            ///< coarse lattice (coincident, flat, axis-aligned, degenerate: what an
            ///< object-space hierarchy gets wrong), with mirrors and glass; the frame rendered
            ///< under every accel must be the same, bit for bit (the hits are brute force's)
};

/// Runs one input as a sequence of C ABI calls. Returns 0; aborts with a message when the
/// library breaks a promise. With `log`, writes each failed call and the outcome there.
int run_capi_input(const uint8_t* data, size_t size, std::FILE* log = nullptr,
                   CapiMode mode = CapiMode::Calls);

} // namespace sheaf::fuzz

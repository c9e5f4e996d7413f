// The interface between libsheaf and the CUDA module (libsheaf_cuda.so.0, built in gpu/).
// libsheaf never links the CUDA runtime: it dlopen()s the module at first use and asks it
// for this table. Both sides are built from the same tree; the ABI version and a signature
// (the sizes of the C++ types passed through `void*`, and a hash of the core's headers) guard
// against a module from another build.
#pragma once

#include "core/frame/frame.h"
#include "core/frame/render_frame.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"
#include "core/shading/surface.h"

#include <cstddef>
#include <cstdint>

#define SHEAF_CUDA_MODULE_ABI 2
#define SHEAF_CUDA_MODULE_ENTRY "sheaf_cuda_module"
#define SHEAF_CUDA_MODULE_FILE "libsheaf_cuda.so.0"

namespace sheaf {

/// Sizes of the C++ types that cross the module boundary, folded into one number.
constexpr uint64_t cuda_module_layout() {
    return uint64_t(sizeof(PreparedScene)) * 1000003u + uint64_t(sizeof(RenderSettings)) * 10007u +
           uint64_t(sizeof(Frame)) * 101u + uint64_t(sizeof(Material)) * 31u +
           uint64_t(sizeof(Light)) * 7u + uint64_t(sizeof(Pigment)) * 3u + sizeof(SurfaceHit);
}

#ifdef SHEAF_BUILD_ID
/// The layout and this build's identity (SHEAF_BUILD_ID: a hash of the core's headers when
/// the build was configured, defined for the loader and the module only).
constexpr uint64_t cuda_module_signature() {
    return cuda_module_layout() ^ uint64_t(SHEAF_BUILD_ID);
}
#endif

} // namespace sheaf

extern "C" {

/// What the module found: the device it renders on, or why there is none.
struct SheafCudaProbe {
    int device_count; // CUDA devices visible
    int device;       // the device used (0, or $SHEAF_CUDA_DEVICE)
    char name[256];   // its name
    int cc_major, cc_minor;
    unsigned long long memory_bytes;
    char error[512]; // empty when the device is usable; else e.g. "cudaErrorNoDevice: ..."
};

/// SHEAF_CUDA_BROKEN: the render failed and left the device's context unusable (a kernel
/// fault: every later CUDA call fails too), so the process stops using the module.
enum SheafCudaStatus {
    SHEAF_CUDA_OK = 0,
    SHEAF_CUDA_FAILED = 1,
    SHEAF_CUDA_CANCELLED = 2,
    SHEAF_CUDA_BROKEN = 3
};

struct SheafCudaModule {
    int abi_version;           // SHEAF_CUDA_MODULE_ABI
    unsigned long long layout; // sheaf::cuda_module_signature() of the module's build
    const char* build;         // "CUDA 13.0, sm 80 90"
    /// Fills *out; SHEAF_CUDA_OK when a device is usable. Never throws.
    int (*probe)(SheafCudaProbe* out);
    /// Renders `scene` (const sheaf::PreparedScene*) with `settings` (const
    /// sheaf::RenderSettings*) into `frame` (sheaf::Frame*, empty), calling `progress`
    /// (const sheaf::ProgressFn*, may be empty). On failure `error` receives the message.
    int (*render)(const void* scene, const void* settings, const void* progress, void* frame,
                  char* error, size_t error_size);
};

/// The module's one export: its table, or null when `abi_version` / `layout` (the caller's
/// cuda_module_signature()) do not match.
typedef const SheafCudaModule* (*SheafCudaModuleEntry)(int abi_version, unsigned long long layout);

} // extern "C"

// Finding and loading the CUDA module at run time, so that libsheaf itself never links the
// CUDA runtime and loads and renders on machines without a CUDA driver.
#pragma once

#include "core/backend/cuda_module_abi.h"

#include <string>
#include <vector>

namespace sheaf {

struct CudaBackendStatus {
    const SheafCudaModule* module = nullptr; // null when no module could be loaded
    std::string path;                        // the module file loaded
    std::string error;  // why there is no module, or why its device is not usable (short)
    std::string detail; // the same with every path tried and what the loader said
    SheafCudaProbe probe{};
    bool usable = false; // module loaded and a device found
};

/// Where the module is looked for, in order: $SHEAF_CUDA_MODULE (a file; when set, only it),
/// beside the image that holds this code (libsheaf.so, or a program linking the core
/// statically), the build tree's gpu/ output (set at configure time), then the dynamic
/// loader's own search path (LD_LIBRARY_PATH, ld.so.cache).
std::vector<std::string> cuda_module_candidates();

/// The module file this build made (configured by gpu/CMakeLists.txt), or empty when the
/// build had no nvcc.
std::string cuda_module_build_path();

/// Loads the first candidate that opens and probes it. Not cached.
CudaBackendStatus load_cuda_backend(const std::vector<std::string>& candidates);

/// The process's CUDA backend: loaded and probed once, at first use (thread-safe).
const CudaBackendStatus& cuda_backend();

} // namespace sheaf

// Where a frame is computed (setting `backend`): the CPU backend (core/frame/render_frame.h),
// or the CUDA module's frame pipeline. `auto` takes CUDA when the module loads, a device is
// usable and the scene has nothing the device cannot do; otherwise the CPU, and the frame
// says why.
#pragma once

#include "core/backend/cuda_loader.h"
#include "core/frame/render_frame.h"

#include <string>

namespace sheaf {

/// Renders one frame on the backend the settings ask for: the CPU backend, or the CUDA
/// module; the frame says which (Frame::backend, Frame::backend_line, statistic backend.cuda).
/// Throws RenderError (backend=cuda without a usable device, cancelled, a failed render), or
/// SceneError for scene settings that do not parse.
Frame render_frame(const PreparedScene& scene, const RenderSettings& settings,
                   const ProgressFn& progress = {});

struct BackendChoice {
    bool cuda = false;
    std::string line;    // "backend: cpu (no CUDA device: cudaErrorNoDevice: ...)"
    std::string why_not; // when not CUDA: why, with details (for backend=cuda's error)
};

/// The choice for `scene` under `requested`, given what the CUDA loader found.
BackendChoice choose_backend(const PreparedScene& scene, Backend requested,
                             const CudaBackendStatus& cuda);

/// Renders through the CUDA module (throws RenderError with the module's message). A render
/// that loses the device's context (SHEAF_CUDA_BROKEN) marks the module unusable for the
/// rest of the process.
Frame render_frame_cuda(const CudaBackendStatus& cuda, const PreparedScene& scene,
                        const RenderSettings& settings, const ProgressFn& progress = {});

/// render_frame with `cuda` as what the loader found (render_frame passes cuda_backend()).
Frame render_frame_with(const CudaBackendStatus& cuda, const PreparedScene& scene,
                        const RenderSettings& settings, const ProgressFn& progress = {});

} // namespace sheaf

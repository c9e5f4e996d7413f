// The frame of paper 000 on this machine's cores: raster primary visibility, then every
// secondary ray through the chosen accel (brute, rah, crsh), bounce by bounce. The frame is
// written once (frame_pipeline.h) against the exec and tracer seams (seam.h); the CPU backend
// runs it under the CPU policy with the CPU's tracer, the CUDA module (gpu/) under the CUDA
// policy with the wavefront tracer. render_frame, which picks the backend, is in
// core/backend/backend.h.
#pragma once

#include "core/frame/frame.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"

#include <functional>
#include <string>

namespace sheaf {

/// Called between stages with the share of the frame done (0..1); return false to cancel,
/// which makes the render throw RenderError("cancelled").
using ProgressFn = std::function<bool(float done)>;

/// The CPU backend itself, whatever `settings.backend` says: the frame pipeline under the CPU
/// policy (oneTBB, host memory: the scene bound, not copied) with the CPU's tracer
/// (HostTracer).
Frame render_frame_cpu(const PreparedScene& scene, const RenderSettings& settings,
                       const ProgressFn& progress = {});

/// The same frame with the CUDA module's tracer (the wavefront of launches,
/// wavefront_tracer.h) in place of the CPU's: the same image and statistics as
/// render_frame_cpu (except time_ms.*, memory.* and device.*), which the tests check on any
/// machine.
Frame render_frame_wavefront_cpu(const PreparedScene& scene, const RenderSettings& settings,
                                 const ProgressFn& progress = {});

/// Why the CUDA backend cannot render `scene` as the CPU does (empty when it can): image
/// textures are sampled through OpenImageIO, on the host only.
std::string wavefront_unsupported(const PreparedScene& scene);

} // namespace sheaf

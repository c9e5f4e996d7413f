// The wavefront ("device") pipeline: the whole frame as launches over arrays, written once
// against an execution seam and compiled twice: with the CPU policy into libsheaf (this
// header's render_frame_wavefront_cpu, which the unit tests compare with the CPU renderer),
// and with the CUDA policy into the CUDA module (gpu/).
#pragma once

#include "core/render/renderer.h"

#include <string>

namespace sheaf {

/// Why the wavefront pipeline cannot render `scene` as the CPU renderer does (empty when it
/// can): image textures are sampled through OpenImageIO on the host only.
std::string wavefront_unsupported(const PreparedScene& scene);

/// The frame pipeline under the CPU execution policy with the CUDA module's tracer (the
/// wavefront of launches, wf_trace.h) in place of the CPU's: the same image and statistics
/// as render_frame_cpu (except time_ms.*, memory.* and device.*), which the tests check.
Frame render_frame_wavefront_cpu(const PreparedScene& scene, const RenderSettings& settings,
                                 const ProgressFn& progress = {});

} // namespace sheaf

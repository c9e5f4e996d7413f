// The frame pipeline of paper 000: raster primary visibility, then every secondary ray through
// the chosen accel (brute, rah, crsh), bounce by bounce.
#pragma once

#include "core/render/frame.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"

#include <functional>

namespace sheaf {

/// Called between stages with the share of the frame done (0..1); return false to cancel,
/// which makes render_frame throw RenderError("cancelled").
using ProgressFn = std::function<bool(float done)>;

/// Renders one frame on the backend the settings ask for (core/backend/backend.h): the CPU
/// renderer, or the CUDA module's wavefront pipeline; the frame says which (Frame::backend,
/// Frame::backend_line, statistic backend.cuda). Throws RenderError (backend=cuda without a
/// usable device, cancelled, a failed render), or SceneError for scene settings that do not
/// parse.
Frame render_frame(const PreparedScene& scene, const RenderSettings& settings,
                   const ProgressFn& progress = {});

/// The CPU renderer itself, whatever `settings.backend` says.
Frame render_frame_cpu(const PreparedScene& scene, const RenderSettings& settings,
                       const ProgressFn& progress = {});

} // namespace sheaf

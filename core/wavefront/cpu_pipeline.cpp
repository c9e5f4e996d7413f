// The wavefront pipeline compiled for the CPU execution policy.
#include "core/wavefront/wavefront.h"

#include "core/wavefront/cpu_exec.h"
#include "core/wavefront/wf_frame.h"

#include <tbb/task_arena.h>

namespace sheaf {

std::string wavefront_unsupported(const PreparedScene& scene) {
    if (scene.sampler && !scene.textures.empty())
        return "the scene has image textures, which are sampled on the host only (OpenImageIO)";
    return {};
}

Frame render_frame_wavefront_cpu(const PreparedScene& scene, const RenderSettings& s,
                                 const ProgressFn& progress) {
    const std::string why = wavefront_unsupported(scene);
    if (!why.empty()) throw RenderError("wavefront pipeline: " + why);
    Frame f;
    tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        wavefront::CpuExec exec;
        wavefront::DeviceFrame<wavefront::CpuExec>(exec, scene, s, progress, f).run();
    });
    return f;
}

} // namespace sheaf

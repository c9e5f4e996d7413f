// The frame pipeline compiled for the CPU execution policy: the CPU backend (with the CPU's
// tracer), and the same frame with the CUDA module's wavefront tracer, which the tests hold
// against it.
#include "core/frame/render_frame.h"

#include "core/frame/cpu_exec.h"
#include "core/frame/frame_pipeline.h"
#include "core/frame/host_tracer.h"

#include <tbb/task_arena.h>

namespace sheaf {

std::string wavefront_unsupported(const PreparedScene& scene) {
    if (scene.sampler && !scene.textures.empty())
        return "the scene has image textures, which are sampled on the host only (OpenImageIO)";
    return {};
}

namespace {

template <class Tracer>
Frame render_on_cpu(const PreparedScene& scene, const RenderSettings& s,
                    const ProgressFn& progress) {
    Frame f;
    tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        wavefront::CpuExec exec;
        wavefront::FramePipeline<wavefront::CpuExec, Tracer>(exec, scene, s, progress, f).run();
    });
    return f;
}

} // namespace

Frame render_frame_cpu(const PreparedScene& scene, const RenderSettings& s,
                       const ProgressFn& progress) {
    return render_on_cpu<wavefront::HostTracer>(scene, s, progress);
}

Frame render_frame_wavefront_cpu(const PreparedScene& scene, const RenderSettings& s,
                                 const ProgressFn& progress) {
    return render_on_cpu<wavefront::WavefrontTracer<wavefront::CpuExec>>(scene, s, progress);
}

} // namespace sheaf

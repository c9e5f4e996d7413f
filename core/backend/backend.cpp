#include "core/backend/backend.h"

#include "core/backend/device_stack.h"
#include "core/base/error.h"
#include "core/frame/render_frame.h"

#include <map>
#include <mutex>

namespace sheaf {

namespace {

std::string device_words(const SheafCudaProbe& p) {
    return std::string(p.name) + ", compute " + std::to_string(p.cc_major) + "." +
           std::to_string(p.cc_minor);
}

/// The modules that lost their device's context in this process, and why.
struct Broken {
    std::mutex m;
    std::map<const SheafCudaModule*, std::string> why;
};
Broken& broken() {
    static Broken b;
    return b;
}
std::string broken_why(const SheafCudaModule* module) {
    std::lock_guard<std::mutex> lock(broken().m);
    const auto it = broken().why.find(module);
    return it == broken().why.end() ? std::string() : it->second;
}

void mark(Frame& f, bool cuda, const std::string& line) {
    f.backend = cuda ? "cuda" : "cpu";
    f.backend_line = line;
    f.stats.set("backend.cuda", cuda ? 1 : 0);
}

} // namespace

BackendChoice choose_backend(const PreparedScene& scene, Backend requested,
                             const CudaBackendStatus& cuda) {
    BackendChoice c;
    if (requested == Backend::Cpu) {
        c.line = "backend: cpu (backend=cpu)";
        c.why_not = "backend=cpu";
        return c;
    }
    std::string why = wavefront_unsupported(scene);
    if (why.empty() && device_stack_bytes(scene) > kDeviceStackCap) {
        const int fn = fn_pigment_nesting(scene);
        why = "CSG nested " + std::to_string(csg_nesting(scene)) + " levels deep" +
              (fn > 0 ? " with functions reading pigments nested " + std::to_string(fn) + " deep"
                      : std::string()) +
              " needs more device stack than the CUDA module allows (" +
              std::to_string((kDeviceStackCap - kDeviceStackBase) / kDeviceStackPerCsgLevel) +
              " levels)";
    }
    if (!why.empty()) {
        c.line = "backend: cpu (" + why + ")";
        c.why_not = why;
        return c;
    }
    if (!cuda.usable) {
        c.line = "backend: cpu (" + cuda.error + ")";
        c.why_not = cuda.detail.empty() ? cuda.error : cuda.detail;
        return c;
    }
    c.cuda = true;
    c.line = "backend: cuda (" + device_words(cuda.probe) + ")";
    return c;
}

Frame render_frame_cuda(const CudaBackendStatus& cuda, const PreparedScene& scene,
                        const RenderSettings& s, const ProgressFn& progress) {
    if (!cuda.module) throw RenderError("backend=cuda: " + cuda.error);
    Frame f;
    char error[1024] = {0};
    const int rc = cuda.module->render(&scene, &s, &progress, &f, error, sizeof error);
    if (rc == SHEAF_CUDA_CANCELLED) throw RenderError("cancelled");
    if (rc == SHEAF_CUDA_BROKEN) {
        std::lock_guard<std::mutex> lock(broken().m);
        broken().why.emplace(cuda.module,
                             std::string("the CUDA device failed earlier in this process: ") +
                                 (error[0] ? error : "no message from the module"));
    }
    if (rc != SHEAF_CUDA_OK)
        throw RenderError(std::string("the CUDA render failed: ") +
                          (error[0] ? error : "no message from the module"));
    return f;
}

Frame render_frame(const PreparedScene& scene, const RenderSettings& s,
                   const ProgressFn& progress) {
    if (s.backend == Backend::Cpu) { // without loading the module
        Frame f = render_frame_cpu(scene, s, progress);
        mark(f, false, "backend: cpu (backend=cpu)");
        return f;
    }
    return render_frame_with(cuda_backend(), scene, s, progress);
}

Frame render_frame_with(const CudaBackendStatus& loaded, const PreparedScene& scene,
                        const RenderSettings& s, const ProgressFn& progress) {
    CudaBackendStatus cuda = loaded;
    if (const std::string why = cuda.module ? broken_why(cuda.module) : ""; !why.empty()) {
        cuda.usable = false;
        cuda.error = cuda.detail = why;
    }
    const BackendChoice c = choose_backend(scene, s.backend, cuda);
    if (!c.cuda) {
        if (s.backend == Backend::Cuda)
            throw RenderError("backend=cuda: the CUDA backend cannot render this frame: " +
                              c.why_not);
        Frame f = render_frame_cpu(scene, s, progress);
        mark(f, false, c.line);
        return f;
    }
    try {
        Frame f = render_frame_cuda(cuda, scene, s, progress);
        mark(f, true, c.line);
        return f;
    } catch (const RenderError& e) {
        const std::string what = e.what();
        if (what == "cancelled") throw;
        if (s.backend == Backend::Cuda) throw RenderError("backend=cuda: " + what);
        // auto: the device failed (out of memory, a driver error); the CPU still renders.
        Frame f = render_frame_cpu(scene, s, progress);
        mark(f, false, "backend: cpu (" + what + ")");
        return f;
    }
}

} // namespace sheaf

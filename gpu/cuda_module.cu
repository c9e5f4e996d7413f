// libsheaf_cuda.so.0: the CUDA backend. One export, sheaf_cuda_module(), gives libsheaf the
// table of core/backend/cuda_module_abi.h: probe (is there a usable device?) and render (the
// frame pipeline of core/frame under the CUDA execution policy). libsheaf dlopen()s
// this module at first use; nothing of CUDA is linked into libsheaf itself.
#include "core/backend/cuda_module_abi.h"
#include "core/backend/device_stack.h"
#include "core/frame/frame_pipeline.h"
#include "gpu/cuda_exec.cuh"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>

namespace sheaf::gpu {
namespace {

#define SHEAF_STRINGIFY2(x) #x
#define SHEAF_STRINGIFY(x) SHEAF_STRINGIFY2(x)

constexpr const char* kBuild = "CUDA " SHEAF_STRINGIFY(__CUDACC_VER_MAJOR__) "." SHEAF_STRINGIFY(
    __CUDACC_VER_MINOR__) ", sm " SHEAF_CUDA_ARCHS;

void copy_message(char* dst, size_t size, const std::string& msg) {
    if (!dst || size == 0) return;
    std::snprintf(dst, size, "%s", msg.c_str());
}

std::string runtime_error(cudaError_t e) {
    return std::string(cudaGetErrorName(e)) + ": " + cudaGetErrorString(e);
}

/// The device to render on: $SHEAF_CUDA_DEVICE, else 0.
int chosen_device() {
    const char* env = std::getenv("SHEAF_CUDA_DEVICE");
    return env && *env ? std::atoi(env) : 0;
}

__global__ void probe_kernel(int* out) {
    *out = 42;
}

int probe_device(SheafCudaProbe* out) {
    std::memset(out, 0, sizeof *out);
    int count = 0;
    cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess) {
        copy_message(out->error, sizeof out->error, runtime_error(e));
        return SHEAF_CUDA_FAILED;
    }
    out->device_count = count;
    if (count == 0) {
        copy_message(out->error, sizeof out->error, "no CUDA-capable device is detected");
        return SHEAF_CUDA_FAILED;
    }
    const int device = chosen_device();
    out->device = device;
    if (device < 0 || device >= count) {
        copy_message(out->error, sizeof out->error,
                     "SHEAF_CUDA_DEVICE=" + std::to_string(device) + " but there are " +
                         std::to_string(count) + " devices");
        return SHEAF_CUDA_FAILED;
    }
    cudaDeviceProp prop{};
    if ((e = cudaGetDeviceProperties(&prop, device)) != cudaSuccess) {
        copy_message(out->error, sizeof out->error, runtime_error(e));
        return SHEAF_CUDA_FAILED;
    }
    copy_message(out->name, sizeof out->name, prop.name);
    out->cc_major = prop.major, out->cc_minor = prop.minor;
    out->memory_bytes = prop.totalGlobalMem;
    if (prop.major < 8) {
        copy_message(out->error, sizeof out->error,
                     std::string(prop.name) + " has compute capability " +
                         std::to_string(prop.major) + "." + std::to_string(prop.minor) +
                         "; the module is built for 8.0 and newer");
        return SHEAF_CUDA_FAILED;
    }
    // One tiny kernel: proves the module's code runs on this device and driver.
    int* d = nullptr;
    int v = 0;
    if ((e = cudaSetDevice(device)) != cudaSuccess || (e = cudaMalloc(&d, sizeof(int))) != cudaSuccess) {
        copy_message(out->error, sizeof out->error, runtime_error(e));
        return SHEAF_CUDA_FAILED;
    }
    probe_kernel<<<1, 1>>>(d);
    if ((e = cudaGetLastError()) == cudaSuccess)
        e = cudaMemcpy(&v, d, sizeof v, cudaMemcpyDeviceToHost);
    cudaFree(d);
    if (e != cudaSuccess || v != 42) {
        copy_message(out->error, sizeof out->error,
                     "a test kernel did not run: " +
                         (e != cudaSuccess ? runtime_error(e) : std::string("wrong result")));
        return SHEAF_CUDA_FAILED;
    }
    return SHEAF_CUDA_OK;
}

int probe(SheafCudaProbe* out) {
    try {
        return probe_device(out);
    } catch (...) {
        copy_message(out->error, sizeof out->error, "the CUDA probe failed (out of host memory)");
        return SHEAF_CUDA_FAILED;
    }
}

/// The exec frames run on one after another, made at the first frame and kept for the process
/// with the scene copy it made last (wavefront::SceneKeep). Never destroyed: at the process's
/// end the CUDA runtime may be gone before static destructors run, and the driver frees it all.
struct Resident {
    std::mutex m;
    CudaExec* exec = nullptr;
    wavefront::SceneKeep<CudaExec> keep;
};
Resident& resident() {
    static Resident* r = new Resident;
    return *r;
}

/// After a failed render: SHEAF_CUDA_BROKEN when the context is lost (a sticky error, which
/// every call returns from then on), else `status`.
int unless_broken(int status, char* error, size_t error_size) {
    const cudaError_t e = cudaDeviceSynchronize();
    if (e == cudaSuccess) return status;
    const std::string before = error && error[0] ? std::string(error) + "; " : std::string();
    copy_message(error, error_size, before + "the device's context is lost: " + runtime_error(e));
    return SHEAF_CUDA_BROKEN;
}

int render(const void* scene_p, const void* settings_p, const void* progress_p, void* frame_p,
           char* error, size_t error_size) {
    try {
        const PreparedScene& scene = *static_cast<const PreparedScene*>(scene_p);
        const RenderSettings& s = *static_cast<const RenderSettings*>(settings_p);
        static const ProgressFn none;
        const ProgressFn& progress = progress_p ? *static_cast<const ProgressFn*>(progress_p) : none;
        Frame& f = *static_cast<Frame*>(frame_p);
        const size_t stack = device_stack_bytes(scene);
        if (stack > kDeviceStackCap)
            throw RenderError("CSG nested " + std::to_string(csg_nesting(scene)) +
                              " levels deep needs more device stack than the module allows");
        // The resident exec when no other frame holds it (its stream, CUB's scratch and the
        // scene copied last stay for the next frame); else one for this frame alone.
        const int device = chosen_device();
        Resident& r = resident();
        std::unique_lock<std::mutex> lock(r.m, std::try_to_lock);
        std::unique_ptr<CudaExec> own;
        CudaExec* exec = nullptr;
        wavefront::SceneKeep<CudaExec>* keep = nullptr;
        if (lock.owns_lock()) {
            if (r.exec && r.exec->device() != device) {
                r.keep.clear();
                delete r.exec;
                r.exec = nullptr;
            }
            if (r.exec)
                r.exec->begin_frame(stack);
            else
                r.exec = new CudaExec(device, stack);
            exec = r.exec, keep = &r.keep;
        } else {
            own = std::make_unique<CudaExec>(device, stack);
            exec = own.get();
        }
        wavefront::FramePipeline<CudaExec> frame(*exec, scene, s, progress, f, keep);
        frame.run();
        check(cudaStreamSynchronize(exec->stream()), "the end of the frame");
        if (exec->profiling()) {
            std::fprintf(stderr, "profile: host steps:");
            for (const auto& [step, ms] : frame.host_steps())
                std::fprintf(stderr, " %s %.3f ms;", step, ms);
            std::fprintf(stderr, "\n");
        }
        exec->end_frame();
        return SHEAF_CUDA_OK;
    } catch (const RenderError& e) {
        if (std::strcmp(e.what(), "cancelled") == 0) return SHEAF_CUDA_CANCELLED;
        copy_message(error, error_size, e.what());
    } catch (const std::bad_alloc&) {
        copy_message(error, error_size, "out of host memory");
    } catch (const std::exception& e) {
        copy_message(error, error_size, e.what());
    } catch (...) {
        copy_message(error, error_size, "unknown error");
    }
    return unless_broken(SHEAF_CUDA_FAILED, error, error_size);
}

const SheafCudaModule kModule = {SHEAF_CUDA_MODULE_ABI, cuda_module_signature(), kBuild, probe,
                                 render};

} // namespace
} // namespace sheaf::gpu

extern "C" __attribute__((visibility("default"))) const SheafCudaModule*
sheaf_cuda_module(int abi_version, unsigned long long layout) {
    if (abi_version != SHEAF_CUDA_MODULE_ABI || layout != sheaf::cuda_module_signature())
        return nullptr;
    return &sheaf::gpu::kModule;
}

#include "core/backend/cuda_loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

namespace sheaf {

namespace {

std::string directory_of_this_image() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<const void*>(&cuda_module_candidates), &info) || !info.dli_fname)
        return {};
    const std::string file = info.dli_fname;
    const size_t slash = file.rfind('/');
    return slash == std::string::npos ? std::string(".") : file.substr(0, slash);
}

} // namespace

std::string cuda_module_build_path() {
#ifdef SHEAF_CUDA_MODULE_BUILD_PATH
    return SHEAF_CUDA_MODULE_BUILD_PATH;
#else
    return {};
#endif
}

std::vector<std::string> cuda_module_candidates() {
    if (const char* env = std::getenv("SHEAF_CUDA_MODULE"); env && *env) return {env};
    std::vector<std::string> c;
    if (const std::string dir = directory_of_this_image(); !dir.empty())
        c.push_back(dir + "/" SHEAF_CUDA_MODULE_FILE);
    if (const std::string built = cuda_module_build_path(); !built.empty()) c.push_back(built);
    c.push_back(SHEAF_CUDA_MODULE_FILE); // the dynamic loader's search path
    return c;
}

CudaBackendStatus load_cuda_backend(const std::vector<std::string>& candidates) {
    CudaBackendStatus st;
    std::string tried;
    for (const std::string& path : candidates) {
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            tried += std::string(tried.empty() ? "" : "; ") + (e ? e : path + ": cannot be opened");
            continue;
        }
        auto entry = reinterpret_cast<SheafCudaModuleEntry>(dlsym(handle, SHEAF_CUDA_MODULE_ENTRY));
        const SheafCudaModule* m =
            entry ? entry(SHEAF_CUDA_MODULE_ABI, cuda_module_signature()) : nullptr;
        if (!m) {
            tried += std::string(tried.empty() ? "" : "; ") + path +
                     (entry ? ": built from another version of Sheaf"
                            : ": no " SHEAF_CUDA_MODULE_ENTRY " in it");
            dlclose(handle);
            continue;
        }
        // Loaded for the life of the process: never dlclose'd, the CUDA runtime inside stays.
        st.module = m;
        st.path = path;
        break;
    }
    if (!st.module) {
        st.error = "no CUDA module: " SHEAF_CUDA_MODULE_FILE " not found or not loadable";
        st.detail = st.error + " (" + tried + ")";
        return st;
    }
    if (st.module->probe(&st.probe) == SHEAF_CUDA_OK) {
        st.usable = true;
    } else {
        st.error = std::string("no CUDA device: ") +
                   (st.probe.error[0] ? st.probe.error : "the module found none");
        st.detail = st.error + " (module " + st.path + ")";
    }
    return st;
}

const CudaBackendStatus& cuda_backend() {
    static std::once_flag once;
    static CudaBackendStatus status;
    std::call_once(once, [] { status = load_cuda_backend(cuda_module_candidates()); });
    return status;
}

} // namespace sheaf

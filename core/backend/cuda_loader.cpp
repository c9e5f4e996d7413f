#include "core/backend/cuda_loader.h"

#include "core/base/module_loader.h"

#include <mutex>

namespace sheaf {

std::string cuda_module_build_path() {
#ifdef SHEAF_CUDA_MODULE_BUILD_PATH
    return SHEAF_CUDA_MODULE_BUILD_PATH;
#else
    return {};
#endif
}

std::vector<std::string> cuda_module_candidates() {
    return module_candidates("SHEAF_CUDA_MODULE", SHEAF_CUDA_MODULE_FILE, cuda_module_build_path());
}

CudaBackendStatus load_cuda_backend(const std::vector<std::string>& candidates) {
    CudaBackendStatus st;
    const OpenedModule m = open_module(
        candidates, SHEAF_CUDA_MODULE_ENTRY, [](void* symbol, std::string& why) -> const void* {
            if (!symbol) return nullptr;
            const SheafCudaModule* t = reinterpret_cast<SheafCudaModuleEntry>(symbol)(
                SHEAF_CUDA_MODULE_ABI, cuda_module_signature());
            if (!t) why = "built from another version of Sheaf";
            return t;
        });
    // Loaded for the life of the process: the CUDA runtime inside stays.
    st.module = static_cast<const SheafCudaModule*>(m.table);
    st.path = m.path;
    const std::string& tried = m.tried;
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

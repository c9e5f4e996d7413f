#include "core/base/module_loader.h"

#include <dlfcn.h>

#include <cstdlib>

namespace sheaf {

namespace {

std::string directory_of_this_image() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<const void*>(&module_candidates), &info) || !info.dli_fname)
        return {};
    const std::string file = info.dli_fname;
    const size_t slash = file.rfind('/');
    return slash == std::string::npos ? std::string(".") : file.substr(0, slash);
}

} // namespace

std::vector<std::string> module_candidates(const char* env, const char* file,
                                           const std::string& build_path) {
    if (const char* e = std::getenv(env); e && *e) return {e};
    std::vector<std::string> c;
    if (const std::string dir = directory_of_this_image(); !dir.empty())
        c.push_back(dir + "/" + file);
    if (!build_path.empty()) c.push_back(build_path);
    c.push_back(file);
    return c;
}

OpenedModule open_module(const std::vector<std::string>& candidates, const char* entry,
                         const ModuleAccept& accept) {
    OpenedModule m;
    for (const std::string& path : candidates) {
        auto refuse = [&](const std::string& why) {
            m.tried += (m.tried.empty() ? "" : "; ") + why;
        };
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            refuse(e ? e : path + ": cannot be opened");
            continue;
        }
        std::string why;
        const void* table = accept(dlsym(handle, entry), why);
        if (!table) {
            refuse(path + ": " + (why.empty() ? "no " + std::string(entry) + " in it" : why));
            dlclose(handle);
            continue;
        }
        m.table = table;
        m.path = path;
        break;
    }
    return m;
}

} // namespace sheaf

// The C ABI's version queries and the names of the built-in scenes.
#include "capi_internal.h"

#include "core/scenes/builtin.h"

using namespace sheaf::capi;

extern "C" {

SHEAF_API void sheafGetVersion(int* major, int* minor, int* patch) {
    if (major) *major = SHEAF_VERSION_MAJOR;
    if (minor) *minor = SHEAF_VERSION_MINOR;
    if (patch) *patch = SHEAF_VERSION_PATCH;
}

SHEAF_API const char* sheafGetVersionString(void) {
    return SHEAF_VERSION_STRING;
}

SHEAF_API const char* sheafGetDefaultSceneName(void) {
    try {
        return sheaf::default_builtin_scene();
    } catch (...) {
        return "";
    }
}

SHEAF_API SheafError sheafGetBuiltinSceneCount(size_t* count) {
    return barrier([&] { *require(count, "count") = sheaf::builtin_scene_names().size(); });
}

SHEAF_API SheafError sheafGetBuiltinSceneName(size_t index, const char** name) {
    return barrier([&] {
        require(name, "name");
        const std::vector<std::string>& names = sheaf::builtin_scene_names();
        if (index >= names.size())
            throw InvalidArgument("built-in scene index " + std::to_string(index) +
                                  " is out of range (" + std::to_string(names.size()) + " scenes)");
        *name = names[index].c_str();
    });
}

} // extern "C"

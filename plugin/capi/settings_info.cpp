// The C ABI's description of every setting: key, default, allowed values and help text.
#include "capi_internal.h"

#include <vector>

using namespace sheaf::capi;

namespace {

struct SettingInfo {
    std::string key, default_value, allowed, help;
};

/// Built once; the strings live as long as the process.
const std::vector<SettingInfo>& setting_infos() {
    static const std::vector<SettingInfo> infos = [] {
        std::vector<SettingInfo> out;
        for (const sheaf::SettingSpec& s : sheaf::setting_specs())
            out.push_back({s.key, s.default_value, sheaf::describe_allowed(s), s.help});
        return out;
    }();
    return infos;
}

} // namespace

extern "C" {

SHEAF_API SheafError sheafGetSettingCount(size_t* count) {
    return barrier([&] { *require(count, "count") = setting_infos().size(); });
}

SHEAF_API SheafError sheafGetSettingInfo(size_t index, const char** key, const char** default_value,
                                         const char** allowed, const char** help) {
    return barrier([&] {
        const std::vector<SettingInfo>& infos = setting_infos();
        if (index >= infos.size())
            throw InvalidArgument("setting index " + std::to_string(index) + " is out of range (" +
                                  std::to_string(infos.size()) + " settings)");
        const SettingInfo& info = infos[index];
        if (key) *key = info.key.c_str();
        if (default_value) *default_value = info.default_value.c_str();
        if (allowed) *allowed = info.allowed.c_str();
        if (help) *help = info.help.c_str();
    });
}

} // extern "C"

// Small helpers the benchmark programs share for their command lines.
#pragma once

#include "core/settings/settings.h"

#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace sheaf::bench {

/// "a,b,,c" -> {"a", "b", "c"}.
inline std::vector<std::string> split_list(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

/// Adds a `--set KEY=VALUE` argument to `settings`, checked at once. Returns false, with the
/// reason in `error`, when it has no '=' or the key or value is not a render setting's.
inline bool add_setting(Settings& settings, const std::string& kv, std::string& error) {
    const size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
        error = "--set expects KEY=VALUE, got '" + kv + "'";
        return false;
    }
    try {
        settings.set(kv.substr(0, eq), kv.substr(eq + 1));
    } catch (const std::exception& e) {
        error = std::string("--set ") + kv + ": " + e.what();
        return false;
    }
    return true;
}

} // namespace sheaf::bench

// Setting presets: named sets of settings in small XML files (presets/*.xml), such as the
// configurations the papers compare (brute, rah, crsh).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sheaf {

struct Preset {
    std::string name, description;
    /// (key, canonical value) in file order.
    std::vector<std::pair<std::string, std::string>> values;
};

/// Reads and validates a preset file:
///   <preset name="crsh" description="..."> <set key="accel" value="crsh"/> ... </preset>
/// Every key and value is checked with canonical_setting. Throws SettingsError "FILE:LINE: ..."
/// for a missing file, malformed XML, an unknown element or attribute, or a bad setting.
Preset load_preset(const std::string& path);

/// Resolves a preset name to a file. A name containing '/' or ending in ".xml" is a path and is
/// returned as it is; otherwise the first dirs[i]/NAME.xml that exists. Throws SettingsError
/// listing the directories searched and the presets found there when there is none.
std::string find_preset(const std::string& name_or_path, const std::vector<std::string>& dirs);

/// The names of the presets (NAME of NAME.xml) in `dirs`, sorted, without duplicates.
std::vector<std::string> list_presets(const std::vector<std::string>& dirs);

} // namespace sheaf

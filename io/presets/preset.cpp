// Setting presets: XML parsing with pugixml, validation with canonical_setting, file lookup.
#include "io/presets/preset.h"

#include "core/base/error.h"
#include "core/settings/settings.h"

#include <pugixml.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

namespace sheaf {

namespace {

namespace fs = std::filesystem;

/// Maps byte offsets of the file to 1-based line numbers.
class LineMap {
  public:
    explicit LineMap(const std::string& text) {
        for (size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') newlines_.push_back(i);
    }
    size_t line(ptrdiff_t offset) const {
        if (offset < 0) return 0;
        return size_t(std::lower_bound(newlines_.begin(), newlines_.end(), size_t(offset)) -
                      newlines_.begin()) +
               1;
    }

  private:
    std::vector<size_t> newlines_;
};

class PresetReader {
  public:
    PresetReader(std::string path, const std::string& text)
        : path_(std::move(path)), lines_(text) {}

    [[noreturn]] void fail_at(ptrdiff_t offset, const std::string& message) const {
        const size_t line = lines_.line(offset);
        throw SettingsError(path_ + ":" + (line ? std::to_string(line) : std::string("?")) + ": " +
                            message);
    }
    [[noreturn]] void fail(const pugi::xml_node& node, const std::string& message) const {
        fail_at(node.offset_debug(), message);
    }

    /// Rejects attributes other than `allowed`.
    void check_attributes(const pugi::xml_node& node,
                          std::initializer_list<const char*> allowed) const {
        for (const pugi::xml_attribute& a : node.attributes()) {
            bool known = false;
            for (const char* name : allowed) known = known || std::string(a.name()) == name;
            if (!known) {
                std::string names;
                for (const char* name : allowed)
                    names += (names.empty() ? "" : ", ") + std::string(name);
                fail(node, "unknown attribute '" + std::string(a.name()) + "' on <" + node.name() +
                               ">; expected " + names);
            }
        }
    }

    Preset read(const pugi::xml_document& doc) const {
        pugi::xml_node root;
        for (const pugi::xml_node& n : doc.children()) {
            if (n.type() != pugi::node_element) continue;
            if (root) fail(n, "more than one root element");
            root = n;
        }
        if (!root) fail_at(0, "no <preset> element");
        if (std::string(root.name()) != "preset")
            fail(root, "unknown element <" + std::string(root.name()) + ">; expected <preset>");
        check_attributes(root, {"name", "description"});

        Preset preset;
        preset.name = root.attribute("name").as_string(fs::path(path_).stem().string().c_str());
        preset.description = root.attribute("description").as_string();
        std::set<std::string> seen;
        for (const pugi::xml_node& n : root.children()) {
            if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata)
                fail(n, "unexpected text in <preset>");
            if (n.type() != pugi::node_element) continue;
            if (std::string(n.name()) != "set")
                fail(n, "unknown element <" + std::string(n.name()) + ">; expected <set>");
            check_attributes(n, {"key", "value"});
            if (n.first_child()) fail(n, "<set> takes no content");
            const pugi::xml_attribute key = n.attribute("key"), value = n.attribute("value");
            if (!key) fail(n, "<set> without a key attribute");
            if (!value) fail(n, "<set key=\"" + std::string(key.value()) + "\"> without a value");
            std::string canonical;
            try {
                canonical = canonical_setting(key.value(), value.value());
            } catch (const SettingsError& e) {
                fail(n, e.what());
            }
            if (!seen.insert(key.value()).second)
                fail(n, "setting '" + std::string(key.value()) + "' is set twice");
            preset.values.emplace_back(key.value(), std::move(canonical));
        }
        return preset;
    }

  private:
    std::string path_;
    LineMap lines_;
};

} // namespace

Preset load_preset(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw SettingsError(path + ": is a directory, not a preset file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SettingsError(path + ": cannot open preset file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

    PresetReader reader(path, text);
    pugi::xml_document doc;
    const pugi::xml_parse_result result =
        doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) reader.fail_at(result.offset, std::string("XML error: ") + result.description());
    return reader.read(doc);
}

std::string find_preset(const std::string& name_or_path, const std::vector<std::string>& dirs) {
    const std::string& s = name_or_path;
    const bool is_path = s.find('/') != std::string::npos ||
                         (s.size() >= 4 && s.compare(s.size() - 4, 4, ".xml") == 0);
    if (is_path) return s;
    if (s.empty()) throw SettingsError("empty preset name");
    std::error_code ec;
    for (const std::string& dir : dirs) {
        if (dir.empty()) continue;
        const fs::path candidate = fs::path(dir) / (s + ".xml");
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
    }
    std::string searched, available;
    for (const std::string& dir : dirs)
        if (!dir.empty()) searched += (searched.empty() ? "" : ", ") + dir;
    for (const std::string& name : list_presets(dirs))
        available += (available.empty() ? "" : ", ") + name;
    throw SettingsError("unknown preset '" + s + "'; searched " +
                        (searched.empty() ? std::string("no directories") : searched) +
                        "; available: " + (available.empty() ? std::string("none") : available));
}

std::vector<std::string> list_presets(const std::vector<std::string>& dirs) {
    std::set<std::string> names;
    for (const std::string& dir : dirs) {
        if (dir.empty()) continue;
        std::error_code ec;
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            const fs::path& p = it->path();
            if (p.extension() == ".xml" && it->is_regular_file(ec)) names.insert(p.stem().string());
        }
    }
    return {names.begin(), names.end()};
}

} // namespace sheaf

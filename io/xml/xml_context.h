// What every part of the XML scene reader shares: the file's text for locations
// ("FILE:LINE:COL"), errors that carry them, and the checked reading of attributes, numbers and
// child elements. Nothing here knows the scene schema.
#pragma once

#include "core/math/vec3.h"

#include <pugixml.hpp>

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace sheaf::io::xml {

/// The file being read: its path (for messages and relative paths) and text (for locations).
class XmlContext {
  public:
    XmlContext(std::string path, std::string text);

    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }
    /// A path in the file relative to the scene file's folder, as given when absolute.
    std::string resolve(const std::string& relative) const;

    /// "FILE:LINE:COL" of a byte offset into the text (1-based; columns count characters).
    std::string location(ptrdiff_t offset) const;
    /// Byte offset of an element, of an attribute's value, of a text node.
    ptrdiff_t offset(const pugi::xml_node& node) const;
    ptrdiff_t offset(const pugi::xml_node& node, const pugi::xml_attribute& attribute) const;

    /// Throws SceneError "FILE:LINE:COL: error: MESSAGE".
    [[noreturn]] void fail_at(ptrdiff_t offset, const std::string& message) const;
    [[noreturn]] void fail(const pugi::xml_node& node, const std::string& message) const;
    [[noreturn]] void fail(const pugi::xml_node& node, const pugi::xml_attribute& attribute,
                           const std::string& message) const;

  private:
    std::string path_, text_;
    std::vector<size_t> line_starts_;
};

/// "<name>" of an element, for messages.
std::string tag(const pugi::xml_node& node);

/// The attributes of one element, read by name. Every getter records the name as known;
/// finish() rejects any attribute that no getter asked for (naming it and the known ones) and
/// attributes given twice. Getters leave `out` unchanged when the attribute is absent and
/// return whether it was present.
class Attributes {
  public:
    Attributes(const XmlContext& ctx, const pugi::xml_node& node);

    bool has(const char* name);
    bool get(const char* name, std::string& out);
    bool get(const char* name, float& out);
    bool get(const char* name, int& out, int min, int max);
    bool get(const char* name, bool& out);
    /// Three numbers "x y z" (commas allowed); `allow_scalar`: one number s means "s s s".
    bool get(const char* name, Vec3& out, bool allow_scalar = false);
    /// One of `choices`; returns the index in `out`.
    bool get(const char* name, int& out, std::initializer_list<const char*> choices);
    /// Any count of numbers.
    bool get_numbers(const char* name, std::vector<float>& out);
    /// A required attribute: fails naming it when absent.
    void require(const char* name) const;
    void finish() const;

    const pugi::xml_node& node() const { return node_; }

  private:
    pugi::xml_attribute find(const char* name);
    const XmlContext& ctx_;
    pugi::xml_node node_;
    std::vector<std::string> known_;
};

/// Numbers in text ("1 2.5, -3"): finite floats, or vertex indices (integers >= 0). `offset`
/// is where the text starts in the file, so that a bad number is reported where it stands.
std::vector<float> parse_floats(const XmlContext& ctx, std::string_view text, ptrdiff_t offset);
std::vector<uint32_t> parse_indices(const XmlContext& ctx, std::string_view text, ptrdiff_t offset);

/// The numbers an element holds as text (<positions>1 2 3</positions>); a child element in it
/// is an error, comments are skipped. The element must take no attributes.
std::vector<float> element_floats(const XmlContext& ctx, const pugi::xml_node& node);
std::vector<uint32_t> element_indices(const XmlContext& ctx, const pugi::xml_node& node);

/// The element children of `node`, in order. Text other than whitespace is an error (elements
/// of the schema hold either elements or numbers, never mixed content); comments are skipped.
std::vector<pugi::xml_node> child_elements(const XmlContext& ctx, const pugi::xml_node& node);

/// Fails at `child` naming it as unknown inside `parent` and listing what is allowed there.
[[noreturn]] void unknown_element(const XmlContext& ctx, const pugi::xml_node& child,
                                  const pugi::xml_node& parent,
                                  const std::vector<std::string>& allowed);

/// "a, b, c".
std::string join(const std::vector<std::string>& names);

} // namespace sheaf::io::xml

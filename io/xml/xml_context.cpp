// XmlContext, Attributes and the number readers: see xml_context.h.
#include "io/xml/xml_context.h"

#include "core/base/error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace sheaf::io::xml {
namespace {

bool is_separator(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

/// Calls fn(token, offset of the token in text) for every separated token.
template <class Fn> void for_each_token(std::string_view text, Fn&& fn) {
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && is_separator(text[i])) ++i;
        const size_t start = i;
        while (i < text.size() && !is_separator(text[i])) ++i;
        if (i > start) fn(text.substr(start, i - start), start);
    }
}

/// A token as quoted in messages: 'token', cut after 40 characters.
std::string quoted(std::string_view token) {
    std::string s = "'";
    s += token.substr(0, 40);
    if (token.size() > 40) s += "...";
    s += '\'';
    return s;
}

/// Calls fn(text, offset) for every text chunk of an element that holds numbers.
template <class Fn> void for_each_text(const XmlContext& ctx, const pugi::xml_node& node, Fn&& fn) {
    if (node.first_attribute())
        ctx.fail(node, node.first_attribute(),
                 "unknown attribute '" + std::string(node.first_attribute().name()) + "' on " +
                     tag(node) + "; it takes no attributes, only numbers");
    for (const pugi::xml_node& c : node.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
            fn(std::string_view(c.value()), ctx.offset(c));
        else if (c.type() == pugi::node_element)
            ctx.fail(c, tag(node) + " holds numbers; found the element " + tag(c));
    }
}

} // namespace

XmlContext::XmlContext(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
    line_starts_.push_back(0);
    for (size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n') line_starts_.push_back(i + 1);
}

std::string XmlContext::resolve(const std::string& relative) const {
    const std::filesystem::path p(relative);
    if (p.is_absolute() || relative.empty()) return relative;
    return (std::filesystem::path(path_).parent_path() / p).lexically_normal().string();
}

std::string XmlContext::location(ptrdiff_t offset) const {
    if (offset < 0) return path_;
    const size_t off = std::min(size_t(offset), text_.size());
    const size_t line = size_t(std::upper_bound(line_starts_.begin(), line_starts_.end(), off) -
                               line_starts_.begin());
    size_t column = 1;
    for (size_t i = line_starts_[line - 1]; i < off; ++i)
        if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column; // UTF-8 characters
    return path_ + ":" + std::to_string(line) + ":" + std::to_string(column);
}

ptrdiff_t XmlContext::offset(const pugi::xml_node& node) const {
    ptrdiff_t off = node.offset_debug();
    // An element's offset is its name's; report the '<' before it.
    if (node.type() == pugi::node_element && off > 0 && size_t(off) <= text_.size() &&
        text_[size_t(off) - 1] == '<')
        --off;
    return off;
}

ptrdiff_t XmlContext::offset(const pugi::xml_node& node,
                             const pugi::xml_attribute& attribute) const {
    const ptrdiff_t base = node.offset_debug();
    if (base < 0 || !attribute) return offset(node);
    // Both point into the document's copy of the text: the value starts where it stood.
    const ptrdiff_t off = base + (attribute.value() - node.name());
    if (off < base || size_t(off) > text_.size()) return offset(node);
    return off;
}

void XmlContext::fail_at(ptrdiff_t offset, const std::string& message) const {
    throw SceneError(location(offset) + ": error: " + message);
}
void XmlContext::fail(const pugi::xml_node& node, const std::string& message) const {
    fail_at(offset(node), message);
}
void XmlContext::fail(const pugi::xml_node& node, const pugi::xml_attribute& attribute,
                      const std::string& message) const {
    fail_at(offset(node, attribute), message);
}

std::string tag(const pugi::xml_node& node) {
    std::string s = "<";
    s += node.name();
    s += '>';
    return s;
}

std::string join(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

std::vector<float> parse_floats(const XmlContext& ctx, std::string_view text, ptrdiff_t offset) {
    std::vector<float> out;
    for_each_token(text, [&](std::string_view token, size_t at) {
        std::string_view digits = token;
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
        float v = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (ec == std::errc::result_out_of_range)
            ctx.fail_at(offset + ptrdiff_t(at), quoted(token) + " is out of range of a float");
        if (ec != std::errc() || end != digits.data() + digits.size())
            ctx.fail_at(offset + ptrdiff_t(at), quoted(token) + " is not a number");
        if (!std::isfinite(v))
            ctx.fail_at(offset + ptrdiff_t(at), quoted(token) + " is not a finite number");
        out.push_back(v);
    });
    return out;
}

std::vector<uint32_t> parse_indices(const XmlContext& ctx, std::string_view text,
                                    ptrdiff_t offset) {
    std::vector<uint32_t> out;
    for_each_token(text, [&](std::string_view token, size_t at) {
        uint32_t v = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec != std::errc() || end != token.data() + token.size())
            ctx.fail_at(offset + ptrdiff_t(at),
                        quoted(token) + " is not a vertex index (an integer from 0 to " +
                            std::to_string(UINT32_MAX) + ")");
        out.push_back(v);
    });
    return out;
}

std::vector<float> element_floats(const XmlContext& ctx, const pugi::xml_node& node) {
    std::vector<float> out;
    for_each_text(ctx, node, [&](std::string_view text, ptrdiff_t offset) {
        std::vector<float> part = parse_floats(ctx, text, offset);
        out.insert(out.end(), part.begin(), part.end());
    });
    return out;
}

std::vector<uint32_t> element_indices(const XmlContext& ctx, const pugi::xml_node& node) {
    std::vector<uint32_t> out;
    for_each_text(ctx, node, [&](std::string_view text, ptrdiff_t offset) {
        std::vector<uint32_t> part = parse_indices(ctx, text, offset);
        out.insert(out.end(), part.begin(), part.end());
    });
    return out;
}

std::vector<pugi::xml_node> child_elements(const XmlContext& ctx, const pugi::xml_node& node) {
    std::vector<pugi::xml_node> out;
    for (const pugi::xml_node& c : node.children()) {
        if (c.type() == pugi::node_element) {
            out.push_back(c);
        } else if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
            const std::string_view v(c.value());
            if (std::any_of(v.begin(), v.end(),
                            [](char ch) { return !is_separator(ch) || ch == ','; }))
                ctx.fail(c, "unexpected text in " + tag(node) + ": " + quoted(v));
        }
    }
    return out;
}

void unknown_element(const XmlContext& ctx, const pugi::xml_node& child,
                     const pugi::xml_node& parent, const std::vector<std::string>& allowed) {
    std::vector<std::string> tags;
    for (const std::string& a : allowed) tags.push_back("<" + a + ">");
    ctx.fail(child, "unknown element " + tag(child) + " in " + tag(parent) +
                        (tags.empty() ? std::string("; it takes no elements")
                                      : "; expected one of " + join(tags)));
}

// ---- Attributes ----

Attributes::Attributes(const XmlContext& ctx, const pugi::xml_node& node)
    : ctx_(ctx), node_(node) {}

pugi::xml_attribute Attributes::find(const char* name) {
    if (std::find(known_.begin(), known_.end(), name) == known_.end()) known_.push_back(name);
    return node_.attribute(name);
}

bool Attributes::has(const char* name) {
    return bool(find(name));
}

void Attributes::require(const char* name) const {
    if (!node_.attribute(name))
        ctx_.fail(node_, tag(node_) + " needs the attribute '" + std::string(name) + "'");
}

bool Attributes::get(const char* name, std::string& out) {
    const pugi::xml_attribute a = find(name);
    if (!a) return false;
    out = a.value();
    return true;
}

bool Attributes::get_numbers(const char* name, std::vector<float>& out) {
    const pugi::xml_attribute a = find(name);
    if (!a) return false;
    out = parse_floats(ctx_, a.value(), ctx_.offset(node_, a));
    return true;
}

bool Attributes::get(const char* name, float& out) {
    std::vector<float> v;
    if (!get_numbers(name, v)) return false;
    if (v.size() != 1)
        ctx_.fail(node_, node_.attribute(name),
                  "attribute '" + std::string(name) + "' of " + tag(node_) +
                      ": expected one number, found " + std::to_string(v.size()));
    out = v[0];
    return true;
}

bool Attributes::get(const char* name, int& out, int min, int max) {
    const pugi::xml_attribute a = find(name);
    if (!a) return false;
    const std::string_view s(a.value());
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty() || v < min || v > max)
        ctx_.fail(node_, a,
                  "attribute '" + std::string(name) + "' of " + tag(node_) + ": " + quoted(s) +
                      " is not allowed; expected an integer in " + std::to_string(min) + ".." +
                      std::to_string(max));
    out = v;
    return true;
}

bool Attributes::get(const char* name, bool& out) {
    const pugi::xml_attribute a = find(name);
    if (!a) return false;
    const std::string_view s(a.value());
    if (s == "true" || s == "1")
        out = true;
    else if (s == "false" || s == "0")
        out = false;
    else
        ctx_.fail(node_, a,
                  "attribute '" + std::string(name) + "' of " + tag(node_) + ": " + quoted(s) +
                      " is not allowed; expected true or false");
    return true;
}

bool Attributes::get(const char* name, Vec3& out, bool allow_scalar) {
    std::vector<float> v;
    if (!get_numbers(name, v)) return false;
    if (allow_scalar && v.size() == 1)
        out = Vec3(v[0]);
    else if (v.size() == 3)
        out = Vec3(v[0], v[1], v[2]);
    else
        ctx_.fail(node_, node_.attribute(name),
                  "attribute '" + std::string(name) + "' of " + tag(node_) + ": expected " +
                      (allow_scalar ? "one or three numbers" : "three numbers") + ", found " +
                      std::to_string(v.size()));
    return true;
}

bool Attributes::get(const char* name, int& out, std::initializer_list<const char*> choices) {
    const pugi::xml_attribute a = find(name);
    if (!a) return false;
    int i = 0;
    std::vector<std::string> names;
    for (const char* c : choices) {
        if (std::string_view(a.value()) == c) {
            out = i;
            return true;
        }
        names.push_back(c);
        ++i;
    }
    ctx_.fail(node_, a,
              "attribute '" + std::string(name) + "' of " + tag(node_) + ": " + quoted(a.value()) +
                  " is not one of " + join(names));
}

void Attributes::finish() const {
    for (pugi::xml_attribute a = node_.first_attribute(); a; a = a.next_attribute()) {
        const std::string name = a.name();
        if (std::find(known_.begin(), known_.end(), name) == known_.end())
            ctx_.fail(node_, a,
                      "unknown attribute '" + name + "' on " + tag(node_) +
                          (known_.empty() ? std::string("; it takes no attributes")
                                          : "; expected one of " + join(known_)));
        for (pugi::xml_attribute b = a.next_attribute(); b; b = b.next_attribute())
            if (name == b.name())
                ctx_.fail(node_, b, "attribute '" + name + "' is given twice on " + tag(node_));
    }
}

} // namespace sheaf::io::xml

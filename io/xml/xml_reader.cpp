// The XML scene reader: the document, the <scene> element and its dispatch, and the tables of
// names (materials, textures, meshes, pigments, normals, switches) that later elements refer to.
#include "io/xml/xml_reader.h"

#include "core/base/error.h"
#include "io/xml/xml_scene.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace sheaf::io {
namespace xml {

void SceneReader::define(NameTable& table, const char* kind, const std::string& name,
                         const pugi::xml_node& node, uint32_t id) {
    if (name.empty()) ctx_.fail(node, tag(node) + ": the name must not be empty");
    auto [it, added] = table.try_emplace(name, Named{id, ctx_.offset(node)});
    if (!added)
        ctx_.fail(node, std::string(kind) + " '" + name + "' is defined twice (first at " +
                            ctx_.location(it->second.offset) + ")");
}

uint32_t SceneReader::lookup(const NameTable& table, const char* kind, const std::string& name,
                             const pugi::xml_node& node,
                             const pugi::xml_attribute& attribute) const {
    const auto it = table.find(name);
    if (it != table.end()) return it->second.id;
    std::vector<std::string> names;
    for (const auto& [n, _] : table) names.push_back("'" + n + "'");
    ctx_.fail(node, attribute,
              "unknown " + std::string(kind) + " '" + name + "'" +
                  (names.empty() ? "; none is defined before this point"
                                 : "; defined before this point: " + join(names)));
}

uint32_t SceneReader::material_of(Attributes& a, std::optional<uint32_t> fallback) {
    std::string name;
    if (a.get("material", name))
        return lookup(materials_, "material", name, a.node(), a.node().attribute("material"));
    if (fallback) return *fallback;
    if (!default_material_) default_material_ = scene_.add_material(Material{});
    return *default_material_;
}

uint8_t SceneReader::object_flags(Attributes& a) {
    bool no_shadow = false, no_reflection = false, no_image = false;
    a.get("no_shadow", no_shadow);
    a.get("no_reflection", no_reflection);
    a.get("no_image", no_image);
    return uint8_t((no_shadow ? kNoShadow : 0) | (no_reflection ? kNoReflection : 0) |
                   (no_image ? kNoImage : 0));
}

void SceneReader::read_scene(const pugi::xml_node& root) {
    Attributes a(ctx_, root);
    int version = 1;
    a.get("version", version, 1, 1);
    a.finish();
    for (const pugi::xml_node& n : child_elements(ctx_, root)) {
        const std::string_view name = n.name();
        if (name == "settings")
            read_settings(n);
        else if (name == "camera")
            read_camera(n);
        else if (name == "background")
            read_background(n);
        else if (name == "light")
            read_light(n);
        else if (name == "texture")
            read_texture(n);
        else if (name == "material")
            read_material(n);
        else if (name == "pigment")
            read_pigment(n);
        else if (name == "normal")
            read_normal(n);
        else if (name == "switch")
            read_switch(n);
        else if (name == "sky")
            read_sky(n);
        else if (name == "fog")
            read_fog(n);
        else if (name == "mesh")
            read_mesh(n, true);
        else if (name == "subdivision")
            read_subdivision(n, true);
        else if (name == "object")
            read_object(n);
        else if (is_shape(n))
            read_shape_object(n);
        else
            unknown_element(ctx_, n, root,
                            {"settings", "camera",   "background",  "sky",          "fog",
                             "light",    "texture",  "pigment",     "normal",       "switch",
                             "material", "mesh",     "subdivision", "object",       "sphere",
                             "box",      "cylinder", "cone",        "disc",         "plane",
                             "torus",    "union",    "merge",       "intersection", "difference"});
    }
}

} // namespace xml

SceneFile parse_xml_scene(const std::string& text, const std::string& path) {
    const xml::XmlContext ctx(path, text);
    pugi::xml_document doc;
    const pugi::xml_parse_result result =
        doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) ctx.fail_at(result.offset, std::string("XML syntax: ") + result.description());
    pugi::xml_node root;
    for (const pugi::xml_node& n : doc.children()) {
        if (n.type() != pugi::node_element) continue;
        if (root) ctx.fail(n, "more than one root element; a scene file has one <scene>");
        root = n;
    }
    if (!root) ctx.fail_at(0, "no <scene> element");
    if (std::string_view(root.name()) != "scene")
        ctx.fail(root, "unknown root element " + xml::tag(root) + "; expected <scene>");
    xml::SceneReader reader(ctx);
    reader.read_scene(root);
    SceneFile out;
    out.scene = std::move(reader.scene());
    try {
        out.scene.validate();
    } catch (const SceneError& e) {
        throw SceneError(path + ": error: " + e.what());
    }
    return out;
}

SceneFile read_xml_scene(const std::string& path, const SceneFileOptions&) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw SceneError(path + ": is a directory, not a scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw SceneError(path + ": cannot read file");
    return parse_xml_scene(text, path);
}

} // namespace sheaf::io

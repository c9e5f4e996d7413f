// <material> and <texture>. A material's attributes are the fields of sheaf::Material, listed
// once in kMaterialFields: a new numeric or colour field is one line there (and one row in
// docs/xml-scene.md).
#include "io/xml/xml_reader.h"

#include <cmath>
#include <filesystem>

namespace sheaf::io::xml {
namespace {

/// One attribute of <material>: a number or a colour field of Material.
struct MaterialField {
    const char* attribute;
    float Material::*number;
    Vec3 Material::*colour;
    bool positive; // numbers: > 0 (else >= 0)
};

constexpr MaterialField kMaterialFields[] = {
    {"color", nullptr, &Material::color, false},
    {"emission", nullptr, &Material::emission, false},
    {"ambient", &Material::ambient, nullptr, false},
    {"diffuse", &Material::diffuse, nullptr, false},
    {"specular", &Material::specular, nullptr, false},
    {"phong_exponent", &Material::phong_exponent, nullptr, false},
    {"mirror", &Material::mirror, nullptr, false},
    {"transmission", &Material::transmission, nullptr, false},
    {"ior", &Material::ior, nullptr, true},
};

} // namespace

void SceneReader::read_material(const pugi::xml_node& node) {
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    if (!children.empty()) unknown_element(ctx_, children[0], node, {});
    Attributes a(ctx_, node);
    std::string name, base, texture;
    a.get("name", name);
    Material m;
    if (a.get("base", base))
        m = scene_.materials[lookup(materials_, "material", base, node, node.attribute("base"))];
    for (const MaterialField& f : kMaterialFields) {
        if (f.colour) {
            a.get(f.attribute, m.*f.colour, true);
            continue;
        }
        float v = 0;
        if (!a.get(f.attribute, v)) continue;
        if (f.positive ? !(v > 0) : !(v >= 0))
            ctx_.fail(node, node.attribute(f.attribute),
                      "attribute '" + std::string(f.attribute) +
                          "' of <material>: " + std::to_string(v) +
                          " is not allowed; expected a number " + (f.positive ? "> 0" : ">= 0"));
        m.*f.number = v;
    }
    if (a.get("texture", texture))
        m.texture =
            texture.empty()
                ? -1
                : int32_t(lookup(textures_, "texture", texture, node, node.attribute("texture")));
    a.finish();
    a.require("name");
    define(materials_, "material", name, node, 0);
    materials_[name].id = scene_.add_material(m);
}

void SceneReader::read_texture(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    std::string name, file;
    int mapping = 0, colorspace = -1;
    a.get("name", name);
    a.get("file", file);
    a.get("mapping", mapping, {"uv", "planar", "spherical", "cylindrical"});
    a.get("colorspace", colorspace, {"srgb", "linear"});
    a.finish();
    a.require("name");
    a.require("file");
    Affine placement; // texture space -> world
    for (const pugi::xml_node& c : child_elements(ctx_, node))
        if (!apply_transform(c, placement))
            unknown_element(ctx_, c, node, {"translate", "rotate", "scale", "matrix"});
    if (std::fabs(placement.determinant()) < 1e-20f)
        ctx_.fail(node, "the texture's transform is singular");

    Texture t;
    t.path = ctx_.resolve(file);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(t.path, ec))
        ctx_.fail(node, node.attribute("file"), "texture file '" + t.path + "' does not exist");
    constexpr TextureMapping kMappings[] = {TextureMapping::Uv, TextureMapping::Planar,
                                            TextureMapping::Spherical, TextureMapping::Cylindrical};
    t.mapping = kMappings[mapping];
    t.transform = placement.inverse();
    t.colorspace = colorspace == 0 ? "srgb" : colorspace == 1 ? "linear" : "";
    t.origin = ctx_.location(ctx_.offset(node));
    define(textures_, "texture", name, node, uint32_t(scene_.textures.size()));
    scene_.textures.push_back(std::move(t));
}

} // namespace sheaf::io::xml

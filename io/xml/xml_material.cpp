// <material> and <texture>. A material's attributes are the fields of sheaf::Material, listed
// once in kMaterialFields: a new number, colour or flag field is one line there (and one row in
// docs/xml-scene.md). The procedural textures are named: 'pigment', 'normal' and 'switch' refer to
// <pigment>, <normal> and <switch> elements defined before (xml_pigments.cpp).
#include "io/xml/xml_reader.h"

#include <cmath>
#include <filesystem>

namespace sheaf::io::xml {
namespace {

/// One attribute of <material>: a number, colour or flag field of Material.
struct MaterialField {
    const char* attribute;
    float Material::*number = nullptr;
    Vec3 Material::*colour = nullptr;
    bool Material::*flag = nullptr;
    bool positive = false; // numbers: > 0 (else >= 0)
};

constexpr MaterialField number(const char* a, float Material::*f, bool positive = false) {
    return {a, f, nullptr, nullptr, positive};
}
constexpr MaterialField colour(const char* a, Vec3 Material::*f) {
    return {a, nullptr, f, nullptr, false};
}
constexpr MaterialField flag(const char* a, bool Material::*f) {
    return {a, nullptr, nullptr, f, false};
}

const MaterialField kMaterialFields[] = {
    colour("color", &Material::color),
    colour("emission", &Material::emission),
    number("ambient", &Material::ambient),
    number("diffuse", &Material::diffuse),
    number("specular", &Material::specular),
    number("phong_exponent", &Material::phong_exponent),
    number("mirror", &Material::mirror),
    number("transmission", &Material::transmission),
    number("ior", &Material::ior, true),
    // POV-Ray's finish and interior terms (core/scene/scene.h).
    number("brilliance", &Material::brilliance),
    number("blinn", &Material::blinn),
    number("blinn_exponent", &Material::blinn_exponent),
    number("metallic", &Material::metallic),
    colour("mirror_color", &Material::mirror_color),
    number("mirror_min", &Material::mirror_min),
    number("mirror_falloff", &Material::mirror_falloff),
    flag("mirror_fresnel", &Material::mirror_fresnel),
    flag("mirror_metallic", &Material::mirror_metallic),
    flag("conserve_energy", &Material::conserve_energy),
    flag("fresnel_split", &Material::fresnel_split),
    colour("fade_color", &Material::fade_color),
    number("fade_distance", &Material::fade_distance),
    number("fade_power", &Material::fade_power),
    number("caustics", &Material::caustics),
    number("irid", &Material::irid),
    number("irid_thickness", &Material::irid_thickness),
    number("irid_turbulence", &Material::irid_turbulence),
    colour("irid_wavelength", &Material::irid_wavelength),
};

} // namespace

void SceneReader::read_material(const pugi::xml_node& node) {
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    if (!children.empty()) unknown_element(ctx_, children[0], node, {});
    Attributes a(ctx_, node);
    std::string name, base;
    a.get("name", name);
    Material m;
    if (a.get("base", base))
        m = scene_.materials[lookup(materials_, "material", base, node, node.attribute("base"))];
    // A reference to a named thing, or "" for none (dropping the base's).
    auto reference = [&](const char* attribute, const NameTable& table, const char* kind,
                         int32_t& out) {
        std::string ref;
        if (a.get(attribute, ref))
            out = ref.empty() ? -1
                              : int32_t(lookup(table, kind, ref, node, node.attribute(attribute)));
    };
    reference("switch", switches_, "switch", m.select);
    if (m.select >= 0) {
        // The switch picks another material at every point: nothing of this one is seen.
        for (pugi::xml_attribute at = node.first_attribute(); at; at = at.next_attribute()) {
            const std::string_view n = at.name();
            if (n != "name" && n != "base" && n != "switch" && n != "inside")
                ctx_.fail(node, at,
                          "attribute '" + std::string(n) +
                              "' of <material> is not used with a switch (the switch's materials "
                              "are seen); a material with a switch takes name, base, switch and "
                              "inside");
        }
    }
    for (const MaterialField& f : kMaterialFields) {
        if (f.colour) {
            a.get(f.attribute, m.*f.colour, true);
            continue;
        }
        if (f.flag) {
            a.get(f.attribute, m.*f.flag);
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
    // This format's fade_power 0 is no fading (the core's, POV-Ray's, halves refracted light).
    if (m.fade_power == 0) m.fade_distance = 0;
    reference("texture", textures_, "texture", m.texture);
    reference("pigment", pigments_, "pigment", m.pigment);
    reference("normal", normals_, "normal", m.normal);
    reference("inside", materials_, "material", m.inside);
    if (m.inside >= 0 && scene_.materials[size_t(m.inside)].inside >= 0)
        ctx_.fail(node, node.attribute("inside"),
                  "material '" + std::string(node.attribute("inside").value()) +
                      "' has an inside material of its own; an inside material has none");
    a.finish();
    a.require("name");
    if (m.pigment >= 0)
        for (const char* replaced : {"color", "texture", "transmission"})
            if (node.attribute(replaced))
                ctx_.fail(node, node.attribute(replaced),
                          "attribute '" + std::string(replaced) +
                              "' of <material> is not used with a pigment (the pigment gives "
                              "the colour, filter and transmit)");
    define(materials_, "material", name, node, 0);
    materials_[name].id = scene_.add_material(m);
}

void SceneReader::read_texture(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    std::string name, file;
    int mapping = 0, colorspace = -1;
    a.get("name", name);
    a.get("file", file);
    a.get("mapping", mapping, {"uv", "planar", "spherical", "cylindrical", "torus"});
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
                                            TextureMapping::Spherical, TextureMapping::Cylindrical,
                                            TextureMapping::Torus};
    t.mapping = kMappings[mapping];
    t.transform = placement.inverse();
    t.colorspace = colorspace == 0 ? "srgb" : colorspace == 1 ? "linear" : "";
    t.origin = ctx_.location(ctx_.offset(node));
    define(textures_, "texture", name, node, uint32_t(scene_.textures.size()));
    scene_.textures.push_back(std::move(t));
}

} // namespace sheaf::io::xml

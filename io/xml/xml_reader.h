// The XML scene reader's state and its element handlers, shared by the files that implement
// them: xml_reader.cpp (the document, <scene>, names), xml_transform.cpp, xml_material.cpp
// (<material>, <texture>), xml_meshes.cpp (<mesh>, <subdivision>, <object>), xml_shapes.cpp
// (analytic shapes and CSG), xml_view.cpp (<camera>, <light>, <background>, <settings>).
#pragma once

#include "core/math/affine.h"
#include "core/scene/scene.h"
#include "io/xml/xml_context.h"

#include <map>
#include <optional>
#include <string>

namespace sheaf::io::xml {

class SceneReader {
  public:
    explicit SceneReader(const XmlContext& ctx) : ctx_(ctx) {}
    /// Reads the <scene> element into scene().
    void read_scene(const pugi::xml_node& root);
    Scene& scene() { return scene_; }

  private:
    /// Named things a later element may refer to, with where they were defined.
    struct Named {
        uint32_t id;
        ptrdiff_t offset;
    };
    using NameTable = std::map<std::string, Named, std::less<>>;

    // xml_reader.cpp
    void define(NameTable& table, const char* kind, const std::string& name,
                const pugi::xml_node& node, uint32_t id);
    uint32_t lookup(const NameTable& table, const char* kind, const std::string& name,
                    const pugi::xml_node& node, const pugi::xml_attribute& attribute) const;
    /// The material an element names in its 'material' attribute, else `fallback`, else the
    /// scene's default material (added when first needed).
    uint32_t material_of(Attributes& a, std::optional<uint32_t> fallback);
    /// ObjectFlag bits from the attributes no_shadow, no_reflection and no_image.
    static uint8_t object_flags(Attributes& a);

    // xml_transform.cpp: whether `child` is a transform element; if so, applies it after `t`.
    bool apply_transform(const pugi::xml_node& child, Affine& t) const;

    // xml_material.cpp
    void read_material(const pugi::xml_node& node);
    void read_texture(const pugi::xml_node& node);

    // xml_meshes.cpp
    uint32_t read_mesh(const pugi::xml_node& node, bool top_level);
    uint32_t read_subdivision(const pugi::xml_node& node, bool top_level);
    void read_object(const pugi::xml_node& node);

    // xml_shapes.cpp
    static bool is_shape(const pugi::xml_node& node);
    void read_shape_object(const pugi::xml_node& node);
    /// Appends the node (and its subtree) to `o`; `placement` is the transform of the CSG
    /// operations above it (inside the object), `material` the nearest one named above.
    void read_csg_node(const pugi::xml_node& node, ShapeObject& o, const Affine& placement,
                       std::optional<uint32_t> material, int depth, bool top_level);

    // xml_view.cpp
    void read_camera(const pugi::xml_node& node);
    void read_light(const pugi::xml_node& node);
    void read_background(const pugi::xml_node& node);
    void read_settings(const pugi::xml_node& node);

    const XmlContext& ctx_;
    Scene scene_;
    NameTable materials_, textures_, meshes_;
    std::optional<uint32_t> default_material_;
    bool camera_seen_ = false, background_seen_ = false;
};

} // namespace sheaf::io::xml

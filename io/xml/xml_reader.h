// The XML scene reader's state and its element handlers, shared by the files that implement
// them: xml_reader.cpp (the document, <scene>, names), xml_transform.cpp, xml_material.cpp
// (<material>, <texture>), xml_meshes.cpp (<mesh>, <subdivision>, <object>), xml_shapes.cpp
// (analytic shapes and CSG), xml_view.cpp (<camera>, <light>, <background>, <sky>, <fog>,
// <settings>), xml_patterns.cpp (the pattern attributes, placement and map entries that
// procedural textures share), xml_pigments.cpp (<pigment>, <normal>, <switch>).
#pragma once

#include "core/math/affine.h"
#include "core/scene/scene.h"
#include "io/font/font.h"
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
    FontCache fonts_; // <text>'s fonts

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

    // xml_patterns.cpp
    /// What a pattern is read for: only pigments may show an image.
    enum class PatternUse { Pigment, Normal, Switch };
    /// The kind named by the required 'pattern' attribute (PatternKind in lower case, and
    /// POV-Ray's aliases bumps and spotted for bozo).
    PatternKind pattern_kind(Attributes& a, PatternUse use) const;
    /// A pattern of `kind` from its attributes: turbulence, octaves, omega, lambda, frequency,
    /// phase, wave, wave_exponent and the kind's own (vector, arms, agate_turb, brick_size,
    /// mortar). An attribute of another kind is an error naming the kind it belongs to.
    Pattern read_pattern(Attributes& a, PatternKind kind) const;
    /// A mandel or julia pattern's attributes: iterations, exponent, magnet, c, interior,
    /// exterior (read_pattern has checked that no other pattern has them).
    void read_fractal(Attributes& a, PatternKind kind, FractalParams& f) const;
    void read_slope(Attributes& a, Pattern& pt) const;
    /// Sets pattern.to_pattern from the placement (pattern space -> world) the transform
    /// children gave; a singular placement is an error at `node`.
    void place_pattern(const pugi::xml_node& node, const Affine& placement, Pattern& pattern) const;
    /// How the <entry> elements of a pattern are told apart: by value (continuous patterns:
    /// values in [0, 1], none below the one before) or by position (list patterns, layers,
    /// averages: no values). `previous` carries the last value between calls.
    float entry_value(Attributes& e, const char* ordered_by, float& previous) const;
    /// Fails unless a list pattern has exactly the entries it picks from (checker 2 ...) and
    /// any other has at least one.
    void check_entry_count(const pugi::xml_node& node, PatternKind kind, size_t count) const;

    // xml_pigments.cpp
    void read_pigment(const pugi::xml_node& node);
    PigmentEntry read_pigment_entry(const pugi::xml_node& node, const char* ordered_by,
                                    float& previous);
    void read_normal(const pugi::xml_node& node);
    void read_switch(const pugi::xml_node& node);

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
    void read_sky(const pugi::xml_node& node);
    void read_fog(const pugi::xml_node& node);
    void read_settings(const pugi::xml_node& node);

    const XmlContext& ctx_;
    Scene scene_;
    NameTable materials_, textures_, meshes_, pigments_, normals_, switches_;
    std::optional<uint32_t> default_material_;
    bool camera_seen_ = false, background_seen_ = false, sky_seen_ = false, fog_seen_ = false;
};

} // namespace sheaf::io::xml

// The procedural textures (core/scene/pattern.h): <pigment> (a solid colour; a pattern whose
// <entry> elements are colours or earlier pigments; layers; an average; an image), <normal>
// (a pattern tilting the shading normal) and <switch> (a pattern choosing among materials).
// Each is named, and names only what was defined before it, so pigments refer to earlier
// pigments only, as Scene::validate requires.
#include "io/xml/xml_reader.h"

#include <cmath>

namespace sheaf::io::xml {
namespace {

const std::vector<std::string> kTransforms = {"translate", "rotate", "scale", "matrix"};

bool is_transform(const pugi::xml_node& n) {
    const std::string_view name = n.name();
    return name == "translate" || name == "rotate" || name == "scale" || name == "matrix";
}

/// 'filter' and 'transmit' (each in 0..1) into c[3] and c[4].
void read_filter_transmit(const XmlContext& ctx, Attributes& a, float c[5]) {
    for (int i : {3, 4}) {
        const char* name = i == 3 ? "filter" : "transmit";
        if (a.get(name, c[i]) && !(c[i] >= 0 && c[i] <= 1))
            ctx.fail(a.node(), a.node().attribute(name),
                     "attribute '" + std::string(name) + "' of " + tag(a.node()) +
                         ": expected a number in 0..1");
    }
}

/// 'color' (one or three numbers), 'filter' and 'transmit' into c[0..4].
void read_color5(const XmlContext& ctx, Attributes& a, float c[5]) {
    Vec3 rgb(c[0], c[1], c[2]);
    if (a.get("color", rgb, true)) c[0] = rgb.x, c[1] = rgb.y, c[2] = rgb.z;
    read_filter_transmit(ctx, a, c);
}

} // namespace

PigmentEntry SceneReader::read_pigment_entry(const pugi::xml_node& node, const char* ordered_by,
                                             float& previous) {
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    if (!children.empty()) unknown_element(ctx_, children[0], node, {});
    Attributes e(ctx_, node);
    PigmentEntry out;
    out.value = entry_value(e, ordered_by, previous);
    std::string pigment;
    const bool has_pigment = e.get("pigment", pigment);
    read_color5(ctx_, e, out.color);
    e.finish();
    const bool has_color = bool(node.attribute("color"));
    if (has_color && has_pigment)
        ctx_.fail(node, node.attribute("pigment"),
                  "an <entry> is a colour or a pigment; it has both 'color' and 'pigment'");
    if (!has_color && !has_pigment)
        ctx_.fail(node, "an <entry> of a <pigment> needs 'color' (with 'filter' and 'transmit' "
                        "if it lets light through) or 'pigment'");
    if (has_pigment) {
        for (const char* f : {"filter", "transmit"})
            if (node.attribute(f))
                ctx_.fail(node, node.attribute(f),
                          "attribute '" + std::string(f) +
                              "' goes with 'color'; a pigment brings its own filter and transmit");
        out.pigment =
            int32_t(lookup(pigments_, "pigment", pigment, node, node.attribute("pigment")));
    }
    return out;
}

void SceneReader::read_pigment(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    std::string name;
    a.get("name", name);
    bool layers = false, average = false;
    a.get("layers", layers);
    a.get("average", average);
    const bool patterned = bool(node.attribute("pattern"));
    if (int(patterned) + int(layers) + int(average) > 1)
        ctx_.fail(node, "a <pigment> has a pattern, layers=\"true\" or average=\"true\" (or none "
                        "of them: a solid colour); this one has more than one");
    const PatternKind kind =
        patterned ? pattern_kind(a, PatternUse::Pigment) : PatternKind::Gradient;
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    // Children where none belong: transforms get a word on what places what.
    auto no_children = [&](const std::string& transforms, const std::string& entries) {
        if (children.empty()) return;
        const pugi::xml_node& c = children[0];
        if (is_transform(c)) ctx_.fail(c, tag(c) + " in " + tag(node) + ": " + transforms);
        if (std::string_view(c.name()) == "entry")
            ctx_.fail(c, "<entry> in " + tag(node) + ": " + entries);
        unknown_element(ctx_, c, node, {});
    };

    Pigment pg;
    std::vector<PigmentEntry> entries;
    if (!patterned && !layers && !average) {
        read_color5(ctx_, a, pg.color);
        a.finish();
        a.require("name");
        if (!node.attribute("color"))
            ctx_.fail(node, "a solid <pigment> needs the attribute 'color' (or 'pattern', "
                            "layers=\"true\" or average=\"true\")");
        no_children("a solid colour has no pattern to place",
                    "a solid colour has no entries (give it a pattern)");
    } else if (kind == PatternKind::Image) {
        std::string texture;
        a.get("texture", texture);
        PigmentEntry tint; // the filter and transmit of every texel
        tint.color[0] = tint.color[1] = tint.color[2] = 1;
        read_filter_transmit(ctx_, a, tint.color);
        if (node.attribute("color"))
            ctx_.fail(node, node.attribute("color"),
                      "an image pigment's colours are the image's; it takes no 'color'");
        a.finish();
        a.require("name");
        a.require("texture");
        const uint32_t image =
            lookup(textures_, "texture", texture, node, node.attribute("texture"));
        no_children("an image pigment is placed by the transforms of its <texture>",
                    "an image pigment's colours are the image's");
        pg.solid = false;
        pg.pattern.kind = PatternKind::Image;
        pg.pattern.image = int32_t(image);
        pg.pattern.to_pattern = Affine(); // the texture's own transform places the image
        entries.push_back(tint);
    } else {
        if (patterned) pg.pattern = read_pattern(a, kind);
        a.finish();
        a.require("name");
        pg.solid = false;
        pg.layers = layers;
        pg.average = average;
        const std::string ordered_by = layers                  ? "a layered pigment"
                                       : average               ? "an average"
                                       : pattern_is_list(kind) ? "a list pattern"
                                                               : "";
        Affine placement; // pattern space -> world
        float previous = 0;
        for (const pugi::xml_node& c : children) {
            if (apply_transform(c, placement)) {
                if (!patterned)
                    ctx_.fail(c, tag(c) + " in " + tag(node) +
                                     ": layers and averages have no pattern to place; place the "
                                     "pigments of their entries");
                continue;
            }
            if (std::string_view(c.name()) != "entry") {
                std::vector<std::string> allowed = {"entry"};
                if (patterned)
                    allowed.insert(allowed.end(), kTransforms.begin(), kTransforms.end());
                unknown_element(ctx_, c, node, allowed);
            }
            entries.push_back(
                read_pigment_entry(c, ordered_by.empty() ? nullptr : ordered_by.c_str(), previous));
        }
        check_entry_count(node, kind, entries.size());
        if (patterned) place_pattern(node, placement, pg.pattern);
    }
    define(pigments_, "pigment", name, node, uint32_t(scene_.pigments.size()));
    pg.first = uint32_t(scene_.pigment_entries.size());
    pg.count = uint32_t(entries.size());
    scene_.pigment_entries.insert(scene_.pigment_entries.end(), entries.begin(), entries.end());
    scene_.pigments.push_back(pg);
}

void SceneReader::read_normal(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    std::string name;
    a.get("name", name);
    NormalPattern np;
    a.get("average", np.average);
    const bool patterned = bool(node.attribute("pattern"));
    if (np.average && patterned)
        ctx_.fail(node, node.attribute("pattern"),
                  "an average=\"true\" <normal> averages its entries; it has no pattern");
    const PatternKind kind =
        np.average ? PatternKind::Gradient : pattern_kind(a, PatternUse::Normal);
    if (!np.average) {
        np.pattern = read_pattern(a, kind);
        np.form = normal_form_of(node.attribute("pattern").value());
    }
    if (np.pattern.uv)
        ctx_.fail(node, node.attribute("mapping"),
                  "attribute 'mapping' of " + tag(node) +
                      ": normals are evaluated in space (mapping=\"uv\" is for <pigment> and "
                      "<switch>)");
    a.get("amount", np.amount);
    a.finish();
    a.require("name");
    // Entries: a slope map (height, slope), or a normal map (other normals), not both.
    Affine placement;
    std::vector<SlopeEntry> slopes;
    std::vector<NormalMapEntry> map;
    float previous = 0;
    for (const pugi::xml_node& c : child_elements(ctx_, node)) {
        if (apply_transform(c, placement)) {
            if (np.average)
                ctx_.fail(c,
                          tag(c) + " in " + tag(node) +
                              ": an average has no pattern to place; place its entries' normals");
            continue;
        }
        if (std::string_view(c.name()) != "entry") {
            std::vector<std::string> allowed = {"entry"};
            if (!np.average) allowed.insert(allowed.end(), kTransforms.begin(), kTransforms.end());
            unknown_element(ctx_, c, node, allowed);
        }
        Attributes e(ctx_, c);
        if (np.average || c.attribute("normal")) {
            if (!slopes.empty())
                ctx_.fail(c, "a <normal>'s entries are a slope map (height, slope) or a normal "
                             "map (normal), not both");
            NormalMapEntry m;
            if (np.average) {
                m.value = 1;
                e.get("weight", m.value);
                if (!std::isfinite(m.value))
                    ctx_.fail(c, c.attribute("weight"), "a weight must be finite");
            } else {
                m.value =
                    entry_value(e, pattern_is_list(kind) ? "a list pattern" : nullptr, previous);
            }
            std::string normal;
            e.get("normal", normal);
            e.finish();
            if (!c.attribute("normal"))
                ctx_.fail(c, "an <entry> of an average needs the attribute 'normal' (\"\": the "
                             "surface's own normal)");
            if (!normal.empty()) {
                const uint32_t n = lookup(normals_, "normal", normal, c, c.attribute("normal"));
                if (scene_.normal_patterns[n].map_count > 0)
                    ctx_.fail(c, c.attribute("normal"),
                              "normal '" + normal +
                                  "' has a normal map of its own; map entries "
                                  "name normals without maps");
                m.normal = int32_t(n);
            }
            map.push_back(m);
            continue;
        }
        if (!map.empty() || np.average)
            ctx_.fail(c, "a <normal>'s entries are a slope map (height, slope) or a normal map "
                         "(normal), not both");
        if (pattern_is_list(kind))
            ctx_.fail(c, "the " + std::string(node.attribute("pattern").value()) +
                             " pattern picks from a list; a slope map needs a continuous pattern");
        SlopeEntry sl;
        sl.value = entry_value(e, nullptr, previous);
        e.get("height", sl.height);
        e.get("slope", sl.slope);
        e.finish();
        slopes.push_back(sl);
    }
    if (slopes.size() > 256) ctx_.fail(node, "a slope map of more than 256 entries");
    if (map.size() > 256) ctx_.fail(node, "a normal map of more than 256 entries");
    if (np.average || (pattern_is_list(kind) && !map.empty()))
        check_entry_count(node, np.average ? PatternKind::Gradient : kind, map.size());
    float weights = 0;
    for (const NormalMapEntry& m : map) weights += m.value;
    if (np.average && !(weights != 0))
        ctx_.fail(node, "the weights of an average's entries sum to 0");
    if (!np.average) place_pattern(node, placement, np.pattern);
    np.slope_first = uint32_t(scene_.slope_entries.size());
    np.slope_count = uint32_t(slopes.size());
    scene_.slope_entries.insert(scene_.slope_entries.end(), slopes.begin(), slopes.end());
    np.map_first = uint32_t(scene_.normal_map_entries.size());
    np.map_count = uint32_t(map.size());
    scene_.normal_map_entries.insert(scene_.normal_map_entries.end(), map.begin(), map.end());
    define(normals_, "normal", name, node, uint32_t(scene_.normal_patterns.size()));
    scene_.normal_patterns.push_back(np);
}

void SceneReader::read_switch(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    std::string name;
    a.get("name", name);
    MaterialSwitch sw;
    const PatternKind kind = pattern_kind(a, PatternUse::Switch);
    sw.pattern = read_pattern(a, kind);
    a.finish();
    a.require("name");
    Affine placement;
    std::vector<MaterialEntry> entries;
    float previous = 0;
    for (const pugi::xml_node& c : child_elements(ctx_, node)) {
        if (apply_transform(c, placement)) continue;
        if (std::string_view(c.name()) != "entry") {
            std::vector<std::string> allowed = {"entry"};
            allowed.insert(allowed.end(), kTransforms.begin(), kTransforms.end());
            unknown_element(ctx_, c, node, allowed);
        }
        const std::vector<pugi::xml_node> inner = child_elements(ctx_, c);
        if (!inner.empty()) unknown_element(ctx_, inner[0], c, {});
        Attributes e(ctx_, c);
        MaterialEntry entry;
        entry.value = entry_value(e, pattern_is_list(kind) ? "a list pattern" : nullptr, previous);
        std::string material;
        e.get("material", material);
        e.finish();
        if (!c.attribute("material"))
            ctx_.fail(c, "an <entry> of a <switch> needs the attribute 'material'");
        entry.material = lookup(materials_, "material", material, c, c.attribute("material"));
        entries.push_back(entry);
    }
    check_entry_count(node, kind, entries.size());
    place_pattern(node, placement, sw.pattern);
    define(switches_, "switch", name, node, uint32_t(scene_.material_switches.size()));
    sw.first = uint32_t(scene_.material_entries.size());
    sw.count = uint32_t(entries.size());
    scene_.material_entries.insert(scene_.material_entries.end(), entries.begin(), entries.end());
    scene_.material_switches.push_back(sw);
}

} // namespace sheaf::io::xml

// Triangle meshes and subdivision surfaces: <mesh> (inline numbers or a mesh file),
// <subdivision> (a cage, inline or from a mesh file, refined by OpenSubdiv) and <object>, which
// places one of them with a material and transforms.
#include "io/xml/xml_reader.h"

#include "core/base/error.h"
#include "core/scene/scene.h"
#include "io/mesh/mesh_file.h"
#include "io/subdiv/subdivide.h"

namespace sheaf::io::xml {
namespace {

std::vector<Vec3> triples(const XmlContext& ctx, const pugi::xml_node& node) {
    const std::vector<float> v = element_floats(ctx, node);
    if (v.size() % 3 != 0)
        ctx.fail(node, tag(node) + " holds " + std::to_string(v.size()) +
                           " numbers; expected three per vertex");
    std::vector<Vec3> out(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    return out;
}

std::vector<float> pairs(const XmlContext& ctx, const pugi::xml_node& node) {
    std::vector<float> v = element_floats(ctx, node);
    if (v.size() % 2 != 0)
        ctx.fail(node, tag(node) + " holds " + std::to_string(v.size()) +
                           " numbers; expected two per vertex");
    return v;
}

/// Each element of `names` at most once among `children`.
void check_once(const XmlContext& ctx, const std::vector<pugi::xml_node>& children,
                std::initializer_list<const char*> names) {
    for (const char* name : names) {
        const pugi::xml_node* first = nullptr;
        for (const pugi::xml_node& c : children) {
            if (std::string_view(c.name()) != name) continue;
            if (first) ctx.fail(c, tag(c) + " is given twice");
            first = &c;
        }
    }
}

/// Reads a file through `read`, reporting its errors at the element that named it.
template <class Read>
auto read_file(const XmlContext& ctx, const pugi::xml_node& node, const std::string& file,
               Read&& read) {
    try {
        return read(ctx.resolve(file));
    } catch (const SceneError& e) {
        ctx.fail(node, node.attribute("file"), e.what());
    }
}

std::string label(const pugi::xml_node& node, const std::string& name) {
    return tag(node) + (name.empty() ? std::string() : " '" + name + "'");
}

} // namespace

uint32_t SceneReader::read_mesh(const pugi::xml_node& node, bool top_level) {
    Attributes a(ctx_, node);
    std::string name, file;
    if (top_level) a.get("name", name);
    const bool from_file = a.get("file", file);
    a.finish();
    if (top_level) a.require("name");
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    Mesh mesh;
    if (from_file) {
        if (!children.empty())
            ctx_.fail(children[0],
                      "a <mesh> read from a file holds no elements; found " + tag(children[0]));
        mesh = read_file(ctx_, node, file, [](const std::string& p) { return read_mesh_file(p); });
    } else {
        check_once(ctx_, children, {"positions", "normals", "uvs", "triangles"});
        bool has_positions = false;
        for (const pugi::xml_node& c : children) {
            const std::string_view n = c.name();
            if (n == "positions")
                mesh.positions = triples(ctx_, c), has_positions = true;
            else if (n == "normals")
                mesh.normals = triples(ctx_, c);
            else if (n == "uvs")
                mesh.uvs = pairs(ctx_, c);
            else if (n == "triangles")
                mesh.indices = element_indices(ctx_, c);
            else
                unknown_element(ctx_, c, node, {"positions", "normals", "uvs", "triangles"});
        }
        if (!has_positions)
            ctx_.fail(node, "a <mesh> needs a file attribute or a <positions> element");
        try {
            validate_mesh(mesh, label(node, name));
        } catch (const SceneError& e) {
            ctx_.fail(node, e.what());
        }
    }
    const uint32_t id = scene_.add_mesh(std::move(mesh));
    if (top_level) define(meshes_, "mesh", name, node, id);
    return id;
}

uint32_t SceneReader::read_subdivision(const pugi::xml_node& node, bool top_level) {
    Attributes a(ctx_, node);
    std::string name, file;
    int scheme = 0, boundary = 0;
    SubdivOptions options;
    if (top_level) a.get("name", name);
    const bool from_file = a.get("file", file);
    a.get("scheme", scheme, {"catmull-clark", "loop"});
    a.get("level", options.level, 0, kMaxSubdivLevel);
    a.get("boundary", boundary, {"edge-only", "edge-and-corner", "none"});
    a.get("limit", options.limit);
    a.finish();
    if (top_level) a.require("name");
    options.scheme = scheme == 1 ? SubdivScheme::Loop : SubdivScheme::CatmullClark;
    constexpr SubdivBoundary kBoundaries[] = {SubdivBoundary::EdgeOnly,
                                              SubdivBoundary::EdgeAndCorner, SubdivBoundary::None};
    options.boundary = kBoundaries[boundary];

    SubdivCage cage;
    if (from_file) {
        PolygonCage c =
            read_file(ctx_, node, file, [](const std::string& p) { return read_polygon_cage(p); });
        cage.positions = std::move(c.positions);
        cage.face_sizes = std::move(c.face_sizes);
        cage.face_indices = std::move(c.face_indices);
    }
    const std::vector<pugi::xml_node> children = child_elements(ctx_, node);
    check_once(ctx_, children, {"positions", "face_sizes", "face_indices", "uvs"});
    bool has_positions = false, has_sizes = false, has_indices = false;
    for (const pugi::xml_node& c : children) {
        const std::string_view n = c.name();
        const bool cage_part = n == "positions" || n == "face_sizes" || n == "face_indices";
        if (cage_part && from_file)
            ctx_.fail(c, "a <subdivision> read from a file takes its cage from the file; " +
                             tag(c) + " is not allowed with it");
        if (n == "positions") {
            cage.positions = triples(ctx_, c), has_positions = true;
        } else if (n == "face_sizes") {
            cage.face_sizes = element_indices(ctx_, c), has_sizes = true;
        } else if (n == "face_indices") {
            cage.face_indices = element_indices(ctx_, c), has_indices = true;
        } else if (n == "uvs") {
            cage.uvs = pairs(ctx_, c);
        } else if (n == "crease") {
            Attributes ca(ctx_, c);
            std::vector<float> edge;
            float sharpness = 10.0f;
            ca.get_numbers("edge", edge);
            ca.get("sharpness", sharpness);
            ca.finish();
            ca.require("edge");
            if (!child_elements(ctx_, c).empty())
                unknown_element(ctx_, child_elements(ctx_, c)[0], c, {});
            const pugi::xml_attribute e = c.attribute("edge");
            if (edge.size() != 2 || edge[0] < 0 || edge[1] < 0 || edge[0] != std::floor(edge[0]) ||
                edge[1] != std::floor(edge[1]) || edge[0] > 4e9f || edge[1] > 4e9f)
                ctx_.fail(c, e, "a crease's edge is two vertex indices");
            if (!(sharpness >= 0))
                ctx_.fail(c, c.attribute("sharpness"), "a crease's sharpness must be >= 0");
            cage.crease_edges.insert(cage.crease_edges.end(),
                                     {uint32_t(edge[0]), uint32_t(edge[1])});
            cage.crease_sharpness.push_back(sharpness);
        } else {
            unknown_element(ctx_, c, node,
                            {"positions", "face_sizes", "face_indices", "uvs", "crease"});
        }
    }
    if (!from_file && !(has_positions && has_sizes && has_indices))
        ctx_.fail(node, "a <subdivision> needs a file attribute or <positions>, <face_sizes> and "
                        "<face_indices> elements");
    Mesh mesh;
    try {
        mesh = subdivide(cage, options, label(node, name));
    } catch (const SceneError& e) {
        ctx_.fail(node, e.what());
    }
    const uint32_t id = scene_.add_mesh(std::move(mesh));
    if (top_level) define(meshes_, "mesh", name, node, id);
    return id;
}

void SceneReader::read_object(const pugi::xml_node& node) {
    Attributes a(ctx_, node);
    Object o;
    std::string mesh;
    a.get("name", o.name);
    const bool named_mesh = a.get("mesh", mesh);
    o.material = material_of(a, std::nullopt);
    o.flags = object_flags(a);
    a.finish();
    bool has_mesh = false;
    if (named_mesh) {
        o.mesh = lookup(meshes_, "mesh", mesh, node, node.attribute("mesh"));
        has_mesh = true;
    }
    for (const pugi::xml_node& c : child_elements(ctx_, node)) {
        if (apply_transform(c, o.transform)) continue;
        const std::string_view n = c.name();
        if (n != "mesh" && n != "subdivision")
            unknown_element(ctx_, c, node,
                            {"mesh", "subdivision", "translate", "rotate", "scale", "matrix"});
        if (has_mesh)
            ctx_.fail(c, "an <object> places one mesh; it has one already" +
                             std::string(named_mesh ? " (its mesh attribute)" : ""));
        o.mesh = n == "mesh" ? read_mesh(c, false) : read_subdivision(c, false);
        has_mesh = true;
    }
    if (!has_mesh)
        ctx_.fail(node, "an <object> needs a mesh: a mesh attribute naming one, or a <mesh> or "
                        "<subdivision> element");
    scene_.add_object(std::move(o));
}

} // namespace sheaf::io::xml

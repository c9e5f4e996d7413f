// Analytic shapes and CSG: <sphere>, <box>, <cylinder>, <cone>, <disc>, <plane>, <torus>, <poly>,
// <superellipsoid>, <julia>, <text>, <lathe>, <sor> and <union>, <merge>, <intersection>,
// <difference> over them. The geometric attributes (centre, radius, base and cap, ...) become the
// transform from the core's canonical shape (core/geometry/shape.h); transform elements then place
// the node. A <text> is a union of glyph shapes, one per character with ink, laid out by io/font.
#include "io/xml/xml_reader.h"

#include "core/geometry/blob_build.h"
#include "core/geometry/revolution_profile.h"

#include <cmath>

namespace sheaf::io::xml {
namespace {

constexpr int kMaxCsgDepth = kMaxCsgNesting;

const std::vector<std::string> kShapeElements = {
    "sphere", "box",   "cylinder",       "cone",  "disc",         "plane",
    "torus",  "poly",  "superellipsoid", "text",  "lathe",        "sor",
    "blob",   "julia", "union",          "merge", "intersection", "difference"};

/// The transform taking local z from `base` to `cap`, with local x and y scaled by `radius`.
Affine axis_frame(Vec3 base, Vec3 cap, float radius) {
    const Vec3 w = cap - base;
    const Vec3 axis = normalize(w);
    const Vec3 helper = std::fabs(axis.x) < 0.6f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 e1 = normalize(cross(helper, axis));
    const Vec3 e2 = cross(axis, e1);
    Affine a;
    for (int r = 0; r < 3; ++r) {
        a.m[r][0] = e1[r] * radius;
        a.m[r][1] = e2[r] * radius;
        a.m[r][2] = w[r];
        a.m[r][3] = base[r];
    }
    return a;
}

} // namespace

bool SceneReader::is_shape(const pugi::xml_node& node) {
    const std::string_view n = node.name();
    for (const std::string& s : kShapeElements)
        if (n == s) return true;
    return false;
}

void SceneReader::read_shape_object(const pugi::xml_node& node) {
    ShapeObject o;
    read_csg_node(node, o, Affine{}, std::nullopt, 0, true);
    scene_.add_shape_object(std::move(o));
}

void SceneReader::read_csg_node(const pugi::xml_node& node, ShapeObject& o, const Affine& placement,
                                std::optional<uint32_t> material, int depth, bool top_level) {
    if (depth > kMaxCsgDepth)
        ctx_.fail(node, "CSG nested deeper than " + std::to_string(kMaxCsgDepth) + " levels");
    const std::string_view kind = node.name();
    Attributes a(ctx_, node);
    if (top_level) {
        a.get("name", o.name);
        o.flags = object_flags(a);
    }
    CsgNode n;
    a.get("inverse", n.inverse);
    const uint32_t index = uint32_t(o.nodes.size());

    // Transform elements of this node; for an operation, its other children are its operands.
    Affine own;
    std::vector<pugi::xml_node> operands;
    const bool leaf =
        !(kind == "union" || kind == "merge" || kind == "intersection" || kind == "difference");
    auto read_children = [&] {
        for (const pugi::xml_node& c : child_elements(ctx_, node)) {
            if (apply_transform(c, own)) continue;
            if (leaf) unknown_element(ctx_, c, node, {"translate", "rotate", "scale", "matrix"});
            if (!is_shape(c)) {
                std::vector<std::string> allowed = kShapeElements;
                allowed.insert(allowed.end(), {"translate", "rotate", "scale", "matrix"});
                unknown_element(ctx_, c, node, allowed);
            }
            operands.push_back(c);
        }
    };

    if (leaf) {
        Affine frame;
        Shape& s = n.shape;
        std::vector<PlacedGlyph> glyphs; // <text>
        auto fail_attr = [&](const char* attr, const std::string& why) {
            ctx_.fail(node, node.attribute(attr), tag(node) + ": " + why);
        };
        if (kind == "sphere") {
            Vec3 centre;
            float radius = 1;
            a.get("center", centre);
            a.get("radius", radius);
            if (!(radius > 0)) fail_attr("radius", "the radius must be > 0");
            s.kind = ShapeKind::Sphere;
            frame = Affine::translate(centre) * Affine::scale(Vec3(radius));
        } else if (kind == "box") {
            Vec3 lo(-1), hi(1);
            a.get("min", lo);
            a.get("max", hi);
            if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
                fail_attr("max", "max must be greater than min in x, y and z");
            s.kind = ShapeKind::Box;
            frame = Affine::translate((lo + hi) * 0.5f) * Affine::scale((hi - lo) * 0.5f);
        } else if (kind == "cylinder" || kind == "cone") {
            Vec3 base(0, 0, 0), cap(0, 1, 0);
            a.get("base", base);
            a.get("cap", cap);
            a.get("open", s.open);
            if (!(length(cap - base) > 0)) fail_attr("cap", "base and cap must differ");
            if (kind == "cylinder") {
                float radius = 1;
                a.get("radius", radius);
                if (!(radius > 0)) fail_attr("radius", "the radius must be > 0");
                s.kind = ShapeKind::Cylinder;
                frame = axis_frame(base, cap, radius);
            } else {
                float r0 = 1, r1 = 0;
                a.get("base_radius", r0);
                a.get("cap_radius", r1);
                if (!(r0 >= 0 && r1 >= 0 && (r0 > 0 || r1 > 0)))
                    fail_attr("base_radius", "the radii must be >= 0 and not both 0");
                s.kind = ShapeKind::Cone, s.a = r0, s.b = r1;
                frame = axis_frame(base, cap, 1.0f);
            }
        } else if (kind == "disc") {
            Vec3 centre, normal(0, 1, 0);
            float radius = 1, hole = 0;
            a.get("center", centre);
            a.get("normal", normal);
            a.get("radius", radius);
            a.get("hole", hole);
            if (!(length(normal) > 0)) fail_attr("normal", "the normal must not be zero");
            if (!(radius > 0)) fail_attr("radius", "the radius must be > 0");
            if (!(hole >= 0 && hole <= radius))
                fail_attr("hole", "the hole's radius must lie in 0..radius");
            s.kind = ShapeKind::Disc, s.a = hole / radius;
            frame = axis_frame(centre, centre + normalize(normal), radius);
        } else if (kind == "plane") {
            Vec3 normal(0, 1, 0);
            float offset = 0;
            a.get("normal", normal);
            a.get("offset", offset);
            if (!(length(normal) > 0)) fail_attr("normal", "the normal must not be zero");
            const Vec3 u = normalize(normal);
            s.kind = ShapeKind::Plane;
            frame = axis_frame(u * offset, u * (offset + 1), 1.0f);
        } else if (kind == "superellipsoid") {
            float e = 1, en = 1;
            a.get("e", e);
            a.get("n", en);
            if (!(e >= 1e-3f)) fail_attr("e", "the exponent e must be at least 0.001");
            if (!(en >= 1e-3f)) fail_attr("n", "the exponent n must be at least 0.001");
            s.kind = ShapeKind::Superellipsoid, s.a = e, s.b = en;
        } else if (kind == "julia") {
            // POV-Ray's julia_fractal (core/geometry/julia.h): c and the slice as four numbers.
            auto j = std::make_shared<JuliaFractal>();
            auto four = [&](const char* attr, double* out) {
                std::vector<float> v;
                a.get_numbers(attr, v);
                if (v.empty()) return;
                if (v.size() != 4) fail_attr(attr, "four numbers are needed: x y z w");
                for (int i = 0; i < 4; ++i) out[i] = v[size_t(i)];
            };
            a.require("c");
            four("c", j->c);
            four("slice", j->slice);
            double len = 0;
            for (double v : j->slice) len += v * v;
            len = std::sqrt(len);
            if (!(std::fabs(j->slice[3]) >= 1e-10 && len < 1e30))
                fail_attr("slice", "the slice's w component must not be zero");
            for (double& v : j->slice) v /= len;
            float dist = 0, precision = 20;
            a.get("slice_distance", dist);
            j->slice_dist = dist;
            int algebra = 0, function = 0, iterations = 20;
            a.get("algebra", algebra, {"quaternion", "hypercomplex"});
            a.get("function", function, {"sqr", "cube"});
            a.get("iterations", iterations, 1, int(kJuliaMaxIterations));
            a.get("precision", precision);
            if (!(precision >= 1) || !std::isfinite(precision))
                fail_attr("precision", "the precision must be a number of at least 1");
            j->iterations = uint32_t(iterations);
            j->min_step = 1.0 / precision;
            j->algebra = algebra == 1    ? JuliaAlgebra::HypercomplexSqr
                         : function == 1 ? JuliaAlgebra::QuaternionCube
                                         : JuliaAlgebra::QuaternionSqr;
            s.kind = ShapeKind::Julia;
            n.julia = std::move(j);
        } else if (kind == "poly") {
            int order = 2;
            a.get("order", order, 2, kPolyMaxDegree);
            std::vector<float> c;
            a.require("coefficients");
            a.get_numbers("coefficients", c);
            const size_t count = poly_coefficient_count(order);
            if (c.size() != count)
                fail_attr("coefficients", "order " + std::to_string(order) + " needs " +
                                              std::to_string(count) + " coefficients, not " +
                                              std::to_string(c.size()));
            auto poly = std::make_shared<PolyCoeffs>(poly_from_pov_order(order, c.data()));
            if (poly_is_zero(*poly)) fail_attr("coefficients", "every coefficient is zero");
            s.kind = ShapeKind::Poly;
            n.poly = std::move(poly);
        } else if (kind == "lathe" || kind == "sor") {
            // The profile's points "r h r h ...", turned about y (the shape's z).
            std::vector<float> v;
            a.require("points");
            a.get_numbers("points", v);
            if (v.size() % 2 != 0)
                fail_attr("points", "the points are pairs of numbers (radius, height)");
            std::vector<Vec3> p;
            for (size_t i = 0; i + 1 < v.size(); i += 2) p.push_back(Vec3(v[i], v[i + 1], 0));
            try {
                if (kind == "lathe") {
                    int spline = 0;
                    a.get("spline", spline, {"linear", "quadratic", "cubic", "bezier"});
                    bool solid = false;
                    n.revolution = std::make_shared<RevolutionProfile>(
                        lathe_profile(p, LatheSpline(spline), solid));
                    s.open = !solid;
                } else {
                    a.get("open", s.open);
                    n.revolution = std::make_shared<RevolutionProfile>(sor_profile(p, s.open));
                }
            } catch (const ProfileError& e) {
                fail_attr("points", e.what());
            }
            s.kind = ShapeKind::Revolution;
            frame.m[1][1] = 0, frame.m[2][2] = 0, frame.m[1][2] = 1, frame.m[2][1] = 1;
        } else if (kind == "blob") {
            // Components as numbers: spheres "x y z radius strength ...", cylinders
            // "x0 y0 z0 x1 y1 z1 radius strength ...".
            auto blob = std::make_shared<BlobModel>();
            a.get("threshold", blob->threshold);
            if (!(blob->threshold > 0) || !std::isfinite(blob->threshold))
                fail_attr("threshold", "the threshold must be a positive number");
            std::vector<float> sp, cy;
            a.get_numbers("spheres", sp);
            a.get_numbers("cylinders", cy);
            if (sp.size() % 5 != 0)
                fail_attr("spheres", "each sphere is 5 numbers: x y z radius strength");
            if (cy.size() % 8 != 0)
                fail_attr("cylinders",
                          "each cylinder is 8 numbers: x0 y0 z0 x1 y1 z1 radius strength");
            if (sp.empty() && cy.empty())
                fail_attr("spheres", "a blob needs at least one sphere or cylinder");
            const char* at = "spheres";
            try {
                for (size_t i = 0; i < sp.size(); i += 5)
                    add_blob_sphere(*blob, Vec3(sp[i], sp[i + 1], sp[i + 2]), sp[i + 3], sp[i + 4],
                                    Affine());
                at = "cylinders";
                for (size_t i = 0; i < cy.size(); i += 8)
                    add_blob_cylinder(*blob, Vec3(cy[i], cy[i + 1], cy[i + 2]),
                                      Vec3(cy[i + 3], cy[i + 4], cy[i + 5]), cy[i + 6], cy[i + 7],
                                      Affine());
            } catch (const BlobError& e) {
                fail_attr(at, e.what());
            }
            s.kind = ShapeKind::Blob;
            n.blob = std::move(blob);
        } else if (kind == "text") {
            std::string font_name, text;
            float thickness = 1;
            Vec3 offset(0);
            a.require("font");
            a.require("string");
            a.get("font", font_name);
            a.get("string", text);
            a.get("thickness", thickness);
            a.get("offset", offset);
            if (!(std::isfinite(thickness) && thickness != 0))
                fail_attr("thickness", "the thickness must be a finite number other than 0");
            const std::string path = ctx_.resolve(font_name);
            try {
                glyphs = layout_text(fonts_.open(path), text, offset);
            } catch (const FontError& e) {
                fail_attr("font", e.what());
            }
            if (glyphs.empty()) fail_attr("string", "the text has no visible character");
            frame = Affine::scale(Vec3(1, 1, thickness));
        } else { // torus
            Vec3 centre;
            float major = 1, minor = 0.25f;
            a.get("center", centre);
            a.get("major", major);
            a.get("minor", minor);
            if (!(major > 0)) fail_attr("major", "the major radius must be > 0");
            if (!(minor > 0)) fail_attr("minor", "the minor radius must be > 0");
            s.kind = ShapeKind::Torus, s.a = minor / major;
            // The core's torus lies around z; this one lies in the xz plane, around y.
            frame = Affine::translate(centre) * Affine::rotate(Vec3(1, 0, 0), -0.5f * float(M_PI)) *
                    Affine::scale(Vec3(major));
        }
        n.material = material_of(a, material);
        a.finish();
        read_children();
        if (top_level) o.transform = own;
        const Affine place = top_level ? Affine{} : placement * own;
        if (kind == "text") { // a union of its glyphs
            n.op = CsgOp::Union;
            o.nodes.push_back(n);
            for (const PlacedGlyph& g : glyphs) {
                CsgNode leaf_node;
                leaf_node.op = CsgOp::Leaf;
                leaf_node.shape.kind = ShapeKind::Glyph;
                leaf_node.glyph = g.outline;
                leaf_node.material = n.material;
                leaf_node.transform = place * Affine::translate(g.position) * frame;
                o.nodes[index].children.push_back(uint32_t(o.nodes.size()));
                o.nodes.push_back(std::move(leaf_node));
            }
            return;
        }
        n.op = CsgOp::Leaf;
        n.transform = place * frame;
        o.nodes.push_back(n);
        return;
    }

    std::optional<uint32_t> inner = material;
    std::string mname;
    if (a.get("material", mname))
        inner = lookup(materials_, "material", mname, node, node.attribute("material"));
    a.finish();
    read_children();
    const size_t needed = (kind == "difference" || kind == "intersection") ? 2 : 1;
    if (operands.size() < needed)
        ctx_.fail(node, tag(node) + " needs at least " + std::to_string(needed) +
                            (needed == 1 ? " shape" : " shapes") + "; it has " +
                            std::to_string(operands.size()));
    n.op = kind == "union"          ? CsgOp::Union
           : kind == "merge"        ? CsgOp::Merge
           : kind == "intersection" ? CsgOp::Intersection
                                    : CsgOp::Difference;
    o.nodes.push_back(n);
    const Affine inner_placement = top_level ? Affine{} : placement * own;
    if (top_level) o.transform = own;
    for (const pugi::xml_node& c : operands) {
        const uint32_t child = uint32_t(o.nodes.size());
        o.nodes[index].children.push_back(child);
        read_csg_node(c, o, inner_placement, inner, depth + 1, false);
    }
}

} // namespace sheaf::io::xml

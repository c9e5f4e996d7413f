// Objects: the analytic shapes (sphere, box, cylinder, cone, disc, plane, torus) placed on
// their canonical forms (core/geometry/shape.h), CSG, object references, the modifiers and
// transforms. Transforms are applied to the object as they are read, in POV-Ray's own
// coordinates; rotations follow POV-Ray (x, then y, then z, degrees).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>
#include <set>

namespace sheaf::io::pov {

/// Sets `hollow` on o and on its members, as POV-Ray's `hollow` on a CSG does.
void set_hollow(PovObject& o, bool hollow);

namespace {

const std::set<std::string>& supported_objects() {
    static const std::set<std::string> s = {"sphere",       "box",           "cylinder",
                                            "cone",         "disc",          "plane",
                                            "torus",        "triangle",      "smooth_triangle",
                                            "mesh",         "mesh2",         "polygon",
                                            "union",        "merge",         "intersection",
                                            "difference",   "object",        "light_source",
                                            "light_group",  "quadric",       "cubic",
                                            "quartic",      "poly",          "superellipsoid",
                                            "text",         "prism",         "lathe",
                                            "sor",          "blob",          "isosurface",
                                            "height_field", "bicubic_patch", "julia_fractal",
                                            "sphere_sweep"};
    return s;
}

const std::set<std::string>& unsupported_objects() {
    static const std::set<std::string> s = {"parametric", "polynomial", "ovus", "lemon"};
    return s;
}

} // namespace

Affine frame(Vec3 o, Vec3 c0, Vec3 c1, Vec3 c2) {
    Affine a;
    for (int i = 0; i < 3; ++i)
        a.m[i][0] = c0[i], a.m[i][1] = c1[i], a.m[i][2] = c2[i], a.m[i][3] = o[i];
    return a;
}

void basis(Vec3 w, Vec3& u, Vec3& v) {
    const Vec3 a = std::fabs(w.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    u = normalize(cross(a, w));
    v = cross(w, u);
}

bool Parser::is_object_start(const Token& t) const {
    return t.kind == TokKind::Ident &&
           (supported_objects().count(t.text) || unsupported_objects().count(t.text));
}

size_t Parser::object_bytes(const PovObject& o) {
    size_t bytes = sizeof(PovObject);
    if (o.poly && o.poly.use_count() == 1) bytes += sizeof(PolyCoeffs);
    if (o.texture && o.texture.use_count() == 1) // its own texture, not a shared declaration
        bytes += sizeof(PovTexture) + (o.texture->pigment ? sizeof(PovPigment) : 0) +
                 (o.texture->normal ? sizeof(PovNormal) : 0);
    return bytes;
}

bool Parser::parse_object(PovObject& o) {
    const Token kw = next();
    const Nest nest(*this, kw);
    o = PovObject();
    o.where = kw;
    count_objects(kw);
    const std::string& k = kw.text;
    if (unsupported_objects().count(k)) {
        unsupported(kw, "object '" + k + "'");
        skip_block();
        return false;
    }
    if (k == "light_group") {
        parse_csg(kw, o);
        o.op = CsgOp::Union;
        o.light_group = true;
        return true;
    }
    if (k == "union" || k == "merge" || k == "intersection" || k == "difference") {
        parse_csg(kw, o);
        return true;
    }
    if (k == "object") return parse_object_block(o);
    if (k == "triangle" || k == "smooth_triangle") {
        parse_triangle(kw, o, k == "smooth_triangle");
        return true;
    }
    if (k == "mesh") {
        parse_mesh(kw, o);
        return true;
    }
    if (k == "mesh2") {
        parse_mesh2(kw, o);
        return true;
    }
    if (k == "polygon") {
        parse_polygon(kw, o);
        return true;
    }
    if (k == "light_source") {
        parse_light(kw, o);
        return true;
    }
    if (k == "quadric" || k == "cubic" || k == "quartic" || k == "poly") return parse_poly(kw, o);
    if (k == "prism") return parse_prism(kw, o);
    if (k == "lathe") return parse_lathe(kw, o);
    if (k == "sor") return parse_sor(kw, o);
    if (k == "blob") return parse_blob(kw, o);
    if (k == "isosurface") return parse_isosurface(kw, o);
    if (k == "julia_fractal") return parse_julia_fractal(kw, o);
    if (k == "height_field") return parse_height_field(kw, o);
    if (k == "bicubic_patch") return parse_bicubic_patch(kw, o);
    if (k == "sphere_sweep") return parse_sphere_sweep(kw, o);
    if (k == "text") {
        parse_text(kw, o);
        return true;
    }
    parse_shape(kw, o);
    return true;
}

bool Parser::parse_object_block(PovObject& o) {
    expect_sym("{");
    const Token& t = peek();
    bool ok = true;
    Value declared;
    if (accept_declared_any(declared)) {
        if (declared.type == VType::Other && declared.str == "object")
            ok = false; // an unsupported object, warned where it was declared
        else if (declared.type == VType::Object)
            o = declared.as<PovObject>();
        else
            error_expected(t, std::string("an object, not ") + type_name(declared.type));
    } else if (is_object_start(t)) {
        ok = parse_object(o);
    } else {
        error_expected(t, "an object identifier or an object");
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return ok;
}

void Parser::parse_shape(const Token& kw, PovObject& o) {
    const std::string& k = kw.text;
    o.kind = PovKind::Shape;
    expect_sym("{");
    if (k == "sphere") {
        const Vec3 c = parse_vector();
        accept_sym(",");
        const float r = float(parse_float());
        o.shape.kind = ShapeKind::Sphere;
        o.local = Affine::translate(c) * Affine::scale(Vec3(r));
    } else if (k == "box") {
        const Vec3 a = parse_vector();
        accept_sym(",");
        const Vec3 b = parse_vector();
        o.shape.kind = ShapeKind::Box;
        Vec3 h = (b - a) * 0.5f;
        for (int i = 0; i < 3; ++i) h[i] = std::max(std::fabs(h[i]), 1e-6f);
        o.local = Affine::translate((a + b) * 0.5f) * Affine::scale(h);
    } else if (k == "cylinder" || k == "cone") {
        const Vec3 base = parse_vector();
        accept_sym(",");
        float r0 = 0;
        if (k == "cone") {
            r0 = float(parse_float());
            accept_sym(",");
        }
        const Vec3 cap = parse_vector();
        accept_sym(",");
        const float r1 = float(parse_float());
        const Vec3 axis = cap - base;
        if (length(axis) <= 0) { // POV-Ray stops here; left out, so the rest still loads
            unsupported(kw, "degenerate " + k + " (its base and cap are the same point; left out)");
            o.kind = PovKind::Csg, o.op = CsgOp::Union;
            bool texture_here = false;
            parse_object_modifiers(o, texture_here);
            return;
        }
        Vec3 u, v;
        basis(normalize(axis), u, v);
        if (k == "cylinder") {
            o.shape.kind = ShapeKind::Cylinder;
            o.local = frame(base, u * r1, v * r1, axis);
        } else {
            o.shape.kind = ShapeKind::Cone;
            o.shape.a = std::fabs(r0), o.shape.b = std::fabs(r1);
            o.local = frame(base, u, v, axis);
        }
    } else if (k == "disc") {
        const Vec3 c = parse_vector();
        accept_sym(",");
        const Vec3 n = parse_vector();
        accept_sym(",");
        const float r = float(parse_float());
        float hole = 0;
        if (accept_sym(",")) hole = float(parse_float());
        if (length(n) <= 0 || r <= 0) error_at(kw, "degenerate disc (zero normal or radius)");
        Vec3 u, v;
        const Vec3 w = normalize(n);
        basis(w, u, v);
        o.shape.kind = ShapeKind::Disc;
        o.shape.a = std::clamp(hole / r, 0.0f, 1.0f);
        o.local = frame(c, u * r, v * r, w);
    } else if (k == "plane") {
        const Vec3 n = parse_vector();
        accept_sym(",");
        const float d = float(parse_float());
        if (length(n) <= 0) error_at(kw, "degenerate plane (zero normal)");
        Vec3 u, v;
        const Vec3 w = normalize(n);
        basis(w, u, v);
        o.shape.kind = ShapeKind::Plane;
        o.local = frame(w * d, u, v, w);
    } else if (k == "superellipsoid") {
        const Token& at = peek();
        const Vec3 v = parse_vector(); // <e, n>
        if (!(v.x > 0 && v.y > 0))
            error_at(at, "a superellipsoid's exponents <e, n> must be greater than 0");
        o.shape.kind = ShapeKind::Superellipsoid;
        o.shape.a = std::max(v.x, 1e-3f), o.shape.b = std::max(v.y, 1e-3f);
        o.local = Affine(); // [-1, 1]^3, n along z: POV-Ray's own frame
    } else if (k == "torus") {
        const float R = float(parse_float());
        accept_sym(",");
        const float r = float(parse_float());
        if (R <= 0) error_at(kw, "a torus needs a positive major radius");
        o.shape.kind = ShapeKind::Torus;
        o.shape.a = r / R;
        // Canonical torus around z; POV-Ray's lies around y.
        o.local = frame({0, 0, 0}, {R, 0, 0}, {0, 0, -R}, {0, R, 0});
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
}

void Parser::parse_csg(const Token& kw, PovObject& o) {
    const std::string& k = kw.text;
    o.kind = PovKind::Csg;
    o.op = k == "union"          ? CsgOp::Union
           : k == "merge"        ? CsgOp::Merge
           : k == "intersection" ? CsgOp::Intersection
                                 : CsgOp::Difference;
    expect_sym("{");
    bool texture_here = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (is_object_start(t)) {
            PovObject child;
            if (parse_object(child)) {
                // A CSG keeps its objects until it is placed or dropped: charged as taken, so
                // that an endless loop inside a union ends at the data budget (it reached 8.7
                // GB at the object limit when each object had a texture of its own).
                charge(object_bytes(child), t);
                o.children.push_back(std::move(child));
            }
            continue;
        }
        if (!parse_modifier(o, texture_here)) error_expected(t, "an object, a modifier or '}'");
    }
}

void Parser::parse_object_modifiers(PovObject& o, bool& texture_here) {
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (!parse_modifier(o, texture_here)) error_expected(t, "an object modifier or '}'");
    }
}

bool Parser::parse_modifier(PovObject& o, bool& texture_here) {
    Affine m;
    if (parse_transform_item(m)) {
        apply_transform(o, m);
        return true;
    }
    const Token& t = peek();
    if (t.kind != TokKind::Ident) return false;
    const std::string& k = t.text;
    // Pigments, normals and finishes given after a texture change that texture, in its space.
    auto current = [&]() { return o.texture ? *o.texture : model.default_texture; };
    // The object's texture from now on (uv-mapped after the object's uv_mapping).
    auto set_texture = [&](PovTextureRef t) { o.texture = o.uv_mapping ? uv_mapped(t) : t; };
    if (k == "texture") {
        advance();
        PovTextureRef tex = parse_texture_layers(model.default_texture);
        if (texture_here && o.texture) { // another texture in the same block: a layer on top
            auto layered = std::make_shared<PovTexture>(*tex);
            std::vector<PovTextureRef> below = o.texture->below;
            auto lower = std::make_shared<PovTexture>(*o.texture);
            lower->below.clear();
            below.push_back(lower);
            below.insert(below.end(), tex->below.begin(), tex->below.end());
            layered->below = std::move(below);
            tex = layered;
        }
        set_texture(tex);
        texture_here = true;
    } else if (k == "pigment") {
        advance();
        PovTexture tex = current();
        tex.pigment = parse_pigment(tex.pigment ? *tex.pigment : PovPigment{});
        set_texture(std::make_shared<const PovTexture>(std::move(tex)));
    } else if (k == "normal") {
        advance();
        PovTexture tex = current();
        tex.normal = parse_normal(tex.normal.get());
        set_texture(std::make_shared<const PovTexture>(std::move(tex)));
    } else if (k == "finish") {
        advance();
        PovTexture tex = current();
        parse_finish(tex.finish);
        set_texture(std::make_shared<const PovTexture>(std::move(tex)));
    } else if (k == "interior") {
        advance();
        o.interior = std::make_shared<const PovInterior>(
            parse_interior(o.interior ? *o.interior : PovInterior{}));
    } else if (k == "material") {
        advance();
        expect_sym("{");
        for (;;) {
            const Token& i = peek();
            if (accept_sym("}")) break;
            Value mat;
            if (accept_declared(VType::Material, mat, "a material")) {
                const PovMaterial& m = mat.as<PovMaterial>();
                if (m.texture) o.texture = m.texture, texture_here = true;
                if (m.interior) o.interior = m.interior;
            } else if (!parse_modifier(o, texture_here)) {
                error_expected(i, "texture, interior or '}' in material");
            }
        }
    } else if (k == "interior_texture") {
        advance();
        o.interior_texture = parse_texture_layers(model.default_texture);
    } else if (k == "photons") {
        advance();
        parse_object_photons(o);
    } else if (k == "radiosity") {
        advance();
        skip_block();
    } else if (k == "inverse") {
        advance();
        o.inverse = !o.inverse;
    } else if (k == "open") {
        advance();
        if (o.kind == PovKind::Shape) o.shape.open = parse_bool_opt(true);
    } else if (k == "hollow") {
        advance();
        set_hollow(o, parse_bool_opt(true));
    } else if (k == "sturm" || k == "no_radiosity" || k == "double_illuminate" ||
               k == "split_union" || k == "cutaway_textures" || k == "hierarchy" || k == "smooth") {
        advance();
        parse_bool_opt(true);
    } else if (k == "global_lights") {
        advance();
        o.global_lights = parse_bool_opt(true);
    } else if (k == "uv_mapping") { // the object's textures, given before or after it
        advance();
        o.uv_mapping = true;
        set_texture(o.texture);
    } else if (k == "no_shadow" || k == "no_reflection" || k == "no_image") {
        advance();
        const uint8_t flag = k == "no_shadow"       ? kNoShadow
                             : k == "no_reflection" ? kNoReflection
                                                    : kNoImage;
        if (parse_bool_opt(true))
            o.flags |= flag;
        else
            o.flags &= uint8_t(~flag);
    } else if (k == "inside_vector") {
        advance();
        parse_vector();
    } else if (k == "bounded_by") {
        advance();
        parse_bounded_by(o);
    } else if (k == "clipped_by") {
        advance();
        parse_clipped_by(t, o);
    } else {
        return false;
    }
    return true;
}

namespace {

bool analytic(const PovObject& o) {
    if (o.kind == PovKind::Shape) return true;
    if (o.kind != PovKind::Csg) return false;
    for (const PovObject& c : o.children)
        if (!analytic(c)) return false;
    return true;
}

} // namespace

void Parser::parse_bounded_by(PovObject& o) {
    expect_sym("{");
    auto bound = std::make_shared<PovObject>();
    bound->kind = PovKind::Csg, bound->op = CsgOp::Union;
    bool clip = false; // bounded_by { clipped_by }: the clip bounds it, already in the object
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("clipped_by")) {
            clip = true;
            continue;
        }
        if (!is_object_start(t)) error_expected(t, "an object or '}'");
        PovObject c;
        if (parse_object(c)) bound->children.push_back(std::move(c));
    }
    if (!clip && !bound->children.empty()) o.bounded_by = std::move(bound);
}

void Parser::parse_clipped_by(const Token& kw, PovObject& o) {
    expect_sym("{");
    std::vector<PovObject> clips;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("bounded_by")) continue; // clipped_by { bounded_by }: nothing to add
        if (!is_object_start(t)) error_expected(t, "an object or '}'");
        PovObject c;
        if (parse_object(c)) clips.push_back(std::move(c));
    }
    if (clips.empty()) return;
    bool ok = analytic(o);
    for (const PovObject& c : clips) ok = ok && analytic(c);
    if (!ok) {
        unsupported(kw, "clipped_by on a mesh (ignored)");
        return;
    }
    PovObject group;
    group.kind = PovKind::Csg;
    group.op = CsgOp::Clip;
    group.where = o.where;
    group.texture = o.texture;
    group.interior = o.interior;
    group.flags = o.flags;
    for (PovObject& c : clips) {
        if (!c.texture) c.texture = o.texture;
        c.inverse = c.inverse; // clips keep their own inside
    }
    group.children.push_back(std::move(o));
    for (PovObject& c : clips) group.children.push_back(std::move(c));
    o = std::move(group);
}

bool Parser::parse_transform_item(Affine& m) {
    const Token& t = peek();
    if (t.kind != TokKind::Ident) return false;
    if (t.text == "translate") {
        advance();
        m = Affine::translate(parse_vector());
    } else if (t.text == "scale") {
        advance();
        Vec3 s = parse_vector();
        for (int i = 0; i < 3; ++i)
            if (s[i] == 0) s[i] = 1; // POV-Ray too (with a warning)
        m = Affine::scale(s);
    } else if (t.text == "rotate") {
        advance();
        const Vec3 r = parse_vector() * float(M_PI / 180);
        m = Affine::rotate({0, 0, 1}, r.z) * Affine::rotate({0, 1, 0}, r.y) *
            Affine::rotate({1, 0, 0}, r.x);
    } else if (t.text == "matrix") {
        advance();
        expect_sym("<");
        double v[12];
        ++no_gt_;
        for (int i = 0; i < 12; ++i) {
            v[i] = parse_float();
            if (i < 11) expect_sym(",", "',' (a matrix has 12 values)");
        }
        --no_gt_;
        expect_sym(">");
        m = Affine();
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) m.m[r][c] = float(v[c * 3 + r]);
            m.m[r][3] = float(v[9 + r]);
        }
    } else if (t.text == "transform") {
        advance();
        m = parse_transform_block();
    } else {
        return false;
    }
    return true;
}

Affine Parser::parse_transform_block() {
    const Token& t = peek();
    Value declared;
    if (accept_declared(VType::Transform, declared, "a transform")) return declared.as<Affine>();
    expect_sym("{", "'{' or a transform identifier");
    Affine total;
    bool inverse = false;
    for (;;) {
        const Token& i = peek();
        if (accept_sym("}")) break;
        if (accept_kw("inverse")) {
            inverse = !inverse;
            continue;
        }
        if (accept_declared(VType::Transform, declared, "a transform")) {
            total = declared.as<Affine>() * total;
            continue;
        }
        Affine m;
        if (!parse_transform_item(m)) error_expected(i, "translate, rotate, scale, matrix or '}'");
        total = m * total;
    }
    if (inverse) {
        if (std::fabs(total.determinant()) < 1e-20f) error_at(t, "inverse of a singular transform");
        total = total.inverse();
    }
    return total;
}

void set_hollow(PovObject& o, bool hollow) {
    o.hollow = hollow;
    for (PovObject& c : o.children) set_hollow(c, hollow);
}

void Parser::apply_transform(PovObject& o, const Affine& m) {
    if (o.bounded_by) {
        auto b = std::make_shared<PovObject>(*o.bounded_by);
        apply_transform(*b, m);
        o.bounded_by = std::move(b);
    }
    o.texture = transformed(o.texture, m);
    o.interior_texture = transformed(o.interior_texture, m);
    for (PovTextureRef& t : o.face_textures) t = transformed(t, m);
    if (o.interior && !o.interior->media.empty()) { // its media move with the object
        auto in = std::make_shared<PovInterior>(*o.interior);
        in->local = m * in->local;
        o.interior = std::move(in);
    }
    switch (o.kind) {
    case PovKind::Shape:
    case PovKind::Mesh:
        o.local = m * o.local;
        break;
    case PovKind::Csg:
        for (PovObject& c : o.children) apply_transform(c, m);
        break;
    case PovKind::Light:
        o.light.light.position = m.point(o.light.light.position);
        o.light.point_at = m.point(o.light.point_at);
        o.light.axis1 = m.vector(o.light.axis1);
        o.light.axis2 = m.vector(o.light.axis2);
        break;
    }
}

} // namespace sheaf::io::pov

// Triangle objects: triangle, smooth_triangle, mesh, mesh2 and polygon (ear-clipped in its
// plane; each closed sub-polygon is filled on its own). They become core Mesh objects.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>

namespace sheaf::io::pov {

namespace {

/// Adds a triangle of its own three corners, with their normals and POV-Ray uv coordinates
/// (u, v in x and y) when given.
void add_triangle(Mesh& m, Vec3 a, Vec3 b, Vec3 c, const Vec3* n, const Vec3* uv = nullptr) {
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c});
    if (n) m.normals.insert(m.normals.end(), {n[0], n[1], n[2]});
    if (uv)
        for (int k = 0; k < 3; ++k) m.uvs.insert(m.uvs.end(), {uv[k].x, uv[k].y});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
}

/// POV-Ray's uv coordinates of a mesh whose triangles give them: the triangles that give none
/// take (0, 0) at every corner, as POV-Ray does; none at all: none.
void complete_uvs(Mesh& m, bool any_uv, const std::vector<bool>& has_uv) {
    if (!any_uv) {
        m.uvs.clear();
        return;
    }
    std::vector<float> uvs;
    size_t k = 0;
    for (bool given : has_uv) {
        for (int c = 0; c < 6; ++c) uvs.push_back(given ? m.uvs[k + size_t(c)] : 0.0f);
        if (given) k += 6;
    }
    m.uvs = std::move(uvs);
}

/// Gives flat triangles (no normals) face normals when some triangles of the mesh are smooth.
void complete_normals(Mesh& m, bool any_smooth, const std::vector<bool>& smooth) {
    if (!any_smooth) {
        m.normals.clear();
        return;
    }
    std::vector<Vec3> normals;
    size_t k = 0;
    for (size_t t = 0; t < smooth.size(); ++t) {
        if (smooth[t]) {
            normals.insert(normals.end(), {m.normals[k], m.normals[k + 1], m.normals[k + 2]});
            k += 3;
        } else {
            const Vec3 a = m.positions[3 * t], b = m.positions[3 * t + 1],
                       c = m.positions[3 * t + 2];
            Vec3 n = cross(b - a, c - a);
            n = length(n) > 0 ? normalize(n) : Vec3(0, 1, 0);
            normals.insert(normals.end(), {n, n, n});
        }
    }
    m.normals = std::move(normals);
}

} // namespace

void Parser::parse_triangle(const Token& kw, PovObject& o, bool smooth) {
    expect_sym("{");
    Vec3 p[3], n[3];
    for (int i = 0; i < 3; ++i) {
        if (i) accept_sym(",");
        p[i] = parse_vector();
        if (smooth) {
            accept_sym(",");
            n[i] = parse_vector();
        }
    }
    auto mesh = std::make_shared<Mesh>();
    add_triangle(*mesh, p[0], p[1], p[2], smooth ? n : nullptr);
    o.kind = PovKind::Mesh;
    o.mesh = mesh;
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    (void)kw;
}

bool Parser::accept_declared_mesh(PovObject& o) {
    const Token& t = peek();
    Value declared;
    if (!accept_declared(VType::Object, declared, "a mesh")) return false;
    if (declared.as<PovObject>().kind != PovKind::Mesh) error_expected(t, "a mesh identifier");
    o = declared.as<PovObject>();
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

void Parser::parse_mesh(const Token& kw, PovObject& o) {
    expect_sym("{");
    if (accept_declared_mesh(o)) return; // mesh { MESH_ID modifiers }
    auto mesh = std::make_shared<Mesh>();
    std::vector<bool> smooth, has_uv;
    bool any_smooth = false, any_uv = false;
    std::vector<PovTextureRef> textures; // the triangles' own textures
    std::vector<int32_t> face_texture;   // per triangle: its texture there (-1: the mesh's)
    for (;;) {
        const Token& t = peek();
        const bool tri = is_kw_tok(t, "triangle"), stri = is_kw_tok(t, "smooth_triangle");
        if (!tri && !stri) break;
        advance();
        expect_sym("{");
        Vec3 p[3], n[3];
        for (int i = 0; i < 3; ++i) {
            if (i) accept_sym(",");
            p[i] = parse_vector();
            if (stri) {
                accept_sym(",");
                n[i] = parse_vector();
            }
        }
        Vec3 uv[3];
        bool given_uv = false;
        int32_t own_texture = -1;
        for (;;) {
            const Token& i = peek();
            if (accept_sym("}")) break;
            if (accept_kw("uv_vectors")) {
                for (int k = 0; k < 3; ++k) {
                    if (k) accept_sym(",");
                    uv[k] = parse_vector();
                }
                given_uv = true;
            } else if (accept_kw("texture")) {
                textures.push_back(parse_texture_block(model.default_texture));
                own_texture = int32_t(textures.size() - 1);
            } else {
                error_expected(i, "uv_vectors, texture or '}'");
            }
        }
        // Its corners, indices, normals and uv coordinates, and its own texture's index.
        charge(3 * sizeof(Vec3) + 4 * sizeof(uint32_t) + (stri ? 3 * sizeof(Vec3) : 0) +
                   (given_uv ? 6 * sizeof(float) : 0),
               t);
        add_triangle(*mesh, p[0], p[1], p[2], stri ? n : nullptr, given_uv ? uv : nullptr);
        smooth.push_back(stri);
        any_smooth = any_smooth || stri;
        has_uv.push_back(given_uv);
        any_uv = any_uv || given_uv;
        face_texture.push_back(own_texture);
        if (mesh->positions.size() > size_t(kMaxArrayElements)) error_at(t, "mesh too large");
    }
    if (mesh->indices.empty()) error_expected(peek(), "triangle or smooth_triangle in mesh");
    complete_normals(*mesh, any_smooth, smooth);
    complete_uvs(*mesh, any_uv, has_uv);
    o.kind = PovKind::Mesh;
    o.mesh = mesh;
    o.face_texture.reset();
    o.face_textures.clear();
    if (!textures.empty()) { // triangles wearing textures of their own
        o.face_texture = std::make_shared<const std::vector<int32_t>>(std::move(face_texture));
        o.face_textures = std::move(textures);
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    (void)kw;
}

void Parser::parse_mesh2(const Token& kw, PovObject& o) {
    expect_sym("{");
    if (accept_declared_mesh(o)) return; // mesh2 { MESH_ID modifiers }
    std::vector<Vec3> vertices, normals, uvs;
    std::vector<Vec3> faces, normal_faces, uv_faces; // index triples as floats
    std::vector<std::array<int32_t, 3>> face_tex;    // the faces' texture indices (-1: none)
    std::vector<PovTextureRef> textures;             // texture_list
    Token textures_at;
    // A section: "NAME { count, item, item ... }"; vectors are kept, the floats after a vector
    // (a face's texture indices) go to `extra` (skipped without).
    auto section = [&](std::vector<Vec3>& out,
                       std::vector<std::array<int32_t, 3>>* extra = nullptr) {
        expect_sym("{");
        const Token& at = peek();
        const Value count = parse_additive(); // "14 <-1, ...>": a count, not a comparison
        if (count.type != VType::Float) error_expected(at, "the item count");
        const double n = count.v[0];
        if (n < 0 || n > double(kMaxArrayElements)) error_at(at, "bad item count");
        charge(size_t(n) * sizeof(Vec3), at);
        out.reserve(size_t(n));
        accept_sym(",");
        int after = 0; // floats after the last vector
        while (!accept_sym("}")) {
            const Token& t = peek();
            const Value v = parse_expr();
            if (v.type == VType::Vector || v.type == VType::Color) {
                out.emplace_back(float(v.v[0]), float(v.v[1]), float(v.dim > 2 ? v.v[2] : 0));
                if (extra) extra->push_back({-1, -1, -1});
                after = 0;
            } else if (v.type != VType::Float) {
                error_expected(t, "a vector");
            } else if (extra) {
                if (out.empty() || after == 3) error_expected(t, "a face's <a, b, c>");
                const double k = v.v[0];
                if (!(k >= 0 && k < 1e9)) error_at(t, "a texture index must be a number >= 0");
                extra->back()[size_t(after++)] = int32_t(k);
            }
            accept_sym(",");
        }
        if (out.size() != size_t(n))
            error_at(at, "the section says " + std::to_string(size_t(n)) + " items but has " +
                             std::to_string(out.size()));
    };
    for (;;) {
        const Token& t = peek();
        if (accept_kw("vertex_vectors"))
            section(vertices);
        else if (accept_kw("normal_vectors"))
            section(normals);
        else if (accept_kw("face_indices"))
            section(faces, &face_tex);
        else if (accept_kw("normal_indices"))
            section(normal_faces);
        else if (accept_kw("uv_vectors"))
            section(uvs);
        else if (accept_kw("uv_indices"))
            section(uv_faces);
        else if (accept_kw("texture_list")) {
            textures_at = t;
            textures = parse_texture_list();
        } else {
            break;
        }
    }
    if (vertices.empty() || faces.empty())
        error_at(kw, "mesh2 needs vertex_vectors and face_indices");
    auto mesh = std::make_shared<Mesh>();
    const bool smooth = !normals.empty(), uv = !uvs.empty();
    if (smooth && !normal_faces.empty() && normal_faces.size() != faces.size())
        error_at(kw, "normal_indices and face_indices differ in count");
    if (uv && !uv_faces.empty() && uv_faces.size() != faces.size())
        error_at(kw, "uv_indices and face_indices differ in count");
    auto index = [&](float f, size_t count) {
        if (f < 0 || size_t(f) >= count)
            error_at(kw, "mesh2 index " + std::to_string(long(f)) + " out of range (" +
                             std::to_string(count) + ")");
        return uint32_t(f);
    };
    // Normals and uv coordinates indexed apart from the vertices (or counted differently):
    // every triangle gets corners of its own.
    const bool own_normals = smooth && (!normal_faces.empty() || normals.size() != vertices.size());
    const bool own_uvs = uv && (!uv_faces.empty() || uvs.size() != vertices.size());
    if (own_normals || own_uvs) {
        const std::vector<Vec3>& nf = normal_faces.empty() ? faces : normal_faces;
        const std::vector<Vec3>& tf = uv_faces.empty() ? faces : uv_faces;
        for (size_t f = 0; f < faces.size(); ++f) {
            Vec3 p[3], n[3], t[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = vertices[index(faces[f][k], vertices.size())];
                if (smooth) n[k] = normals[index(nf[f][k], normals.size())];
                if (uv) t[k] = uvs[index(tf[f][k], uvs.size())];
            }
            add_triangle(*mesh, p[0], p[1], p[2], smooth ? n : nullptr, uv ? t : nullptr);
        }
    } else {
        mesh->positions = vertices;
        if (smooth) mesh->normals = normals;
        for (const Vec3& t : uvs) mesh->uvs.insert(mesh->uvs.end(), {t.x, t.y});
        for (const Vec3& f : faces)
            for (int k = 0; k < 3; ++k) mesh->indices.push_back(index(f[k], vertices.size()));
    }
    o.kind = PovKind::Mesh;
    o.mesh = mesh;
    // Faces naming textures of the texture_list wear them (the first, when a face names one
    // for each corner: POV-Ray blends the three); the others, the object's texture.
    o.face_textures.clear();
    o.face_texture.reset();
    bool any = false, blended = false;
    for (size_t f = 0; f < face_tex.size(); ++f) {
        const auto& k = face_tex[f];
        for (int32_t i : k)
            if (i >= 0 && size_t(i) >= textures.size())
                error_at(kw, "mesh2 face " + std::to_string(f) + " names texture " +
                                 std::to_string(i) + " of a texture_list of " +
                                 std::to_string(textures.size()));
        any = any || k[0] >= 0;
        blended = blended || (k[1] >= 0 && (k[1] != k[0] || k[2] != k[0]));
    }
    if (blended)
        unsupported(textures_at, "a texture for each corner of a mesh2 face (the first is used)");
    if (any) {
        auto per_face = std::make_shared<std::vector<int32_t>>(face_tex.size());
        for (size_t f = 0; f < face_tex.size(); ++f) (*per_face)[f] = face_tex[f][0];
        o.face_texture = std::move(per_face);
        o.face_textures = std::move(textures);
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
}

std::vector<PovTextureRef> Parser::parse_texture_list() {
    expect_sym("{");
    const Token& at = peek();
    const double n = parse_float();
    if (!(n >= 0 && n <= double(kMaxArrayElements))) error_at(at, "bad texture count");
    accept_sym(",");
    std::vector<PovTextureRef> out;
    while (!accept_sym("}")) {
        const Token& t = peek();
        if (!accept_kw("texture")) error_expected(t, "texture or '}'");
        out.push_back(parse_texture_block(model.default_texture));
        accept_sym(",");
    }
    if (out.size() != size_t(n))
        error_at(at, "the texture_list says " + std::to_string(size_t(n)) + " textures but has " +
                         std::to_string(out.size()));
    return out;
}

namespace {

/// The plane's axes a flat outline is measured in: u and v of the largest component of its
/// Newell normal, and the sign that makes its area positive.
struct FlatAxes {
    int u = 0, v = 1;
    float sign = 1;
};

FlatAxes flat_axes(const std::vector<Vec3>& pts) {
    Vec3 n(0, 0, 0); // Newell's normal
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 a = pts[i], b = pts[(i + 1) % pts.size()];
        n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    int ax = 0;
    if (std::fabs(n.y) > std::fabs(n[ax])) ax = 1;
    if (std::fabs(n.z) > std::fabs(n[ax])) ax = 2;
    return {(ax + 1) % 3, (ax + 2) % 3, n[ax] >= 0 ? 1.0f : -1.0f};
}

/// Twice the signed area of a closed outline in the axes' plane.
double outline_area(const std::vector<Vec3>& c, const FlatAxes& f) {
    double a = 0;
    for (size_t i = 0; i < c.size(); ++i) {
        const Vec3 p = c[i], q = c[(i + 1) % c.size()];
        a += double(p[f.u]) * q[f.v] - double(q[f.u]) * p[f.v];
    }
    return a;
}

/// Whether point p lies inside the closed outline c (even-odd, in the axes' plane).
bool inside_outline(Vec3 p, const std::vector<Vec3>& c, const FlatAxes& f) {
    bool in = false;
    for (size_t i = 0, j = c.size() - 1; i < c.size(); j = i++) {
        const float ui = c[i][f.u], vi = c[i][f.v], uj = c[j][f.u], vj = c[j][f.v];
        if ((vi > p[f.v]) != (vj > p[f.v]) && p[f.u] < (uj - ui) * (p[f.v] - vi) / (vj - vi) + ui)
            in = !in;
    }
    return in;
}

/// Whether the open segments ab and cd cross (in the axes' plane; touching ends do not).
bool segments_cross(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const FlatAxes& f) {
    auto orient = [&](Vec3 p, Vec3 q, Vec3 r) {
        const double x = (double(q[f.u]) - p[f.u]) * (double(r[f.v]) - p[f.v]) -
                         (double(q[f.v]) - p[f.v]) * (double(r[f.u]) - p[f.u]);
        return x > 0 ? 1 : x < 0 ? -1 : 0;
    };
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

/// Joins each hole to `outer` by a bridge (there and back along one edge) from the hole's
/// vertex furthest along u to the nearest vertex it sees, so that one outline remains for ear
/// clipping. `outer` runs with positive area, each hole with negative. False when a hole finds
/// no vertex to join (left unjoined).
bool bridge_holes(std::vector<Vec3>& outer, std::vector<std::vector<Vec3>> holes,
                  const FlatAxes& f) {
    std::sort(holes.begin(), holes.end(), [&](const auto& a, const auto& b) {
        auto far = [&](const std::vector<Vec3>& h) {
            float m = h[0][f.u];
            for (const Vec3& p : h) m = std::max(m, p[f.u]);
            return m;
        };
        return far(a) > far(b);
    });
    bool all = true;
    for (size_t k = 0; k < holes.size(); ++k) {
        const std::vector<Vec3>& h = holes[k];
        size_t m = 0;
        for (size_t i = 1; i < h.size(); ++i)
            if (h[i][f.u] > h[m][f.u]) m = i;
        auto blocked = [&](Vec3 a, Vec3 b) {
            for (size_t i = 0; i < outer.size(); ++i)
                if (segments_cross(a, b, outer[i], outer[(i + 1) % outer.size()], f)) return true;
            for (size_t j = k; j < holes.size(); ++j)
                for (size_t i = 0; i < holes[j].size(); ++i)
                    if (segments_cross(a, b, holes[j][i], holes[j][(i + 1) % holes[j].size()], f))
                        return true;
            return false;
        };
        size_t best = outer.size();
        float best_d = 0;
        for (size_t i = 0; i < outer.size(); ++i) {
            const Vec3 d = outer[i] - h[m];
            const float dd = d[f.u] * d[f.u] + d[f.v] * d[f.v];
            if ((best == outer.size() || dd < best_d) && !blocked(h[m], outer[i]))
                best = i, best_d = dd;
        }
        if (best == outer.size()) {
            all = false;
            continue;
        }
        // outer[..best], hole from m round to m, outer[best..]
        std::vector<Vec3> joined(outer.begin(), outer.begin() + long(best) + 1);
        for (size_t i = 0; i <= h.size(); ++i) joined.push_back(h[(m + i) % h.size()]);
        joined.insert(joined.end(), outer.begin() + long(best), outer.end());
        outer = std::move(joined);
    }
    return all;
}

/// Ear clipping of one simple polygon (no repeated closing point) in 3D; a bridged outline's
/// repeated vertices do not block its ears.
void triangulate(const std::vector<Vec3>& pts, Mesh& m) {
    if (pts.size() < 3) return;
    const FlatAxes f = flat_axes(pts);
    const int u = f.u, v = f.v;
    const float sign = f.sign;
    auto area = [&](Vec3 a, Vec3 b, Vec3 c) {
        return sign * ((b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]));
    };
    std::vector<size_t> idx(pts.size());
    for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), pts.begin(), pts.end());
    size_t guard = 0;
    while (idx.size() > 3 && guard++ < 4 * pts.size() * pts.size()) {
        bool clipped = false;
        for (size_t i = 0; i < idx.size(); ++i) {
            const size_t a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i],
                         c = idx[(i + 1) % idx.size()];
            if (area(pts[a], pts[b], pts[c]) <= 0) continue;
            bool inside = false;
            for (size_t j : idx) {
                if (j == a || j == b || j == c) continue;
                if (pts[j] == pts[a] || pts[j] == pts[b] || pts[j] == pts[c]) continue;
                if (area(pts[a], pts[b], pts[j]) >= 0 && area(pts[b], pts[c], pts[j]) >= 0 &&
                    area(pts[c], pts[a], pts[j]) >= 0) {
                    inside = true;
                    break;
                }
            }
            if (inside) continue;
            m.indices.insert(m.indices.end(),
                             {base + uint32_t(a), base + uint32_t(b), base + uint32_t(c)});
            idx.erase(idx.begin() + long(i));
            clipped = true;
            break;
        }
        if (!clipped) break; // degenerate: fan the rest
    }
    for (size_t i = 1; i + 1 < idx.size(); ++i)
        m.indices.insert(m.indices.end(), {base + uint32_t(idx[0]), base + uint32_t(idx[i]),
                                           base + uint32_t(idx[i + 1])});
}

} // namespace

void Parser::parse_polygon(const Token& kw, PovObject& o) {
    expect_sym("{");
    const Token& at = peek();
    const Value count = parse_additive();
    if (count.type != VType::Float) error_expected(at, "the point count");
    const double n = count.v[0];
    if (n < 3 || n > double(kMaxArrayElements)) error_at(at, "a polygon needs at least 3 points");
    std::vector<Vec3> pts;
    for (size_t i = 0; i < size_t(n); ++i) {
        accept_sym(",");
        pts.push_back(parse_vector());
    }
    // The closed outlines: each ends where it began.
    std::vector<std::vector<Vec3>> outlines;
    std::vector<Vec3> cur;
    for (const Vec3& p : pts) {
        if (!cur.empty() && cur.size() > 2 && p == cur.front()) {
            outlines.push_back(std::move(cur));
            cur.clear();
            continue;
        }
        cur.push_back(p);
    }
    if (cur.size() >= 3) {
        if (cur.back() == cur.front()) cur.pop_back();
        outlines.push_back(std::move(cur));
    }
    auto mesh = std::make_shared<Mesh>();
    if (outlines.size() == 1) {
        triangulate(outlines[0], *mesh);
    } else if (!outlines.empty()) {
        // Even-odd, as POV-Ray fills them: an outline inside an odd number of others is a hole
        // in the smallest of them that holds it, joined to it by a bridge before ear clipping.
        const FlatAxes f = flat_axes(outlines[0]);
        const size_t n_out = outlines.size();
        // The nesting costs outlines x points, the bridges outlines x points^2: beyond these
        // bounds (a polygon of thousands of outlines) each outline is filled on its own.
        const double points = double(pts.size());
        bool joined = double(n_out) * points <= 5e7 && double(n_out) * points * points <= 2e8;
        std::vector<int> depth(n_out, 0), parent(n_out, -1);
        for (size_t i = 0; i < n_out && joined; ++i)
            for (size_t j = 0; j < n_out; ++j)
                if (i != j && inside_outline(outlines[i][0], outlines[j], f)) {
                    ++depth[i];
                    if (parent[i] < 0 ||
                        std::fabs(outline_area(outlines[j], f)) <
                            std::fabs(outline_area(outlines[size_t(parent[i])], f)))
                        parent[i] = int(j);
                }
        for (size_t i = 0; i < n_out && joined; ++i) {
            if (depth[i] % 2) continue; // a hole
            std::vector<Vec3> outer = outlines[i];
            if (outline_area(outer, f) < 0) std::reverse(outer.begin(), outer.end());
            std::vector<std::vector<Vec3>> holes;
            for (size_t j = 0; j < n_out; ++j)
                if (depth[j] % 2 && parent[j] == int(i)) {
                    holes.push_back(outlines[j]);
                    if (outline_area(holes.back(), f) > 0)
                        std::reverse(holes.back().begin(), holes.back().end());
                }
            joined = bridge_holes(outer, holes, f);
            triangulate(outer, *mesh);
        }
        if (!joined) {
            unsupported(kw, "polygon holes that no bridge reaches, or too many outlines (each "
                            "closed outline is filled on its own)");
            mesh = std::make_shared<Mesh>();
            for (const auto& c : outlines) triangulate(c, *mesh);
        }
    }
    if (mesh->indices.empty()) error_at(kw, "degenerate polygon");
    o.kind = PovKind::Mesh;
    o.mesh = mesh;
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
}

} // namespace sheaf::io::pov

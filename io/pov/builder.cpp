// PovModel -> sheaf::Scene (see builder.h).
#include "io/pov/builder.h"

#include "io/pov/materials.h"

#include "core/base/error.h"
#include "core/scene/prepared_scene.h"
#include "core/scenes/shapes.h"
#include "core/settings/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <tuple>

namespace sheaf::io::pov {

Affine pov_to_sheaf() {
    return Affine::scale({1, 1, -1});
}

namespace {

/// Whether transform a squeezes space to a segment or a point (its linear part's rank at
/// most 1: every 2 x 2 minor negligible against its largest entry squared).
bool squeezed_to_a_line(const Affine& a) {
    double big = 0, minor = 0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) big = std::max(big, std::fabs(double(a.m[r][c])));
    for (int r1 = 0; r1 < 3; ++r1)
        for (int r2 = r1 + 1; r2 < 3; ++r2)
            for (int c1 = 0; c1 < 3; ++c1)
                for (int c2 = c1 + 1; c2 < 3; ++c2)
                    minor = std::max(minor, std::fabs(double(a.m[r1][c1]) * a.m[r2][c2] -
                                                      double(a.m[r1][c2]) * a.m[r2][c1]));
    return minor <= 1e-10 * big * big;
}

/// Whether `o` is a solid squeezed to a segment or a point (a degenerate shape, not inverse,
/// of rank at most 1): it has no surface to show, in POV-Ray either.
bool vanishing_solid(const PovObject& o) {
    return o.kind == PovKind::Shape && !o.inverse &&
           !(std::fabs(o.local.determinant()) >= 1e-20f) && squeezed_to_a_line(o.local);
}

/// The aa.samples value that gives a pixel `samples` samples or more: n x n of them, n within
/// the setting's range (an explicit aa.samples, +A or -A, overrides the scene's).
std::string aa_samples_for(int samples) {
    const int most = int(find_setting("aa.samples")->max);
    return std::to_string(std::clamp(int(std::ceil(std::sqrt(double(samples)) - 1e-9)), 1, most));
}

/// The triangles `faces` of m, with the vertices they use (normals and uv coordinates kept).
Mesh submesh(const Mesh& m, const std::vector<uint32_t>& faces) {
    Mesh out;
    std::vector<uint32_t> remap(m.positions.size(), UINT32_MAX);
    for (uint32_t f : faces)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = m.indices[3 * size_t(f) + size_t(k)];
            if (remap[v] == UINT32_MAX) {
                remap[v] = uint32_t(out.positions.size());
                out.positions.push_back(m.positions[v]);
                if (!m.normals.empty()) out.normals.push_back(m.normals[v]);
                if (!m.uvs.empty()) out.uvs.insert(out.uvs.end(), {m.uvs[2 * v], m.uvs[2 * v + 1]});
            }
            out.indices.push_back(remap[v]);
        }
    return out;
}

struct Builder {
    Parser& p;
    Scene& scene;
    MaterialBuilder materials;
    Affine flip = pov_to_sheaf();
    PhotonObject photons_;          // the photons block of the unions around the object being built
    std::map<uint32_t, Mesh> loose; // single triangles by material, in Sheaf world space
    size_t names = 0;
    bool geometry_only = false; // every surface material 0 (textures not built)
    // Inside a light_group: its Material::light_group (its number, and kGlobalLights with
    // global_lights on); 0 outside every group.
    uint16_t group = 0;
    uint16_t groups = 0;                                            // light groups so far
    std::map<std::pair<uint32_t, uint16_t>, uint32_t> grouped = {}; // (material, group) -> copy
    // The box of the bounded_by objects around the object being built (POV-Ray's space):
    // unbounded when none is given.
    Vec3 bound_lo_ = Vec3(-INFINITY), bound_hi_ = Vec3(INFINITY);

    /// Builds `body` as the members of light group `o` when it is one.
    template <class Body> auto in_group(const PovObject& o, Body body) {
        if (!o.light_group) return body();
        if (groups == kMaxLightGroup)
            p.error_at(o.where, "more than " + std::to_string(kMaxLightGroup) + " light groups");
        const ScopedValue<uint16_t> scope(
            group, uint16_t(++groups | (o.global_lights ? kGlobalLights : 0)));
        return body();
    }

    uint32_t material(const PovTexture& t, const PovInterior* in, const PovTexture* inside) {
        if (geometry_only) return 0;
        const uint32_t m = materials.material(t, in, inside);
        if (group == 0) return m;
        auto [it, added] = grouped.emplace(std::make_pair(m, group), 0);
        if (added) { // a copy lit by the group's lights (plain materials are shared)
            Material copy = scene.materials[m];
            copy.light_group = group;
            it->second = scene.add_material(copy);
            ungrouped[it->second] = m;
        }
        return it->second;
    }
    std::map<uint32_t, uint32_t> ungrouped = {}; // grouped copy -> the material it copies

    bool uses_uv(uint32_t m) const {
        const auto it = ungrouped.find(m);
        return materials.uses_uv(it == ungrouped.end() ? m : it->second);
    }

    /// The loose triangles as one mesh object per material.
    void add_loose() {
        for (auto& [mat, mesh] : loose) {
            mesh.normals.clear();
            scene.add_mesh_object("triangles#" + std::to_string(mat), std::move(mesh), mat, {});
        }
        loose.clear();
    }

    std::map<const IsoRef*, std::shared_ptr<const IsoRef>> isos = {}; // by the parsed one

    /// The isosurface of `o` with its function compiled.
    std::shared_ptr<const IsoRef> isosurface(const PovObject& o) {
        auto& done = isos[o.iso.get()];
        if (!done) {
            auto iso = std::make_shared<IsoRef>(*o.iso);
            iso->program = uint32_t(materials.function(*o.iso_function));
            done = std::move(iso);
        }
        return done;
    }

    std::string name(const PovObject& o) {
        return o.where.text + "@" + std::to_string(o.where.line) + "#" + std::to_string(names++);
    }

    void light(const PovObject& o) {
        const PovLight& pl = o.light;
        for (const PovObject& shape : o.children) { // looks_like, at the light
            PovObject placed = shape;
            p.apply_transform(placed, Affine::translate(pl.light.position));
            top(placed, p.model.default_texture, nullptr, nullptr, 0);
        }
        Light l = pl.light;
        l.group = uint16_t(group & kMaxLightGroup);
        // POV-Ray keeps the cosines: a radius whose cosine is not positive (radius -90 of the
        // "cosine falloff" idiom) makes no cone at all, which Sheaf's radius 90 means.
        l.spot_falloff = std::clamp(std::fabs(l.spot_falloff), 0.01f, 180.0f);
        if (std::cos(double(l.spot_radius) * M_PI / 180) <= 1e-9)
            l.spot_radius = 90;
        else
            l.spot_radius = std::min(std::fabs(l.spot_radius), l.spot_falloff);
        const Vec3 aim = pl.point_at - pl.light.position;
        if (!is_finite(pl.light.position) || !is_finite(l.color) || !is_finite(aim) ||
            !is_finite(pl.axis1) || !is_finite(pl.axis2))
            p.error_at(o.where, "the light's position, colour or aim is not a finite number");
        if (l.type != LightType::Point)
            l.direction = length(aim) > 0 ? normalize(flip.vector(aim)) : Vec3(0, -1, 0);
        if (!pl.area || (pl.n1 == 1 && pl.n2 == 1)) {
            l.position = flip.point(pl.light.position);
            scene.add_light(l);
            return;
        }
        std::mt19937 rng(12345); // fixed: the same scene gives the same lights
        std::uniform_real_distribution<float> jitter(-0.5f, 0.5f);
        const int n = pl.n1 * pl.n2;
        l.color = l.color / float(n);
        for (int i = 0; i < pl.n1; ++i)
            for (int j = 0; j < pl.n2; ++j) {
                const float u = pl.n1 > 1 ? (i + 0.5f + jitter(rng)) / pl.n1 - 0.5f : 0.0f;
                const float v = pl.n2 > 1 ? (j + 0.5f + jitter(rng)) / pl.n2 - 0.5f : 0.0f;
                Light s = l;
                s.position = flip.point(pl.light.position + pl.axis1 * u + pl.axis2 * v);
                s.centred = !pl.area_illumination;
                s.centre = flip.point(pl.light.position);
                // POV-Ray's area lights shoot photons as one light; the middle sample shoots
                // them for all.
                if (i == pl.n1 / 2 && j == pl.n2 / 2)
                    s.photon_weight = float(n);
                else
                    s.photon_reflection = s.photon_refraction = PhotonSwitch::Off;
                scene.add_light(s);
            }
    }

    /// o's photons block over what the unions around it passed down: its own settings win.
    PhotonObject photons_of(const PovObject& o) const {
        PhotonObject r = photons_;
        if (o.photons.target > 0) r.target = o.photons.target;
        if (o.photons.reflection != PhotonSwitch::Unset) r.reflection = o.photons.reflection;
        if (o.photons.refraction != PhotonSwitch::Unset) r.refraction = o.photons.refraction;
        return r;
    }

    void mesh(const PovObject& o, const PovTexture& tex, const PovInterior* in,
              const PovTexture* inside, uint8_t flags) {
        // Media fill the analytic objects that hold them (core/shading/media.h).
        if (in && !in->media.empty()) p.unsupported(o.where, "media in a mesh (ignored)");
        const Affine t = flip * o.local;
        for (const Vec3& v : o.mesh->positions)
            if (!is_finite(t.point(v)))
                p.error_at(o.where, "a vertex is not a finite number (a division by zero, or a "
                                    "scale beyond 1e38?)");
        if (o.face_texture && !geometry_only) { // faces wearing textures of their own
            // One mesh object per texture, its faces in their order.
            std::map<int32_t, std::vector<uint32_t>> groups;
            for (size_t f = 0; f < o.face_texture->size(); ++f)
                groups[(*o.face_texture)[f]].push_back(uint32_t(f));
            for (const auto& [id, faces] : groups) {
                const PovTexture& ft = id >= 0 ? *o.face_textures[size_t(id)] : tex;
                const uint32_t obj = scene.add_mesh_object(name(o), submesh(*o.mesh, faces),
                                                           material(ft, in, inside), t);
                scene.objects[obj].flags = flags;
                scene.objects[obj].photons = photons_of(o);
            }
            return;
        }
        const uint32_t mat = material(tex, in, inside);
        const PhotonObject photons = photons_of(o);
        if (o.mesh->triangle_count() == 1 && o.mesh->normals.empty() && o.mesh->uvs.empty() &&
            flags == 0 && !(photons.target > 0)) {
            append_mesh(loose[mat], *o.mesh, t);
            return;
        }
        const uint32_t id = scene.add_mesh_object(name(o), *o.mesh, mat, t);
        scene.objects[id].flags = flags;
        scene.objects[id].photons = photons;
    }

    /// Adds the CSG node for `o` to `so`; -1 when nothing of it can be shown analytically.
    int node(const PovObject& o, const PovTexture& parent, const PovInterior* parent_in,
             const PovTexture* parent_inside, uint8_t parent_flags, ShapeObject& so,
             bool in_union) {
        return in_group(o, [&] {
            return node_in(o, parent, parent_in, parent_inside, parent_flags, so, in_union);
        });
    }

    int node_in(const PovObject& o, const PovTexture& parent, const PovInterior* parent_in,
                const PovTexture* parent_inside, uint8_t parent_flags, ShapeObject& so,
                bool in_union) {
        const PovTexture& tex = o.texture ? *o.texture : parent;
        const PovInterior* in = o.interior ? o.interior.get() : parent_in;
        const PovTexture* inside = o.interior_texture ? o.interior_texture.get() : parent_inside;
        const uint8_t flags = uint8_t(o.flags | parent_flags);
        switch (o.kind) {
        case PovKind::Light:
            light(o);
            return -1;
        case PovKind::Mesh:
            if (in_union) {
                if (o.inverse) p.unsupported(o.where, "inverse of a mesh (ignored)");
                mesh(o, tex, in, inside, flags);
            } else {
                p.unsupported(o.where, "mesh inside intersection or difference (left out)");
            }
            return -1;
        case PovKind::Shape: {
            if (!o.local.finite() || !std::isfinite(o.shape.a) || !std::isfinite(o.shape.b))
                p.error_at(o.where, "the shape's size or placement is not a finite number "
                                    "(a division by zero, or a scale beyond 1e38?)");
            if (!(std::fabs(o.local.determinant()) >= 1e-20f)) { // as Scene::validate
                if (in_union && vanishing_solid(o)) return -1;   // among unions: exact

                p.unsupported(o.where, "degenerate shape (a zero scale; left out)");
                return -1;
            }
            CsgNode n;
            n.op = CsgOp::Leaf;
            n.shape = o.shape;
            n.poly = o.poly;
            n.glyph = o.glyph;
            n.revolution = o.revolution;
            n.blob = o.blob;
            n.julia = o.julia;
            if (o.shape.kind == ShapeKind::Isosurface) n.iso = isosurface(o);
            n.transform = o.local;
            n.material = material(tex, in, inside);
            if (!geometry_only && uses_uv(n.material))
                p.unsupported(o.where, "uv_mapping on " + o.where.text +
                                           " (only meshes carry uv coordinates; the pattern is "
                                           "evaluated at the point's x and y)");
            n.inverse = o.inverse;
            so.nodes.push_back(n);
            return int(so.nodes.size() - 1);
        }
        case PovKind::Csg:
            break;
        }
        const bool uni = o.op == CsgOp::Union || o.op == CsgOp::Merge;
        if (o.op == CsgOp::Merge)
            for (const PovObject& c : o.children)
                if (c.kind == PovKind::Mesh) {
                    p.unsupported(c.where, "mesh inside merge (rendered as in a union)");
                    break;
                }
        // An intersection with, or a difference from, a solid squeezed to a segment or a
        // point is empty: among unions, leaving it out is exact.
        if (in_union && !o.inverse && (o.op == CsgOp::Intersection || o.op == CsgOp::Difference))
            for (size_t i = 0; i < (o.op == CsgOp::Difference ? 1 : o.children.size()); ++i)
                if (vanishing_solid(o.children[i])) return -1;
        std::vector<uint32_t> kids;
        for (size_t i = 0; i < o.children.size(); ++i) {
            const int k = node(o.children[i], tex, in, inside, flags, so, uni && in_union);
            if (k >= 0)
                kids.push_back(uint32_t(k));
            else if ((o.op == CsgOp::Difference || o.op == CsgOp::Clip) && i == 0 &&
                     o.children[0].kind != PovKind::Light)
                return -1; // nothing to cut from
        }
        if (kids.empty()) return -1;
        if (o.op == CsgOp::Clip && kids.size() < 2) return int(kids[0]); // nothing clips it
        if (o.op == CsgOp::Union && !in_union && kids.size() > 1 && !geometry_only &&
            lets_light_in(so, kids))
            p.approximated(o.where, "union inside an intersection or difference: drawn as a "
                                    "merge, without its members' inner surfaces (POV-Ray shows "
                                    "them through its clear material)");
        if (kids.size() == 1 && uni && !o.inverse) return int(kids[0]);
        CsgNode n;
        n.op = o.op;
        n.inverse = o.inverse;
        n.children = kids;
        so.nodes.push_back(n);
        return int(so.nodes.size() - 1);
    }

    void top(const PovObject& o, const PovTexture& parent, const PovInterior* parent_in,
             const PovTexture* parent_inside, uint8_t parent_flags) {
        const Vec3 outer_lo = bound_lo_, outer_hi = bound_hi_;
        Vec3 lo, hi;
        // A bound the size of POV-Ray's "huge" (a plane, a polynomial) bounds nothing.
        if (o.bounded_by && object_extent(*o.bounded_by, lo, hi) &&
            std::fmax(std::fmax(std::fabs(lo.x), std::fabs(lo.y)), std::fabs(lo.z)) < 1e9f &&
            std::fmax(std::fmax(std::fabs(hi.x), std::fabs(hi.y)), std::fabs(hi.z)) < 1e9f)
            bound_lo_ = vmax(bound_lo_, lo), bound_hi_ = vmin(bound_hi_, hi);
        in_group(o, [&] { top_in(o, parent, parent_in, parent_inside, parent_flags); });
        bound_lo_ = outer_lo, bound_hi_ = outer_hi;
    }

    /// The bounded_by box around the object being built in Sheaf's world, padded for
    /// rounding (infinite: none; bounds that do not meet leave an empty box).
    WorldBox bound_box() const {
        if (!(std::fabs(bound_lo_.x) < INFINITY) || !(std::fabs(bound_hi_.x) < INFINITY))
            return WorldBox();
        const Vec3 a = flip.point(bound_lo_), b = flip.point(bound_hi_);
        const Vec3 pad = (vmax(vabs(a), vabs(b)) + vabs(b - a)) * 1e-5f;
        WorldBox w;
        w.lo = vmin(a, b) - pad, w.hi = vmax(a, b) + pad;
        if (bound_lo_.x > bound_hi_.x || bound_lo_.y > bound_hi_.y || bound_lo_.z > bound_hi_.z)
            w.hi = w.lo - Vec3(1.0f); // empty
        return w;
    }

    /// Whether a leaf under nodes `kids` of `so` has a material that may let light through.
    bool lets_light_in(const ShapeObject& so, const std::vector<uint32_t>& kids) const {
        for (uint32_t k : kids) {
            const CsgNode& n = so.nodes[k];
            if (n.op == CsgOp::Leaf ? material_may_pass(scene, n.material)
                                    : lets_light_in(so, n.children))
                return true;
        }
        return false;
    }

    void top_in(const PovObject& o, const PovTexture& parent, const PovInterior* parent_in,
                const PovTexture* parent_inside, uint8_t parent_flags) {
        const PovTexture& tex = o.texture ? *o.texture : parent;
        const PovInterior* in = o.interior ? o.interior.get() : parent_in;
        const PovTexture* inside = o.interior_texture ? o.interior_texture.get() : parent_inside;
        const uint8_t flags = uint8_t(o.flags | parent_flags);
        if (o.kind == PovKind::Light) return light(o);
        if (o.kind == PovKind::Mesh) {
            if (o.inverse) p.unsupported(o.where, "inverse of a mesh (ignored)");
            return mesh(o, tex, in, inside, flags);
        }
        if (o.kind == PovKind::Csg && o.op == CsgOp::Union && !o.inverse) {
            // A union of separate objects renders exactly as those objects (its photons block
            // passes to them: each is a target the way the union was).
            const PhotonObject outer = photons_;
            photons_ = photons_of(o);
            for (const PovObject& c : o.children) top(c, tex, in, inside, flags);
            photons_ = outer;
            return;
        }
        ShapeObject built; // children before parents
        const int root = node(o, parent, parent_in, parent_inside, parent_flags, built, true);
        if (root < 0) return;
        // The core wants parents before children: copy the tree in preorder from the root
        // (as deep as the parser's nesting limit at most).
        ShapeObject so;
        so.name = name(o);
        so.transform = flip;
        std::function<uint32_t(uint32_t)> copy = [&](uint32_t i) {
            const uint32_t at = uint32_t(so.nodes.size());
            so.nodes.push_back(built.nodes[i]);
            std::vector<uint32_t> kids;
            for (uint32_t c : built.nodes[i].children) kids.push_back(copy(c));
            so.nodes[at].children = kids;
            return at;
        };
        so.root = copy(uint32_t(root));
        if (const int nesting = csg_nesting(so); nesting > kMaxCsgNesting)
            p.error_at(o.where, "CSG nested " + std::to_string(nesting) +
                                    " levels deep; Sheaf renders " +
                                    std::to_string(kMaxCsgNesting) +
                                    " (unions of separate objects do not count)");
        // POV-Ray's objects are solid unless `hollow`: media around them leave them out.
        so.flags = uint8_t(flags | (o.hollow ? 0 : kSolid));
        so.photons = photons_of(o);
        so.bound = bound_box();
        scene.add_shape_object(std::move(so));
    }

    /// The mesh camera's meshes in Sheaf's world, and its settings: POV-Ray's location z moves
    /// the rays' origins along the face normals, a direction z below 0 reverses them (loc and
    /// dir: the camera's, transformed, in POV-Ray's space).
    void mesh_camera(const PovCamera& c, Vec3 loc, Vec3 dir) {
        Camera& out = scene.camera;
        out.mesh_rays = uint32_t(c.mesh_rays);
        out.mesh_distribution = uint8_t(c.mesh_distribution);
        out.mesh_smooth = c.mesh_smooth;
        out.mesh_offset = loc.z;
        out.mesh_reverse = dir.z < -1e-6f;
        for (const PovObject& o : c.meshes) {
            // POV-Ray's face normal is cross(c - a, b - a) in the mesh's space; Sheaf's mesh
            // camera takes cross(b - a, c - a), so each face's b and c trade places.
            CameraMesh cm{*o.mesh, flip * o.local};
            for (size_t t = 0; t + 2 < cm.mesh.indices.size(); t += 3)
                std::swap(cm.mesh.indices[t + 1], cm.mesh.indices[t + 2]);
            for (const Vec3& v : cm.mesh.positions)
                if (!is_finite(cm.transform.point(v)))
                    p.error_at(o.where, "a vertex of the camera's mesh is not a finite number");
            scene.camera_meshes.push_back(std::move(cm));
        }
        // POV-Ray shoots the rays a pixel takes itself; Sheaf takes them as its anti-aliasing
        // samples, each taking one ray (Camera::mesh_distribution).
        if (c.mesh_rays > 1) scene.settings["aa.samples"] = aa_samples_for(c.mesh_rays);
    }

    /// Where a perspective camera looks: its direction less the part of it that lies in the
    /// plane of right and up, which becomes the camera's lens shift (POV-Ray casts dir + x right
    /// + y up whatever their angles; a camera sheared by its transform, to keep verticals
    /// vertical, leans its direction out of that plane). Right and up that are not perpendicular
    /// cannot be drawn: up is then turned perpendicular, with a warning. Vectors transformed,
    /// in POV-Ray's space.
    Vec3 perspective_view(const PovCamera& c, Vec3 dir, Vec3 right, Vec3 up, Camera& out) {
        if (c.projection != Projection::Perspective) return dir;
        const float rr = dot(right, right), uu = dot(up, up);
        const Vec3 n = cross(right, up);
        const float nl = length(n);
        if (!(rr > 0) || !(uu > 0) || !(nl > 0) || !std::isfinite(nl)) return dir;
        if (std::fabs(dot(right, up)) > 1e-4f * std::sqrt(rr * uu))
            p.approximated(c.where, "camera whose right and up are not perpendicular: drawn "
                                    "with up turned perpendicular to right");
        const Vec3 along = n * (dot(dir, n) / (nl * nl));
        const Vec3 lean = dir - along;
        const float sx = dot(lean, right) / rr, sy = dot(lean, up) / uu;
        // Cameras whose direction is square to right and up (look_at gives them) stay as
        // they are, rounding and all.
        if (!(std::fabs(sx) > 1e-5f || std::fabs(sy) > 1e-5f) || !(length(along) > 0)) return dir;
        out.shift_x = sx;
        out.shift_y = sy;
        return along;
    }

    void camera() {
        const PovCamera& c = p.model.camera;
        Vec3 loc = c.location, dir = c.direction, right = c.right, up = c.up;
        // POV-Ray keeps the camera's handedness through look_at: right -x (a right-handed
        // camera) shows the image mirrored. Only a positive handedness counts as left-handed:
        // an up parallel to the direction (up z with the default direction) mirrors too.
        const bool left_handed = dot(cross(up, dir), right) > 0;
        if (c.angle > 0 && c.angle < 180 && c.projection == Projection::Perspective)
            dir = normalize(dir) * (0.5f * length(right) / std::tan(float(c.angle * M_PI / 360)));
        if (c.has_look_at && length(c.look_at - loc) > 0) {
            const float dl = length(dir), rl = length(right), ul = length(up);
            dir = normalize(c.look_at - loc) * dl;
            Vec3 r = cross(c.sky, dir);
            if (length(r) == 0) r = Vec3(1, 0, 0);
            right = normalize(r) * (left_handed ? rl : -rl);
            up = normalize(cross(dir, r)) * ul;
        }
        loc = c.transform.point(loc);
        dir = c.transform.vector(dir);
        up = c.transform.vector(up);
        Camera& out = scene.camera;
        const Vec3 view = perspective_view(c, dir, c.transform.vector(right), up, out);
        out.position = flip.point(loc);
        out.look_at = flip.point(loc + view);
        out.up = length(up) > 0 ? normalize(flip.vector(up)) : Vec3(0, 1, 0);
        out.mirror = dot(cross(up, dir), c.transform.vector(right)) < 0;
        // Screen space: the camera's transforms do not move its normal. POV-Ray takes the
        // pattern's gradient as a world vector, and MaterialBuilder::pattern puts the z mirror
        // between Sheaf's world and POV-Ray's into every pattern's transform (the screen
        // point, at z 0, stays where it is), so nothing more is needed here.
        if (c.normal && !geometry_only) out.normal = materials.normal(*c.normal, Affine());
        // POV-Ray maps |right| across the image and |up| down it, whatever the image's shape.
        // A ratio equal to image_width / image_height (right x * image_width / image_height)
        // follows the image the host renders, also when the host did not say its size.
        const float rl = length(c.transform.vector(right)), ul = length(up);
        const float image = float(p.options_.image_width) / float(p.options_.image_height);
        if (rl > 0 && ul > 0 && std::isfinite(rl / ul) &&
            std::fabs(rl / ul - image) > 1e-3f * image)
            out.aspect = rl / ul;
        out.projection = c.projection;
        if (c.projection == Projection::Mesh) mesh_camera(c, loc, dir);
        if (c.aperture > 0) {
            if (c.projection == Projection::Perspective ||
                c.projection == Projection::Orthographic) {
                // POV-Ray moves the eye up to a quarter of the aperture (half of it times
                // sample points within 1/2 of the centre) and keeps sharp the plane across the
                // view at the focal point's distance from the eye.
                out.lens_radius = float(0.25 * c.aperture);
                out.focal_distance = length(c.focal_point - c.location);
                if (!(out.focal_distance > 0))
                    p.error_at(c.aperture_at, "a camera with an aperture needs a focal_point "
                                              "away from its location");
            } else {
                p.unsupported(c.aperture_at, "focal blur with this camera type (ignored)");
            }
        }
        if (traced_projection(c.projection)) {
            // The angle is the projection's own (not a direction's length); the vectors'
            // lengths shape the view as they are.
            const bool spherical = c.projection == Projection::Spherical;
            out.angle_degrees = float(c.angle > 0 ? c.angle : spherical ? 360 : 90);
            out.v_angle_degrees = float(c.v_angle >= 0 ? c.v_angle
                                        : c.angle > 0  ? 0.5 * c.angle
                                                       : 180);
            if (!(out.v_angle_degrees > 0)) out.v_angle_degrees = 180;
            out.right_length = rl;
            out.up_length = ul;
            out.direction_length = length(dir);
            for (float l : {rl, ul, out.direction_length})
                if (!camera_length_ok(l))
                    p.error_at(c.type_at, "this camera's right, up and direction need lengths "
                                          "above 0 and below 1e6");
        } else if (c.projection == Projection::Orthographic) {
            out.ortho_height = length(up) > 0 ? length(up) : 1.0f;
            // POV-Ray sees the image area a perspective camera would at the look_at point's
            // distance (the default look_at's, <0, 0, 1>, when none is given) when an angle is
            // given, or when neither up nor right is: up and right grow by that distance over
            // the direction's length. The angle sets the width seen there.
            const float d = length(c.look_at - c.location);
            if (c.angle > 0 && c.angle < 180) {
                out.ortho_height = 2 * d * std::tan(float(c.angle * M_PI / 360)) * length(up) /
                                   std::max(length(right), 1e-6f);
            } else if (!c.has_up && !c.has_right && d > 0 && length(c.direction) > 0) {
                out.ortho_height *= d / length(c.direction);
            }
        } else {
            out.fov_y_degrees =
                float(2 * std::atan(0.5 * length(up) / std::max(length(view), 1e-6f)) * 180 / M_PI);
        }
    }
};

} // namespace

double build_scene(Parser& p, Scene& scene) {
    const PovModel& m = p.model;
    const double gamma = m.assumed_gamma > 0                     ? m.assumed_gamma
                         : (!m.version_given || m.version < 3.7) ? 2.2
                                                                 : 1.0;
    // POV-Ray computes in its working space: colours stay as written, and the frame's values
    // are light to the power of the gamma (Scene::working_gamma).
    scene.working_gamma = float(gamma);
    Builder b{p, scene, MaterialBuilder(p, scene), pov_to_sheaf(), {}, {}, 0};
    for (const PovObject& o : m.objects) b.top(o, m.default_texture, nullptr, nullptr, 0);
    b.add_loose();
    b.camera();
    scene.background = rgb(m.background);
    scene.sky = b.materials.sky(m.sky.pigments, m.sky.local);
    scene.sky_untinted = m.version < 3.695; // POV-Ray's sky sphere before 3.7
    if (!m.atmosphere.empty()) scene.atmosphere = int32_t(b.materials.atmosphere(m.atmosphere));
    scene.photons = m.photons;
    for (const PovModel::Rainbow& r : m.rainbows) {
        if (!r.colors || !(r.width != 0)) continue; // shows nothing, as in POV-Ray
        Rainbow out;
        const Vec3 dir = normalize(b.flip.vector(r.direction));
        const Vec3 right = normalize(cross(b.flip.vector(r.up), dir));
        out.antisolar = dir, out.right = right, out.up = normalize(cross(dir, right));
        const double rad = M_PI / 180;
        // POV-Ray's angle is the band's middle; a negative width turns the colours round.
        out.start = float((r.angle - r.width / 2) * rad), out.width = float(r.width * rad);
        out.distance = float(r.distance), out.jitter = float(r.jitter);
        // arc_angle and falloff_angle span both sides of up.
        out.arc = float(r.arc / 2 * rad), out.falloff = float(r.falloff / 2 * rad);
        out.colors = uint32_t(b.materials.sky({r.colors}, Affine()));
        scene.rainbows.push_back(out);
    }
    for (const PovModel::Fog& pf : m.fogs) {
        Fog& f = scene.fog.layer[scene.fog.count++];
        f.distance = float(pf.distance);
        f.color = rgb(pf.color);
        f.filter = float(std::clamp(pf.color[3], 0.0, 1.0));
        f.transmit = float(std::clamp(pf.color[4], 0.0, 1.0));
        f.alt = float(pf.alt);
        f.offset = float(pf.offset);
        f.up = normalize(b.flip.vector(pf.up));
        // The turbulence reads POV-Ray's point, whose z is Sheaf's mirrored.
        f.turb = Vec3(float(pf.turb.x), float(pf.turb.y), -float(pf.turb.z));
        f.octaves = pf.octaves;
        f.omega = float(pf.omega), f.lambda = float(pf.lambda);
        f.turb_depth = float(pf.turb_depth);
        f.noise_generator = m.noise_generator > 0 ? m.noise_generator : 2;
    }
    if (m.max_trace_level >= 0)
        scene.settings["trace.depth"] = std::to_string(std::clamp(m.max_trace_level - 1, 0, 64));
    // POV-Ray stops a ray whose share of its pixel falls below adc_bailout (1/255 unless the
    // scene says): deep glass (advanced/blocks/stackertransp.pov, max_trace_level 50) would
    // otherwise trace far more rays than POV-Ray, and paint them.
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", m.adc_bailout);
        scene.settings["trace.bailout"] = text;
    }
    if (scene.camera.lens_radius > 0) {
        // Focal blur takes its samples as anti-aliasing does: blur_samples (16 when not given).
        const std::string n =
            aa_samples_for(m.camera.blur_samples > 0 ? m.camera.blur_samples : 16);
        scene.settings["aa.samples"] = n;
        p.approximated(m.camera.aperture_at,
                       "focal blur: every pixel takes " + n + " x " + n +
                           " samples, where POV-Ray stops once its samples agree (confidence, "
                           "variance): the blur's grain differs, and it takes longer");
    }
    if (m.radiosity) {
        scene.settings["radiosity.samples"] = std::to_string(m.radiosity_count);
        scene.settings["radiosity.depth"] = std::to_string(m.radiosity_depth);
        scene.settings["radiosity.brightness"] =
            canonical_setting("radiosity.brightness", std::to_string(m.radiosity_brightness));
    }
    return gamma;
}

void build_object_geometry(Parser& p, const PovObject& o, Scene& scene) {
    scene.add_material(Material{});
    p.captures_.emplace_back(); // its warnings were given where it was made
    Builder b{p, scene, MaterialBuilder(p, scene), pov_to_sheaf(), {}, {}, 0, true};
    try {
        b.top(o, p.model.default_texture, nullptr, nullptr, 0);
        b.add_loose();
    } catch (...) {
        p.captures_.pop_back();
        throw;
    }
    p.captures_.pop_back();
}

} // namespace sheaf::io::pov

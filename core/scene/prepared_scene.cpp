#include "core/scene/prepared_scene.h"

#include "core/geometry/blob_build.h"
#include "core/geometry/min_sphere.h"
#include "core/hash/ray_hash.h"
#include "core/scene/analytic.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>
#include <utility>

namespace sheaf {

namespace {

/// The index of `key`'s entry in `refs`, made by `make()` (which also appends the data the
/// entry points into) on the key's first use: shapes that share an outline, a profile or a
/// blob share its tables (a text's repeated characters share one outline).
template <class Key, class Ref, class Make>
uint32_t shared_index(std::map<const Key*, uint32_t>& seen, const Key& key, std::vector<Ref>& refs,
                      Make&& make) {
    const auto [it, fresh] = seen.emplace(&key, uint32_t(refs.size()));
    if (fresh) refs.push_back(make());
    return it->second;
}

GlyphRef glyph_ref(PreparedScene& p, const GlyphOutline& g) {
    GlyphRef r;
    r.first = uint32_t(p.glyph_segments.size());
    r.count = uint32_t(g.segments.size());
    r.lo_x = r.lo_y = FLT_MAX, r.hi_x = r.hi_y = -FLT_MAX;
    for (const GlyphSegment& s : g.segments) {
        for (float x : {s.x0, s.x1, s.x2})
            r.lo_x = std::fmin(r.lo_x, x), r.hi_x = std::fmax(r.hi_x, x);
        for (float y : {s.y0, s.y1, s.y2})
            r.lo_y = std::fmin(r.lo_y, y), r.hi_y = std::fmax(r.hi_y, y);
        p.glyph_segments.push_back(s);
    }
    if (g.segments.empty()) r.lo_x = r.lo_y = r.hi_x = r.hi_y = 0;
    r.even_odd = g.even_odd ? 1 : 0;
    return r;
}

RevolutionRef revolution_ref(PreparedScene& p, const RevolutionProfile& g) {
    RevolutionRef r;
    r.first = uint32_t(p.revolution_segments.size());
    r.count = uint32_t(g.segments.size());
    r.squared = g.squared ? 1 : 0;
    revolution_bounds(g, r.r_max, r.h_lo, r.h_hi);
    p.revolution_segments.insert(p.revolution_segments.end(), g.segments.begin(), g.segments.end());
    return r;
}

BlobRef blob_ref(PreparedScene& p, const BlobModel& g) {
    BlobRef b;
    b.first = uint32_t(p.blob_elements.size());
    b.count = uint32_t(g.elements.size());
    b.threshold = g.threshold;
    blob_bound(g, b.bound);
    p.blob_elements.insert(p.blob_elements.end(), g.elements.begin(), g.elements.end());
    return b;
}

// An isosurface with the sphere around its container.
IsoRef iso_ref(const IsoRef& g) {
    IsoRef r = g;
    const Vec3 c = g.sphere ? g.lo : (g.lo + g.hi) * 0.5f;
    const float radius = g.sphere ? g.hi.x : length(g.hi - g.lo) * 0.5f;
    r.bound[0] = c.x, r.bound[1] = c.y, r.bound[2] = c.z, r.bound[3] = radius;
    return r;
}

// Puts triangles [b, e) of one object in the Morton order of their centroids within the
// object's box (ties in the mesh's order), so that runs of consecutive primitives are compact
// whatever order the mesh came in: cull.cluster culls such runs (core/rsh/cull_units.h).
void spatial_order(PreparedScene& p, size_t b, size_t e) {
    if (e - b < 3) return;
    auto centroid = [&](size_t i) {
        return (p.tris[i].a + p.tris[i].b + p.tris[i].c) * (1.0f / 3.0f);
    };
    Vec3 lo(FLT_MAX), hi(-FLT_MAX);
    for (size_t i = b; i < e; ++i) lo = vmin(lo, centroid(i)), hi = vmax(hi, centroid(i));
    const Vec3 ext = hi - lo;
    auto cell = [](float v, float l, float x) {
        return x > 0 ? uint32_t(std::clamp((v - l) / x, 0.0f, 1.0f) * 1023.0f) : 0u;
    };
    std::vector<std::pair<uint32_t, uint32_t>> order(e - b);
    for (size_t i = b; i < e; ++i) {
        const Vec3 c = centroid(i);
        order[i - b] = {
            morton3(cell(c.x, lo.x, ext.x), cell(c.y, lo.y, ext.y), cell(c.z, lo.z, ext.z)),
            uint32_t(i)};
    }
    std::sort(order.begin(), order.end());
    auto permute = [&](auto& v) {
        if (v.empty()) return; // normals or texture coordinates no mesh has
        std::vector<std::decay_t<decltype(v[0])>> tmp(e - b);
        for (size_t k = 0; k < e - b; ++k) tmp[k] = v[order[k].second];
        std::copy(tmp.begin(), tmp.end(), v.begin() + std::ptrdiff_t(b));
    };
    permute(p.tris);
    permute(p.normals);
    permute(p.uvs);
    permute(p.prim_sphere);
}

// Whether a pigment has filter or transmit anywhere (entries and nested pigments included).
bool pigment_may_pass(const Scene& s, int32_t index, int depth = 0) {
    if (index < 0 || depth > 16) return false;
    const Pigment& pg = s.pigments[size_t(index)];
    if (pg.solid) return pg.color[3] > 0 || pg.color[4] > 0;
    // An image seen once is clear off the image.
    if (pg.pattern.kind == PatternKind::Image && pg.pattern.image >= 0 &&
        size_t(pg.pattern.image) < s.textures.size() && s.textures[size_t(pg.pattern.image)].once)
        return true;
    for (uint32_t e = pg.first; e < pg.first + pg.count; ++e) {
        const PigmentEntry& en = s.pigment_entries[e];
        if (en.pigment >= 0 ? pigment_may_pass(s, en.pigment, depth + 1)
                            : en.color[3] > 0 || en.color[4] > 0)
            return true;
    }
    return false;
}

// Whether `test` holds for material m or, when m is a texture map's switch, for any material
// the switch leads to (16 levels deep at most).
template <class Test>
bool any_material(const Scene& s, uint32_t m, const Test& test, int depth = 0) {
    const Material& mt = s.materials[m];
    if (depth > 16) return false;
    if (mt.select < 0) return test(mt);
    const MaterialSwitch& sw = s.material_switches[size_t(mt.select)];
    for (uint32_t e = sw.first; e < sw.first + sw.count; ++e)
        if (any_material(s, s.material_entries[e].material, test, depth + 1)) return true;
    return false;
}

// Whether material m, or a material its texture maps lead to, holds media.
bool has_media(const Scene& s, uint32_t m) {
    return any_material(s, m, [](const Material& mt) { return mt.media_count > 0; });
}

} // namespace

bool material_may_pass(const Scene& s, uint32_t m) {
    return any_material(s, m, [&](const Material& mt) {
        return mt.pigment >= 0 ? pigment_may_pass(s, mt.pigment) : mt.transmission > 0;
    });
}

void copy_texture_tables(const Scene& scene, PreparedScene& p) {
    p.materials = scene.materials;
    p.pigments = scene.pigments;
    p.pigment_entries = scene.pigment_entries;
    p.normal_patterns = scene.normal_patterns;
    p.slope_entries = scene.slope_entries;
    p.normal_map_entries = scene.normal_map_entries;
    p.material_switches = scene.material_switches;
    p.warps = scene.warps;
    p.material_entries = scene.material_entries;
    p.media = scene.media;
    p.medium_densities = scene.medium_densities;
    p.density_grids = scene.density_grids;
    p.density_voxels = scene.density_voxels;
    p.fn_programs = scene.fn_programs;
    p.fn_code = scene.fn_code;
    p.fn_patterns = scene.fn_patterns;
    p.fn_pigments = scene.fn_pigments;
    p.fn_pigment_entries = scene.fn_pigment_entries;
    p.working_gamma = scene.working_gamma;
    p.textures = scene.textures;
}

PreparedScene prepare_scene(const Scene& scene) {
    scene.validate();
    PreparedScene p;
    const size_t n = scene.triangle_count();
    p.tris.resize(n);
    // Vertex normals and texture coordinates only where some mesh has them (96 bytes a
    // triangle otherwise spent on zeros): empty arrays, null pointers in SceneView.
    bool any_normals = false, any_uvs = false;
    for (const Object& obj : scene.objects) {
        any_normals = any_normals || !scene.meshes[obj.mesh].normals.empty();
        any_uvs = any_uvs || !scene.meshes[obj.mesh].uvs.empty();
    }
    if (any_normals) p.normals.resize(n);
    if (any_uvs) p.uvs.resize(n);
    p.prim_object.resize(n);
    p.prim_sphere.resize(n);
    p.object_begin.reserve(scene.objects.size() + 1);
    p.object_begin.push_back(0);

    size_t base = 0;
    std::vector<Vec3> world;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const Mesh& mesh = scene.meshes[obj.mesh];
        world.resize(mesh.positions.size());
        for (size_t i = 0; i < world.size(); ++i) world[i] = obj.transform.point(mesh.positions[i]);
        const bool smooth = !mesh.normals.empty();
        const size_t tc = mesh.triangle_count();
        tbb::parallel_for(size_t(0), tc, [&](size_t t) {
            const uint32_t* ix = &mesh.indices[3 * t];
            TriangleVerts tv{world[ix[0]], world[ix[1]], world[ix[2]]};
            p.tris[base + t] = tv;
            p.prim_sphere[base + t] = triangle_sphere(tv.a, tv.b, tv.c);
            p.prim_object[base + t] = uint32_t(o);
            TriangleNormals tn{};
            if (smooth) {
                tn.na = obj.transform.normal(mesh.normals[ix[0]]);
                tn.nb = obj.transform.normal(mesh.normals[ix[1]]);
                tn.nc = obj.transform.normal(mesh.normals[ix[2]]);
            }
            if (any_normals) p.normals[base + t] = tn;
            TriangleUvs tu{};
            if (!mesh.uvs.empty())
                for (int k = 0; k < 3; ++k)
                    tu.s[k] = mesh.uvs[2 * ix[k]], tu.t[k] = mesh.uvs[2 * ix[k] + 1];
            if (any_uvs) p.uvs[base + t] = tu;
        });
        spatial_order(p, base, base + tc);
        base += tc;
        p.object_begin.push_back(uint32_t(base));
        // Only the vertices the object's triangles use count towards its sphere.
        std::vector<char> used(world.size(), 0);
        for (uint32_t i : mesh.indices) used[i] = 1;
        std::vector<Vec3> pts;
        pts.reserve(world.size());
        for (size_t i = 0; i < world.size(); ++i)
            if (used[i]) pts.push_back(world[i]);
        p.object_sphere.push_back(min_sphere(pts));
        p.object_material.push_back(obj.material);
        p.object_name.push_back(obj.name);
        p.object_photons.push_back(obj.photons);
    }
    // Analytic objects: one primitive each, its CSG tree flattened into the scene's arrays.
    std::map<const GlyphOutline*, uint32_t> glyphs_seen;
    std::map<const RevolutionProfile*, uint32_t> revolutions_seen;
    std::map<const BlobModel*, uint32_t> blobs_seen;
    std::map<const IsoRef*, uint32_t> isos_seen;
    for (size_t so = 0; so < scene.shape_objects.size(); ++so) {
        const ShapeObject& obj = scene.shape_objects[so];
        const uint32_t base = uint32_t(p.csg.size());
        p.csg.resize(base + obj.nodes.size());
        uint32_t first_material = 0;
        bool have_material = false;
        bool holds_media = false; // some leaf's material (or a texture map's) has media
        for (size_t i = 0; i < obj.nodes.size(); ++i) {
            const CsgNode& node = obj.nodes[i];
            PreparedCsgNode& out = p.csg[base + i];
            out.op = node.op;
            out.inverse = node.inverse;
            if (node.op == CsgOp::Leaf) {
                out.first = uint32_t(p.shapes.size());
                out.count = 0;
                Shape shape = node.shape;
                if (shape.kind == ShapeKind::Poly) {
                    shape.index = uint32_t(p.polys.size());
                    p.polys.push_back(*node.poly);
                }
                if (shape.kind == ShapeKind::Julia) {
                    shape.index = uint32_t(p.julias.size());
                    p.julias.push_back(*node.julia);
                }
                if (shape.kind == ShapeKind::Glyph)
                    shape.index = shared_index(glyphs_seen, *node.glyph, p.glyphs,
                                               [&] { return glyph_ref(p, *node.glyph); });
                if (shape.kind == ShapeKind::Revolution)
                    shape.index = shared_index(revolutions_seen, *node.revolution, p.revolutions,
                                               [&] { return revolution_ref(p, *node.revolution); });
                if (shape.kind == ShapeKind::Blob)
                    shape.index = shared_index(blobs_seen, *node.blob, p.blobs,
                                               [&] { return blob_ref(p, *node.blob); });
                if (shape.kind == ShapeKind::Isosurface)
                    shape.index = shared_index(isos_seen, *node.iso, p.isosurfaces,
                                               [&] { return iso_ref(*node.iso); });
                p.shapes.push_back(place_shape(shape, obj.transform * node.transform));
                p.shape_material.push_back(node.material);
                if (!have_material) first_material = node.material, have_material = true;
                holds_media = holds_media || has_media(scene, node.material);
            } else {
                out.first = uint32_t(p.csg_children.size());
                out.count = uint32_t(node.children.size());
                for (uint32_t c : node.children) p.csg_children.push_back(base + c);
            }
        }
        const uint32_t root = base + obj.root;
        if (holds_media) p.media_containers.push_back(uint32_t(p.analytic_root.size()));
        p.analytic_root.push_back(root);
        Sphere bound = set_csg_boxes(p, root);
        WorldBox box = p.csg[root].box;
        // bounded_by: its box where it meets the object's own (parts apart: a point), and the
        // sphere around it where that is smaller.
        const WorldBox& given = obj.bound;
        box.lo = vmax(box.lo, given.lo), box.hi = vmin(box.hi, given.hi);
        if (box.lo.x > box.hi.x || box.lo.y > box.hi.y || box.lo.z > box.hi.z) box.hi = box.lo;
        if (max_component(vabs(given.lo)) < INFINITY && max_component(vabs(given.hi)) < INFINITY) {
            const Vec3 c = (given.lo + given.hi) * 0.5f;
            const float r =
                given.lo.x > given.hi.x || given.lo.y > given.hi.y || given.lo.z > given.hi.z
                    ? 0.0f
                    : pad_radius(length(given.hi - given.lo) * 0.5f, c);
            if (r < bound.radius) bound = {c, r};
        }
        p.analytic_box.push_back(box);
        p.prim_sphere.push_back(bound);
        p.prim_object.push_back(uint32_t(p.object_sphere.size()));
        p.object_sphere.push_back(bound);
        p.object_material.push_back(first_material);
        p.object_name.push_back(obj.name);
        p.object_photons.push_back(obj.photons);
        p.object_begin.push_back(uint32_t(p.tris.size() + p.analytic_root.size()));
    }
    p.atmosphere = scene.atmosphere;
    // Fog that fades a light's shadow rays fills only what is outside solid objects too
    // (fog_transmittance, core/shading/media.h).
    const bool fogged_lights =
        scene.fog.any() &&
        std::any_of(scene.lights.begin(), scene.lights.end(),
                    [](const Light& l) { return l.media_attenuation && l.media_interaction; });
    if (p.has_media() || fogged_lights)
        for (size_t so = 0; so < scene.shape_objects.size(); ++so) {
            if (!(scene.shape_objects[so].flags & kSolid)) continue;
            if (p.atmosphere >= 0 || fogged_lights) { // the atmosphere (fog) is everywhere
                p.media_solids.push_back(uint32_t(so));
                continue;
            }
            const Sphere& s = p.prim_sphere[p.tris.size() + so];
            for (uint32_t c : p.media_containers) {
                const Sphere& b = p.prim_sphere[p.tris.size() + c];
                if (!(std::fabs(s.radius) <= FLT_MAX) || !(std::fabs(b.radius) <= FLT_MAX) ||
                    length(s.center - b.center) <= s.radius + b.radius) {
                    p.media_solids.push_back(uint32_t(so));
                    break;
                }
            }
        }
    // A BVH over the solid objects in media, so that a ray through the media meets only
    // those on its way (leave_solids; a fog over a whole landscape has thousands).
    if (!p.media_solids.empty()) {
        std::vector<uint32_t> prims;
        for (uint32_t so : p.media_solids) prims.push_back(uint32_t(p.tris.size()) + so);
        p.media_solid_bvh = build_bvh_over(p, prims);
    }
    p.prim_flags.resize(p.prim_count());
    std::vector<char> passes(scene.materials.size());
    for (size_t m = 0; m < passes.size(); ++m) passes[m] = material_may_pass(scene, uint32_t(m));
    // With photons on, a target they refract through casts a whole shadow, as in POV-Ray:
    // the light through it comes as photons. POV-Ray decides per light; here a target is
    // whole for every light when some light's photons refract through it.
    auto photon_shadow = [&](const PhotonObject& po, uint8_t flags) {
        if (!scene.photons.enabled() || !(po.target > 0) || (flags & kPassPhotons)) return false;
        for (const Light& l : scene.lights)
            if (!l.shadowless && photon_switch_on(po.refraction, l.photon_refraction)) return true;
        return false;
    };
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const bool may_pass = passes[scene.objects[o].material] &&
                              !photon_shadow(scene.objects[o].photons, scene.objects[o].flags);
        const uint8_t f = uint8_t(scene.objects[o].flags | (may_pass ? kPrimMayPass : 0));
        for (uint32_t i = p.object_begin[o]; i < p.object_begin[o + 1]; ++i) p.prim_flags[i] = f;
    }
    for (size_t so = 0; so < scene.shape_objects.size(); ++so) {
        uint8_t f = scene.shape_objects[so].flags;
        if (!photon_shadow(scene.shape_objects[so].photons, f))
            for (const CsgNode& n : scene.shape_objects[so].nodes)
                if (n.op == CsgOp::Leaf && passes[n.material]) f |= kPrimMayPass;
        for (const CsgNode& n : scene.shape_objects[so].nodes)
            if (n.op == CsgOp::Clip) f |= kPrimOpen;
        p.prim_flags[p.tris.size() + so] = f;
    }
    copy_texture_tables(scene, p);
    p.sky = scene.sky;
    p.sky_untinted = scene.sky_untinted;
    p.fog = scene.fog;
    p.rainbows = scene.rainbows;
    p.photons = scene.photons;
    p.lights = scene.lights;
    p.camera = scene.camera;
    prepare_camera_faces(scene, p);
    p.background = scene.background;
    p.settings = scene.settings;
    p.cull_units_cache = new_cull_units_cache();
    p.bvh_cache = new_bvh_cache();
    p.strips_cache = new_strips_cache();
    return p;
}

} // namespace sheaf

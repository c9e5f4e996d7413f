#include "core/scene/scene.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace sheaf {

uint32_t Scene::add_mesh(Mesh mesh) {
    meshes.push_back(std::move(mesh));
    return uint32_t(meshes.size() - 1);
}
uint32_t Scene::add_material(const Material& m) {
    materials.push_back(m);
    return uint32_t(materials.size() - 1);
}
uint32_t Scene::add_object(Object o) {
    objects.push_back(std::move(o));
    return uint32_t(objects.size() - 1);
}
uint32_t Scene::add_light(const Light& l) {
    lights.push_back(l);
    return uint32_t(lights.size() - 1);
}
uint32_t Scene::add_mesh_object(std::string name, Mesh mesh, uint32_t material, const Affine& t) {
    Object o;
    o.name = std::move(name);
    o.mesh = add_mesh(std::move(mesh));
    o.material = material;
    o.transform = t;
    return add_object(std::move(o));
}

uint32_t Scene::add_shape(std::string name, const Shape& shape, uint32_t material,
                          const Affine& transform) {
    ShapeObject o;
    o.name = std::move(name);
    CsgNode leaf;
    leaf.shape = shape;
    leaf.material = material;
    o.nodes.push_back(leaf);
    o.transform = transform;
    return add_shape_object(std::move(o));
}

uint32_t Scene::add_shape_object(ShapeObject o) {
    shape_objects.push_back(std::move(o));
    return uint32_t(shape_objects.size() - 1);
}

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Object& o : objects) n += meshes[o.mesh].triangle_count();
    return n;
}

namespace {
std::string where(size_t mesh) {
    return "mesh " + std::to_string(mesh);
}

constexpr const char* kMaxCoordinateText = "1e12";

/// A mesh's bounding box: lo > hi when it has no vertex.
struct MeshBox {
    Vec3 lo{1.0f}, hi{-1.0f};
};
MeshBox box_of(const Mesh& mesh) {
    if (mesh.positions.empty()) return {};
    MeshBox b{mesh.positions[0], mesh.positions[0]};
    for (const Vec3& p : mesh.positions) b.lo = vmin(b.lo, p), b.hi = vmax(b.hi, p);
    return b;
}

/// Whether the mesh's bounding box, placed by `t`, lies within reach (kMaxCoordinate).
bool object_within_reach(const MeshBox& box, const Affine& t) {
    if (box.lo.x > box.hi.x) return true;
    const Vec3 lo = box.lo, hi = box.hi;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z);
        if (!within_reach(t.point(p))) return false;
    }
    return true;
}
} // namespace

int csg_nesting(const ShapeObject& o) {
    // Children are later nodes: heights from the last node back.
    std::vector<int> height(o.nodes.size(), 0);
    for (size_t n = o.nodes.size(); n-- > 0;)
        for (uint32_t c : o.nodes[n].children) height[n] = std::max(height[n], height[c] + 1);
    return o.root < height.size() ? height[o.root] : 0;
}

void validate_mesh(const Mesh& mesh, const std::string& what) {
    if (mesh.indices.empty()) throw SceneError(what + ": the mesh has no faces");
    if (mesh.indices.size() % 3 != 0)
        throw SceneError(what + ": " + std::to_string(mesh.indices.size()) +
                         " triangle indices are not a multiple of 3");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (!is_finite(mesh.positions[i]))
            throw SceneError(what + ": vertex " + std::to_string(i) +
                             " is not finite (NaN or infinity)");
        if (!within_reach(mesh.positions[i]))
            throw SceneError(what + ": vertex " + std::to_string(i) + " lies farther than " +
                             kMaxCoordinateText + " from the origin");
    }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
        throw SceneError(what + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                         std::to_string(mesh.positions.size()) + " vertices");
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        if (!is_finite(mesh.normals[i]))
            throw SceneError(what + ": normal " + std::to_string(i) +
                             " is not finite (NaN or infinity)");
    if (!mesh.uvs.empty() && mesh.uvs.size() != 2 * mesh.positions.size())
        throw SceneError(what + ": " + std::to_string(mesh.uvs.size() / 2) +
                         " texture coordinates for " + std::to_string(mesh.positions.size()) +
                         " vertices");
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i]))
            throw SceneError(what + ": the texture coordinate of vertex " + std::to_string(i / 2) +
                             " is not finite");
    for (size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.positions.size())
            throw SceneError(what + ": triangle " + std::to_string(i / 3) + " names vertex " +
                             std::to_string(mesh.indices[i]) + ", out of range (" +
                             std::to_string(mesh.positions.size()) + " vertices)");
}

namespace {

/// Throws SceneError where the mesh camera's meshes and settings do not fit together.
void validate_mesh_camera(const Camera& c, const std::vector<CameraMesh>& meshes) {
    if (meshes.empty()) throw SceneError("a mesh camera needs at least one mesh");
    for (size_t m = 0; m < meshes.size(); ++m)
        validate_mesh(meshes[m].mesh, "the camera's mesh " + std::to_string(m));
    if (c.mesh_distribution > 3)
        throw SceneError("a mesh camera's distribution must be 0, 1, 2 or 3, not " +
                         std::to_string(c.mesh_distribution));
    if (c.mesh_rays < 1 || c.mesh_rays > kMaxMeshCameraRays)
        throw SceneError("a mesh camera takes 1 to " + std::to_string(kMaxMeshCameraRays) +
                         " rays per pixel, not " + std::to_string(c.mesh_rays));
    if (c.mesh_distribution == 0 && c.mesh_rays > meshes.size())
        throw SceneError("a mesh camera of distribution 0 takes at most one ray per pixel per "
                         "mesh (" +
                         std::to_string(c.mesh_rays) + " rays, " + std::to_string(meshes.size()) +
                         " meshes)");
    if (c.mesh_distribution >= 2 && c.mesh_rays != 1)
        throw SceneError("a mesh camera of distribution 2 or 3 takes one ray per pixel");
    if (c.mesh_smooth && c.mesh_distribution != 3)
        throw SceneError("a mesh camera's smooth needs distribution 3");
    if (c.mesh_distribution == 3 && meshes[0].mesh.uvs.empty())
        throw SceneError("a mesh camera of distribution 3 needs its first mesh's uv coordinates");
    if (!std::isfinite(c.mesh_offset)) throw SceneError("the mesh camera's offset is not finite");
}

} // namespace

void Scene::validate() const {
    for (size_t m = 0; m < meshes.size(); ++m) validate_mesh(meshes[m], where(m));
    // Each mesh's box once: many objects may place one mesh.
    std::vector<MeshBox> boxes;
    if (!objects.empty())
        for (const Mesh& m : meshes) boxes.push_back(box_of(m));
    for (size_t o = 0; o < objects.size(); ++o) {
        const Object& obj = objects[o];
        const std::string name =
            "object " + std::to_string(o) + (obj.name.empty() ? "" : " '" + obj.name + "'");
        if (obj.mesh >= meshes.size())
            throw SceneError(name + " names mesh " + std::to_string(obj.mesh) +
                             ", which does not exist");
        if (obj.material >= materials.size())
            throw SceneError(name + " names material " + std::to_string(obj.material) +
                             ", which does not exist");
        if (!obj.transform.finite()) throw SceneError(name + " has a transform that is not finite");
        if (!object_within_reach(boxes[obj.mesh], obj.transform))
            throw SceneError(name + " reaches farther than " + kMaxCoordinateText +
                             " from the origin once placed");
    }
    for (size_t o = 0; o < shape_objects.size(); ++o) {
        const ShapeObject& so = shape_objects[o];
        const std::string name =
            "shape object " + std::to_string(o) + (so.name.empty() ? "" : " '" + so.name + "'");
        if (so.nodes.empty() || so.root >= so.nodes.size())
            throw SceneError(name + " has no root node");
        for (size_t n = 0; n < so.nodes.size(); ++n) {
            const CsgNode& node = so.nodes[n];
            if (node.op == CsgOp::Leaf) {
                if (node.material >= materials.size())
                    throw SceneError(name + " names material " + std::to_string(node.material) +
                                     ", which does not exist");
                const Shape& s = node.shape;
                if (!std::isfinite(s.a) || !std::isfinite(s.b) || s.a < 0 || s.b < 0 ||
                    (s.kind == ShapeKind::Cone && s.a == 0 && s.b == 0) ||
                    (s.kind == ShapeKind::Disc && s.a > 1) ||
                    (s.kind == ShapeKind::Torus && !(s.a > 0)) ||
                    (s.kind == ShapeKind::Superellipsoid && !(s.a >= 1e-3f && s.b >= 1e-3f)))
                    throw SceneError(name + ": shape parameters out of range");
                if (s.kind == ShapeKind::Poly) {
                    if (!node.poly) throw SceneError(name + ": a poly shape without coefficients");
                    for (double c : node.poly->c)
                        if (!std::isfinite(c))
                            throw SceneError(name + ": a poly coefficient is not finite");
                    if (poly_is_zero(*node.poly))
                        throw SceneError(name + ": a poly shape whose coefficients are all zero");
                }
                if (s.kind == ShapeKind::Glyph) {
                    if (!node.glyph) throw SceneError(name + ": a glyph shape without an outline");
                    if (node.glyph->segments.size() > kMaxGlyphSegments)
                        throw SceneError(name + ": a glyph of more than " +
                                         std::to_string(kMaxGlyphSegments) + " segments");
                    for (const GlyphSegment& g : node.glyph->segments)
                        for (float v : {g.x0, g.y0, g.x1, g.y1, g.x2, g.y2})
                            if (!std::isfinite(v))
                                throw SceneError(name + ": a glyph's outline is not finite");
                    if (s.b > 0 && !(s.a >= 0 && s.a <= 1))
                        throw SceneError(name + ": a conic glyph's base scale is not in [0, 1]");
                }
                if (s.kind == ShapeKind::Revolution) {
                    if (!node.revolution)
                        throw SceneError(name + ": a revolution shape without a profile");
                    for (const RevolutionSegment& g : node.revolution->segments) {
                        if (g.wdeg < 1 || g.wdeg > 3 || g.hdeg < 1 || g.hdeg > 3)
                            throw SceneError(name + ": a profile segment of degree not 1 to 3");
                        for (int i = 0; i < 4; ++i)
                            if (!std::isfinite(g.w[i]) || !std::isfinite(g.h[i]))
                                throw SceneError(name + ": a revolution's profile is not finite");
                    }
                }
                if (s.kind == ShapeKind::Blob) {
                    if (!node.blob) throw SceneError(name + ": a blob shape without components");
                    if (!(node.blob->threshold > 0) || !std::isfinite(node.blob->threshold))
                        throw SceneError(name + ": a blob's threshold must be a positive number");
                    for (const BlobElement& e : node.blob->elements)
                        if (!e.to_unit.finite() || !std::isfinite(e.strength) ||
                            !std::isfinite(e.len) || !(e.len >= 0))
                            throw SceneError(name + ": a blob's component is not finite");
                }
                if (s.kind == ShapeKind::Julia) {
                    if (!node.julia)
                        throw SceneError(name + ": a julia fractal without parameters");
                    const JuliaFractal& j = *node.julia;
                    bool finite = std::isfinite(j.slice_dist) && std::isfinite(j.min_step);
                    for (int i = 0; i < 4; ++i)
                        finite = finite && std::isfinite(j.c[i]) && std::isfinite(j.slice[i]);
                    if (!finite)
                        throw SceneError(name + ": a julia fractal's parameters are not finite");
                    if (!(std::fabs(j.slice[3]) >= 1e-10))
                        throw SceneError(name + ": a julia fractal's slice has no w component");
                    if (!(j.min_step > 0 && j.min_step <= 1))
                        throw SceneError(name + ": a julia fractal's precision must be 1 or more");
                    if (j.iterations < 1 || j.iterations > kJuliaMaxIterations)
                        throw SceneError(name +
                                         ": a julia fractal's max_iteration must lie in 1.." +
                                         std::to_string(kJuliaMaxIterations));
                }
                if (s.kind == ShapeKind::Isosurface) {
                    if (!node.iso) throw SceneError(name + ": an isosurface without a function");
                    const IsoRef& iso = *node.iso;
                    if (!std::isfinite(iso.threshold) || !(iso.max_gradient > 0) ||
                        !std::isfinite(iso.max_gradient) || !(iso.accuracy > 0) ||
                        !std::isfinite(iso.accuracy) || !is_finite(iso.lo) || !is_finite(iso.hi))
                        throw SceneError(name + ": an isosurface's threshold, max_gradient, "
                                                "accuracy or container is not a finite number "
                                                "(max_gradient and accuracy > 0)");
                    if (iso.sphere
                            ? !(iso.hi.x > 0)
                            : !(iso.lo.x < iso.hi.x && iso.lo.y < iso.hi.y && iso.lo.z < iso.hi.z))
                        throw SceneError(name + ": an isosurface's container is empty");
                }
                if (!node.transform.finite())
                    throw SceneError(name + ": a shape's transform is not finite");
                if (!(std::fabs(node.transform.determinant()) >= 1e-20f))
                    throw SceneError(name + ": a shape's transform is singular (a zero scale)");
            } else {
                if (node.children.empty())
                    throw SceneError(name + ": a CSG operation without children");
                if (node.op == CsgOp::Clip && node.children.size() < 2)
                    throw SceneError(name + ": a clip needs the clipped node and a clipping one");
                for (uint32_t c : node.children)
                    if (c >= so.nodes.size() || c <= n)
                        throw SceneError(name + ": CSG child " + std::to_string(c) +
                                         " must be a later node of the object");
            }
        }
        if (!so.transform.finite()) throw SceneError(name + " has a transform that is not finite");
        if (!(std::fabs(so.transform.determinant()) >= 1e-20f))
            throw SceneError(name + " has a singular transform");
        if (const int nesting = csg_nesting(so); nesting > kMaxCsgNesting)
            throw SceneError(name + ": CSG nested " + std::to_string(nesting) +
                             " levels deep, more than " + std::to_string(kMaxCsgNesting));
    }
    for (size_t l = 0; l < lights.size(); ++l) {
        const Light& li = lights[l];
        const std::string name = "light " + std::to_string(l);
        if (!is_finite(li.position) || !is_finite(li.color) || !is_finite(li.direction) ||
            !std::isfinite(li.spot_radius) || !std::isfinite(li.spot_falloff) ||
            !std::isfinite(li.spot_tightness) || !std::isfinite(li.fade_distance) ||
            !std::isfinite(li.fade_power))
            throw SceneError(name + " is not finite");
        if (!within_reach(li.position) || !within_reach(li.direction))
            throw SceneError(name + "'s position or direction lies farther than " +
                             kMaxCoordinateText + " from the origin");
        if (li.type != LightType::Point && length(li.direction) <= 0)
            throw SceneError(name + " has no direction");
        if (li.type == LightType::Spot &&
            !(li.spot_radius >= 0 && li.spot_falloff > 0 && li.spot_falloff <= 180))
            throw SceneError(name +
                             ": a spot light needs 0 <= radius and 0 < falloff <= 180 degrees");
        if (li.fade_distance < 0 || li.fade_power < 0)
            throw SceneError(name + ": fade distance and power must be >= 0");
        if (li.group > kMaxLightGroup)
            throw SceneError(name + ": a light group above " + std::to_string(kMaxLightGroup));
    }
    if (!is_finite(background)) throw SceneError("the background colour is not finite");
    const Camera& c = camera;
    if (!is_finite(c.position) || !is_finite(c.look_at) || !is_finite(c.up))
        throw SceneError("the camera is not finite");
    if (!within_reach(c.position) || !within_reach(c.look_at) || !within_reach(c.up))
        throw SceneError(std::string("the camera's position, look_at or up lies farther than ") +
                         kMaxCoordinateText + " from the origin");
    if (length(c.look_at - c.position) <= 0)
        throw SceneError("the camera looks at its own position");
    if (length(cross(c.look_at - c.position, c.up)) <= 0)
        throw SceneError("the camera's up vector is parallel to its view");
    if (c.projection == Projection::Perspective &&
        !(c.fov_y_degrees > 0 && c.fov_y_degrees < 180)) {
        char fov[32];
        std::snprintf(fov, sizeof fov, "%g", double(c.fov_y_degrees));
        throw SceneError(std::string("the camera's field of view (") + fov +
                         " degrees) must lie in (0, 180) degrees");
    }
    if (c.projection == Projection::Orthographic &&
        !(c.ortho_height > 0 && std::isfinite(c.ortho_height)))
        throw SceneError("an orthographic camera needs a view height > 0");
    if (traced_projection(c.projection)) {
        if (!camera_angle_ok(c.angle_degrees) || !camera_angle_ok(c.v_angle_degrees))
            throw SceneError("the camera's angles must lie in (0, 3600] degrees");
        for (float l : {c.right_length, c.up_length, c.direction_length})
            if (!camera_length_ok(l))
                throw SceneError("the camera's right, up and direction lengths must be finite "
                                 "numbers > 0");
    }
    if (c.projection == Projection::Mesh) validate_mesh_camera(c, camera_meshes);
    if (c.normal >= int32_t(normal_patterns.size()))
        throw SceneError("the camera's normal pattern does not exist");
    if (!(c.lens_radius >= 0 && c.lens_radius < 1e30f) ||
        (c.lens_radius > 0 && !(c.focal_distance > 0 && c.focal_distance < 1e30f)))
        throw SceneError("the camera's lens radius must be finite and >= 0, and with a lens its "
                         "focal distance finite and > 0");
    if (c.lens_radius > 0 && c.projection != Projection::Perspective &&
        c.projection != Projection::Orthographic)
        throw SceneError("a camera lens (depth of field) needs a perspective or orthographic "
                         "camera");
    if (!std::isfinite(c.shift_x) || !std::isfinite(c.shift_y))
        throw SceneError("the camera's shift is not finite");
    if (!(c.aspect >= 0 && c.aspect < 1e6f))
        throw SceneError(
            "the camera's aspect ratio must be 0 (the image's) or a finite number > 0");
    for (size_t m = 0; m < materials.size(); ++m)
        if (!is_finite(materials[m].color) || !is_finite(materials[m].emission) ||
            !(materials[m].ior > 0))
            throw SceneError("material " + std::to_string(m) +
                             " has a colour that is not finite or an ior <= 0");
    for (size_t m = 0; m < materials.size(); ++m) {
        const Material& mt = materials[m];
        for (float v :
             {mt.ambient, mt.diffuse, mt.specular, mt.phong_exponent, mt.mirror, mt.transmission,
              mt.ior, mt.brilliance, mt.blinn, mt.blinn_exponent, mt.metallic, mt.mirror_min,
              mt.mirror_falloff, mt.fade_distance, mt.fade_power})
            if (!std::isfinite(v))
                throw SceneError("material " + std::to_string(m) +
                                 " has a finish or interior value that is not finite");
        if (!is_finite(mt.mirror_color) || !is_finite(mt.fade_color))
            throw SceneError("material " + std::to_string(m) +
                             " has a reflection or fade colour that is not finite");
        if (!(mt.caustics >= 0) || !std::isfinite(mt.caustics))
            throw SceneError("material " + std::to_string(m) +
                             " has caustics that are not finite or < 0");
        if (mt.irid != 0 &&
            (!std::isfinite(mt.irid) || !std::isfinite(mt.irid_thickness) ||
             !std::isfinite(mt.irid_turbulence) || !is_finite(mt.irid_wavelength) ||
             !(mt.irid_wavelength.x > 0 && mt.irid_wavelength.y > 0 && mt.irid_wavelength.z > 0)))
            throw SceneError("material " + std::to_string(m) +
                             " has an iridescence that is not finite or a wavelength <= 0");
    }
    for (size_t m = 0; m < materials.size(); ++m)
        if (materials[m].texture >= int32_t(textures.size()))
            throw SceneError("material " + std::to_string(m) + " names texture " +
                             std::to_string(materials[m].texture) + ", which does not exist");
    for (size_t t = 0; t < textures.size(); ++t)
        if (textures[t].path.empty())
            throw SceneError("texture " + std::to_string(t) + " has no file");
    validate_photons();
    validate_patterns();
    validate_functions();
}

namespace {

void check_warp(const Warp& w, const std::string& name) {
    if (!w.to_inner.finite() || !is_finite(w.a) || !is_finite(w.b) || !is_finite(w.c) ||
        !std::isfinite(w.f[0]) || !std::isfinite(w.f[1]) || !std::isfinite(w.f[2]))
        throw SceneError(name + ": a warp parameter is not finite");
    if (w.kind > WarpKind::BlackHole) throw SceneError(name + ": a warp of an unknown kind");
    if (w.kind == WarpKind::BlackHole && !(w.f[0] > 0))
        throw SceneError(name + ": a black hole's radius must be above 0");
    if (w.kind == WarpKind::Turbulence && (w.octaves < 1 || w.octaves > 16))
        throw SceneError(name + ": a turbulence warp's octaves must lie between 1 and 16");
    if (w.kind == WarpKind::Repeat && (w.axis > 2 || w.f[0] == 0))
        throw SceneError(name + ": a repeat warp needs an axis and a width other than 0");
    if (w.kind >= WarpKind::Planar && w.kind <= WarpKind::Toroidal &&
        !(std::fabs(length(w.b) - 1) < 1e-3f))
        throw SceneError(name + ": a warp's orientation must be a unit vector");
}

// `pigments`: how many pigments a pigment pattern may name (a pigment's pattern only earlier
// ones, so pigments cannot hold themselves).
void check_pattern(const Pattern& p, size_t textures, const std::vector<Warp>& warps,
                   size_t pigments, const std::string& name, size_t grids) {
    if (p.kind == PatternKind::DensityFile && (p.grid < 0 || size_t(p.grid) >= grids))
        throw SceneError(name + ": its density_file names grid " + std::to_string(p.grid) +
                         ", which does not exist");
    if (p.kind == PatternKind::PigmentPattern && (p.pigment < 0 || size_t(p.pigment) >= pigments))
        throw SceneError(name + ": its pigment pattern names pigment " + std::to_string(p.pigment) +
                         ", which is not an earlier pigment");
    if (!p.to_pattern.finite()) throw SceneError(name + ": its transform is not finite");
    if (size_t(p.warp_first) + p.warp_count > warps.size())
        throw SceneError(name + ": its warps lie outside the scene's warps");
    for (uint32_t i = 0; i < p.warp_count; ++i) check_warp(warps[p.warp_first + i], name);
    if (!is_finite(p.turbulence) || !std::isfinite(p.frequency) || !std::isfinite(p.phase) ||
        !is_finite(p.vector) || p.octaves < 1 || p.octaves > 16)
        throw SceneError(name + ": a pattern parameter is out of range");
    if (p.kind == PatternKind::Function && p.program < 0)
        throw SceneError(name + ": a function pattern without a function");
    if ((p.kind == PatternKind::Image || p.kind == PatternKind::ImagePattern) &&
        (p.image < 0 || size_t(p.image) >= textures))
        throw SceneError(name + " names texture " + std::to_string(p.image) +
                         ", which does not exist");
}

} // namespace

void Scene::validate_functions() const {
    for (size_t i = 0; i < fn_patterns.size(); ++i) {
        // Warps and pigment patterns are read when a program runs on a scene (patterns);
        // isosurfaces read them without (the POV reader warns such functions there). The
        // renderer's depth limit (kMaxDepth) bounds pigments and functions that name each other.
        const Pattern& p = fn_patterns[i];
        check_pattern(p, textures.size(), warps, pigments.size(),
                      "function pattern " + std::to_string(i), density_grids.size());
        if (p.kind == PatternKind::Function || p.kind == PatternKind::Image ||
            p.kind == PatternKind::ImagePattern)
            throw SceneError("function pattern " + std::to_string(i) +
                             ": a function's pattern is no function or image");
    }
    for (size_t i = 0; i < fn_pigments.size(); ++i) {
        const FnPigment& pg = fn_pigments[i];
        const std::string name = "function pigment " + std::to_string(i);
        if (pg.count > 0 && (pg.pattern >= fn_patterns.size() ||
                             size_t(pg.first) + pg.count > fn_pigment_entries.size()))
            throw SceneError(name + ": its pattern or entries do not exist");
        if (pg.count > 0 && (pg.list != 0) != pattern_is_list(fn_patterns[pg.pattern].kind))
            throw SceneError(name + ": a list pattern's entries must be a list");
        if (pg.scene_pigment >= 0 && size_t(pg.scene_pigment) >= pigments.size())
            throw SceneError(name + ": its pigment " + std::to_string(pg.scene_pigment) +
                             " does not exist");
    }
    for (size_t i = 0; i < fn_programs.size(); ++i) {
        const std::string why = check_fn_program(fn_programs[i], fn_code.data(), fn_code.size(),
                                                 fn_patterns.size(), fn_pigments.size());
        if (!why.empty()) throw SceneError("function " + std::to_string(i) + ": " + why);
    }
    auto three_params = [&](int32_t program, const std::string& name) {
        if (program < 0 || size_t(program) >= fn_programs.size())
            throw SceneError(name + " names function " + std::to_string(program) +
                             ", which does not exist");
        if (fn_programs[size_t(program)].params != 3)
            throw SceneError(name + ": its function must take x, y and z");
    };
    auto pattern_function = [&](const Pattern& p, const std::string& name) {
        if (p.kind == PatternKind::Function) three_params(p.program, name);
    };
    for (size_t i = 0; i < pigments.size(); ++i)
        if (!pigments[i].solid)
            pattern_function(pigments[i].pattern, "pigment " + std::to_string(i));
    for (size_t i = 0; i < normal_patterns.size(); ++i)
        pattern_function(normal_patterns[i].pattern, "normal pattern " + std::to_string(i));
    for (size_t i = 0; i < material_switches.size(); ++i)
        pattern_function(material_switches[i].pattern, "material switch " + std::to_string(i));
    for (const ShapeObject& o : shape_objects)
        for (const CsgNode& node : o.nodes)
            if (node.op == CsgOp::Leaf && node.shape.kind == ShapeKind::Isosurface && node.iso)
                three_params(int32_t(node.iso->program), o.name + ": its isosurface");
}

void Scene::validate_patterns() const {
    const auto range = [](uint32_t first, uint32_t count, size_t size) {
        return size_t(first) + count <= size;
    };
    for (size_t i = 0; i < pigments.size(); ++i) {
        const Pigment& pg = pigments[i];
        const std::string name = "pigment " + std::to_string(i);
        if (pg.solid) continue;
        check_pattern(pg.pattern, textures.size(), warps, i, name, density_grids.size());
        if (!range(pg.first, pg.count, pigment_entries.size()))
            throw SceneError(name + ": its entries lie outside the pigment entries");
        for (uint32_t e = pg.first; e < pg.first + pg.count; ++e) {
            // Entries name earlier pigments only, so maps cannot refer to themselves.
            const int32_t ref = pigment_entries[e].pigment;
            if (ref >= int32_t(i))
                throw SceneError(name + ": entry " + std::to_string(e - pg.first) +
                                 " names pigment " + std::to_string(ref) +
                                 "; entries must name earlier pigments");
        }
    }
    for (size_t i = 0; i < normal_patterns.size(); ++i) {
        const NormalPattern& np = normal_patterns[i];
        const std::string name = "normal pattern " + std::to_string(i);
        check_pattern(np.pattern, textures.size(), warps, pigments.size(), name,
                      density_grids.size());
        if (!range(np.slope_first, np.slope_count, slope_entries.size()))
            throw SceneError(name + " names slope map entries that do not exist");
        for (uint32_t k = 0; k < np.slope_count; ++k) {
            const SlopeEntry& e = slope_entries[np.slope_first + k];
            if (!std::isfinite(e.value) || !std::isfinite(e.height) || !std::isfinite(e.slope))
                throw SceneError(name + ": a slope map entry is not finite");
            if (k > 0 && e.value < slope_entries[np.slope_first + k - 1].value)
                throw SceneError(name + ": the slope map's values must not decrease");
        }
        if (!range(np.map_first, np.map_count, normal_map_entries.size()))
            throw SceneError(name + " names normal map entries that do not exist");
        float weights = 0;
        for (uint32_t k = 0; k < np.map_count; ++k) {
            const NormalMapEntry& e = normal_map_entries[np.map_first + k];
            if (!std::isfinite(e.value))
                throw SceneError(name + ": a normal map entry's value is not finite");
            if (e.normal >= int32_t(normal_patterns.size()) ||
                (e.normal >= 0 && normal_patterns[size_t(e.normal)].map_count > 0))
                throw SceneError(name + ": normal map entries must name normal patterns "
                                        "without maps of their own");
            if (!np.average && !pattern_is_list(np.pattern.kind) && k > 0 &&
                e.value < normal_map_entries[np.map_first + k - 1].value)
                throw SceneError(name + ": the normal map's values must not decrease");
            weights += e.value;
        }
        if (np.average && (np.map_count == 0 || !(weights != 0)))
            throw SceneError(name + ": an average needs entries whose weights do not sum to 0");
    }
    for (size_t i = 0; i < material_switches.size(); ++i) {
        const MaterialSwitch& ms = material_switches[i];
        const std::string name = "material switch " + std::to_string(i);
        check_pattern(ms.pattern, textures.size(), warps, pigments.size(), name,
                      density_grids.size());
        if (ms.count == 0 || !range(ms.first, ms.count, material_entries.size()))
            throw SceneError(name + ": its entries lie outside the material entries");
        for (uint32_t e = ms.first; e < ms.first + ms.count; ++e)
            if (material_entries[e].material >= materials.size())
                throw SceneError(name + " names material " +
                                 std::to_string(material_entries[e].material) +
                                 ", which does not exist");
    }
    for (size_t m = 0; m < materials.size(); ++m) {
        const Material& mt = materials[m];
        const std::string name = "material " + std::to_string(m);
        if (mt.pigment >= int32_t(pigments.size()) ||
            mt.normal >= int32_t(normal_patterns.size()) ||
            mt.select >= int32_t(material_switches.size()))
            throw SceneError(name + " names a pigment, normal or switch that does not exist");
        if (mt.inside >= int32_t(materials.size()))
            throw SceneError(name + ": its inside material does not exist");
        if (mt.inside >= 0 && materials[size_t(mt.inside)].inside >= 0)
            throw SceneError(name + ": its inside material has an inside material of its own");
        if (!range(mt.media_first, mt.media_count, media.size()))
            throw SceneError(name + ": its media lie outside the scene's media");
    }
    if (atmosphere >= int32_t(materials.size()) ||
        (atmosphere >= 0 && materials[size_t(atmosphere)].media_count == 0))
        throw SceneError("the atmosphere names material " + std::to_string(atmosphere) +
                         ", which does not exist or holds no media");
    for (size_t i = 0; i < media.size(); ++i) {
        const Medium& md = media[i];
        const std::string name = "medium " + std::to_string(i);
        if (!is_finite(md.emission) || !is_finite(md.absorption) || md.absorption.x < 0 ||
            md.absorption.y < 0 || md.absorption.z < 0)
            throw SceneError(name + ": emission must be finite and absorption finite and >= 0");
        if (!is_finite(md.scattering) || md.scattering.x < 0 || md.scattering.y < 0 ||
            md.scattering.z < 0 || !(md.extinction >= 0 && md.extinction <= 1e30f))
            throw SceneError(name + ": scattering and extinction must be finite and >= 0");
        if (uint8_t(md.scatter_type) < 1 || uint8_t(md.scatter_type) > 5)
            throw SceneError(name + ": the scattering type must be 1..5");
        if (!(md.eccentricity > -1 && md.eccentricity < 1))
            throw SceneError(name + ": the eccentricity must lie strictly between -1 and 1");
        if (md.samples < 1 || md.samples > 1024 || md.light_samples < 1 || md.light_samples > 1024)
            throw SceneError(name + ": samples and light_samples must lie in 1..1024");
        if (!range(md.density_first, md.density_count, medium_densities.size()))
            throw SceneError(name + ": its densities lie outside the medium densities");
        for (uint32_t d = md.density_first; d < md.density_first + md.density_count; ++d)
            if (medium_densities[d] >= pigments.size())
                throw SceneError(name + ": a density names a pigment that does not exist");
    }
    for (size_t i = 0; i < density_grids.size(); ++i) {
        const DensityGrid& g = density_grids[i];
        const std::string name = "density grid " + std::to_string(i);
        if (g.nx == 0 || g.ny == 0 || g.nz == 0 || g.interpolation > 2)
            throw SceneError(name + ": it needs a size of at least 1 x 1 x 1 and an "
                                    "interpolation of 0, 1 or 2");
        const uint64_t n = uint64_t(g.nx) * g.ny * g.nz;
        if (g.first > density_voxels.size() || n > density_voxels.size() - g.first)
            throw SceneError(name + ": its voxels lie outside the density voxels");
    }
    // Each value once, however many grids share it.
    for (size_t k = 0; k < density_voxels.size(); ++k)
        if (!(density_voxels[k] >= 0 && density_voxels[k] <= 1))
            throw SceneError("density voxel " + std::to_string(k) + ": its value is not in [0, 1]");
    // A switch may lead to materials with switches of their own, but never back to itself:
    // depth-first, 1 = on the current path, 2 = done.
    std::vector<char> state(materials.size(), 0);
    std::function<void(uint32_t)> visit = [&](uint32_t cur) {
        if (state[cur] == 2) return;
        if (state[cur] == 1)
            throw SceneError("material " + std::to_string(cur) +
                             ": its texture maps lead back to itself");
        state[cur] = 1;
        if (const int32_t sw = materials[cur].select; sw >= 0) {
            const MaterialSwitch& ms = material_switches[size_t(sw)];
            for (uint32_t e = ms.first; e < ms.first + ms.count; ++e)
                visit(material_entries[e].material);
        }
        state[cur] = 2;
    };
    for (size_t m = 0; m < materials.size(); ++m) visit(uint32_t(m));
    if (sky >= int32_t(pigments.size())) throw SceneError("the sky names a missing pigment");
    for (size_t i = 0; i < rainbows.size(); ++i) {
        const Rainbow& r = rainbows[i];
        const std::string name = "rainbow " + std::to_string(i);
        if (r.colors >= pigments.size()) throw SceneError(name + " names a missing pigment");
        const auto unit = [](Vec3 v) { return is_finite(v) && std::fabs(length(v) - 1) < 1e-3f; };
        if (!unit(r.antisolar) || !unit(r.up) || !unit(r.right))
            throw SceneError(name + ": its directions must be unit vectors");
        if (!(r.width != 0 && std::fabs(r.width) <= 1e30f) || !(std::fabs(r.start) <= 1e30f) ||
            !(r.distance > 0) || !(r.jitter >= 0 && r.jitter <= 1e30f) || !(r.arc >= 0) ||
            !(r.falloff >= 0) || r.falloff > r.arc)
            throw SceneError(name + ": width must not be 0, distance must be positive, jitter "
                                    "not negative, and the falloff angle within the arc");
    }
    if (fog.count > Fogs::kMax) throw SceneError("more fogs than Sheaf lays over each other");
    for (uint32_t i = 0; i < fog.count; ++i) {
        const Fog& f = fog.layer[i];
        if (!(f.distance >= 0) || !is_finite(f.color) || !(f.filter >= 0 && f.filter <= 1) ||
            !(f.transmit >= 0 && f.transmit <= 1) || !is_finite(f.turb) ||
            !(f.octaves >= 1 && f.octaves <= 10) ||
            !(f.noise_generator >= 1 && f.noise_generator <= 3) || !std::isfinite(f.omega) ||
            !std::isfinite(f.lambda) || !std::isfinite(f.turb_depth))
            throw SceneError("a fog's distance, colour or turbulence is out of range");
    }
    if (!(working_gamma >= 0.1f && working_gamma <= 10.0f))
        throw SceneError("the working gamma is out of range (0.1 to 10)");
}

void Scene::validate_photons() const {
    const PhotonSettings& p = photons;
    if (!std::isfinite(p.spacing) || p.spacing < 0)
        throw SceneError("photons: spacing must be a finite number, 0 (off) or more");
    if (p.count > 20'000'000) throw SceneError("photons: a count of at most 20 million photons");
    if (!std::isfinite(p.radius_scale) || !(p.radius_scale > 0))
        throw SceneError("photons: the gather radius's multiplier must be a finite number above 0");
    for (size_t l = 0; l < lights.size(); ++l)
        if (!std::isfinite(lights[l].photon_weight) || lights[l].photon_weight < 0)
            throw SceneError("light " + std::to_string(l) +
                             ": photon_weight must be a finite number, 0 or more");
    if (!std::isfinite(p.radius) || p.radius < 0)
        throw SceneError(
            "photons: the gather radius must be a finite number, 0 (estimated) or more");
    if (p.gather_min > p.gather_max || p.gather_max == 0 || p.gather_max > 10000)
        throw SceneError("photons: gather needs 0 <= min <= max and max from 1 to 10000");
    if (!std::isfinite(p.jitter) || p.jitter < 0 || p.jitter > 1)
        throw SceneError("photons: jitter must lie between 0 and 1");
    if (!std::isfinite(p.expand_tolerance) || p.expand_tolerance < 0 || p.steps < 1 || p.steps > 16)
        throw SceneError("photons: expand_thresholds needs a tolerance >= 0, and steps 1 to 16");
    if (!std::isfinite(p.adc_bailout) || p.adc_bailout < 0 || p.adc_bailout >= 1)
        throw SceneError("photons: adc_bailout must lie in [0, 1)");
    auto check = [](const PhotonObject& o, const std::string& name) {
        if (!std::isfinite(o.target) || o.target < 0)
            throw SceneError(name + ": a photon target's spacing multiplier must be a finite "
                                    "number above 0");
    };
    for (size_t o = 0; o < objects.size(); ++o)
        check(objects[o].photons, "object " + std::to_string(o));
    for (size_t o = 0; o < shape_objects.size(); ++o)
        check(shape_objects[o].photons, "shape object " + std::to_string(o));
}

} // namespace sheaf

#include "core/scene/analytic.h"

#include "core/geometry/quadric_bounds.h"

#include <cmath>

namespace sheaf {

PlacedShape place_shape(const Shape& shape, const Affine& local_to_world) {
    PlacedShape p;
    p.shape = shape;
    p.to_local = local_to_world.inverse();
    p.normal_to_world = local_to_world.normal_matrix();
    return p;
}

namespace {

Sphere local_bound(const PreparedScene& scene, const Shape& s) {
    switch (s.kind) {
    case ShapeKind::Sphere:
        return {Vec3(0.0f), 1.0f};
    case ShapeKind::Box:
        return {Vec3(0.0f), std::sqrt(3.0f)};
    case ShapeKind::Cylinder:
        return {Vec3(0, 0, 0.5f), std::sqrt(1.25f)};
    case ShapeKind::Cone: {
        const float r = std::fmax(s.a, s.b);
        return {Vec3(0, 0, 0.5f), std::sqrt(r * r + 0.25f)};
    }
    case ShapeKind::Disc:
        return {Vec3(0.0f), 1.0f};
    case ShapeKind::Plane:
        return {Vec3(0.0f), INFINITY};
    case ShapeKind::Torus:
        return {Vec3(0.0f), 1.0f + s.a};
    case ShapeKind::Poly: // may be unbounded; a clip or intersection around it bounds it
        return {Vec3(0.0f), INFINITY};
    case ShapeKind::Superellipsoid:
        return {Vec3(0.0f), std::sqrt(3.0f)};
    case ShapeKind::Glyph: { // around its box, z from 0 to 1 (a conic one's box down to base a)
        const GlyphRef& g = scene.glyphs[s.index];
        const float k = s.b > 0 ? s.a : 1.0f;
        const Vec3 lo(std::min(g.lo_x, k * g.lo_x), std::min(g.lo_y, k * g.lo_y), 0);
        const Vec3 hi(std::max(g.hi_x, k * g.hi_x), std::max(g.hi_y, k * g.hi_y), 1);
        return {(lo + hi) * 0.5f, length(hi - lo) * 0.5f};
    }
    case ShapeKind::Revolution: { // around its cylinder
        const RevolutionRef& g = scene.revolutions[s.index];
        const float half = 0.5f * (g.h_hi - g.h_lo);
        return {Vec3(0, 0, 0.5f * (g.h_lo + g.h_hi)), std::sqrt(g.r_max * g.r_max + half * half)};
    }
    case ShapeKind::Blob: { // around its positive components
        const BlobRef& b = scene.blobs[s.index];
        return {Vec3(b.bound[0], b.bound[1], b.bound[2]), b.bound[3]};
    }
    case ShapeKind::Julia: // the sphere its points escape beyond
        return {Vec3(0.0f), float(julia_detail::bound_radius(scene.julias[s.index]))};
    case ShapeKind::Isosurface: { // around its container
        const IsoRef& b = scene.isosurfaces[s.index];
        return {Vec3(b.bound[0], b.bound[1], b.bound[2]), b.bound[3]};
    }
    }
    return {Vec3(0.0f), INFINITY};
}

/// The shape's canonical solid's box where the kind has a tight one (shape.h), else the cube
/// around local_bound. False: unbounded.
bool local_box(const PreparedScene& scene, const Shape& s, Vec3& lo, Vec3& hi) {
    switch (s.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Box:
    case ShapeKind::Superellipsoid:
        lo = Vec3(-1.0f), hi = Vec3(1.0f);
        return true;
    case ShapeKind::Cylinder:
        lo = Vec3(-1, -1, 0), hi = Vec3(1, 1, 1);
        return true;
    case ShapeKind::Cone: {
        const float r = std::fmax(std::fabs(s.a), std::fabs(s.b));
        lo = Vec3(-r, -r, 0), hi = Vec3(r, r, 1);
        return true;
    }
    case ShapeKind::Disc:
        lo = Vec3(-1, -1, 0), hi = Vec3(1, 1, 0);
        return true;
    case ShapeKind::Torus: {
        const float r = std::fabs(s.a);
        lo = Vec3(-1 - r, -1 - r, -r), hi = Vec3(1 + r, 1 + r, r);
        return true;
    }
    case ShapeKind::Revolution: {
        const RevolutionRef& g = scene.revolutions[s.index];
        lo = Vec3(-g.r_max, -g.r_max, g.h_lo), hi = Vec3(g.r_max, g.r_max, g.h_hi);
        return true;
    }
    default: {
        const Sphere b = local_bound(scene, s);
        if (!std::isfinite(b.radius)) return false;
        lo = b.center - Vec3(b.radius), hi = b.center + Vec3(b.radius);
        return true;
    }
    }
}

/// The overlap of a and b; where they do not meet (an intersection of parts apart), b.
WorldBox meet(WorldBox a, const WorldBox& b) {
    a.lo = vmax(a.lo, b.lo), a.hi = vmin(a.hi, b.hi);
    if (a.lo.x > a.hi.x || a.lo.y > a.hi.y || a.lo.z > a.hi.z) return b;
    return a;
}

/// b grown by 1e-5 of its size and distance from the origin (finite sides only): a solid cut
/// by planes far from where their offsets lie, its points rounded to that magnitude.
WorldBox padded(WorldBox b) {
    float big = 0;
    for (int k = 0; k < 3; ++k) {
        if (std::isfinite(b.lo[k])) big = std::fmax(big, std::fabs(b.lo[k]));
        if (std::isfinite(b.hi[k])) big = std::fmax(big, std::fabs(b.hi[k]));
    }
    const float pad = 2e-5f * (2 * big + 1);
    for (int k = 0; k < 3; ++k) b.lo[k] -= pad, b.hi[k] += pad; // infinite sides stay so
    return b;
}

/// The cube around a sphere (infinite: unbounded).
WorldBox cube(const Sphere& s) {
    WorldBox b;
    if (std::isfinite(s.radius)) b.lo = s.center - Vec3(s.radius), b.hi = s.center + Vec3(s.radius);
    return b;
}

} // namespace

namespace {

struct NodeBounds {
    Sphere sphere; // csg_bound
    WorldBox box;  // csg_box
};

/// The bounds of `node`, each node of its subtree computed once; `nodes` (scene.csg's own
/// array, when given) receives every one's box.
NodeBounds node_bounds(const PreparedScene& scene, uint32_t node, PreparedCsgNode* nodes) {
    const PreparedCsgNode& n = scene.csg[node];
    NodeBounds out;
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        const Affine to_world = ps.to_local.inverse();
        const Sphere l = local_bound(scene, ps.shape);
        out.sphere = l;
        if (std::isfinite(l.radius)) {
            const Vec3 c = to_world.point(l.center);
            out.sphere = {c, pad_radius(l.radius * to_world.max_scale(), c)};
        }
        if (ps.shape.kind == ShapeKind::Plane) {
            // The half-space z <= 0: bounded on one side where its normal lies along an axis
            // (POV-Ray's plane { y, 5 }), which an intersection of such planes makes a box.
            const Vec3 nz = to_world.vector(Vec3(0, 0, 1)), p0 = to_world.point(Vec3(0.0f));
            for (int k = 0; k < 3; ++k) {
                const float along = nz[k], len = length(nz);
                if (!(std::fabs(along) >= len * (1 - 1e-6f))) continue;
                const float pad = 1e-5f * (std::fabs(p0[k]) + 1);
                if (along > 0)
                    out.box.hi[k] = p0[k] + pad; // inside below the plane along +axis k
                else
                    out.box.lo[k] = p0[k] - pad;
            }
        } else if (Vec3 lo, hi; local_box(scene, ps.shape, lo, hi)) {
            WorldBox b;
            b.lo = Vec3(INFINITY), b.hi = Vec3(-INFINITY);
            for (int c = 0; c < 8; ++c) {
                const Vec3 p = to_world.point(
                    Vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z));
                b.lo = vmin(b.lo, p), b.hi = vmax(b.hi, p);
            }
            // Padded as pad_radius pads a sphere: the box of rounded corners holds the solid.
            const Vec3 pad = (vmax(vabs(b.lo), vabs(b.hi)) + (b.hi - b.lo)) * 1e-5f;
            b.lo = b.lo - pad, b.hi = b.hi + pad;
            out.box = meet(b, cube(out.sphere));
        }
    } else {
        std::vector<NodeBounds> kids;
        for (uint32_t c = 0; c < n.count; ++c)
            kids.push_back(node_bounds(scene, scene.csg_children[n.first + c], nodes));
        if (n.op == CsgOp::Difference) { // inside the first child
            out = kids[0];
        } else if (n.op == CsgOp::Intersection || n.op == CsgOp::Clip) {
            out.sphere = kids[0].sphere; // inside every child: the smallest sphere bounds it
            for (const NodeBounds& k : kids)
                if (k.sphere.radius < out.sphere.radius) out.sphere = k.sphere;
            WorldBox b = cube(out.sphere);
            for (const NodeBounds& k : kids) b = meet(b, k.box);
            // A quadric member (unbounded, as shapes.inc's) bounded by what the others leave.
            for (uint32_t c = 0; c < n.count; ++c) {
                const PreparedCsgNode& kid = scene.csg[scene.csg_children[n.first + c]];
                if (kid.op != CsgOp::Leaf || kid.inverse) continue;
                const PlacedShape& ps = scene.shapes[kid.first];
                WorldQuadric w;
                if (ps.shape.kind == ShapeKind::Poly &&
                    world_quadric(scene.polys[ps.shape.index], ps.to_local, w))
                    narrow_by_quadric(w, b);
            }
            out.box = padded(b);
        } else {
            bool bounded = true;
            std::vector<Sphere> spheres;
            for (const NodeBounds& k : kids) {
                bounded = bounded && std::isfinite(k.sphere.radius);
                spheres.push_back(k.sphere);
            }
            out.sphere = bounded ? sphere_union(spheres.data(), int(spheres.size()))
                                 : Sphere{Vec3(0.0f), INFINITY};
            WorldBox b;
            b.lo = Vec3(INFINITY), b.hi = Vec3(-INFINITY);
            for (const NodeBounds& k : kids)
                b.lo = vmin(b.lo, k.box.lo), b.hi = vmax(b.hi, k.box.hi);
            out.box = meet(b, cube(out.sphere));
        }
    }
    if (n.inverse) out = NodeBounds{{Vec3(0.0f), INFINITY}, WorldBox()};
    if (nodes) nodes[node].box = out.box;
    return out;
}

} // namespace

WorldBox csg_box(const PreparedScene& scene, uint32_t node) {
    return node_bounds(scene, node, nullptr).box;
}

Sphere csg_bound(const PreparedScene& scene, uint32_t node) {
    return node_bounds(scene, node, nullptr).sphere;
}

Sphere set_csg_boxes(PreparedScene& scene, uint32_t root) {
    return node_bounds(scene, root, scene.csg.data()).sphere;
}

} // namespace sheaf

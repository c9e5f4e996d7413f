#include "core/scene/analytic.h"

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

WorldBox csg_box(const PreparedScene& scene, uint32_t node) {
    const PreparedCsgNode& n = scene.csg[node];
    const WorldBox around = cube(csg_bound(scene, node));
    if (n.inverse) return WorldBox();
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        const Affine to_world = ps.to_local.inverse();
        if (ps.shape.kind == ShapeKind::Plane) {
            // The half-space z <= 0: bounded on one side where its normal lies along an axis
            // (POV-Ray's plane { y, 5 }), which an intersection of such planes makes a box.
            const Vec3 nz = to_world.vector(Vec3(0, 0, 1)), p0 = to_world.point(Vec3(0.0f));
            WorldBox b;
            for (int k = 0; k < 3; ++k) {
                const float along = nz[k], len = length(nz);
                if (!(std::fabs(along) >= len * (1 - 1e-6f))) continue;
                const float pad = 1e-5f * (std::fabs(p0[k]) + 1);
                if (along > 0)
                    b.hi[k] = p0[k] + pad; // inside below the plane along +axis k
                else
                    b.lo[k] = p0[k] - pad;
            }
            return b;
        }
        Vec3 lo, hi;
        if (!local_box(scene, ps.shape, lo, hi)) return WorldBox();
        WorldBox b;
        b.lo = Vec3(INFINITY), b.hi = Vec3(-INFINITY);
        for (int c = 0; c < 8; ++c) {
            const Vec3 p =
                to_world.point(Vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z));
            b.lo = vmin(b.lo, p), b.hi = vmax(b.hi, p);
        }
        // Padded as pad_radius pads a sphere: the box of rounded corners holds the solid.
        const Vec3 pad = (vmax(vabs(b.lo), vabs(b.hi)) + (b.hi - b.lo)) * 1e-5f;
        b.lo = b.lo - pad, b.hi = b.hi + pad;
        return meet(b, around);
    }
    std::vector<WorldBox> kids;
    for (uint32_t c = 0; c < n.count; ++c)
        kids.push_back(csg_box(scene, scene.csg_children[n.first + c]));
    if (n.op == CsgOp::Difference) return meet(kids[0], around); // inside the first child
    if (n.op == CsgOp::Intersection || n.op == CsgOp::Clip) {
        WorldBox b = around; // inside every child
        for (const WorldBox& k : kids) b = meet(b, k);
        return padded(b);
    }
    WorldBox b;
    b.lo = Vec3(INFINITY), b.hi = Vec3(-INFINITY);
    for (const WorldBox& k : kids) b.lo = vmin(b.lo, k.lo), b.hi = vmax(b.hi, k.hi);
    return meet(b, around);
}

Sphere csg_bound(const PreparedScene& scene, uint32_t node) {
    const PreparedCsgNode& n = scene.csg[node];
    if (n.inverse) return {Vec3(0.0f), INFINITY};
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        const Sphere l = local_bound(scene, ps.shape);
        if (!std::isfinite(l.radius)) return l;
        const Affine to_world = ps.to_local.inverse();
        const Vec3 c = to_world.point(l.center);
        return {c, pad_radius(l.radius * to_world.max_scale(), c)};
    }
    std::vector<Sphere> kids;
    for (uint32_t c = 0; c < n.count; ++c)
        kids.push_back(csg_bound(scene, scene.csg_children[n.first + c]));
    if (n.op == CsgOp::Difference) return kids[0]; // inside the first child
    if (n.op == CsgOp::Intersection || n.op == CsgOp::Clip) {
        Sphere best = kids[0]; // inside every child: the smallest one bounds it
        for (const Sphere& k : kids)
            if (k.radius < best.radius) best = k;
        return best;
    }
    for (const Sphere& k : kids)
        if (!std::isfinite(k.radius)) return {Vec3(0.0f), INFINITY};
    return sphere_union(kids.data(), int(kids.size()));
}

} // namespace sheaf

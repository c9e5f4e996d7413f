// min_extent and max_extent: an object's axis-aligned bounding box in POV-Ray's coordinates,
// as POV-Ray computes it: the canonical shape's box through the object's transform, a mesh's
// vertices, CSG combined (union: around all; intersection and clip: the overlap; difference:
// the first); unbounded objects (planes, polynomial surfaces, inverse) reach +-2e10, POV-Ray's
// BOUND_HUGE.
#include "io/pov/model.h"

#include "core/geometry/blob_build.h"

#include <algorithm>
#include <cmath>

namespace sheaf::io::pov {

namespace {

constexpr float kHuge = 2e10f;

struct Box {
    Vec3 lo{kHuge, kHuge, kHuge}, hi{-kHuge, -kHuge, -kHuge};
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void add(Vec3 p) { lo = vmin(lo, p), hi = vmax(hi, p); }
};

Box unbounded() {
    Box b;
    b.lo = Vec3(-kHuge), b.hi = Vec3(kHuge);
    return b;
}

Box transformed(const Affine& m, Vec3 lo, Vec3 hi) {
    Box b;
    for (int c = 0; c < 8; ++c)
        b.add(m.point(Vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z)));
    return b;
}

Box shape_box(const PovObject& o) {
    const Shape& s = o.shape;
    switch (s.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Box:
    case ShapeKind::Superellipsoid:
        return transformed(o.local, Vec3(-1), Vec3(1));
    case ShapeKind::Cylinder:
        return transformed(o.local, Vec3(-1, -1, 0), Vec3(1, 1, 1));
    case ShapeKind::Cone: {
        const float r = std::max(s.a, s.b);
        return transformed(o.local, Vec3(-r, -r, 0), Vec3(r, r, 1));
    }
    case ShapeKind::Disc:
        return transformed(o.local, Vec3(-1, -1, 0), Vec3(1, 1, 0));
    case ShapeKind::Torus:
        return transformed(o.local, Vec3(-1 - s.a, -1 - s.a, -s.a), Vec3(1 + s.a, 1 + s.a, s.a));
    case ShapeKind::Plane:
    case ShapeKind::Poly:
        return unbounded();
    case ShapeKind::Glyph: { // its outline's control points, z from 0 to 1 (a conic one's
                             // also at its base scale)
        Vec3 lo(kHuge), hi(-kHuge);
        const float k = s.b > 0 ? s.a : 1.0f;
        if (o.glyph)
            for (const GlyphSegment& g : o.glyph->segments)
                for (int i = 0; i < 3; ++i) {
                    const float* p = &g.x0 + 2 * i;
                    lo = vmin(lo, Vec3(std::min(p[0], k * p[0]), std::min(p[1], k * p[1]), 0));
                    hi = vmax(hi, Vec3(std::max(p[0], k * p[0]), std::max(p[1], k * p[1]), 1));
                }
        return lo.x <= hi.x ? transformed(o.local, lo, hi) : Box();
    }
    case ShapeKind::Revolution: { // its cylinder about z
        if (!o.revolution) return Box();
        float r, h_lo, h_hi;
        revolution_bounds(*o.revolution, r, h_lo, h_hi);
        return transformed(o.local, Vec3(-r, -r, h_lo), Vec3(r, r, h_hi));
    }
    case ShapeKind::Isosurface: { // its container
        if (!o.iso) return Box();
        if (!o.iso->sphere) return transformed(o.local, o.iso->lo, o.iso->hi);
        const Vec3 r(o.iso->hi.x);
        return transformed(o.local, o.iso->lo - r, o.iso->lo + r);
    }
    case ShapeKind::Julia: { // the sphere its points escape beyond
        if (!o.julia) return Box();
        const Vec3 r(float(julia_detail::bound_radius(*o.julia)));
        return transformed(o.local, -r, r);
    }
    case ShapeKind::Blob: { // POV-Ray's: the box around its positive components' spheres
        Vec3 lo, hi;
        if (!o.blob || !blob_box(*o.blob, lo, hi)) return Box();
        return transformed(o.local, lo, hi);
    }
    }
    return unbounded();
}

Box extent(const PovObject& o) {
    if (o.inverse) return unbounded();
    switch (o.kind) {
    case PovKind::Shape:
        return shape_box(o);
    case PovKind::Mesh: {
        Box b;
        if (o.mesh)
            for (const Vec3& p : o.mesh->positions) b.add(o.local.point(p));
        return b;
    }
    case PovKind::Light:
        return Box();
    case PovKind::Csg:
        break;
    }
    if (o.children.empty()) return Box();
    if (o.op == CsgOp::Difference) return extent(o.children[0]);
    if (o.op == CsgOp::Intersection || o.op == CsgOp::Clip) {
        Box b = unbounded();
        for (const PovObject& c : o.children) {
            const Box k = extent(c);
            b.lo = vmax(b.lo, k.lo), b.hi = vmin(b.hi, k.hi);
        }
        return b;
    }
    Box b;
    for (const PovObject& c : o.children) {
        const Box k = extent(c);
        if (!k.empty()) b.add(k.lo), b.add(k.hi);
    }
    return b;
}

} // namespace

bool object_extent(const PovObject& o, Vec3& lo, Vec3& hi) {
    const Box b = extent(o);
    if (b.empty()) return false;
    lo = vmax(b.lo, Vec3(-kHuge)), hi = vmin(b.hi, Vec3(kHuge));
    return true;
}

} // namespace sheaf::io::pov

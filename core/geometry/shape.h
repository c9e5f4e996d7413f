// Analytic shapes, exactly: each kind is a canonical solid (or surface) in its local space,
// placed by an affine transform. A ray is moved into local space without normalising its
// direction, so distances t stay world distances. Every kind reports the spans of the ray
// that lie inside it, which is what CSG needs; a plain shape's hit is the first span end.
//   sphere    unit sphere at the origin
//   box       [-1, 1]^3
//   cylinder  radius 1 around z, z in [0, 1]; open: no caps (a surface)
//   cone      radius r0 at z = 0 to r1 at z = 1; open: no caps (a surface)
//   disc      z = 0, hole radius h <= r <= 1 (a surface)
//   plane     the half-space z <= 0 (unbounded)
//   torus     major radius 1 around z in the plane z = 0, minor radius r
//   poly      P(x, y, z) < 0 for a polynomial of degree <= 4 (core/geometry/poly.h), whose
//             coefficients the scene keeps apart: Shape::index names them
//   superellipsoid  POV-Ray's, exponents e = a and n = b, inside [-1, 1]^3
//             (core/geometry/superellipsoid.h)
//   julia     POV-Ray's julia_fractal, a 3D slice of a 4D Julia set within radius 2 (4 for
//             the hypercomplex algebra) of the origin (core/geometry/julia.h); the scene keeps
//             its parameters: Shape::index names them
//   glyph     an outline in the x-y plane (a character, a prism's splines) swept from z = 0 to
//             z = 1 (core/geometry/glyph.h); the scene keeps the outlines: Shape::index names
//             one; open: its sides only (a surface); b > 0: conic, the outline scaled by
//             a + (1 - a) z at height z (a in [0, 1]; a prism's conic_sweep)
#pragma once

#include "core/geometry/blob.h"
#include "core/geometry/glyph.h"
#include "core/geometry/isosurface.h"
#include "core/geometry/julia.h"
#include "core/geometry/poly.h"
#include "core/geometry/ray.h"
#include "core/geometry/revolution.h"
#include "core/geometry/superellipsoid.h"
#include "core/math/affine.h"

#include <cfloat>
#include <cstdint>

namespace sheaf {

enum class ShapeKind : uint32_t {
    Sphere,
    Box,
    Cylinder,
    Cone,
    Disc,
    Plane,
    Torus,
    Poly,
    Superellipsoid,
    Glyph,
    Revolution,
    Blob,
    Isosurface,
    Julia
};

struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    float a = 0, b = 0; // cone: r0, r1; disc: hole radius; torus: minor radius;
                        // superellipsoid: e, n; glyph: b > 0 conic with base scale a
    bool open = false;  // cylinder, cone and glyph without caps; a revolution's surface only
    uint32_t index = 0; // poly: its coefficients in the scene's polys; glyph: its outline in
                        // the scene's glyphs; revolution: its profile in the scene's
                        // revolutions; blob: its components in the scene's blobs;
                        // isosurface: its entry in the scene's isosurfaces; julia: its
                        // parameters in the scene's julias
};

/// What shapes of some kinds read from the scene beside their Shape: poly coefficients, glyph
/// outlines, revolution profiles, blob components, isosurfaces and the functions they run,
/// julia fractals' parameters. A
/// table a scene lacks is null, and its shapes then have no spans.
struct ShapeTables {
    const PolyCoeffs* polys = nullptr;
    const GlyphRef* glyphs = nullptr;
    const GlyphSegment* glyph_segments = nullptr;
    const RevolutionRef* revolutions = nullptr;
    const RevolutionSegment* revolution_segments = nullptr;
    const BlobRef* blobs = nullptr;
    const BlobElement* blob_elements = nullptr;
    const IsoRef* isosurfaces = nullptr;
    FnView functions;
    const JuliaFractal* julias = nullptr;
};

/// One span [t0, t1] of a ray inside a solid, with the local normals at both ends (pointing
/// out of the solid). A surface (disc, open cylinder) gives spans with t0 == t1.
struct Span {
    float t0, t1;
    Vec3 n0, n1;
};

constexpr int kMaxShapeSpans = 4;

namespace shape_detail {

SHEAF_HD_INLINE bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
    if (fabs(a) < 1e-300) {
        if (fabs(b) < 1e-300) return false;
        t0 = t1 = -c / b;
        return true;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return false;
    const double s = sqrt(disc);
    const double q = b < 0 ? -0.5 * (b - s) : -0.5 * (b + s);
    t0 = q / a;
    t1 = q != 0 ? c / q : t0;
    if (t0 > t1) {
        const double t = t0;
        t0 = t1, t1 = t;
    }
    return true;
}

SHEAF_HD_INLINE int add(Span* out, int n, float t0, float t1, Vec3 n0, Vec3 n1) {
    if (n < kMaxShapeSpans) out[n++] = Span{t0, t1, n0, n1};
    return n;
}

// The frustum z in [0, 1], radius r0 + (r1 - r0) z (r0, r1 >= 0; a cylinder when equal): a
// convex solid, so a ray meets it in at most one span; open, only its side surface counts.
SHEAF_HD_INLINE int frustum_spans(const Ray& r, double r0, double r1, bool open, Span* out) {
    const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    const double k = r1 - r0, rr = r0 + k * oz, rd = k * dz;
    // g(t) = x^2 + y^2 - radius(z)^2 = a t^2 + b t + c; inside the side where g <= 0.
    const double a = dx * dx + dy * dy - rd * rd, b = 2 * (ox * dx + oy * dy - rr * rd),
                 c = ox * ox + oy * oy - rr * rr;
    auto side_normal = [&](double t) {
        const double z = oz + dz * t;
        return Vec3(float(ox + dx * t), float(oy + dy * t), float(-(r0 + k * z) * k));
    };
    double z0, z1; // the slab between the caps
    Vec3 zn0, zn1;
    if (!unit_slab(oz, dz, z0, z1, zn0, zn1)) return 0;
    double t0, t1;
    const bool roots = solve_quadratic(a, b, c, t0, t1);
    if (open) {
        int n = 0;
        if (!roots) return 0;
        if (t0 >= z0 && t0 <= z1)
            n = add(out, n, float(t0), float(t0), side_normal(t0), side_normal(t0));
        if (t1 != t0 && t1 >= z0 && t1 <= z1)
            n = add(out, n, float(t1), float(t1), side_normal(t1), side_normal(t1));
        return n;
    }
    double s0 = z0, s1 = z1;
    Vec3 n0 = zn0, n1 = zn1;
    if (a > 1e-30) { // inside between the roots
        if (!roots) return 0;
        if (t0 > s0) s0 = t0, n0 = side_normal(t0);
        if (t1 < s1) s1 = t1, n1 = side_normal(t1);
    } else if (a < -1e-30) { // inside outside the roots (the ray runs along the cone's opening)
        if (roots) {
            if (s0 <= t0) {
                if (t0 < s1) s1 = t0, n1 = side_normal(t0);
            } else if (t1 > s0) {
                s0 = t1, n0 = side_normal(t1);
            }
        }
    } else if (fabs(b) > 1e-300) { // linear: b t + c <= 0
        const double t = -c / b;
        if (b > 0) {
            if (t < s1) s1 = t, n1 = side_normal(t);
        } else if (t > s0) {
            s0 = t, n0 = side_normal(t);
        }
    } else if (c > 0) {
        return 0;
    }
    if (s0 > s1) return 0;
    return add(out, 0, float(s0), float(s1), n0, n1);
}

struct SpanEnd {
    float t;
    Vec3 n;
};

// The pieces of the ray where P < 0: the real roots of P along the ray split it, and each
// piece is inside or out by P's sign within it. Unbounded pieces end at +-FLT_MAX. Not
// inlined on the device: its tables would otherwise grow every level of csg_spans' recursion.
SHEAF_HD_NOINLINE int poly_spans(const PolyCoeffs& p, const Ray& r, Span* out) {
    double q[5];
    const int deg = ray_polynomial(p, r, q);
    if (deg < 0) return 0; // the ray lies in the surface
    double roots[kPolyMaxDegree];
    int nr = 0;
    if (deg == 2) {
        double t0, t1;
        if (solve_quadratic(q[2], q[1], q[0], t0, t1) && t0 != t1)
            roots[0] = t0, roots[1] = t1, nr = 2; // a double root only touches
    } else {
        nr = poly_roots(q, deg, roots);
    }
    auto end = [&](double t, float sign) {
        if (!(fabs(t) < FLT_MAX)) return SpanEnd{t < 0 ? -FLT_MAX : FLT_MAX, Vec3(0, 0, 1)};
        const double x = r.origin.x + r.dir.x * t, y = r.origin.y + r.dir.y * t,
                     z = r.origin.z + r.dir.z * t;
        Vec3 n = poly_gradient(p, x, y, z);
        if (!(dot(n, n) > 0)) n = r.dir * sign; // a singular point: against the ray
        return SpanEnd{float(t), n};
    };
    int n = 0;
    bool in = false;
    double start = 0;
    for (int i = 0; i <= nr; ++i) {
        const double lo = i > 0 ? roots[i - 1] : -INFINITY, hi = i < nr ? roots[i] : INFINITY;
        const double probe = i > 0 && i < nr ? 0.5 * (lo + hi)
                             : i < nr        ? hi - (1 + fabs(hi))
                             : i > 0         ? lo + (1 + fabs(lo))
                                             : 0.0;
        const bool inside = poly_detail::eval(q, deg, probe) < 0;
        if (inside && !in) start = lo, in = true;
        if (!inside && in) {
            const SpanEnd a = end(start, -1), b = end(lo, 1);
            n = add(out, n, a.t, b.t, a.n, b.n);
            in = false;
        }
    }
    if (in) {
        const SpanEnd a = end(start, -1), b = end(INFINITY, 1);
        n = add(out, n, a.t, b.t, a.n, b.n);
    }
    return n;
}

// Out of line on the device, like poly_spans.
SHEAF_HD_NOINLINE int superellipsoid_spans(const Shape& s, const Ray& r, Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    const int count = superellipsoid_pieces(s.a, s.b, r, t0, t1, kMaxShapeSpans);
    for (int i = 0; i < count; ++i)
        out[i] = Span{float(t0[i]), float(t1[i]),
                      superellipsoid_normal(s.a, s.b, ray_at(r, float(t0[i]))),
                      superellipsoid_normal(s.a, s.b, ray_at(r, float(t1[i])))};
    return count;
}

// Out of line on the device, like poly_spans: its arrays would otherwise grow every level of
// csg_spans' recursion (by 160 bytes on sm_90).
SHEAF_HD_NOINLINE int glyph_spans(const GlyphRef& g, const GlyphSegment* segs, const Shape& s,
                                  const Ray& r, Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    Vec3 n0[kMaxShapeSpans], n1[kMaxShapeSpans];
    const int count = glyph_pieces(g, segs, s.open, r, t0, t1, n0, n1, kMaxShapeSpans,
                                   s.b > 0 ? double(s.a) : -1.0);
    for (int i = 0; i < count; ++i) out[i] = Span{float(t0[i]), float(t1[i]), n0[i], n1[i]};
    return count;
}

// Out of line on the device, like glyph_spans.
SHEAF_HD_NOINLINE int revolution_spans(const RevolutionRef& g, const RevolutionSegment* segs,
                                       bool open, const Ray& r, Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    Vec3 n0[kMaxShapeSpans], n1[kMaxShapeSpans];
    const int count = revolution_pieces(g, segs, open, r, t0, t1, n0, n1, kMaxShapeSpans);
    for (int i = 0; i < count; ++i) out[i] = Span{float(t0[i]), float(t1[i]), n0[i], n1[i]};
    return count;
}

// Out of line on the device, like glyph_spans.
SHEAF_HD_NOINLINE int blob_spans(const BlobRef& b, const BlobElement* elements, const Ray& r,
                                 Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    Vec3 n0[kMaxShapeSpans], n1[kMaxShapeSpans];
    const int count = blob_pieces(b, elements, r, t0, t1, n0, n1, kMaxShapeSpans);
    for (int i = 0; i < count; ++i) out[i] = Span{float(t0[i]), float(t1[i]), n0[i], n1[i]};
    return count;
}

// Out of line on the device, like glyph_spans.
SHEAF_HD_NOINLINE int iso_spans(const IsoRef& s, const FnView& fv, const Ray& r, Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    Vec3 n0[kMaxShapeSpans], n1[kMaxShapeSpans];
    const int count = iso_pieces(s, fv, r, t0, t1, n0, n1, kMaxShapeSpans);
    for (int i = 0; i < count; ++i) out[i] = Span{float(t0[i]), float(t1[i]), n0[i], n1[i]};
    return count;
}

// Out of line on the device, like glyph_spans (julia_pieces itself is too).
SHEAF_HD_NOINLINE int julia_spans(const JuliaFractal& j, const Ray& r, Span* out) {
    double t0[kMaxShapeSpans], t1[kMaxShapeSpans];
    Vec3 n0[kMaxShapeSpans], n1[kMaxShapeSpans];
    const int count = julia_pieces(j, r, t0, t1, n0, n1, kMaxShapeSpans);
    for (int i = 0; i < count; ++i) out[i] = Span{float(t0[i]), float(t1[i]), n0[i], n1[i]};
    return count;
}

} // namespace shape_detail

/// A ray in a shape's space with its origin also in double: a shape far from the world's
/// origin in its own units (a planet of radius 50,000 centred 50,000 below the camera) would
/// otherwise place its hits only to float precision of its size, off its surface by more than
/// the rays leaving them are lifted (advanced/mediasky.pov's sea reflected itself).
struct LocalRay {
    Ray ray;
    double ox = 0, oy = 0, oz = 0;
};

/// Spans of the local-space ray `lr` inside `s`, sorted, at most kMaxShapeSpans. `tables`
/// holds what poly and glyph shapes read (without it they have no spans).
SHEAF_HD_INLINE int shape_spans(const Shape& s, const LocalRay& lr, Span* out,
                                const ShapeTables& tables = {}) {
    using namespace shape_detail;
    const Ray& r = lr.ray;
    const double ox = lr.ox, oy = lr.oy, oz = lr.oz;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    auto at = [&](double t) {
        return Vec3(float(ox + dx * t), float(oy + dy * t), float(oz + dz * t));
    };
    switch (s.kind) {
    case ShapeKind::Sphere: {
        double t0, t1;
        if (!solve_quadratic(dx * dx + dy * dy + dz * dz, 2 * (ox * dx + oy * dy + oz * dz),
                             ox * ox + oy * oy + oz * oz - 1, t0, t1))
            return 0;
        return add(out, 0, float(t0), float(t1), at(t0), at(t1));
    }
    case ShapeKind::Box: {
        double t0 = -DBL_MAX, t1 = DBL_MAX;
        Vec3 n0, n1;
        const double o[3] = {ox, oy, oz}, d[3] = {dx, dy, dz};
        for (int i = 0; i < 3; ++i) {
            if (fabs(d[i]) < 1e-30) {
                if (o[i] < -1 || o[i] > 1) return 0;
                continue;
            }
            double a = (-1 - o[i]) / d[i], b = (1 - o[i]) / d[i];
            float na = -1, nb = 1;
            if (a > b) {
                const double t = a;
                a = b, b = t, na = 1, nb = -1;
            }
            if (a > t0) t0 = a, n0 = Vec3(0, 0, 0), n0[i] = na;
            if (b < t1) t1 = b, n1 = Vec3(0, 0, 0), n1[i] = nb;
        }
        if (t0 > t1) return 0;
        return add(out, 0, float(t0), float(t1), n0, n1);
    }
    case ShapeKind::Cylinder:
        return frustum_spans(r, 1.0, 1.0, s.open, out);
    case ShapeKind::Cone:
        return frustum_spans(r, s.a, s.b, s.open, out);
    case ShapeKind::Disc: {
        if (fabs(dz) < 1e-30) return 0;
        const double t = -oz / dz;
        const Vec3 p = at(t);
        const float rr = p.x * p.x + p.y * p.y;
        if (rr > 1.0f || rr < s.a * s.a) return 0;
        return add(out, 0, float(t), float(t), Vec3(0, 0, 1), Vec3(0, 0, 1));
    }
    case ShapeKind::Plane: {
        const Vec3 n(0, 0, 1);
        if (fabs(dz) < 1e-30) return oz <= 0 ? add(out, 0, -FLT_MAX, FLT_MAX, n, n) : 0;
        const float t = float(-oz / dz);
        return dz > 0 ? add(out, 0, -FLT_MAX, t, n, n) : add(out, 0, t, FLT_MAX, n, n);
    }
    case ShapeKind::Torus: {
        // Roots of (|p|^2 + 1 - r^2)^2 - 4 (x^2 + y^2) along the ray, found inside the bounding
        // sphere of radius 1 + r by sampling sign changes and bisection in double precision.
        const double rmin = s.a, R2 = (1 + rmin) * (1 + rmin);
        double b0, b1;
        if (!solve_quadratic(dx * dx + dy * dy + dz * dz, 2 * (ox * dx + oy * dy + oz * dz),
                             ox * ox + oy * oy + oz * oz - R2, b0, b1))
            return 0;
        auto f = [&](double t) {
            const double x = ox + dx * t, y = oy + dy * t, z = oz + dz * t;
            const double q = x * x + y * y + z * z + 1 - rmin * rmin;
            return q * q - 4 * (x * x + y * y);
        };
        auto normal = [&](double t) {
            const Vec3 p = at(t);
            const float q = p.x * p.x + p.y * p.y + p.z * p.z - 1 - float(rmin * rmin);
            return Vec3(p.x * q, p.y * q, p.z * (q + 2));
        };
        constexpr int kSteps = 96;
        double roots[4];
        int nr = 0;
        double ta = b0, fa = f(ta);
        const double step = (b1 - b0) / kSteps;
        for (int i = 1; i <= kSteps && nr < 4; ++i) {
            const double tb = b0 + step * i, fb = f(tb);
            if ((fa < 0) != (fb < 0)) {
                double lo = ta, hi = tb, flo = fa;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi), fm = f(mid);
                    if ((fm < 0) == (flo < 0))
                        lo = mid, flo = fm;
                    else
                        hi = mid;
                }
                roots[nr++] = 0.5 * (lo + hi);
            }
            ta = tb, fa = fb;
        }
        int n = 0;
        // f < 0 inside: spans between consecutive roots where the ray enters.
        const bool inside_at_start = f(b0) < 0;
        int i = 0;
        if (inside_at_start && nr > 0)
            n = add(out, n, float(b0), float(roots[0]), normal(b0), normal(roots[0])), i = 1;
        for (; i + 1 < nr; i += 2)
            n = add(out, n, float(roots[i]), float(roots[i + 1]), normal(roots[i]),
                    normal(roots[i + 1]));
        return n;
    }
    case ShapeKind::Poly:
        return tables.polys ? poly_spans(tables.polys[s.index], r, out) : 0;
    case ShapeKind::Superellipsoid:
        return superellipsoid_spans(s, r, out);
    case ShapeKind::Glyph:
        return tables.glyphs ? glyph_spans(tables.glyphs[s.index], tables.glyph_segments, s, r, out)
                             : 0;
    case ShapeKind::Revolution:
        return tables.revolutions ? revolution_spans(tables.revolutions[s.index],
                                                     tables.revolution_segments, s.open, r, out)
                                  : 0;
    case ShapeKind::Blob:
        return tables.blobs ? blob_spans(tables.blobs[s.index], tables.blob_elements, r, out) : 0;
    case ShapeKind::Isosurface:
        return tables.isosurfaces && tables.functions.programs
                   ? iso_spans(tables.isosurfaces[s.index], tables.functions, r, out)
                   : 0;
    case ShapeKind::Julia:
        return tables.julias ? julia_spans(tables.julias[s.index], r, out) : 0;
    }
    return 0;
}

/// Spans of a ray already in the shape's space, its origin as it is.
SHEAF_HD_INLINE int shape_spans(const Shape& s, const Ray& r, Span* out,
                                const ShapeTables& tables = {}) {
    return shape_spans(s, LocalRay{r, r.origin.x, r.origin.y, r.origin.z}, out, tables);
}

/// A shape placed in the world: the transforms a ray and a normal need.
struct PlacedShape {
    Shape shape;
    Affine to_local;        // world -> local
    Affine normal_to_world; // linear part: the inverse transpose of local -> world
};

SHEAF_HD_INLINE LocalRay to_local_ray(const PlacedShape& p, const Ray& r) {
    LocalRay l;
    const float(&m)[3][4] = p.to_local.m;
    const double x = r.origin.x, y = r.origin.y, z = r.origin.z;
    l.ox = m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3];
    l.oy = m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3];
    l.oz = m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3];
    l.ray.origin = Vec3(float(l.ox), float(l.oy), float(l.oz));
    l.ray.dir = p.to_local.vector(r.dir); // not normalised: t stays the world distance
    l.ray.tmin = r.tmin;
    l.ray.tmax = r.tmax;
    return l;
}

SHEAF_HD_INLINE Vec3 normal_to_world(const PlacedShape& p, Vec3 n_local) {
    return normalize(p.normal_to_world.vector(n_local));
}

} // namespace sheaf

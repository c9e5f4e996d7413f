// An extruded outline (one character of POV-Ray's text object, or a prism): the region of the
// x-y plane that closed contours of quadratic Bézier segments enclose, by the nonzero winding
// rule (as TrueType fills) or the even-odd rule (as POV-Ray fills a prism), swept from z = 0 to
// z = 1; open, only its sides (a prism's `open`). A conic glyph (a prism's `conic_sweep`) is
// the outline scaled by w(z) = base + (1 - base) z at height z: a frustum of the cone from the
// origin through the outline at w = 1. Exact: a ray's line in the plane meets each
// segment where a quadratic in the segment's parameter vanishes, and the winding number along
// the line changes by one at each such crossing, so the pieces of the line inside the region
// are where the running sum is not zero; those pieces, cut to the slab 0 <= z <= 1, are the
// spans. Each segment's crossings are counted by the signs of its end points (a point on the
// line counts as on its positive side), so segments that share an end point never count a
// crossing twice or miss one, whatever the ray. A conic glyph is
// straightened first: (x, y, z) -> (x / w, y / w) maps the ray's piece between the caps onto a
// line in the outline's plane (a central projection keeps lines straight), whose crossings go
// back to the ray by the projection's rational map of the parameter.
#pragma once

#include "core/geometry/ray.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sheaf {

/// A quadratic Bézier from (x0, y0) to (x2, y2) with control point (x1, y1); a straight
/// segment has its control point anywhere on it (its middle, by convention).
struct GlyphSegment {
    float x0, y0, x1, y1, x2, y2;
};

/// A glyph of a prepared scene: segments [first, first + count) of the scene's glyph segments,
/// the box in the x-y plane that holds their control points, and its fill rule.
struct GlyphRef {
    uint32_t first = 0, count = 0;
    float lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;
    uint32_t even_odd = 0; // 1: inside where the winding number is odd; 0: where it is not 0
};

/// A glyph's outline as the scene model holds it (host only): closed contours, each a chain of
/// segments whose last end point is its first start point.
struct GlyphOutline {
    std::vector<GlyphSegment> segments;
    bool even_odd = false; // the fill rule: even-odd (a prism) or nonzero (a font's glyph)
};

/// A cubic Bézier from p0 to p3 (controls p1, p2) as `pieces` quadratic segments appended to
/// `out`, each through the ends of its share of the cubic with the control point that matches
/// its mean end tangent: exact for a cubic that is a quadratic, otherwise off by at most
/// sqrt(3) / 36 |p0 - 3 p1 + 3 p2 - p3| / pieces^3 (measured: a cubic of size 1.4 with a third
/// difference of 7.4 is 6.9e-4 away at 8 pieces, 8.6e-5 at 16).
inline void cubic_to_quadratics(const double p[4][2], int pieces, std::vector<GlyphSegment>& out) {
    auto at = [&](double t, int k) {
        const double u = 1 - t;
        return u * u * u * p[0][k] + 3 * u * u * t * p[1][k] + 3 * u * t * t * p[2][k] +
               t * t * t * p[3][k];
    };
    auto slope = [&](double t, int k) {
        const double u = 1 - t;
        return 3 * (u * u * (p[1][k] - p[0][k]) + 2 * u * t * (p[2][k] - p[1][k]) +
                    t * t * (p[3][k] - p[2][k]));
    };
    for (int i = 0; i < pieces; ++i) {
        const double t0 = double(i) / pieces, t1 = double(i + 1) / pieces, h = t1 - t0;
        double c[2];
        for (int k = 0; k < 2; ++k)
            c[k] = 0.5 * ((at(t0, k) + slope(t0, k) * h / 2) + (at(t1, k) - slope(t1, k) * h / 2));
        // The ends exactly where the cubic's are, so that contours stay closed.
        const double x0 = i == 0 ? p[0][0] : at(t0, 0), y0 = i == 0 ? p[0][1] : at(t0, 1);
        const double x1 = i + 1 == pieces ? p[3][0] : at(t1, 0);
        const double y1 = i + 1 == pieces ? p[3][1] : at(t1, 1);
        out.push_back({float(x0), float(y0), float(c[0]), float(c[1]), float(x1), float(y1)});
    }
}

/// The most segments one glyph may have (a font's glyphs have tens to a few hundred).
constexpr size_t kMaxGlyphSegments = 1 << 16;

/// The most crossings of one line with one glyph that are kept (the nearest ones): a line
/// across an ornate glyph meets a few dozen segments at most.
constexpr int kMaxGlyphCrossings = 48;

namespace glyph_detail {

struct Crossing {
    double t;
    float nx, ny; // the outline's normal there (either way; oriented by the caller)
    int delta;    // the winding number's change along the line
};

/// Adds the crossing of segment g at parameter s (in [0, 1]) to the sorted list.
SHEAF_HD_INLINE void add_crossing(const GlyphSegment& g, double s, int delta, double ox, double oy,
                                  double dx, double dy, double inv_len2, Crossing* xs, int& n) {
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    const double u = 1 - s;
    const double x = u * u * g.x0 + 2 * s * u * g.x1 + s * s * g.x2;
    const double y = u * u * g.y0 + 2 * s * u * g.y1 + s * s * g.y2;
    double tx = u * (double(g.x1) - g.x0) + s * (double(g.x2) - g.x1);
    double ty = u * (double(g.y1) - g.y0) + s * (double(g.y2) - g.y1);
    if (tx == 0 && ty == 0) tx = double(g.x2) - g.x0, ty = double(g.y2) - g.y0;
    if (tx == 0 && ty == 0) tx = -dy, ty = dx; // a point: face along the line
    insert_nearest(
        xs, n, kMaxGlyphCrossings,
        Crossing{((x - ox) * dx + (y - oy) * dy) * inv_len2, float(ty), float(-tx), delta});
}

/// The crossings of the line (ox, oy) + t (dx, dy) with the outline, sorted by t.
SHEAF_HD_INLINE int crossings(const GlyphSegment* segs, uint32_t count, double ox, double oy,
                              double dx, double dy, Crossing* xs) {
    const double inv_len2 = 1 / (dx * dx + dy * dy);
    int n = 0;
    for (uint32_t i = 0; i < count; ++i) {
        const GlyphSegment& g = segs[i];
        // f(P) = cross(d, P - o): which side of the line P is on; along the segment
        // f(s) = a s^2 + b s + c, a quadratic through f0, f2 with control value f1.
        const double f0 = dx * (g.y0 - oy) - dy * (g.x0 - ox);
        const double f1 = dx * (g.y1 - oy) - dy * (g.x1 - ox);
        const double f2 = dx * (g.y2 - oy) - dy * (g.x2 - ox);
        const bool p0 = f0 >= 0, p2 = f2 >= 0;
        if (p0 == p2 && (f1 >= 0) == p0) continue; // its hull lies on one side
        const double a = f0 - 2 * f1 + f2, b = 2 * (f1 - f0), c = f0;
        if (p0 != p2) { // one crossing
            double s;
            if (fabs(a) <= 1e-12 * (fabs(b) + fabs(c))) {
                s = -c / b;
            } else {
                const double disc = b * b - 4 * a * c;
                const double q = -0.5 * (b + (b < 0 ? -1 : 1) * sqrt(disc > 0 ? disc : 0));
                const double r0 = q / a, r1 = q != 0 ? c / q : r0;
                // the root in [0, 1] (the other lies outside; rounding may nudge either)
                auto off = [](double r) { return r < 0 ? -r : r > 1 ? r - 1 : 0.0; };
                s = off(r0) <= off(r1) ? r0 : r1;
            }
            add_crossing(g, s, p0 ? -1 : 1, ox, oy, dx, dy, inv_len2, xs, n);
        } else { // none or two: the curve dips to the other side between its ends
            const double fmin = c - b * b / (4 * a);
            if ((fmin >= 0) == p0) continue;
            const double disc = b * b - 4 * a * c;
            const double q = -0.5 * (b + (b < 0 ? -1 : 1) * sqrt(disc > 0 ? disc : 0));
            double r0 = q / a, r1 = q != 0 ? c / q : r0;
            if (r0 > r1) {
                const double t = r0;
                r0 = r1, r1 = t;
            }
            add_crossing(g, r0, p0 ? -1 : 1, ox, oy, dx, dy, inv_len2, xs, n);
            add_crossing(g, r1, p0 ? 1 : -1, ox, oy, dx, dy, inv_len2, xs, n);
        }
    }
    return n;
}

/// Whether (x, y) lies in the glyph (on its outline counts as in); `xs` is scratch space.
SHEAF_HD_INLINE bool contains(const GlyphSegment* segs, uint32_t count, uint32_t even_odd, double x,
                              double y, Crossing* xs) {
    const int n = crossings(segs, count, x, y, 1, 0, xs);
    int w = 0;
    for (int i = 0; i < n && xs[i].t < 0; ++i) w += xs[i].delta;
    if ((w & (even_odd ? 1 : -1)) != 0) return true;
    for (int i = 0; i < n; ++i)
        if (xs[i].t == 0) return true;
    return false;
}

/// Cuts [lo, hi] to where lo_b <= o + d t <= hi_b; false when nothing is left.
SHEAF_HD_INLINE bool clip_slab(double o, double d, double lo_b, double hi_b, double& lo,
                               double& hi) {
    if (fabs(d) < 1e-30) return o >= lo_b && o <= hi_b;
    double a = (lo_b - o) / d, b = (hi_b - o) / d;
    if (a > b) {
        const double t = a;
        a = b, b = t;
    }
    lo = a > lo ? a : lo;
    hi = b < hi ? b : hi;
    return lo <= hi;
}

} // namespace glyph_detail

namespace glyph_detail {

/// The pieces of a conic glyph (see glyph_pieces) inside the ray's stretch [z0, z1] between
/// its caps: the stretch straightened into the outline's plane, its crossings there mapped back.
SHEAF_HD_INLINE int conic_pieces(const GlyphSegment* s, uint32_t count, uint32_t even_odd,
                                 double base, bool open, const Ray& r, double z0, double z1,
                                 Vec3 zn0, Vec3 zn1, double* t0, double* t1, Vec3* n0, Vec3* n1,
                                 int max) {
    const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    const double slope = 1 - base;
    const Vec3 dir{float(dx), float(dy), float(dz)};
    Crossing xs[kMaxGlyphCrossings];
    // The line in the outline's plane, a + s (b - a), and the ray's t at its parameter s.
    double ax, ay, bx, by, wa, wb;
    const bool level = fabs(dz) < 1e-30; // at one height: the line is the ray's, scaled
    if (level) {
        wa = wb = base + slope * oz;
        ax = ox / wa, ay = oy / wa, bx = ax + dx / wa, by = ay + dy / wa;
    } else {
        wa = base + slope * (oz + z0 * dz), wb = base + slope * (oz + z1 * dz);
        ax = (ox + z0 * dx) / wa, ay = (oy + z0 * dy) / wa;
        bx = (ox + z1 * dx) / wb, by = (oy + z1 * dy) / wb;
    }
    auto t_at = [&](double u) {
        return level ? u : z0 + (z1 - z0) * (u * wa / (wb * (1 - u) + u * wa));
    };
    // The side's normal where the line crosses the outline at parameter u with the outline's
    // normal (nx, ny): the cone's, (nx, ny, -(1 - base) (nx qx + ny qy)) at the outline point q.
    auto side_normal = [&](const Crossing& c, double u) {
        const double qx = ax + u * (bx - ax), qy = ay + u * (by - ay);
        return normalize(Vec3(c.nx, c.ny, float(-slope * (c.nx * qx + c.ny * qy))));
    };
    const double ex = bx - ax, ey = by - ay;
    if (ex * ex + ey * ey <= 1e-24 * (ax * ax + ay * ay + 1)) { // through the apex's line
        if (open || level || max < 1 || !contains(s, count, even_odd, ax, ay, xs)) return 0;
        t0[0] = z0, t1[0] = z1, n0[0] = zn0, n1[0] = zn1;
        return 1;
    }
    const double u_lo = level ? z0 : 0, u_hi = level ? z1 : 1; // the caps along the line
    const int nx = crossings(s, count, ax, ay, ex, ey, xs);
    int n = 0, w = 0;
    if (open) {
        for (int i = 0; i < nx && n < max; ++i) {
            if (xs[i].t < u_lo || xs[i].t > u_hi) continue;
            Vec3 nn = side_normal(xs[i], xs[i].t);
            if (dot(nn, dir) > 0) nn = -nn;
            t0[n] = t1[n] = t_at(xs[i].t), n0[n] = n1[n] = nn;
            ++n;
        }
        return n;
    }
    const int mask = even_odd ? 1 : -1;
    double enter = 0;
    Vec3 enter_n;
    for (int i = 0; i < nx && n < max; ++i) {
        const int before = w;
        w += xs[i].delta;
        if ((before & mask) == 0 && (w & mask) != 0) {
            enter = xs[i].t;
            enter_n = side_normal(xs[i], enter);
            if (dot(enter_n, dir) > 0) enter_n = -enter_n;
        } else if ((before & mask) != 0 && (w & mask) == 0) {
            const double a = enter > u_lo ? enter : u_lo, b = xs[i].t < u_hi ? xs[i].t : u_hi;
            if (a <= b) {
                Vec3 leave_n = side_normal(xs[i], xs[i].t);
                if (dot(leave_n, dir) < 0) leave_n = -leave_n;
                t0[n] = t_at(a), t1[n] = t_at(b);
                n0[n] = enter > u_lo ? enter_n : zn0;
                n1[n] = xs[i].t < u_hi ? leave_n : zn1;
                ++n;
            }
        }
    }
    return n;
}

} // namespace glyph_detail

/// The pieces of the local ray inside the extruded glyph, sorted, at most `max`: piece i is
/// [t0[i], t1[i]] with outward normals n0[i], n1[i] at its ends. `open`: the sides only, each
/// crossing inside the slab a piece of zero length facing the ray. `base` >= 0: a conic glyph,
/// the outline scaled by base + (1 - base) z at height z (base in [0, 1]); < 0: a straight
/// one. Out of line on the device, so that CSG's per-level frame does not carry the crossing
/// list.
SHEAF_HD_NOINLINE int glyph_pieces(const GlyphRef& g, const GlyphSegment* segs, bool open,
                                   const Ray& r, double* t0, double* t1, Vec3* n0, Vec3* n1,
                                   int max, double base = -1) {
    using namespace glyph_detail;
    const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    double z0, z1; // the slab 0 <= z <= 1 and its caps' normals
    Vec3 zn0, zn1;
    if (!unit_slab(oz, dz, z0, z1, zn0, zn1)) return 0;
    // Nothing of the glyph's box along the ray: no crossing to look for. A conic glyph's
    // outline shrinks towards the origin below z = 1: its box reaches from base times the
    // outline's box to the box.
    double lo = z0, hi = z1;
    const double k = base < 0 ? 1 : base;
    const double lo_x = g.lo_x < k * g.lo_x ? g.lo_x : k * g.lo_x;
    const double lo_y = g.lo_y < k * g.lo_y ? g.lo_y : k * g.lo_y;
    const double hi_x = g.hi_x > k * g.hi_x ? g.hi_x : k * g.hi_x;
    const double hi_y = g.hi_y > k * g.hi_y ? g.hi_y : k * g.hi_y;
    if (!clip_slab(ox, dx, lo_x, hi_x, lo, hi) || !clip_slab(oy, dy, lo_y, hi_y, lo, hi)) return 0;
    const GlyphSegment* s = segs + g.first;
    if (base >= 0) {
        // Where the outline shrinks to a point (base 0, the apex) the cap is no surface: the
        // stretch stops just above it, where the projection is still defined.
        if (base < 1e-6) {
            const double z_apex = (1e-6 - base) / (1 - base);
            if (fabs(dz) < 1e-30) {
                if (oz < z_apex) return 0;
            } else if (!clip_slab(oz, dz, z_apex, 1, z0, z1)) {
                return 0;
            }
        }
        return conic_pieces(s, g.count, g.even_odd, base, open, r, z0, z1, zn0, zn1, t0, t1, n0, n1,
                            max);
    }
    const Vec3 side_dir(float(dx), float(dy), 0);
    const double len2 = dx * dx + dy * dy;
    Crossing xs[kMaxGlyphCrossings];
    if (len2 <= 1e-24 * dz * dz) { // along z: in or out all the way through
        if (open || max < 1 || !contains(s, g.count, g.even_odd, ox, oy, xs)) return 0;
        t0[0] = z0, t1[0] = z1, n0[0] = zn0, n1[0] = zn1;
        return 1;
    }
    const int nx = crossings(s, g.count, ox, oy, dx, dy, xs);
    int count = 0, w = 0;
    if (open) {
        for (int i = 0; i < nx && count < max; ++i) {
            if (xs[i].t < z0 || xs[i].t > z1) continue;
            Vec3 n(xs[i].nx, xs[i].ny, 0);
            if (dot(n, side_dir) > 0) n = -n;
            t0[count] = t1[count] = xs[i].t, n0[count] = n1[count] = n;
            ++count;
        }
        return count;
    }
    const int mask = g.even_odd ? 1 : -1; // the winding numbers that are inside: w & mask
    double enter = 0;
    Vec3 enter_n;
    for (int i = 0; i < nx && count < max; ++i) {
        const int before = w;
        w += xs[i].delta;
        Vec3 n(xs[i].nx, xs[i].ny, 0);
        if ((before & mask) == 0 && (w & mask) != 0) {
            enter = xs[i].t;
            enter_n = dot(n, side_dir) > 0 ? -n : n;
        } else if ((before & mask) != 0 && (w & mask) == 0) {
            if (dot(n, side_dir) < 0) n = -n;
            const double a = enter > z0 ? enter : z0, b = xs[i].t < z1 ? xs[i].t : z1;
            if (a <= b) {
                t0[count] = a, t1[count] = b;
                n0[count] = enter > z0 ? enter_n : zn0;
                n1[count] = xs[i].t < z1 ? n : zn1;
                ++count;
            }
        }
    }
    return count;
}

} // namespace sheaf

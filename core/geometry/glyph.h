// An extruded glyph (one character of POV-Ray's text object): the region of the x-y plane that
// a closed outline of quadratic Bézier segments encloses, by the nonzero winding rule (as
// TrueType fills), swept from z = 0 to z = 1. Exact: a ray's line in the plane meets each
// segment where a quadratic in the segment's parameter vanishes, and the winding number along
// the line changes by one at each such crossing, so the pieces of the line inside the region
// are where the running sum is not zero; those pieces, cut to the slab 0 <= z <= 1, are the
// spans. Each segment's crossings are counted by the signs of its end points (a point on the
// line counts as on its positive side), so segments that share an end point never count a
// crossing twice or miss one, whatever the ray.
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
/// and the box in the x-y plane that holds their control points.
struct GlyphRef {
    uint32_t first = 0, count = 0;
    float lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;
};

/// A glyph's outline as the scene model holds it (host only): closed contours, each a chain of
/// segments whose last end point is its first start point.
struct GlyphOutline {
    std::vector<GlyphSegment> segments;
};

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

SHEAF_HD_INLINE void insert(Crossing* xs, int& n, const Crossing& c) {
    int at;
    if (n < kMaxGlyphCrossings)
        at = n++;
    else if (c.t < xs[n - 1].t)
        at = n - 1; // full: the farthest one gives way
    else
        return;
    for (; at > 0 && xs[at - 1].t > c.t; --at) xs[at] = xs[at - 1];
    xs[at] = c;
}

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
    insert(xs, n,
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
SHEAF_HD_INLINE bool contains(const GlyphSegment* segs, uint32_t count, double x, double y,
                              Crossing* xs) {
    const int n = crossings(segs, count, x, y, 1, 0, xs);
    int w = 0;
    for (int i = 0; i < n && xs[i].t < 0; ++i) w += xs[i].delta;
    if (w != 0) return true;
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

/// The pieces of the local ray inside the extruded glyph, sorted, at most `max`: piece i is
/// [t0[i], t1[i]] with outward normals n0[i], n1[i] at its ends. Out of line on the device, so
/// that CSG's per-level frame does not carry the crossing list.
SHEAF_HD_NOINLINE int glyph_pieces(const GlyphRef& g, const GlyphSegment* segs, const Ray& r,
                                   double* t0, double* t1, Vec3* n0, Vec3* n1, int max) {
    using namespace glyph_detail;
    const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    // The slab 0 <= z <= 1 and its caps' normals.
    double z0 = -DBL_MAX, z1 = DBL_MAX;
    Vec3 zn0(0, 0, -1), zn1(0, 0, 1);
    if (fabs(dz) < 1e-30) {
        if (oz < 0 || oz > 1) return 0;
    } else {
        z0 = -oz / dz, z1 = (1 - oz) / dz;
        if (z0 > z1) {
            const double t = z0;
            z0 = z1, z1 = t;
            zn0 = Vec3(0, 0, 1), zn1 = Vec3(0, 0, -1);
        }
    }
    // Nothing of the glyph's box along the ray: no crossing to look for.
    double lo = z0, hi = z1;
    if (!clip_slab(ox, dx, g.lo_x, g.hi_x, lo, hi) || !clip_slab(oy, dy, g.lo_y, g.hi_y, lo, hi))
        return 0;
    const Vec3 side_dir(float(dx), float(dy), 0);
    const GlyphSegment* s = segs + g.first;
    const double len2 = dx * dx + dy * dy;
    Crossing xs[kMaxGlyphCrossings];
    if (len2 <= 1e-24 * dz * dz) { // along z: in or out all the way through
        if (max < 1 || !contains(s, g.count, ox, oy, xs)) return 0;
        t0[0] = z0, t1[0] = z1, n0[0] = zn0, n1[0] = zn1;
        return 1;
    }
    const int nx = crossings(s, g.count, ox, oy, dx, dy, xs);
    int count = 0, w = 0;
    double enter = 0;
    Vec3 enter_n;
    for (int i = 0; i < nx && count < max; ++i) {
        const int before = w;
        w += xs[i].delta;
        Vec3 n(xs[i].nx, xs[i].ny, 0);
        if (before == 0 && w != 0) {
            enter = xs[i].t;
            enter_n = dot(n, side_dir) > 0 ? -n : n;
        } else if (before != 0 && w == 0) {
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

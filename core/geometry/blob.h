// Blobs (POV-Ray's blob): the solid where a sum of field components exceeds a threshold.
// Each component has a strength S and a region of influence, a sphere or a capsule (a
// cylinder with hemispherical ends), placed by its own affine map; at distance d from its
// centre (the sphere's point, the capsule's segment), in units of its radius, it adds
// S (1 - d^2)^2 for d < 1 and nothing beyond. Strengths may be negative.
//
// Exact: along a ray the squared distance to a component is a quadratic in t between the
// points where the ray enters and leaves its influence (and, for a capsule, crosses the planes
// of its segment's ends), so between consecutive such events the field is one quartic in t.
// The ray is swept event by event; in each interval, the quartic minus the threshold has its
// roots isolated in [0, 1] of the interval (core/geometry/poly.h), its value at each event
// shared by the two intervals that meet there so that rounding never counts a crossing twice
// or misses one. The field is zero far away and each crossing toggles inside and outside.
#pragma once

#include "core/geometry/poly.h"
#include "core/geometry/ray.h"
#include "core/math/affine.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sheaf {

/// One component in its unit space: the blob's point x maps to p = to_unit(x), where the
/// influence is |p| < 1 (a sphere, len = 0) or the distance from p to the segment from the
/// origin to (0, 0, len) is below 1 (a capsule). `bound`: a sphere (centre, radius) in the
/// blob's space holding the influence.
struct BlobElement {
    Affine to_unit;
    float strength = 0, len = 0;
    float bound[4] = {0, 0, 0, 0};
};

/// A blob of a prepared scene: elements [first, first + count) of the scene's blob elements;
/// the threshold (> 0) and a sphere holding the solid (the positive components' bounds).
struct BlobRef {
    uint32_t first = 0, count = 0;
    float threshold = 1;
    float bound[4] = {0, 0, 0, 0};
};

/// A blob as the scene model holds it (host only); built by core/geometry/blob_build.h.
struct BlobModel {
    std::vector<BlobElement> elements;
    float threshold = 1;
};

/// The most components whose influence one ray passes through that are followed (the ones
/// it enters first): beyond where the first left out begins, the ray sees no more crossings.
constexpr int kMaxBlobHits = 64;

namespace blob_detail {

/// Where a ray enters and leaves one component's influence, and where it crosses the planes
/// of a capsule's ends (infinite when it does not, or for a sphere).
struct Hit {
    float t, t_out, tz0, tz1; // enters at t (the name insert_nearest sorts by), leaves at t_out
    uint32_t element;
};

struct D3 {
    double x, y, z;
};

SHEAF_HD_INLINE D3 to_unit_point(const Affine& a, double x, double y, double z) {
    return {a.m[0][0] * x + a.m[0][1] * y + a.m[0][2] * z + a.m[0][3],
            a.m[1][0] * x + a.m[1][1] * y + a.m[1][2] * z + a.m[1][3],
            a.m[2][0] * x + a.m[2][1] * y + a.m[2][2] * z + a.m[2][3]};
}

SHEAF_HD_INLINE D3 to_unit_vector(const Affine& a, double x, double y, double z) {
    return {a.m[0][0] * x + a.m[0][1] * y + a.m[0][2] * z,
            a.m[1][0] * x + a.m[1][1] * y + a.m[1][2] * z,
            a.m[2][0] * x + a.m[2][1] * y + a.m[2][2] * z};
}

/// [lo, hi] of t where |o + t d - c| < 1 along z only by c = (0, 0, cz): a unit sphere at cz.
SHEAF_HD_INLINE bool unit_sphere_interval(D3 o, D3 d, double cz, double& lo, double& hi) {
    const double oz = o.z - cz;
    const double a = d.x * d.x + d.y * d.y + d.z * d.z;
    const double b = o.x * d.x + o.y * d.y + oz * d.z;
    const double c = o.x * o.x + o.y * o.y + oz * oz - 1;
    const double disc = b * b - a * c;
    if (!(a > 0) || !(disc > 0)) return false;
    const double s = sqrt(disc);
    lo = (-b - s) / a, hi = (-b + s) / a;
    return true;
}

/// The interval of the ray (o, d in the unit space) inside a component's influence, and the
/// capsule's plane crossings; false when it misses.
SHEAF_HD_INLINE bool influence(const BlobElement& e, D3 o, D3 d, Hit& h) {
    double lo, hi;
    if (!unit_sphere_interval(o, d, 0, lo, hi)) lo = INFINITY, hi = -INFINITY;
    h.tz0 = h.tz1 = INFINITY;
    if (e.len > 0) {
        const double len = e.len;
        double l1, h1;
        if (unit_sphere_interval(o, d, len, l1, h1)) lo = fmin(lo, l1), hi = fmax(hi, h1);
        // The cylinder between the end planes.
        const double a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y;
        const double c = o.x * o.x + o.y * o.y - 1;
        double cl = -INFINITY, ch = INFINITY;
        bool any = true;
        if (a > 1e-30) {
            const double disc = b * b - a * c;
            if (disc > 0) {
                const double s = sqrt(disc);
                cl = (-b - s) / a, ch = (-b + s) / a;
            } else {
                any = false;
            }
        } else if (!(c < 0)) {
            any = false;
        }
        if (d.z != 0) {
            const double z0 = -o.z / d.z, z1 = (len - o.z) / d.z;
            cl = fmax(cl, fmin(z0, z1)), ch = fmin(ch, fmax(z0, z1));
            h.tz0 = float(z0), h.tz1 = float(z1);
        } else if (!(o.z >= 0 && o.z <= len)) {
            any = false;
        }
        if (any && cl < ch) lo = fmin(lo, cl), hi = fmax(hi, ch);
    }
    if (!(lo < hi)) return false;
    h.t = float(lo), h.t_out = float(hi);
    return h.t < h.t_out;
}

/// For a capsule, moves o (and d) so that the distance is measured from the segment's point
/// nearest to where the interval's middle lies: the end sphere's centre, or the axis.
SHEAF_HD_INLINE void nearest_part(const BlobElement& e, double zmid, D3& o, D3& d) {
    if (!(e.len > 0) || zmid < 0) return;
    if (zmid > e.len) {
        o.z -= e.len;
    } else {
        o.z = 0, d.z = 0;
    }
}

/// Adds the component's field, strength (1 - |o + s d|^2)^2, to q[0..4] (a quartic in s).
SHEAF_HD_INLINE void add_field(double strength, D3 o, D3 d, double* q) {
    const double A = d.x * d.x + d.y * d.y + d.z * d.z;
    const double B = 2 * (o.x * d.x + o.y * d.y + o.z * d.z);
    const double e = 1 - (o.x * o.x + o.y * o.y + o.z * o.z);
    q[0] += strength * e * e;
    q[1] += strength * -2 * e * B;
    q[2] += strength * (B * B - 2 * e * A);
    q[3] += strength * 2 * A * B;
    q[4] += strength * A * A;
}

/// The field's gradient's opposite (the outward normal, unnormalised) at blob point x, from
/// the components in hits[0..n) whose influence holds it.
SHEAF_HD_INLINE Vec3 outward(const BlobElement* el, const Hit* hits, int n, double x, double y,
                             double z) {
    double g[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const BlobElement& e = el[hits[i].element];
        D3 p = to_unit_point(e.to_unit, x, y, z);
        if (e.len > 0) p.z -= p.z < 0 ? 0 : (p.z > e.len ? e.len : p.z);
        const double d2 = p.x * p.x + p.y * p.y + p.z * p.z;
        if (!(d2 < 1)) continue;
        const double k = e.strength * (1 - d2);
        for (int c = 0; c < 3; ++c)
            g[c] +=
                k * (e.to_unit.m[0][c] * p.x + e.to_unit.m[1][c] * p.y + e.to_unit.m[2][c] * p.z);
    }
    return Vec3(float(g[0]), float(g[1]), float(g[2]));
}

} // namespace blob_detail

/// The pieces of the local ray inside the blob, sorted, at most `max`: piece i is
/// [t0[i], t1[i]] with outward normals n0[i], n1[i] at its ends. Out of line on the device,
/// so that CSG's per-level frame does not carry the list of components met.
SHEAF_HD_NOINLINE int blob_pieces(const BlobRef& b, const BlobElement* elements, const Ray& r,
                                  double* t0, double* t1, Vec3* n0, Vec3* n1, int max) {
    using namespace blob_detail;
    const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
    const double dx = r.dir.x, dy = r.dir.y, dz = r.dir.z;
    const double len2 = dx * dx + dy * dy + dz * dz;
    if (!(len2 > 0)) return 0;
    // The components whose influence the ray passes through, the first entered kept.
    Hit hits[kMaxBlobHits];
    int n = 0;
    double limit = INFINITY; // where the first component left out begins
    const BlobElement* el = elements + b.first;
    for (uint32_t k = 0; k < b.count; ++k) {
        const BlobElement& e = el[k];
        const double cx = e.bound[0] - ox, cy = e.bound[1] - oy, cz = e.bound[2] - oz;
        const double along = cx * dx + cy * dy + cz * dz;
        const double miss2 = cx * cx + cy * cy + cz * cz - along * along / len2;
        if (miss2 > double(e.bound[3]) * e.bound[3]) continue;
        Hit h;
        if (!influence(e, to_unit_point(e.to_unit, ox, oy, oz),
                       to_unit_vector(e.to_unit, dx, dy, dz), h))
            continue;
        h.element = k;
        if (n == kMaxBlobHits) {
            if (!(h.t < hits[n - 1].t)) {
                limit = fmin(limit, double(h.t));
                continue;
            }
            limit = fmin(limit, double(hits[n - 1].t));
        }
        insert_nearest(hits, n, kMaxBlobHits, Hit{h.t, h.t_out, h.tz0, h.tz1, k});
    }
    if (n == 0) return 0;

    // Sweep the events in order. `fl`: the field minus the threshold at the interval's start,
    // carried from the previous interval's end so that both agree on its sign.
    const Vec3 dir{float(dx), float(dy), float(dz)};
    const double threshold = b.threshold;
    double u = hits[0].t, fl = -threshold, t_in = 0;
    Vec3 n_in;
    bool inside = false;
    int count = 0;
    auto normal_at = [&](double t, bool facing) {
        Vec3 nv = outward(el, hits, n, ox + dx * t, oy + dy * t, oz + dz * t);
        if (!(dot(nv, nv) > 0)) nv = -dir;
        return (dot(nv, dir) > 0) == facing ? -nv : nv;
    };
    while (count < max && u < limit) {
        double v = INFINITY; // the next event after u
        for (int i = 0; i < n; ++i) {
            const Hit& h = hits[i];
            if (h.t > u && h.t < v) v = h.t;
            if (h.t_out > u && h.t_out < v) v = h.t_out;
            if (h.tz0 > u && h.tz0 < v && h.tz0 < h.t_out) v = h.tz0;
            if (h.tz1 > u && h.tz1 < v && h.tz1 < h.t_out) v = h.tz1;
        }
        if (!(v < INFINITY)) break;
        const bool last = v >= limit;
        if (last) v = limit;
        const double mid = 0.5 * (u + v), w = v - u;
        double q[5] = {0, 0, 0, 0, 0};
        int active = 0;
        for (int i = 0; i < n; ++i) {
            const Hit& h = hits[i];
            if (!(h.t < mid && mid < h.t_out)) continue;
            const BlobElement& e = el[h.element];
            D3 o = to_unit_point(e.to_unit, ox + dx * u, oy + dy * u, oz + dz * u);
            D3 d = to_unit_vector(e.to_unit, dx * w, dy * w, dz * w);
            nearest_part(e, o.z + 0.5 * d.z, o, d);
            add_field(e.strength, o, d, q);
            ++active;
        }
        q[0] -= threshold;
        double fr = active ? q[0] + q[1] + q[2] + q[3] + q[4] : -threshold;
        if (active) {
            q[0] = fl;
            double roots[5];
            int deg = 4;
            while (deg > 0 && q[deg] == 0) --deg;
            int nr = poly_roots_in<4>(q, deg, 0.0, 1.0, roots);
            nr = reconcile_roots(roots, nr, fl, fr);
            for (int i = 0; i < nr && count < max; ++i) {
                const double t = u + roots[i] * w;
                if (!inside) {
                    t_in = t, n_in = normal_at(t, true);
                } else {
                    t0[count] = t_in, t1[count] = t, n0[count] = n_in;
                    n1[count] = normal_at(t, false);
                    ++count;
                }
                inside = !inside;
            }
        }
        if (last && inside && count < max) { // cut where the components followed end
            t0[count] = t_in, t1[count] = limit, n0[count] = n_in, n1[count] = dir;
            ++count;
        }
        fl = fr, u = v;
    }
    return count;
}

} // namespace sheaf

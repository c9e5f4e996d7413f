// Photon maps as shading reads them: photons in an implicit balanced kd-tree, the search for
// the photons near a point, and the light they bring (POV-Ray's caustics).
// Host-and-device functions; the photon pass that fills the map is photon_pass.h.
#pragma once

#include "core/base/device.h"
#include "core/math/hd_math.h"
#include "core/math/vec3.h"

#include <cstdint>

namespace sheaf {

/// A photon where a light's path left it on a surface.
struct Photon {
    Vec3 position;
    Vec3 power;        // the light it brings, as POV-Ray scales it (spread^2 x path length^2)
    Vec3 from;         // unit direction back along the path's last leg
    uint32_t axis = 0; // the kd-tree's split axis at this photon (0 x, 1 y, 2 z)
};

/// A stored photon map: `photons` form an implicit kd-tree (the node of [lo, hi] is the
/// middle photon (lo + hi) / 2, splitting on its axis; smaller coordinates to the left), and
/// the search settings (PhotonSettings, with the radius estimated when the scene gives none).
struct PhotonMapView {
    const Photon* photons = nullptr;
    uint32_t count = 0;
    float radius = 0.0f; // the first search's radius
    float step = 0.0f;   // what each wider search adds to it
    uint32_t steps = 1, gather_min = 20, gather_max = 100, expand_min = 40;
    float expand_tolerance = 0.2f;
};

namespace photon_detail {

/// POV-Ray's distance for gathering on a surface (squared, flattened): photons off the
/// surface's plane (unit normal n) count as farther, so corners do not bleed.
SHEAF_HD_INLINE float flat_distance2(Vec3 v, Vec3 n) {
    const float d = dot(v, v);
    return d + 16.0f * fabsf(dot(n, v)) * d;
}

SHEAF_HD_INLINE float axis_of(Vec3 v, uint32_t a) {
    return a == 0 ? v.x : a == 1 ? v.y : v.z;
}

} // namespace photon_detail

/// Calls f(photon) for every photon within flattened distance sqrt(r2) of p (surface normal
/// n), in the kd-tree's order (the same on every run).
template <class F>
SHEAF_HD_INLINE void for_photons_near(const PhotonMapView& m, Vec3 p, Vec3 n, float r2, F&& f) {
    if (m.count == 0) return;
    // Ranges still to visit; a balanced tree of 2^32 photons is 32 deep, two per level.
    uint32_t lo_stack[64], hi_stack[64];
    int top = 0;
    lo_stack[0] = 0, hi_stack[0] = m.count - 1, top = 1;
    while (top > 0) {
        --top;
        const uint32_t lo = lo_stack[top], hi = hi_stack[top];
        const uint32_t mid = lo + (hi - lo) / 2;
        const Photon& ph = m.photons[mid];
        const Vec3 v = ph.position - p;
        if (photon_detail::flat_distance2(v, n) < r2) f(ph);
        const float delta = photon_detail::axis_of(v, ph.axis); // photon minus point
        // The photons before `mid` have coordinates up to the photon's, those after from it:
        // a side is worth visiting when its nearest possible coordinate is within reach (the
        // flattened distance is never below the plain one). The stack holds at most one
        // range per level and two at the deepest: 34 for 2^32 photons.
        const float r = sqrtf(r2);
        if (mid > lo && delta > -r && top < 64) lo_stack[top] = lo, hi_stack[top] = mid - 1, ++top;
        if (mid < hi && delta < r && top < 64) lo_stack[top] = mid + 1, hi_stack[top] = hi, ++top;
    }
}

/// How many photons lie within flattened distance sqrt(r2) of p.
SHEAF_HD_INLINE uint32_t photons_within(const PhotonMapView& m, Vec3 p, Vec3 n, float r2) {
    uint32_t c = 0;
    for_photons_near(m, p, n, r2, [&](const Photon&) { ++c; });
    return c;
}

/// One search of radius `size`: at most about gather_max photons, the nearest. Returns how
/// many and sets r2 to the squared radius they lie within: size^2, or, where more lie there,
/// a smaller one found by scaling the area by gather_max over the count (as if the photons
/// were spread evenly), at most four times, until the count is within a tenth of gather_max
/// (POV-Ray keeps exactly the gather_max nearest).
SHEAF_HD_INLINE uint32_t photon_search(const PhotonMapView& m, Vec3 p, Vec3 n, float size,
                                       float& r2) {
    r2 = size * size;
    uint32_t c = photons_within(m, p, n, r2);
    if (c <= m.gather_max) return c;
    const float want = float(m.gather_max), slack = 0.1f * want;
    // Never below a hundredth of the search radius: photons focused onto one point would
    // otherwise shrink the area to nothing and their light to infinity.
    const float floor2 = 1e-4f * size * size;
    for (int i = 0; i < 4 && fabsf(float(c) - want) > slack; ++i) {
        const float next = hdm::fmaxf(floor2, r2 * want / float(c > 0 ? c : 1));
        if (next >= r2) break;
        const uint32_t k = photons_within(m, p, n, next);
        if (k == 0) break; // the photons are clustered: keep the last radius that held some
        r2 = next, c = k;
    }
    return c;
}

/// POV-Ray's adaptive search at p: the first radius, then, while fewer than gather_min photons
/// were found, wider ones, each kept when its density differs little from the last or when it
/// found a few (fewer than expand_min). Returns the photons' count and sets r2.
SHEAF_HD_INLINE uint32_t photon_gather(const PhotonMapView& m, Vec3 p, Vec3 n, float& r2) {
    float size = m.radius;
    uint32_t c = photon_search(m, p, n, size, r2);
    float prev = r2 > 0 ? float(c) / r2 : 0.0f;
    if (!(prev > 0)) prev = 1e-16f;
    for (uint32_t step = 1; c < m.gather_min && step < m.steps; ++step) {
        size += m.step;
        float r2b;
        const uint32_t cb = photon_search(m, p, n, size, r2b);
        const float density = r2b > 0 ? float(cb) / r2b : 0.0f;
        if ((density - prev) / prev < m.expand_tolerance || (cb < m.expand_min && cb > 0)) {
            prev = density > 0 ? density : 1e-16f;
            c = cb, r2 = r2b;
        } else {
            break;
        }
    }
    return c;
}

} // namespace sheaf

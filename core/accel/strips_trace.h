// One ray through the strips (core/accel/strips.h), host-and-device: the tracer's strips
// launch runs it per ray on both backends. The top level is accel=bvh's walk; a strip is
// entered at its bounds and descended as a spatial kd-tree (paper 004, section 5.1): each node
// narrows the ray's interval by one plane per child, nearest child first. In a leaf the ray's
// edge tests (the 2D cross products of the edges projected along the ray, the sign of the
// ray's Plücker product with each edge) are taken once per edge and shared by the triangles
// on either side of it. A triangle whose edges do not put the ray clearly outside then takes
// the exact test of brute force, so the hits, and the image, are brute force's.
#pragma once

#include "core/accel/bvh_trace.h"
#include "core/accel/strips.h"

namespace sheaf {

// The maximum as a comparison (maxss): fmaxf is a call into libm on the host without
// -ffast-math. No NaN reaches it.
SHEAF_HD_INLINE float strip_max(float a, float b) {
    return a > b ? a : b;
}

/// What a ray's edge tests need: the axis it runs most along (kz), the other two, and the
/// shear that projects a point along the ray onto the plane kz = 0 (Woop et al.'s
/// watertight test uses the same projection).
struct StripRay {
    int kx, ky, kz;
    float sx, sy;
    float slack; // (1 + |sx| + |sy|)^2: how the shear grows rounding errors
    float reach; // the largest coordinate of the origin (L-infinity)
};

SHEAF_HD_INLINE StripRay strip_ray(const Ray& r) {
    const Vec3 a{fabsf(r.dir.x), fabsf(r.dir.y), fabsf(r.dir.z)};
    StripRay s;
    s.kz = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    s.kx = (s.kz + 1) % 3, s.ky = (s.kz + 2) % 3;
    const float dz = r.dir[s.kz];
    s.sx = dz != 0 ? r.dir[s.kx] / dz : 0.0f;
    s.sy = dz != 0 ? r.dir[s.ky] / dz : 0.0f;
    const float g = 1.0f + fabsf(s.sx) + fabsf(s.sy);
    s.slack = g * g;
    s.reach = strip_max(fabsf(r.origin.x), strip_max(fabsf(r.origin.y), fabsf(r.origin.z)));
    return s;
}

/// How far past zero an edge value must lie to put the ray outside, for a strip whose
/// coordinates reach `reach` and whose longest edge is `edge` (L1). Bounds the rounding of both
/// the edge values and the exact test (a ray the exact test may take, even where rounding
/// decides, is never put outside), with room to spare; see docs/architecture.md, "Strips".
SHEAF_HD_INLINE float strip_tolerance(const StripRay& s, float reach, float edge) {
    return 64.0f * 1.1920929e-7f * (s.reach + reach) * edge * s.slack;
}

/// Whether the three edge values of a triangle (taken around it) may have the ray inside:
/// not one clearly positive and another clearly negative.
SHEAF_HD_INLINE bool strip_edges_may_hit(float a, float b, float c, float tol) {
    const bool pos = a > tol || b > tol || c > tol;
    const bool neg = a < -tol || b < -tol || c < -tol;
    return !(pos && neg);
}

/// Triangles [l, l + m) (m <= kStripLeaf) of strip h: the ray's edge values, once per edge,
/// then the exact test of each triangle the ray may meet, in strip order. False when the ray
/// is finished. The edge from vertex q to r has the value px[q] * ey - py[q] * ex: p the
/// projection of vertex q less the origin, e the projection of the edge (from the vertices'
/// own difference, exact where they are close). Triangle j (vertices j, j + 1, j + 2) has the
/// edges j -> j + 1 (`along` j), j + 1 -> j + 2 (`along` j + 1) and j + 2 -> j (`across` j,
/// negated).
template <bool Any>
SHEAF_HD_INLINE bool strip_leaf(const StripsView& sv, const StripHeader& h, uint32_t l, uint32_t m,
                                const Ray& r, const StripRay& s, float tol, BvhHitTest<Any>& test) {
    // The vertices' coordinates in the ray's axis order, padded to whole vectors with the
    // last vertex (the lanes past the leaf are computed and never read).
    constexpr int kV = int(kStripLeaf) + 8;
    float ux[kV], uy[kV], uz[kV];
    const uint16_t* index = sv.index + h.first + l;
    const int read = (int(m) + 5) / 4 * 4 + 2; // every vertex the vectors below read
    for (int q = 0; q < read; ++q) {
        const Vec3& v = sv.verts[h.base_vertex + index[q < int(m) + 2 ? q : int(m) + 1]];
        ux[q] = v[s.kx], uy[q] = v[s.ky], uz[q] = v[s.kz];
    }
    const float ox = r.origin[s.kx], oy = r.origin[s.ky], oz = r.origin[s.kz];
    // Zeroed: the vectors read the lanes past a short leaf, whose triangles are never tested.
    float along[kStripLeaf + 4] = {}, across[kStripLeaf + 4] = {}, px[kV], py[kV];
    // The triangles to test: real ones (no join) of this ray type.
    const uint16_t* ids = sv.ids + h.first + l;
    uint32_t real = 0;
    for (uint32_t j = 0; j < m; ++j)
        if (ids[j] != kStripJoin && !test.skipped(h.base_prim + ids[j])) real |= 1u << j;
    if (!real) return true;
    uint32_t may = 0;
#if !defined(__CUDA_ARCH__) && defined(__SSE2__)
    const __m128 vsx = _mm_set1_ps(s.sx), vsy = _mm_set1_ps(s.sy);
    for (int q = 0; q < int(m) + 2; q += 4) {
        const __m128 dz = _mm_sub_ps(_mm_loadu_ps(uz + q), _mm_set1_ps(oz));
        _mm_storeu_ps(px + q, _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(ux + q), _mm_set1_ps(ox)),
                                         _mm_mul_ps(vsx, dz)));
        _mm_storeu_ps(py + q, _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(uy + q), _mm_set1_ps(oy)),
                                         _mm_mul_ps(vsy, dz)));
    }
    const auto edges = [&](float* out, int q, int step) {
        const __m128 ez = _mm_sub_ps(_mm_loadu_ps(uz + q + step), _mm_loadu_ps(uz + q));
        const __m128 ex = _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(ux + q + step), _mm_loadu_ps(ux + q)),
                                     _mm_mul_ps(vsx, ez));
        const __m128 ey = _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(uy + q + step), _mm_loadu_ps(uy + q)),
                                     _mm_mul_ps(vsy, ez));
        _mm_storeu_ps(out + q, _mm_sub_ps(_mm_mul_ps(_mm_loadu_ps(px + q), ey),
                                          _mm_mul_ps(_mm_loadu_ps(py + q), ex)));
    };
    for (int q = 0; q < int(m) + 1; q += 4) edges(along, q, 1);
    for (int q = 0; q < int(m); q += 4) edges(across, q, 2);
    const __m128 hi = _mm_set1_ps(tol), lo = _mm_set1_ps(-tol);
    for (int j = 0; j < int(m); j += 4) {
        const __m128 a = _mm_loadu_ps(along + j), b = _mm_loadu_ps(along + j + 1);
        const __m128 c = _mm_loadu_ps(across + j); // the third edge's value, negated
        const __m128 pos =
            _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(a, hi), _mm_cmpgt_ps(b, hi)), _mm_cmplt_ps(c, lo));
        const __m128 neg =
            _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(a, lo), _mm_cmplt_ps(b, lo)), _mm_cmpgt_ps(c, hi));
        may |= uint32_t(~_mm_movemask_ps(_mm_and_ps(pos, neg)) & 0xF) << j;
    }
#else
    for (uint32_t q = 0; q < m + 2; ++q) {
        const float dz = uz[q] - oz;
        px[q] = (ux[q] - ox) - s.sx * dz;
        py[q] = (uy[q] - oy) - s.sy * dz;
    }
    const auto edge = [&](uint32_t q, uint32_t t) {
        const float ez = uz[t] - uz[q];
        const float ex = (ux[t] - ux[q]) - s.sx * ez, ey = (uy[t] - uy[q]) - s.sy * ez;
        return px[q] * ey - py[q] * ex;
    };
    for (uint32_t q = 0; q < m + 1; ++q) along[q] = edge(q, q + 1);
    for (uint32_t q = 0; q < m; ++q) across[q] = edge(q, q + 2);
    for (uint32_t j = 0; j < m; ++j)
        if (strip_edges_may_hit(along[j], along[j + 1], -across[j], tol)) may |= 1u << j;
#endif
    for (uint32_t bits = real; bits; bits &= bits - 1) ++test.c.prims.tests;
    for (uint32_t bits = real & may; bits; bits &= bits - 1)
        if (!test.triangle(h.base_prim + ids[lowest_bit(bits)])) return false;
    return true;
}

/// Strip `k` through its hierarchy, nearest part first. False when the ray is finished.
template <bool Any>
SHEAF_HD_INLINE bool strip_trace(const StripsView& sv, uint32_t k, const Ray& r, const Vec3& inv,
                                 const StripRay& s, BvhHitTest<Any>& test) {
    const StripHeader& h = sv.strips[k];
    BvhCounts& c = test.c;
    // The ray within the strip's bounds.
    float t0 = r.tmin, t1 = test.far;
    for (int a = 0; a < 3; ++a) {
        float n = (h.lo[a] - r.origin[a]) * inv[a], f = (h.hi[a] - r.origin[a]) * inv[a];
        if (n > f) {
            const float x = n;
            n = f, f = x;
        }
        f += fabsf(f) * 4e-7f;
        t0 = n > t0 ? n : t0;
        t1 = f < t1 ? f : t1;
    }
    ++c.nodes.tests;
    if (!(t0 <= t1)) return true;
    ++c.nodes.hits;
    const float reach = strip_max(strip_max(strip_max(fabsf(h.lo[0]), fabsf(h.hi[0])),
                                            strip_max(fabsf(h.lo[1]), fabsf(h.hi[1]))),
                                  strip_max(fabsf(h.lo[2]), fabsf(h.hi[2])));
    const float tol = strip_tolerance(s, reach, h.edge);
    struct Part {
        uint32_t node, l, m;
        float t0, t1;
    };
    Part stack[kStripDepth + 1];
    int sp = 0;
    Part cur{0, 0, h.tris, t0, t1};
    for (;;) {
        if (cur.m <= kStripLeaf) {
            if (!strip_leaf<Any>(sv, h, cur.l, cur.m, r, s, tol, test)) return false;
        } else {
            uint32_t first, span;
            strip_split(cur.m, first, span);
            const uint32_t at = h.first_node + cur.node;
            const uint8_t meta = sv.meta[at];
            const StripPlanes pl = sv.planes[at];
            const int axis = meta & 3;
            const float o = r.origin[axis], ia = inv[axis];
            const float tb = (pl.below - o) * ia, ta = (pl.above - o) * ia;
            const float tb_up = tb + fabsf(tb) * 4e-7f, tb_down = tb - fabsf(tb) * 4e-7f;
            const float ta_up = ta + fabsf(ta) * 4e-7f, ta_down = ta - fabsf(ta) * 4e-7f;
            // The lower part (below the plane `below`) and the upper one, as intervals.
            Part lower, upper;
            const Part a{cur.node + 1, cur.l, first, 0, 0};
            const Part b{cur.node + span, cur.l + first, cur.m - first, 0, 0};
            if (meta & 4)
                upper = a, lower = b;
            else
                lower = a, upper = b;
            const bool rising = ia >= 0;
            if (rising) {
                lower.t0 = cur.t0, lower.t1 = tb_up < cur.t1 ? tb_up : cur.t1;
                upper.t0 = ta_down > cur.t0 ? ta_down : cur.t0, upper.t1 = cur.t1;
            } else {
                lower.t0 = tb_down > cur.t0 ? tb_down : cur.t0, lower.t1 = cur.t1;
                upper.t0 = cur.t0, upper.t1 = ta_up < cur.t1 ? ta_up : cur.t1;
            }
            const Part& near = rising ? lower : upper;
            const Part& farther = rising ? upper : lower;
            const float limit = Any ? r.tmax : test.far;
            const bool in_near = near.t0 <= near.t1 && near.t0 <= limit;
            const bool in_far = farther.t0 <= farther.t1 && farther.t0 <= limit;
            c.nodes.tests += 2;
            c.nodes.hits += uint64_t(in_near) + uint64_t(in_far);
            if (in_near) {
                if (in_far) stack[sp++] = farther;
                cur = near;
                continue;
            }
            if (in_far) {
                cur = farther;
                continue;
            }
        }
        // The next waiting part that a closest-hit ray's best hit has not passed.
        while (sp > 0 && (!Any && stack[sp - 1].t0 > test.far)) --sp;
        if (sp == 0) return true;
        cur = stack[--sp];
    }
}

/// Ray i of a batch (r) through the strips against `scene`, after the primitives without
/// bounds: records its hits as brute_trace_ray does (closest[i] for closest-hit queries, Any
/// false; occluded[i] and the pass log for any-hit ones). `skip`: primitive flags that are no
/// candidates for this ray type. Not inlined on the device (one copy of the exact tests a
/// query, as for the BVH).
template <bool Any>
SHEAF_HD_NOINLINE BvhCounts strips_trace_ray_as(const StripsView& sv, const SceneView& scene,
                                                const Ray& r, uint32_t i, bool shadow, uint8_t skip,
                                                const HitSinks& out) {
    BvhCounts c;
    BvhHitTest<Any> test(scene, r, i, shadow, skip, out, c);
    bool done = false;
    for (uint32_t k = 0; k < sv.top.unbounded_count && !done; ++k)
        done = !test(sv.top.unbounded[k]);
    if (sv.top.node_count > 0 && !done) {
        const Vec3 inv = bvh_inverse(r.dir);
        const StripRay s = strip_ray(r);
        bvh_walk<Any>(
            sv.top, r, inv, bvh_planes(inv), 0, test.far, c, [&](uint32_t first, uint32_t count) {
                for (uint32_t k = first; k < first + count; ++k) {
                    const uint32_t item = sv.top.prims[k];
                    const bool go = item & kStripItem
                                        ? strip_trace<Any>(sv, item & ~kStripItem, r, inv, s, test)
                                        : test(item);
                    if (!go) return false;
                }
                return true;
            });
    }
    test.finish(false);
    return c;
}

/// strips_trace_ray_as for a query chosen at run time.
SHEAF_HD_INLINE BvhCounts strips_trace_ray(const StripsView& sv, const SceneView& scene,
                                           const Ray& r, uint32_t i, bool any, bool shadow,
                                           uint8_t skip, const HitSinks& out) {
    return any ? strips_trace_ray_as<true>(sv, scene, r, i, shadow, skip, out)
               : strips_trace_ray_as<false>(sv, scene, r, i, shadow, skip, out);
}

} // namespace sheaf

// Exact ray tests of analytic primitives (a shape or a CSG tree) of a prepared scene.
// Host-and-device: both backends share them.
#pragma once

#include "core/geometry/csg.h"
#include "core/geometry/sphere.h"
#include "core/geometry/world_box.h"
#include "core/scene/scene_view.h"

namespace sheaf {

struct AnalyticHit {
    float t = 0;
    uint32_t leaf = 0; // placed shape of the surface hit
    Vec3 normal;       // world-space, pointing out of the solid
};

namespace analytic_detail {

SHEAF_HD_INLINE bool inside(const SpanList& spans, float t) {
    for (int i = 0; i < spans.n; ++i)
        if (spans.s[i].a.t <= t && t <= spans.s[i].b.t) return true;
    return false;
}

// Adds the boundaries of `base` that lie inside `clip` to `out`, kept in order of t: each
// becomes a span of zero length whose far end is no surface (leaf ~0), so it is hit, and
// crossed, once.
SHEAF_HD_INLINE void clip_spans(const SpanList& base, const SpanList& clip, SpanList& out) {
    for (int i = 0; i < base.n; ++i) {
        const CsgEnd* ends[2] = {&base.s[i].a, &base.s[i].b};
        for (const CsgEnd* e : ends) {
            if (e->leaf == 0xFFFFFFFFu || !inside(clip, e->t) || out.n >= kMaxCsgSpans) continue;
            int at = out.n++;
            for (; at > 0 && out.s[at - 1].a.t > e->t; --at) out.s[at] = out.s[at - 1];
            out.s[at] = {*e, CsgEnd{e->t, 0xFFFFFFFFu, e->n_local, e->flip}};
        }
    }
}

} // namespace analytic_detail

SHEAF_HD inline SpanList csg_spans(const SceneView& scene, uint32_t node, const Ray& ray,
                                   bool solid = false);

/// The surfaces of `node` inside `clip` (POV-Ray's clipped_by): a union keeps every member's
/// surface, its inner ones too (POV-Ray's union, unlike merge, has them), so a clipped union
/// shows what the clip opens up; any other node its solid's boundary.
SHEAF_HD inline void clipped_surfaces(const SceneView& scene, uint32_t node, const Ray& ray,
                                      const SpanList& clip, SpanList& out) {
    const PreparedCsgNode& n = scene.csg[node];
    if (n.op == CsgOp::Union && !n.inverse) {
        for (uint32_t c = 0; c < n.count; ++c)
            clipped_surfaces(scene, scene.csg_children[n.first + c], ray, clip, out);
        return;
    }
    analytic_detail::clip_spans(csg_spans(scene, node, ray), clip, out);
}

/// The spans of the ray inside CSG node `node` (recursive over the node's children). A clipped
/// object (an open surface) has spans of zero length at its surfaces; `solid` gives instead
/// the stretches inside it, as POV-Ray's inside test has them (inside the object and every
/// clipping object), which its interior fades.
SHEAF_HD inline SpanList csg_spans(const SceneView& scene, uint32_t node, const Ray& ray,
                                   bool solid) {
    using namespace analytic_detail;
    const PreparedCsgNode& n = scene.csg[node];
    SpanList out;
    // A line that misses the node's box has no spans in it (an inverse node's box is infinite).
    if (!line_meets_box(n.box, ray.origin, ray.dir)) return out;
    if (n.op == CsgOp::Clip) {
        SpanList clip = csg_spans(scene, scene.csg_children[n.first + 1], ray);
        for (uint32_t c = 2; c < n.count; ++c)
            clip = span_intersection(clip, csg_spans(scene, scene.csg_children[n.first + c], ray));
        if (solid)
            out = span_intersection(csg_spans(scene, scene.csg_children[n.first], ray, true), clip);
        else
            clipped_surfaces(scene, scene.csg_children[n.first], ray, clip, out);
        return n.inverse ? span_complement(out) : out;
    }
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        Span spans[kMaxShapeSpans];
        const int count = shape_spans(ps.shape, to_local_ray(ps, ray), spans, scene.shape_tables());
        for (int i = 0; i < count; ++i)
            out.push({CsgEnd{spans[i].t0, n.first, spans[i].n0, false},
                      CsgEnd{spans[i].t1, n.first, spans[i].n1, false}});
    } else {
        out = csg_spans(scene, scene.csg_children[n.first], ray, solid);
        // Once nothing is left of an intersection or a difference, the rest cannot add to it.
        const bool narrows = n.op == CsgOp::Intersection || n.op == CsgOp::Difference;
        for (uint32_t c = 1; c < n.count && !(narrows && out.n == 0); ++c) {
            const SpanList next = csg_spans(scene, scene.csg_children[n.first + c], ray, solid);
            switch (n.op) {
            case CsgOp::Union:
            case CsgOp::Merge:
                out = span_union(out, next);
                break;
            case CsgOp::Intersection:
                out = span_intersection(out, next);
                break;
            case CsgOp::Difference:
                out = span_difference(out, next);
                break;
            case CsgOp::Leaf:
            case CsgOp::Clip:
                break;
            }
        }
    }
    return n.inverse ? span_complement(out) : out;
}

/// The first surface of analytic primitive `index` (0-based among the analytic ones) along the
/// ray inside (tmin, tmax). Deterministic: the same ray gives the same t on every accel mode.
SHEAF_HD inline bool analytic_first_hit(const SceneView& scene, uint32_t index, const Ray& ray,
                                        AnalyticHit& hit) {
    const SpanList spans = csg_spans(scene, scene.analytic_root[index], ray);
    for (int i = 0; i < spans.n; ++i) {
        const CsgEnd* ends[2] = {&spans.s[i].a, &spans.s[i].b};
        for (const CsgEnd* e : ends) {
            if (!(e->t > ray.tmin && e->t < ray.tmax) || e->leaf == 0xFFFFFFFFu) continue;
            hit.t = e->t;
            hit.leaf = e->leaf;
            const Vec3 n = normal_to_world(scene.shapes[e->leaf], e->n_local);
            hit.normal = e->flip ? -n : n;
            return true;
        }
    }
    return false;
}

/// A world-space sphere holding the node's solid; radius +inf when unbounded (planes,
/// `inverse`), so the node is a candidate for every ray. Host only (scene preparation).
Sphere csg_bound(const PreparedScene& scene, uint32_t node);

/// A world-space axis-aligned box holding the node's solid, within the cube around its
/// csg_bound (a shape's own box through its transform, CSG combined as csg_bound does);
/// infinite where that is. Host only (scene preparation: the BVH's boxes).
WorldBox csg_box(const PreparedScene& scene, uint32_t node);

/// Sets the box of every node of root's tree (PreparedCsgNode::box, csg_box's), each node
/// computed once; returns root's csg_bound. Host only (scene preparation).
Sphere set_csg_boxes(PreparedScene& scene, uint32_t root);

/// Placed shape of a leaf: world <-> local transforms from the leaf's world transform.
PlacedShape place_shape(const Shape& shape, const Affine& local_to_world);

} // namespace sheaf

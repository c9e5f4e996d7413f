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

bool inside(const SpanList& spans, float t) {
    for (int i = 0; i < spans.n; ++i)
        if (spans.s[i].a.t <= t && t <= spans.s[i].b.t) return true;
    return false;
}

// The surface of `base` inside `clip`: each boundary that survives becomes a span of zero
// length whose far end is no surface (leaf ~0), so it is hit, and crossed, once.
SpanList clip_spans(const SpanList& base, const SpanList& clip) {
    SpanList out;
    for (int i = 0; i < base.n; ++i)
        for (const CsgEnd* e : {&base.s[i].a, &base.s[i].b})
            if (e->leaf != 0xFFFFFFFFu && inside(clip, e->t))
                out.push({*e, CsgEnd{e->t, 0xFFFFFFFFu, e->n_local, e->flip}});
    return out;
}

} // namespace

SpanList csg_spans(const PreparedScene& scene, uint32_t node, const Ray& ray) {
    const PreparedCsgNode& n = scene.csg[node];
    SpanList out;
    if (n.op == CsgOp::Clip) {
        SpanList clip = csg_spans(scene, scene.csg_children[n.first + 1], ray);
        for (uint32_t c = 2; c < n.count; ++c)
            clip = span_intersection(clip, csg_spans(scene, scene.csg_children[n.first + c], ray));
        out = clip_spans(csg_spans(scene, scene.csg_children[n.first], ray), clip);
        return n.inverse ? span_complement(out) : out;
    }
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        Span spans[kMaxShapeSpans];
        const int count = shape_spans(ps.shape, to_local_ray(ps, ray), spans);
        for (int i = 0; i < count; ++i)
            out.push({CsgEnd{spans[i].t0, n.first, spans[i].n0, false},
                      CsgEnd{spans[i].t1, n.first, spans[i].n1, false}});
    } else {
        out = csg_spans(scene, scene.csg_children[n.first], ray);
        for (uint32_t c = 1; c < n.count; ++c) {
            const SpanList next = csg_spans(scene, scene.csg_children[n.first + c], ray);
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

bool analytic_first_hit(const PreparedScene& scene, uint32_t index, const Ray& ray,
                        AnalyticHit& hit) {
    const SpanList spans = csg_spans(scene, scene.analytic_root[index], ray);
    for (int i = 0; i < spans.n; ++i)
        for (const CsgEnd* e : {&spans.s[i].a, &spans.s[i].b}) {
            if (!(e->t > ray.tmin && e->t < ray.tmax) || e->leaf == 0xFFFFFFFFu) continue;
            hit.t = e->t;
            hit.leaf = e->leaf;
            const Vec3 n = normal_to_world(scene.shapes[e->leaf], e->n_local);
            hit.normal = e->flip ? -n : n;
            return true;
        }
    return false;
}

namespace {

Sphere local_bound(const Shape& s) {
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
    }
    return {Vec3(0.0f), INFINITY};
}

} // namespace

Sphere csg_bound(const PreparedScene& scene, uint32_t node) {
    const PreparedCsgNode& n = scene.csg[node];
    if (n.inverse) return {Vec3(0.0f), INFINITY};
    if (n.op == CsgOp::Leaf) {
        const PlacedShape& ps = scene.shapes[n.first];
        const Sphere l = local_bound(ps.shape);
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

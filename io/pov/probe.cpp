#include "io/pov/probe.h"

#include "core/accel/bvh_trace.h"
#include "core/base/error.h"
#include "core/geometry/ray_triangle.h"
#include "core/scene/analytic.h"
#include "io/pov/builder.h"

#include <cfloat>
#include <cmath>

namespace sheaf::io::pov {

std::shared_ptr<const ObjectProbe> make_probe(Parser& p, const PovObject& o, const Token& at) {
    auto q = std::make_shared<ObjectProbe>();
    build_object_geometry(p, o, q->scene);
    try {
        q->prepared = prepare_scene(q->scene);
        q->bvh = build_bvh_in_order(q->prepared);
    } catch (const SceneError& e) {
        p.error_at(at, at.text + "() cannot trace this object: " + e.what());
    }
    return q;
}

bool probe_inside(const ObjectProbe& q, Vec3 point) {
    const SceneView view(q.prepared);
    Ray r; // the whole line through the point: inside when a span holds t = 0
    r.origin = pov_to_sheaf().point(point);
    r.dir = normalize(Vec3(0.5773f, 0.5774f, 0.5775f));
    r.tmin = -FLT_MAX, r.tmax = FLT_MAX;
    for (uint32_t a = 0; a < uint32_t(q.prepared.analytic_root.size()); ++a) {
        const SpanList spans = csg_spans(view, q.prepared.analytic_root[a], r);
        for (int i = 0; i < spans.n; ++i)
            if (spans.s[i].a.t <= 0 && 0 <= spans.s[i].b.t) return true;
    }
    return false;
}

Ray probe_ray(Vec3 from, Vec3 dir) {
    const Affine flip = pov_to_sheaf();
    Ray r;
    r.origin = flip.point(from);
    r.dir = normalize(flip.vector(dir));
    r.tmin = 0, r.tmax = FLT_MAX;
    return r;
}

bool probe_trace(const ObjectProbe& q, Vec3 from, Vec3 dir, Vec3& hit, Vec3& normal) {
    if (!(length(dir) > 0)) return false;
    const Affine flip = pov_to_sheaf();
    const SceneView view(q.prepared);
    const Ray r = probe_ray(from, dir);
    float best = FLT_MAX;
    uint32_t best_prim = 0xFFFFFFFFu;
    Vec3 n(0.0f);
    const uint32_t tris = uint32_t(q.prepared.tris.size());
    // The exact tests see the whole ray (r.tmax stays FLT_MAX), so a tie is found and the
    // lower primitive keeps it, whatever order the BVH brings them in.
    auto test = [&](uint32_t p) {
        float t;
        Vec3 normal;
        if (p < tris) {
            const TriangleVerts& tv = q.prepared.tris[p];
            TriangleHit h;
            if (!intersect_triangle(r, tv.a, tv.b, tv.c, h)) return;
            t = h.t, normal = cross(tv.b - tv.a, tv.c - tv.a);
            if (dot(normal, r.dir) > 0) normal = -normal;
        } else {
            AnalyticHit h;
            if (!analytic_first_hit(view, p - tris, r, h)) return;
            t = h.t, normal = h.normal;
        }
        if (t < best || (t == best && p < best_prim)) best = t, best_prim = p, n = normal;
    };
    const BvhView bvh = q.bvh.view();
    for (uint32_t k = 0; k < bvh.unbounded_count; ++k) test(bvh.unbounded[k]);
    if (bvh.node_count > 0) {
        const Vec3 inv = bvh_inverse(r.dir);
        BvhCounts counts;
        bvh_walk<false>(bvh, r, inv, bvh_planes(inv), 0, best, counts,
                        [&](uint32_t first, uint32_t count) {
                            for (uint32_t k = first; k < first + count; ++k) test(bvh.prims[k]);
                            return true;
                        });
    }
    if (!(best < FLT_MAX)) return false;
    hit = flip.point(ray_at(r, best));
    normal = length(n) > 0 ? normalize(flip.vector(n)) : Vec3(0.0f);
    return true;
}

} // namespace sheaf::io::pov

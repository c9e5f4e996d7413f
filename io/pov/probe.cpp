#include "io/pov/probe.h"

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

bool probe_trace(const ObjectProbe& q, Vec3 from, Vec3 dir, Vec3& hit, Vec3& normal) {
    if (!(length(dir) > 0)) return false;
    const Affine flip = pov_to_sheaf();
    const SceneView view(q.prepared);
    Ray r;
    r.origin = flip.point(from);
    r.dir = normalize(flip.vector(dir));
    r.tmin = 0, r.tmax = FLT_MAX;
    float best = FLT_MAX;
    Vec3 n(0.0f);
    for (size_t i = 0; i < q.prepared.tris.size(); ++i) {
        const TriangleVerts& tv = q.prepared.tris[i];
        TriangleHit h;
        if (intersect_triangle(r, tv.a, tv.b, tv.c, h) && h.t < best) {
            best = h.t, r.tmax = h.t, n = cross(tv.b - tv.a, tv.c - tv.a);
            if (dot(n, r.dir) > 0) n = -n;
        }
    }
    for (uint32_t a = 0; a < uint32_t(q.prepared.analytic_root.size()); ++a) {
        AnalyticHit h;
        if (analytic_first_hit(view, a, r, h) && h.t < best) best = h.t, r.tmax = h.t, n = h.normal;
    }
    if (!(best < FLT_MAX)) return false;
    hit = flip.point(ray_at(r, best));
    normal = length(n) > 0 ? normalize(flip.vector(n)) : Vec3(0.0f);
    return true;
}

} // namespace sheaf::io::pov

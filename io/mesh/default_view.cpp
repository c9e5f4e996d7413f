// add_default_view: see default_view.h.
#include "io/mesh/default_view.h"

#include <cfloat>
#include <cmath>

namespace sheaf::io {

void add_default_view(Scene& scene) {
    Vec3 lo(FLT_MAX), hi(-FLT_MAX);
    bool any = false;
    for (const Object& o : scene.objects) {
        if (o.mesh >= scene.meshes.size()) continue;
        for (const Vec3& p : scene.meshes[o.mesh].positions) {
            const Vec3 w = o.transform.point(p);
            if (!is_finite(w)) continue;
            lo = vmin(lo, w), hi = vmax(hi, w), any = true;
        }
    }
    const Vec3 centre = any ? (lo + hi) * 0.5f : scene.camera.look_at;
    const float radius = any ? std::fmax(0.5f * length(hi - lo), 1e-3f) : 1.0f;
    const Vec3 from = normalize(Vec3(0.6f, 0.45f, 1.0f));
    if (any) {
        Camera c; // perspective, y up
        const float half = 0.5f * c.fov_y_degrees * float(M_PI) / 180.0f;
        const float distance = 1.1f * radius / std::sin(half);
        c.position = centre + from * distance;
        c.look_at = centre;
        scene.camera = c;
    }
    Light key;
    key.position = centre + normalize(Vec3(1.0f, 2.0f, 1.5f)) * (3.0f * radius);
    key.color = Vec3(1.0f);
    scene.add_light(key);
}

} // namespace sheaf::io

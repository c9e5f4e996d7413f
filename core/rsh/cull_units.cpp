#include "core/rsh/cull_units.h"

#include "core/base/parallel.h"
#include "core/geometry/min_sphere.h"

#include <algorithm>
#include <map>
#include <mutex>

namespace sheaf {

struct CullUnitsCache {
    std::mutex mutex;
    std::map<int, std::shared_ptr<const CullUnits>> by_cluster;
    std::shared_ptr<const CullUnits> with_bvh;    // whole objects and the BVH
    std::shared_ptr<const CullUnits> with_strips; // whole objects and the strips
};

std::shared_ptr<CullUnitsCache> new_cull_units_cache() {
    return std::make_shared<CullUnitsCache>();
}

CullUnits make_cull_units(const PreparedScene& scene, int cluster) {
    CullUnits u;
    const size_t objects = scene.object_count();
    const size_t k = cluster > 0 ? size_t(cluster) : 0;
    u.begin.push_back(0);
    u.object_units.push_back(0);
    for (size_t o = 0; o < objects; ++o) {
        const uint32_t b = scene.object_begin[o], e = scene.object_begin[o + 1];
        if (k == 0 || e - b <= k) {
            u.begin.push_back(e);
            u.object.push_back(uint32_t(o));
        } else {
            for (uint32_t s = b; s < e; s += uint32_t(k)) {
                u.begin.push_back(uint32_t(std::min<size_t>(e, s + k)));
                u.object.push_back(uint32_t(o));
            }
        }
        u.object_units.push_back(uint32_t(u.object.size()));
    }
    u.sphere.resize(u.object.size());
    parallel_for(
        "cull.units", u.count(),
        [&](size_t i) {
            const uint32_t o = u.object[i];
            if (!u.split(o)) {
                u.sphere[i] = scene.object_sphere[o];
                return;
            }
            std::vector<Vec3> pts;
            pts.reserve(3 * size_t(u.begin[i + 1] - u.begin[i]));
            for (uint32_t p = u.begin[i]; p < u.begin[i + 1]; ++p) {
                const TriangleVerts& t = scene.tris[p];
                pts.push_back(t.a), pts.push_back(t.b), pts.push_back(t.c);
            }
            u.sphere[i] = min_sphere(pts);
        },
        16);
    return u;
}

std::shared_ptr<const CullUnits> cull_units_for(const PreparedScene& scene,
                                                const RenderSettings& settings) {
    const bool bvh = uses_bvh(settings.accel);
    const bool strips = settings.accel == Accel::Strips;
    const int cluster =
        settings.cull_objects && !bvh && !strips ? std::max(0, settings.cull_cluster) : 0;
    const auto make = [&] {
        CullUnits u = make_cull_units(scene, cluster);
        if (bvh) u.bvh = bvh_for(scene);
        if (strips) u.strips = strips_for(scene);
        return std::make_shared<const CullUnits>(std::move(u));
    };
    CullUnitsCache* cache = scene.cull_units_cache.get();
    if (!cache) return make();
    if (bvh || strips) {
        // Built outside this cache's lock (make() then finds it kept).
        if (bvh) bvh_for(scene);
        if (strips) strips_for(scene);
        std::lock_guard<std::mutex> lock(cache->mutex);
        std::shared_ptr<const CullUnits>& kept = bvh ? cache->with_bvh : cache->with_strips;
        if (!kept) kept = make();
        return kept;
    }
    std::lock_guard<std::mutex> lock(cache->mutex);
    std::shared_ptr<const CullUnits>& units = cache->by_cluster[cluster];
    if (!units) units = std::make_shared<const CullUnits>(make_cull_units(scene, cluster));
    return units;
}

} // namespace sheaf

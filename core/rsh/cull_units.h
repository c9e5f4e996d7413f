// What top hierarchy nodes are tested against before primitives (cull.objects): each object's
// bounding sphere and, with cull.cluster = K > 0, for an object of more than K primitives, the
// spheres of its runs of at most K consecutive primitives, tested only where the object's
// sphere is hit. One object of many primitives (a 66,000-triangle mesh) then no longer sends
// every top node that reaches it to every primitive: only to those of the runs it reaches.
// Computed per render from the prepared scene, on the host, and used alike by the CPU
// traversal and the wavefront's.
#pragma once

#include "core/accel/bvh.h"
#include "core/accel/strips.h"
#include "core/geometry/sphere.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace sheaf {

/// Units: an unsplit object is one unit; a split object's units are its runs. Unit u holds
/// primitives [begin[u], begin[u + 1]) of object object[u]; object o's units are
/// [object_units[o], object_units[o + 1]).
struct CullUnits {
    std::vector<uint32_t> begin;        // count() + 1 entries
    std::vector<Sphere> sphere;         // per unit: encloses its primitives
    std::vector<uint32_t> object;       // per unit
    std::vector<uint32_t> object_units; // objects + 1 entries
    /// accel=bvh, crsh-bvh, rah-bvh: the scene's object-space hierarchy (bvh_for), which the
    /// traversal tests instead of the units; null otherwise.
    std::shared_ptr<const Bvh> bvh;
    /// accel=strips: the scene's strips (strips_for); null otherwise.
    std::shared_ptr<const Strips> strips;
    size_t count() const { return sphere.size(); }
    bool split(uint32_t o) const { return object_units[o + 1] - object_units[o] > 1; }
};

/// Units of `scene`: every object whole when `cluster` is 0; otherwise an object of more
/// than `cluster` primitives is split into runs of `cluster` (the last shorter), each under
/// the minimal sphere of its triangles' vertices (only meshes split: an analytic object is
/// one primitive).
CullUnits make_cull_units(const PreparedScene& scene, int cluster);

/// The units a render with `settings` culls by (whole objects unless cull.objects and
/// cull.cluster split them), computed once per scene and cluster size when the scene came
/// from prepare_scene (its cull_units_cache), else computed here. Under accel=bvh, whole
/// objects and the scene's BVH.
std::shared_ptr<const CullUnits> cull_units_for(const PreparedScene& scene,
                                                const RenderSettings& settings);

} // namespace sheaf

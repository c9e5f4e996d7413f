// The photon pass (POV-Ray's photon mapping, for caustics): before a frame, every light that
// sends photons shoots them at every target object, in rings around the way to the target's
// bounding sphere; they are traced through the ray hierarchy as a ray type of their own
// (`photon`), reflect and refract at the surfaces whose switches allow it, and are kept where
// they land after their first surface. The kept photons become a kd-tree whose search radius
// is estimated from their density; shading gathers them (photon_gather.h, photon_light in
// frame_kernels.h).
#pragma once

#include "core/base/memory.h"
#include "core/rsh/cull_units.h"
#include "core/scene/photon_gather.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <vector>

namespace sheaf {

/// A frame's photons and their search settings.
struct PhotonMap {
    std::vector<Photon> photons; // the kd-tree (PhotonMapView)
    PhotonMapView settings;      // without photons and count: view() fills them
    PhotonMapView view() const {
        PhotonMapView v = settings;
        v.photons = photons.data();
        v.count = uint32_t(photons.size());
        return v;
    }
};

/// Photons a frame may shoot at most: a spacing that would shoot more is refused with a
/// message that names it (RenderError).
constexpr uint64_t kMaxPhotonsShot = 20'000'000;
/// Photon rays a frame may trace at most (paths split at every surface that both reflects and
/// refracts): more is refused the same way.
constexpr uint64_t kMaxPhotonRays = 100'000'000;

/// Runs the photon pass of `scene` under `settings` (empty when the scene has no photons:
/// PreparedScene::has_photons). Adds photons.shot, photons.stored, photons.radius, rays.photon,
/// tests.photon.* and time_ms.photons to `stats`.
PhotonMap shoot_photons(const PreparedScene& scene, const CullUnits& units,
                        const RenderSettings& settings, Stats& stats, MemoryTracker& memory);

/// Orders `photons` into the implicit kd-tree PhotonMapView reads (median splits on the
/// widest axis).
void build_photon_tree(std::vector<Photon>& photons);

/// POV-Ray's estimate of the first search radius from the photons' density: the mean density
/// of the gather_max nearest photons around a sample of them, the radius that holds
/// gather_max at that density, widened where many samples are much sparser.
float estimate_photon_radius(const std::vector<Photon>& tree, uint32_t gather_max);

} // namespace sheaf

// What every frame pipeline (on either backend)
// shares on the host: the statistics keys declared up front, the scene's extent that sets the
// ray offsets, and the totals added at the end.
#pragma once

#include "core/rays/ray_gen.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <cstdint>

namespace sheaf {

/// Every frame lists the same keys in the same order, whatever the scene exercises.
void declare_frame_keys(Stats& st);

/// How far the scene reaches from the origin (bounded objects, lights, the camera).
float scene_extent(const PreparedScene& scene);
/// The same without the lights: how far the objects (those with bounds) and the camera reach.
float geometry_extent(const PreparedScene& scene);

/// The ray generation parameters of a frame: offsets relative to the scene's extent.
RayGenParams frame_ray_params(const PreparedScene& scene, const RenderSettings& s);

/// rays.secondary, the tests.* totals, frame.*, scene.* and memory.* (peak_bytes: `peak`).
void frame_totals(Stats& st, const PreparedScene& scene, const RenderSettings& s, int64_t peak);

} // namespace sheaf

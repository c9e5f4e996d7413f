// Primary visibility by rasterisation: a visibility buffer holding, per pixel, the nearest
// primitive packed with its depth in 64 bits (depth in the high word, so the minimum is the
// nearest hit and equal depths fall to the lower primitive id: ties break deterministically).
#pragma once

#include "core/raster/camera.h"
#include "core/raster/sample_window.h"
#include "core/scene/prepared_scene.h"

#include <cstdint>
#include <vector>

namespace sheaf {

constexpr uint64_t kEmptyPixel = ~uint64_t(0);

SHEAF_HD_INLINE uint32_t vis_prim(uint64_t v) {
    return uint32_t(v & 0xFFFFFFFFu);
}

/// The least near clipping distance of the set-up (core/raster/raster_tri.h, which also keeps
/// each triangle's near plane within its own precision): just in front of the eye, relative
/// to the eye's distance from the origin; 0 for orthographic views.
double raster_near(const CameraFrame& camera);

/// Fills `vis` (width * height entries, top row first). Triangles are clipped against a near
/// plane, covered at pixel centres with the top-left fill rule, and depth-tested on the
/// perspective-correct camera-space depth. Multithreaded over screen tiles.
void rasterize(const PreparedScene& scene, const CameraFrame& camera, std::vector<uint64_t>& vis);
/// The same into host memory the caller holds (width * height entries).
void rasterize(const PreparedScene& scene, const CameraFrame& camera, uint64_t* vis);
/// Only the samples of `window` (window.count() entries, its rows in order): each the same key
/// as in the whole grid.
void rasterize(const PreparedScene& scene, const CameraFrame& camera, const SampleWindow& window,
               uint64_t* vis);

} // namespace sheaf

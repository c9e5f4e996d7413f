// A batch of secondary rays of one type, as structure-of-arrays, with what each ray brings
// back to its pixel.
#pragma once

#include "core/base/device.h"
#include "core/base/memory.h"
#include "core/geometry/ray.h"

#include <cstdint>

namespace sheaf {

/// Diffuse: radiosity's gather rays (closest hit, like reflection and refraction). Camera: the
/// primary rays of the projections that cannot be rasterised (core/raster/camera.h).
enum class RayType : uint8_t {
    Shadow = 0,
    Reflection = 1,
    Refraction = 2,
    Ao = 3,
    Diffuse = 4,
    Camera = 5,
    Photon = 6 // photons from the lights (core/frame/photon_pass.h): closest hit
};
constexpr int kRayTypeCount = 7;

inline const char* ray_type_name(RayType t) {
    switch (t) {
    case RayType::Shadow:
        return "shadow";
    case RayType::Reflection:
        return "reflection";
    case RayType::Refraction:
        return "refraction";
    case RayType::Ao:
        return "ao";
    case RayType::Diffuse:
        return "diffuse";
    case RayType::Camera:
        return "camera";
    case RayType::Photon:
        return "photon";
    }
    return "?";
}

/// Shadow and ambient-occlusion rays ask whether anything is hit; the others ask what is hit first.
SHEAF_HD inline bool any_hit_query(RayType t) {
    return t == RayType::Shadow || t == RayType::Ao;
}

struct RayBatch {
    explicit RayBatch(RayType t, MemoryTracker& m)
        : type(t), rays(TrackedAllocator<Ray>(&m)), pixel(TrackedAllocator<uint32_t>(&m)),
          weight(TrackedAllocator<Vec3>(&m)), light(TrackedAllocator<uint32_t>(&m)) {}

    RayType type;
    TrackedVector<Ray> rays;
    TrackedVector<uint32_t> pixel; // sample the ray's result goes to
    // Shadow and AO rays: radiance added to the pixel when nothing is hit.
    // Reflection and refraction rays: the throughput carried to what they hit.
    TrackedVector<Vec3> weight;
    // Shadow rays: the light index (the crsh key uses it). Diffuse rays: the path tag the
    // point they find carries (SurfaceHit::gather).
    TrackedVector<uint32_t> light;

    size_t size() const { return rays.size(); }
    void resize(size_t n) {
        rays.resize(n), pixel.resize(n), weight.resize(n);
        if (type == RayType::Shadow || type == RayType::Diffuse) light.resize(n);
    }
};

} // namespace sheaf

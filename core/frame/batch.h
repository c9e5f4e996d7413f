// What crosses the frame pipeline's intersection seam (seam.h): a batch of rays of one type and
// what tracing it gives, as structure-of-arrays buffers on the executing side.
#pragma once

#include "core/frame/buffer.h"
#include "core/rays/ray_gen.h"
#include "core/rsh/trace_kernels.h"

#include <cstddef>
#include <cstdint>

namespace sheaf::wavefront {

/// A batch of rays of one type, structure-of-arrays, on the executing side.
template <class Exec> struct DeviceBatch {
    RayType type = RayType::Shadow;
    size_t n = 0;
    DeviceBuffer<Ray, Exec> rays;
    DeviceBuffer<uint32_t, Exec> pixel;
    DeviceBuffer<Vec3, Exec> weight;
    DeviceBuffer<uint32_t, Exec> light; // shadow rays: the light; diffuse rays: the path tag

    DeviceBatch(Exec& ex, RayType t, size_t count) : type(t), n(count) {
        rays = DeviceBuffer<Ray, Exec>(ex, n);
        pixel = DeviceBuffer<uint32_t, Exec>(ex, n);
        weight = DeviceBuffer<Vec3, Exec>(ex, n);
        if (t == RayType::Shadow || t == RayType::Diffuse)
            light = DeviceBuffer<uint32_t, Exec>(ex, n);
    }
    RaySlots slots() const { return {rays.data(), pixel.data(), weight.data(), light.data()}; }
};

/// What tracing a batch gives, indexed like the batch.
template <class Exec> struct DeviceTraceResult {
    DeviceBuffer<uint64_t, Exec> closest;  // reflection and refraction rays
    DeviceBuffer<uint8_t, Exec> occluded;  // shadow and AO rays
    DeviceBuffer<uint64_t, Exec> pass_log; // shadow rays through transparent surfaces, or empty
    DeviceBuffer<uint32_t, Exec> tests;    // exact tests each ray took part in
    HitSinks sinks() const { return {closest.data(), occluded.data(), pass_log.data()}; }
};

} // namespace sheaf::wavefront

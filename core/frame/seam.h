// The frame pipeline's two seams, in one place: what an execution policy provides (FrameExec:
// the CPU policy cpu_exec.h, the CUDA policy gpu/cuda_exec.cuh, the strict test policy
// strict_exec.h) and what an intersection stage provides (FrameTracer: HostTracer, the CPU
// backend's; WavefrontTracer, the wavefront of launches the CUDA module runs). The frame
// (frame_pipeline.h) is written once against both; see docs/architecture.md.
#pragma once

#include "core/base/device.h"
#include "core/base/memory.h"
#include "core/frame/batch.h"
#include "core/frame/compact.h"
#include "core/frame/phases.h"
#include "core/frame/scene_copy.h"
#include "core/rsh/cull_units.h"
#include "core/rsh/test_count.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <concepts>
#include <cstddef>
#include <cstdint>

namespace sheaf::wavefront {

namespace seam_detail {

/// Stand-ins for the per-element functions a launch takes.
struct Each {
    SHEAF_HD void operator()(size_t) const {}
};
struct Count {
    SHEAF_HD size_t operator()() const { return 0; }
};
struct Compact {
    SHEAF_HD Compacted operator()(size_t) const { return {}; }
};
struct Emit {
    SHEAF_HD void operator()(size_t, uint64_t, uint32_t) const {}
};
struct Tally {
    SHEAF_HD TestCount operator()(size_t) const { return {}; }
};

} // namespace seam_detail

/// An execution policy: memory on its side, launches over index ranges, the scans, sorts and
/// compactions the frame is made of, phase stopwatches, and what it counts.
template <class E>
concept FrameExec = requires(E& ex, const E& cex, void* p, const void* cp, size_t n,
                             uint32_t* u32, TestCount* sums) {
    /// Whether the executing side reads host memory: the scene is then bound, not copied,
    /// and the frame's host-side stages (the tile rasteriser, the ordered sums) run there.
    { E::kHostMemory } -> std::convertible_to<bool>;
    { ex.allocate(n) } -> std::same_as<void*>;
    ex.deallocate(p, n);
    ex.copy_to_device(p, cp, n);
    ex.copy_to_host(p, cp, n);
    ex.copy_on_device(p, cp, n);
    ex.launch("name", n, seam_detail::Each{});
    ex.launch_compact("name", n, seam_detail::Count{}, u32, sums, seam_detail::Compact{},
                      seam_detail::Emit{});
    ex.launch_tally("name", n, seam_detail::Count{}, sums, seam_detail::Tally{});
    { ex.exclusive_scan(u32, n) } -> std::same_as<uint32_t>;
    ex.exclusive_scan_async(u32, n);
    ex.sort_pairs(u32, 1, u32, n);
    ex.synchronize();
    ex.stopwatch();
    { cex.peak_bytes() } -> std::convertible_to<int64_t>;
    { cex.auto_batch_pairs() } -> std::convertible_to<size_t>;
    { cex.launches() } -> std::convertible_to<uint64_t>;
    { cex.host_waits() } -> std::convertible_to<uint64_t>;
} && (!E::kHostMemory || requires(E& ex) {
    /// Host memory: the tracker its buffers count into, which the frame limits.
    { ex.memory() } -> std::same_as<MemoryTracker&>;
});

/// An intersection stage: given a batch of rays and the bound scene, the closest hits or the
/// occlusion of each ray, its exact-test count, and the statistics rows (rays.<type>,
/// tests.<type>.*, hierarchy.<type>.*), added by trace or, for counts kept on the executing
/// side, by flush at the frame's end. Every tracer gives the same results and counts.
template <class T, class E>
concept FrameTracer =
    std::constructible_from<T, E&, const PreparedScene&, const SceneView&, const CullUnits&,
                            const CullView&, const RenderSettings&, Stats&, PhaseClock<E>&> &&
    requires(T& t, const T& ct, const DeviceBatch<E>& batch, DeviceTraceResult<E>& out) {
        /// Whether its work is a device's launches (the frame then reports device.*).
        { T::kDeviceWork } -> std::convertible_to<bool>;
        t.trace(batch, out);
        t.flush();
        { ct.batch_pairs() } -> std::convertible_to<size_t>;
    };

} // namespace sheaf::wavefront

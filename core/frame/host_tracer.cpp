#include "core/frame/host_tracer.h"

#include "core/rsh/trace.h"

namespace sheaf::wavefront {

void HostTracer::trace(const DeviceBatch<CpuExec>& batch, DeviceTraceResult<CpuExec>& out) {
    const size_t n = batch.n;
    const bool any = any_hit_query(batch.type);
    out = DeviceTraceResult<CpuExec>();
    // Sized here, filled by trace_rays: no pass over them before it.
    if (any)
        out.occluded = DeviceBuffer<uint8_t, CpuExec>(ex_, n);
    else
        out.closest = DeviceBuffer<uint64_t, CpuExec>(ex_, n);
    if (batch.type == RayType::Shadow && transparent_)
        out.pass_log = DeviceBuffer<uint64_t, CpuExec>(ex_, 3 * n);
    out.tests = DeviceBuffer<uint32_t, CpuExec>(ex_, n);
    const RaySpan rays{batch.type, n, batch.rays.data(), batch.pixel.data(), batch.light.data()};
    trace_rays(host_, units_, rays, s_, st_, ex_.memory(),
               {out.closest.data(), out.occluded.data(), out.pass_log.data(), out.tests.data()});
}

} // namespace sheaf::wavefront

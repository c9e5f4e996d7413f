#include "core/frame/host_tracer.h"

#include "core/frame/phases.h"
#include "core/frame/scene_copy.h"

namespace sheaf {

namespace {

template <wavefront::Traversal kTraversal>
void trace_with(const PreparedScene& scene, const CullUnits& units, const RayBatch& batch,
                const RenderSettings& s, Stats& stats, MemoryTracker& memory, TraceResult& out) {
    using wavefront::CpuExec;
    CpuExec ex(&memory);
    wavefront::PhaseClock<CpuExec> clock(ex);
    wavefront::WavefrontTracer<CpuExec, kTraversal> tracer(
        ex, scene, SceneView(scene), units, wavefront::host_cull_view(units), s, stats, clock);
    const size_t n = batch.size();
    wavefront::DeviceBatch<CpuExec> b(ex, batch.type, n);
    b.rays.upload(batch.rays.data(), n);
    b.pixel.upload(batch.pixel.data(), n);
    b.weight.upload(batch.weight.data(), n);
    if (!b.light.empty()) b.light.upload(batch.light.data(), n);
    wavefront::DeviceTraceResult<CpuExec> r;
    tracer.trace(b, r);
    tracer.flush();
    clock.add_to(stats);
    out.closest = r.closest.download();
    out.occluded = r.occluded.download();
    out.pass_log = r.pass_log.download();
    out.tests = r.tests.download();
}

} // namespace

void trace_batch(const PreparedScene& scene, const RayBatch& batch, const RenderSettings& s,
                 Stats& stats, MemoryTracker& memory, TraceResult& out,
                 wavefront::Traversal traversal) {
    trace_batch(scene, *cull_units_for(scene, s), batch, s, stats, memory, out, traversal);
}

void trace_batch(const PreparedScene& scene, const CullUnits& units, const RayBatch& batch,
                 const RenderSettings& s, Stats& stats, MemoryTracker& memory, TraceResult& out,
                 wavefront::Traversal traversal) {
    if (traversal == wavefront::Traversal::Host)
        trace_with<wavefront::Traversal::Host>(scene, units, batch, s, stats, memory, out);
    else
        trace_with<wavefront::Traversal::Wavefront>(scene, units, batch, s, stats, memory, out);
}

} // namespace sheaf

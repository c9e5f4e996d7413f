// The CPU backend's implementation of the intersection seam (seam.h): the tracer's stages as
// launches on the CPU policy (hash, order, hierarchy, exact-test counts), with the traversal
// on host memory through per-thread candidate lists (core/rsh/cpu_traversal.h) instead of a
// count, compaction and launch per level. Same hits, tests and statistics as the wavefront
// traversal, which the CUDA module runs; faster on CPU cores.
#pragma once

#include "core/frame/cpu_exec.h"
#include "core/frame/wavefront_tracer.h"
#include "core/rays/ray_batch.h"
#include "core/rsh/trace.h"

namespace sheaf {

namespace wavefront {
using HostTracer = WavefrontTracer<CpuExec, Traversal::Host>;
} // namespace wavefront

/// Traces `batch` through the CPU backend's tracer outside a frame (the photon pass, tests):
/// results indexed like the batch; adds rays.<type>, tests.<type>.*, hierarchy.<type>.* and
/// time_ms.* entries to `stats`; its buffers count into `memory`. `units`: the scene's
/// culling units under the settings (cull_units_for). `traversal`: the CPU's, or the
/// wavefront's (the CUDA module's, which the tests hold against it).
void trace_batch(const PreparedScene& scene, const CullUnits& units, const RayBatch& batch,
                 const RenderSettings& settings, Stats& stats, MemoryTracker& memory,
                 TraceResult& result,
                 wavefront::Traversal traversal = wavefront::Traversal::Host);
/// The same, with the scene's culling units under the settings.
void trace_batch(const PreparedScene& scene, const RayBatch& batch, const RenderSettings& settings,
                 Stats& stats, MemoryTracker& memory, TraceResult& result,
                 wavefront::Traversal traversal = wavefront::Traversal::Host);

} // namespace sheaf

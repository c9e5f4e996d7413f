// The CPU's implementation of the frame pipeline's intersection seam (core/frame/seam.h):
// the traversal of core/rsh/trace.cpp (per-thread candidate lists, no count-scan-fill per
// level), reading the batch and writing the results where the CPU policy's frame keeps them,
// in host memory, with no copy. Same hits, tests and statistics as the wavefront tracer
// (wavefront_tracer.h), which the CUDA module runs; faster on CPU cores.
#pragma once

#include "core/frame/cpu_exec.h"
#include "core/frame/wavefront_tracer.h"
#include "core/rsh/cull_units.h"

namespace sheaf::wavefront {

class HostTracer {
  public:
    /// Its launches are not a device's: the frame reports no device.* counters for it.
    static constexpr bool kDeviceWork = false;

    HostTracer(CpuExec& ex, const PreparedScene& host, const SceneView&, const CullUnits& units,
               const CullView&, const RenderSettings& s, Stats& stats, PhaseClock<CpuExec>&)
        : ex_(ex), host_(host), units_(units), s_(s), st_(stats),
          transparent_(shadows_pass_surfaces(host)) {}

    /// Candidate pairs a level holds at once.
    size_t batch_pairs() const { return s_.batch_or(kCpuBatchPairs); }

    void trace(const DeviceBatch<CpuExec>& batch, DeviceTraceResult<CpuExec>& out);

    /// Every count is in the statistics when trace returns.
    void flush() {}

  private:
    CpuExec& ex_;
    const PreparedScene& host_;
    const CullUnits& units_;
    const RenderSettings& s_;
    Stats& st_;
    bool transparent_; // some primitive may let a shadow ray through: pass logs kept
};

} // namespace sheaf::wavefront

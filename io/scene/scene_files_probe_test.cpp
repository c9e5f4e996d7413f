// tests/support/analytic_probe.h under the CPU execution policy: every sample scene's analytic
// objects and isosurfaces, probed ray by ray through the scene's packed copy (DeviceScene)
// against the host's own, bit for bit. It proves the probe that gpu/analytic_bits_test.cu runs
// on a device, and that packing the scene changes no answer.
#include "core/frame/cpu_exec.h"
#include "tests/support/analytic_probe.h"
#include "tests/support/sample_scenes.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

TEST(WavefrontSceneFiles, AnalyticObjectsProbeTheSame) {
    probe::Tally tally;
    io::for_each_sample_scene(SHEAF_SCENES_DIR, 64, 48,
                              [&](const std::string& name, const PreparedScene& scene) {
                                  wavefront::CpuExec ex;
                                  probe::probe_scene(ex, name, scene, tally);
                              });
    EXPECT_GT(tally.objects, 50u);
    EXPECT_GT(tally.isosurfaces, 4u);
    EXPECT_GT(tally.rays, tally.objects * probe::kRaysPerObject - 1);
}

} // namespace
} // namespace sheaf

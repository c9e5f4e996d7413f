// The analytic shapes' exact tests on the device against the host, ray by ray (CTest
// `cuda_bits`, label cuda; skips without a device): tests/support/analytic_probe.h over every
// sample scene. Isosurfaces are also taken apart (their function, their march), because their
// frames are the one known exception to bit-for-bit equality (gpu/cuda_backend_test.cpp); where
// a ray parts, the first such is printed whole, so one run on a GPU says where the sides part.
// The same probe runs on the CPU exec in the unit tests (io/scene/scene_files_probe_test.cpp).
#include "core/backend/device_stack.h"
#include "gpu/cuda_exec.cuh"
#include "tests/support/analytic_probe.h"
#include "tests/support/sample_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace sheaf {
namespace {

TEST(CudaBits, AnalyticObjectsMatchTheHost) {
    int count = 0;
    const cudaError_t e = cudaGetDeviceCount(&count);
    if (e != cudaSuccess || count == 0)
        GTEST_SKIP() << "no usable CUDA device: "
                     << (e != cudaSuccess ? cudaGetErrorString(e) : "none found");
    probe::Tally tally;
    io::for_each_sample_scene(
        SHEAF_SCENES_DIR, 64, 48, [&](const std::string& name, const PreparedScene& scene) {
            gpu::CudaExec ex(0, device_stack_bytes(scene));
            probe::probe_scene(ex, name, scene, tally);
            gpu::check(cudaStreamSynchronize(ex.stream()), "the end of the scene's probes");
        });
    std::printf("%zu analytic objects (%zu rays) and %zu isosurfaces probed\n", tally.objects,
                tally.rays, tally.isosurfaces);
    EXPECT_GT(tally.objects, 50u);
    EXPECT_GT(tally.isosurfaces, 4u);
}

} // namespace
} // namespace sheaf

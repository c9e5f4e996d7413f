// Every sample scene (scenes/*.pov and *.xml) through the wavefront pipeline under the CPU
// execution policy against the CPU backend: the same images, passes and statistics. The CUDA
// backend runs that pipeline with another exec (gpu/cuda_backend_test.cpp makes the same
// comparison on a device); this makes it on any machine, for the scene files' features that
// the pipeline test scenes do not reach.
#include "core/frame/render_frame.h"
#include "tests/support/sample_scenes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

TEST(WavefrontSceneFiles, MatchTheCpuRenderer) {
    io::for_each_sample_scene(
        SHEAF_SCENES_DIR, 48, 36, [](const std::string& name, const PreparedScene& scene) {
            if (!wavefront_unsupported(scene).empty()) return; // the CPU renders these alone
            const RenderSettings s = test::settings_for(scene, {}, 48, 36);
            test::expect_same_frame(render_frame_cpu(scene, s),
                                    render_frame_wavefront_cpu(scene, s), name);
        });
}

} // namespace
} // namespace sheaf

// Every sample scene (scenes/*.pov and *.xml) under accel=bvh renders the frame of the default
// accel: the same image and primary passes, value for value.
#include "core/frame/render_frame.h"
#include "tests/support/same_image.h"
#include "tests/support/sample_scenes.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

TEST(BvhSceneFiles, MatchTheDefaultAccel) {
    io::for_each_sample_scene(
        SHEAF_SCENES_DIR, 48, 36, [](const std::string& name, const PreparedScene& scene) {
            const RenderSettings ref = test::settings_for(scene, {}, 48, 36);
            const RenderSettings bvh = test::settings_for(scene, {{"accel", "bvh"}}, 48, 36);
            test::expect_same_image(render_frame_cpu(scene, ref), render_frame_cpu(scene, bvh),
                                    name);
        });
}

} // namespace
} // namespace sheaf

// Every sample scene (scenes/*.pov and *.xml) under accel=bvh, crsh and crsh-bvh renders the
// frame of the default accel: the same image and primary passes, value for value.
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
            const Frame want = render_frame_cpu(scene, ref);
            for (const char* accel : {"bvh", "crsh", "crsh-bvh", "strips"}) {
                const RenderSettings s = test::settings_for(scene, {{"accel", accel}}, 48, 36);
                test::expect_same_image(want, render_frame_cpu(scene, s),
                                        name + ", accel=" + accel);
            }
        });
}

} // namespace
} // namespace sheaf

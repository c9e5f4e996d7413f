// SceneKeep under the strict policy (device memory, as a GPU's: the CPU policy binds host
// memory and copies nothing): an exec that renders several frames copies a scene once and
// binds the kept copy while the arrays are the same, copies anew when they change, and every
// frame is the CPU backend's.
#include "core/frame/frame_pipeline.h"
#include "core/frame/render_frame.h"
#include "core/scenes/builtin.h"
#include "tests/support/strict_exec.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

struct KeptFrames {
    wavefront::StrictExec exec;
    wavefront::SceneKeep<wavefront::StrictExec> keep;

    Frame render(const PreparedScene& scene, const RenderSettings& s) {
        Frame f;
        wavefront::FramePipeline<wavefront::StrictExec>(exec, scene, s, {}, f, &keep).run();
        return f;
    }
};

/// Renders with the keep and checks the frame against the CPU backend; returns it.
Frame expect_cpu_frame(KeptFrames& k, const PreparedScene& scene, const RenderSettings& s,
                       bool kept, const std::string& what) {
    const Frame f = k.render(scene, s);
    EXPECT_EQ(f.stats.get("device.scene_kept"), kept ? 1.0 : 0.0) << what;
    EXPECT_GT(f.stats.get("device.scene_bytes"), 0.0) << what;
    test::expect_same_frame(render_frame_cpu(scene, s), f, what);
    return f;
}

TEST(SceneKeep, SameArraysBindTheKeptCopy) {
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    const RenderSettings s = test::settings_for(office, {{"ao.samples", "2"}}, 48, 36);
    KeptFrames k;
    EXPECT_FALSE(k.keep.holds());
    const Frame first = expect_cpu_frame(k, office, s, false, "first frame");
    EXPECT_TRUE(k.keep.holds());
    const Frame again = expect_cpu_frame(k, office, s, true, "second frame");
    EXPECT_EQ(first.stats.get("device.scene_bytes"), again.stats.get("device.scene_bytes"));
    // Another PreparedScene object with the same arrays: the content decides, not the address.
    const PreparedScene copy = office;
    expect_cpu_frame(k, copy, s, true, "a copy of the scene");
    // Settings that leave the scene's arrays alone (image size, AO) keep it too.
    expect_cpu_frame(k, office, test::settings_for(office, {}, 40, 30), true, "other settings");
}

/// office at 48x36 on an exec with a keep, its first frame rendered (and copied).
class SceneKeepOffice : public ::testing::Test {
  protected:
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    const RenderSettings s = test::settings_for(office, {}, 48, 36);
    KeptFrames k;
    const Frame before = expect_cpu_frame(k, office, s, false, "office");
};

TEST_F(SceneKeepOffice, ChangedArraysAreCopiedAnew) {
    PreparedScene recoloured = office;
    ASSERT_FALSE(recoloured.materials.empty());
    recoloured.materials[0].color = Vec3(0.9f, 0.1f, 0.1f);
    const Frame after = expect_cpu_frame(k, recoloured, s, false, "a material changed");
    EXPECT_NE(before.rgba, after.rgba);

    PreparedScene moved = office;
    ASSERT_FALSE(moved.tris.empty());
    moved.tris[0].a = moved.tris[0].a + Vec3(0.0f, 1e-3f, 0.0f);
    expect_cpu_frame(k, moved, s, false, "a vertex moved");

    // Back to the first scene: the keep holds one scene, so it is copied again.
    expect_cpu_frame(k, office, s, false, "the first scene again");
    expect_cpu_frame(k, office, s, true, "and once more");

    const PreparedScene cornell = prepare_scene(make_builtin_scene("cornell"));
    expect_cpu_frame(k, cornell, test::settings_for(cornell, {}, 48, 36), false, "cornell");
}

TEST_F(SceneKeepOffice, PlainValuesComeFromTheFramesScene) {
    // The camera is a plain value of the scene, not one of the arrays copied: the kept copy
    // is bound, and the frame still sees the new camera.
    PreparedScene turned = office;
    turned.camera.position = turned.camera.position + Vec3(0.5f, 0.2f, 0.0f);
    const Frame after = expect_cpu_frame(k, turned, s, true, "the camera moved");
    EXPECT_NE(before.depth, after.depth);
}

TEST(SceneKeep, CullingUnitsArePartOfTheCopy) {
    // cull.cluster changes the culling units the copy holds under crsh, not the scene: copied
    // anew.
    const PreparedScene office = prepare_scene(make_builtin_scene("office"));
    const auto crsh = [&](const char* cluster) {
        return test::settings_for(office, {{"accel", "crsh"}, {"cull.cluster", cluster}}, 40, 30);
    };
    KeptFrames k;
    expect_cpu_frame(k, office, crsh("0"), false, "whole objects");
    expect_cpu_frame(k, office, crsh("3"), false, "clusters");
    k.keep.clear();
    EXPECT_FALSE(k.keep.holds());
    expect_cpu_frame(k, office, crsh("3"), false, "after clear");
}

} // namespace
} // namespace sheaf

// A mesh file as a whole scene (load_scene_file("model.obj")): one object per placed mesh, the
// default camera framing it and a default light, so it renders with the mesh in the middle.
#include "io/mesh/mesh_scene.h"

#include "core/backend/backend.h"
#include "io/scene/scene_file.h"
#include "tests/support/mesh_test_files.h"

#include <gtest/gtest.h>

namespace sheaf {
namespace {

TEST(MeshScene, AMeshFileRendersFramedAndLit) {
    const auto dir = test::temp_folder("mesh_scene");
    // A tetrahedron, so that the default light shows different shades on its faces.
    const std::string path =
        test::write_text(dir / "tetra.obj", "v 10 10 10\nv 12 10 10\nv 10 12 10\nv 10 10 12\n"
                                            "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const io::SceneFile f = io::load_scene_file(path);
    ASSERT_EQ(f.scene.objects.size(), 1u);
    ASSERT_EQ(f.scene.lights.size(), 1u);
    EXPECT_TRUE(f.warnings.empty());
    const PreparedScene p = prepare_scene(f.scene);
    RenderSettings rs;
    rs.width = rs.height = 48;
    const Frame frame = render_frame(p, rs);
    // The mesh is in the middle of the picture, and the corners see the background.
    EXPECT_EQ(frame.object_id[24 * 48 + 24], 0u);
    EXPECT_EQ(frame.object_id[0], 0xFFFFFFFFu);
    EXPECT_EQ(frame.object_id[48 * 48 - 1], 0xFFFFFFFFu);
    float lo = 1e9f, hi = -1e9f;
    for (size_t i = 0; i < frame.object_id.size(); ++i)
        if (frame.object_id[i] == 0)
            lo = std::min(lo, frame.rgba[4 * i]), hi = std::max(hi, frame.rgba[4 * i]);
    EXPECT_GT(hi, 0.3f) << "the default light should light the mesh";
    EXPECT_GT(hi - lo, 0.02f) << "the faces should be lit differently";
}

TEST(MeshScene, GltfScenesGetOneObjectPerPlacedMesh) {
    const auto dir = test::temp_folder("mesh_scene_gltf");
    const io::SceneFile f = io::load_scene_file(test::write_glb(dir / "quads.glb"));
    EXPECT_EQ(f.scene.objects.size(), 2u);
    EXPECT_NO_THROW(prepare_scene(f.scene));
}

} // namespace
} // namespace sheaf

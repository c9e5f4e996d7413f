// The mesh camera (Projection::Mesh, POV-Ray's mesh_camera): a mesh of one tiny face per pixel
// at an orthographic camera's pixel origins sees what that camera sees; each distribution
// picks the faces POV-Ray picks; the offset, the reversal, smooth normals and the mesh's
// transform (normals by the inverse transpose) shape the rays; what does not fit is an error.
#include "core/shading/mesh_camera.h"

#include "core/backend/backend.h"
#include "core/base/error.h"
#include "core/shading/frame_kernels.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sheaf {
namespace {

constexpr float kSide = 1e-4f; // a face's size: its centroid is its pixel's origin

/// A face at `o` whose normal (cross(b - a, c - a)) is `forward`, for a camera whose screen
/// axes are `right` and `up`.
void add_face(Mesh& m, Vec3 o, Vec3 right, Vec3 up, float side = kSide) {
    const uint32_t base = uint32_t(m.positions.size());
    // The centroid (a + b + c) / 3 is o.
    const Vec3 a = o - (up + right) * (side / 3);
    m.positions.insert(m.positions.end(), {a, a + up * side, a + right * side});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
}

/// One face per pixel, row by row from the top, at the pixel origins of `cam` (orthographic),
/// a row lower, as POV-Ray's demo meshes are built: pixel row y shows face row y - 1.
Mesh pixel_mesh(const CameraFrame& cam) {
    Mesh m;
    for (int y = 1; y <= cam.height; ++y)
        for (int x = 0; x < cam.width; ++x)
            add_face(m, cam.pixel_ray(x, std::min(y, cam.height - 1)).origin, cam.right, cam.up);
    return m;
}

Scene ortho_scene() {
    Scene s = test::glass_mirror_scene();
    s.camera.projection = Projection::Orthographic;
    s.camera.ortho_height = 3;
    return s;
}

const float* pixel(const Frame& f, int x, int y) {
    return &f.rgba[4 * (size_t(y) * f.width + x)];
}

TEST(MeshCamera, APixelMeshSeesWhatItsOrthographicCameraSees) {
    constexpr int W = 24, H = 18;
    const Scene ortho = ortho_scene();
    const CameraFrame cam = make_camera_frame(ortho.camera, W, H);
    Scene mesh = ortho;
    mesh.camera.projection = Projection::Mesh;
    mesh.camera_meshes.push_back({pixel_mesh(cam), Affine()});
    RenderSettings rs;
    rs.width = W, rs.height = H;
    const Frame want = render_frame(prepare_scene(ortho), rs);
    const Frame got = render_frame(prepare_scene(mesh), rs);
    double diff = 0;
    for (int y = 1; y < H; ++y) // row 0 shows face row 0 too (POV-Ray's)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c)
                diff += std::fabs(pixel(got, x, y)[c] - pixel(want, x, y)[c]);
    EXPECT_LT(diff / (W * (H - 1) * 3), 2e-3);
    EXPECT_GT(got.stats.get("rays.camera"), 0);
    EXPECT_EQ(got.stats.get("rays.camera"), double(W * H));
}

/// The ray of sample (x, y) in a width x height grid, n x n samples a pixel.
bool ray_at(const PreparedScene& p, int x, int y, int width, int height, int n, Ray& r) {
    const CameraFrame cam = make_camera_frame(p.camera, width * n, height * n, n);
    return camera_ray(SceneView(p), cam, x, y, r);
}

/// A row of `count` faces facing -z along x at height y0 and depth z.
Mesh row(int count, float y0, float z = 0) {
    Mesh m;
    for (int i = 0; i < count; ++i)
        add_face(m, Vec3(float(i), y0, z), Vec3(1, 0, 0), Vec3(0, 1, 0));
    return m;
}

void expect_near(Vec3 got, Vec3 want, float tol = 1e-3f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

TEST(MeshCamera, DistributionsPickTheFacesPovRayPicks) {
    Scene s;
    s.camera.projection = Projection::Mesh;
    s.camera_meshes.push_back({row(6, 0), Affine()});
    s.camera_meshes.push_back({row(6, 10), Affine()});
    Ray r;
    // Pixel (x, y) is face x + (y - 1) * width, row 0 its own (POV-Ray's rows).
    // 0: pixel i is face i of mesh k for sample k (two rays: samples 0, 2 mesh 0; 1, 3 mesh 1).
    s.camera.mesh_distribution = 0, s.camera.mesh_rays = 2;
    PreparedScene p = prepare_scene(s);
    ASSERT_TRUE(ray_at(p, 2 * 2 + 0, 2 * 2 + 0, 3, 3, 2, r)); // pixel (2, 2): 5, sample 0
    expect_near(r.origin, Vec3(5, 0, 0));
    expect_near(r.dir, Vec3(0, 0, -1));
    ASSERT_TRUE(ray_at(p, 2 * 2 + 1, 2 * 2 + 0, 3, 3, 2, r)); // sample 1
    expect_near(r.origin, Vec3(5, 10, 0));
    ASSERT_TRUE(ray_at(p, 2 * 2 + 0, 2 * 2 + 1, 3, 3, 2, r)); // sample 2
    expect_near(r.origin, Vec3(5, 0, 0));
    ASSERT_TRUE(ray_at(p, 2 * 1, 0, 3, 3, 2, r)); // pixel (1, 0): face 1
    expect_near(r.origin, Vec3(1, 0, 0));
    ASSERT_TRUE(ray_at(p, 2 * 1, 2 * 1, 3, 3, 2, r)); // pixel (1, 1): face 1 too
    expect_near(r.origin, Vec3(1, 0, 0));
    EXPECT_FALSE(ray_at(p, 0, 2 * 3, 3, 4, 2, r)); // pixel (0, 3): face 6, past them: black
    // More rays than samples: an even share of the meshes (2 rays, 1 sample: mesh 0).
    ASSERT_TRUE(ray_at(p, 1, 0, 3, 2, 1, r));
    expect_near(r.origin, Vec3(1, 0, 0));

    // 1: the meshes' faces one after another.
    s.camera.mesh_distribution = 1, s.camera.mesh_rays = 1;
    p = prepare_scene(s);
    ASSERT_TRUE(ray_at(p, 2, 3, 4, 4, 1, r)); // face 10: mesh 1's face 4
    expect_near(r.origin, Vec3(4, 10, 0));
    EXPECT_FALSE(ray_at(p, 0, 4, 4, 5, 1, r)); // face 12 of 12

    // 2: the meshes side by side; pixel (x, y) of a band is face (y - 1) * (width / 2) + x.
    s.camera.mesh_distribution = 2;
    p = prepare_scene(s);
    ASSERT_TRUE(ray_at(p, 1, 2, 4, 3, 1, r)); // mesh 0, face 2 + 1
    expect_near(r.origin, Vec3(3, 0, 0));
    ASSERT_TRUE(ray_at(p, 2, 0, 4, 3, 1, r)); // mesh 1, face 0 + 2 (POV-Ray's indexing)
    expect_near(r.origin, Vec3(2, 10, 0));
    ASSERT_TRUE(ray_at(p, 3, 2, 4, 3, 1, r)); // mesh 1, face 2 + 3
    expect_near(r.origin, Vec3(5, 10, 0));
    EXPECT_FALSE(ray_at(p, 3, 3, 4, 4, 1, r)); // mesh 1, face 4 + 3: past its 6
}

TEST(MeshCamera, UvDistributionFindsThePointHoldingTheSample) {
    // Two faces over the uv square (a quad at z = 0 from (0, 0) to (4, 2), facing -z), the
    // second with normals tilted towards +x at its corners.
    Mesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(0, 2, 0), Vec3(4, 0, 0), Vec3(4, 2, 0)};
    m.indices = {0, 1, 2, 2, 1, 3};
    m.uvs = {0, 0, 0, 1, 1, 0, 1, 1};
    const Vec3 t = normalize(Vec3(1, 0, -1));
    m.normals = {Vec3(0, 0, -1), t, t, t};
    Scene s;
    s.camera.projection = Projection::Mesh;
    s.camera.mesh_distribution = 3;
    s.camera_meshes.push_back({m, Affine()});
    PreparedScene p = prepare_scene(s);
    Ray r;
    // Pixel (1, 3) of 8 x 4 at its corner: (u, v) = (1 / 8, 1 - 3 / 4) (POV-Ray's).
    ASSERT_TRUE(ray_at(p, 1, 3, 8, 4, 1, r));
    expect_near(r.origin, Vec3(0.5f, 0.5f, 0));
    expect_near(r.dir, Vec3(0, 0, -1));
    // (u, v) = (0.875, 0.75): the second face; smooth takes its corners' normals.
    ASSERT_TRUE(ray_at(p, 7, 1, 8, 4, 1, r));
    expect_near(r.origin, Vec3(3.5f, 1.5f, 0));
    expect_near(r.dir, Vec3(0, 0, -1));
    s.camera.mesh_smooth = true;
    p = prepare_scene(s);
    ASSERT_TRUE(ray_at(p, 7, 1, 8, 4, 1, r));
    expect_near(r.dir, t);
    // 2 x 2 samples spread around the corner: sample (0, 0) of pixel (1, 3) is at
    // (0.75, 2.75) pixels: (u, v) = (0.75 / 8, 1 - 2.75 / 4).
    ASSERT_TRUE(ray_at(p, 2, 6, 8, 4, 2, r));
    expect_near(r.origin, Vec3(0.75f / 8 * 4, (1 - 2.75f / 4) * 2, 0));
    // Outside every face's uv triangle: no ray.
    s.camera_meshes[0].mesh.uvs = {0, 0, 0, 0.5f, 0.5f, 0, 0.5f, 0.5f};
    p = prepare_scene(s);
    EXPECT_FALSE(ray_at(p, 7, 1, 8, 4, 1, r));
}

TEST(MeshCamera, OffsetReversalAndTransformShapeTheRay) {
    Scene s;
    s.camera.projection = Projection::Mesh;
    // A face whose normal is (1, 0, -1) / sqrt 2, stretched by 2 along x and moved.
    Mesh m;
    add_face(m, Vec3(0), normalize(Vec3(1, 0, 1)), Vec3(0, 1, 0));
    s.camera_meshes.push_back({m, Affine::translate(Vec3(0, 0, 3)) * Affine::scale(Vec3(2, 1, 1))});
    s.camera.mesh_offset = 0.5f;
    PreparedScene p = prepare_scene(s);
    Ray r;
    ASSERT_TRUE(ray_at(p, 0, 0, 1, 1, 1, r));
    const float h = std::sqrt(0.5f);
    // The origin moves half a unit along the mesh's own normal, then the transform applies;
    // the direction is the normal through the inverse transpose: (h / 2, 0, -h) normalised.
    expect_near(r.origin, Vec3(2 * 0.5f * h, 0, 3 - 0.5f * h));
    expect_near(r.dir, normalize(Vec3(h / 2, 0, -h)));
    s.camera.mesh_reverse = true;
    p = prepare_scene(s);
    ASSERT_TRUE(ray_at(p, 0, 0, 1, 1, 1, r));
    expect_near(r.origin, Vec3(2 * 0.5f * h, 0, 3 - 0.5f * h)); // still moved along it
    expect_near(r.dir, -normalize(Vec3(h / 2, 0, -h)));
    // A degenerate face is not a face (as in POV-Ray): the next one is pixel 0's.
    Mesh d;
    d.positions = {Vec3(0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    d.indices = {0, 1, 2};
    add_face(d, Vec3(7, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
    s.camera_meshes = {{d, Affine()}};
    s.camera.mesh_offset = 0, s.camera.mesh_reverse = false;
    p = prepare_scene(s);
    EXPECT_EQ(p.camera_faces.size(), 1u);
    ASSERT_TRUE(ray_at(p, 0, 0, 1, 1, 1, r));
    expect_near(r.origin, Vec3(7, 0, 0));
}

TEST(MeshCamera, WhatDoesNotFitIsAnError) {
    auto error = [](const Scene& s) {
        try {
            s.validate();
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    Scene s;
    s.camera.projection = Projection::Mesh;
    EXPECT_NE(error(s).find("needs at least one mesh"), std::string::npos);
    s.camera_meshes.push_back({row(2, 0), Affine()});
    EXPECT_EQ(error(s), "no error");
    s.camera.mesh_rays = 2;
    EXPECT_NE(error(s).find("at most one ray per pixel per mesh"), std::string::npos);
    s.camera.mesh_distribution = 2;
    EXPECT_NE(error(s).find("takes one ray per pixel"), std::string::npos);
    s.camera.mesh_rays = 1, s.camera.mesh_distribution = 4;
    EXPECT_NE(error(s).find("distribution must be 0, 1, 2 or 3"), std::string::npos);
    s.camera.mesh_distribution = 1, s.camera.mesh_smooth = true;
    EXPECT_NE(error(s).find("smooth needs distribution 3"), std::string::npos);
    s.camera.mesh_distribution = 3;
    EXPECT_NE(error(s).find("needs its first mesh's uv coordinates"), std::string::npos);
    s.camera.mesh_distribution = 0, s.camera.mesh_smooth = false;
    s.camera_meshes[0].mesh.indices.push_back(99);
    EXPECT_NE(error(s).find("the camera's mesh 0"), std::string::npos);
    // Distribution 3 over faces piled on the whole uv square a hundred times: an error, not a
    // grid of a hundred thousand entries.
    Mesh piled;
    for (uint32_t i = 0; i < 100; ++i) {
        piled.positions.insert(piled.positions.end(), {Vec3(0), Vec3(0, 1, 0), Vec3(1, 0, 0)});
        piled.uvs.insert(piled.uvs.end(), {0, 0, 0, 1, 1, 1});
        piled.indices.insert(piled.indices.end(), {3 * i, 3 * i + 1, 3 * i + 2});
    }
    s.camera_meshes = {{piled, Affine()}};
    s.camera.mesh_distribution = 3;
    EXPECT_EQ(error(s), "no error");
    try {
        prepare_scene(s);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("covers its uv square more than"), std::string::npos);
    }
}

} // namespace
} // namespace sheaf

// Rasterised primary visibility against ray-cast primary hits, pixel by pixel: they may
// differ only where two triangles tie (a shared edge, coplanar faces) or a ray grazes an edge.
#include "core/raster/rasterizer.h"

#include "core/geometry/ray_triangle.h"
#include "core/scenes/builtin.h"
#include "core/scenes/shapes.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

// Double-precision ray-plane hit and barycentrics: how far inside the triangle (the smallest
// barycentric, negative outside) and at what distance.
struct Reference {
    double t, inside;
};
Reference reference(const Ray& r, const TriangleVerts& tv) {
    auto d = [](Vec3 v) { return std::array<double, 3>{v.x, v.y, v.z}; };
    auto a = d(tv.a), b = d(tv.b), c = d(tv.c), o = d(r.origin), dir = d(r.dir);
    std::array<double, 3> e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    auto cross = [](auto u, auto v) {
        return std::array<double, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                     u[0] * v[1] - u[1] * v[0]};
    };
    auto dot = [](auto u, auto v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    const auto p = cross(dir, e2);
    const double det = dot(e1, p);
    if (std::fabs(det) < 1e-300) return {INFINITY, -1};
    const std::array<double, 3> s{o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    const double u = dot(s, p) / det;
    const auto q = cross(s, e1);
    const double v = dot(dir, q) / det;
    const double t = dot(e2, q) / det;
    const double inside = std::min({u, v, 1 - u - v});
    // Scale-free: barycentric slack relative to one pixel's footprint is what a tie means.
    return {t, inside};
}

void compare(const PreparedScene& scene, int w, int h, const std::string& name) {
    const CameraFrame cam = make_camera_frame(scene.camera, w, h);
    std::vector<uint64_t> vis;
    rasterize(scene, cam, vis);
    int differ = 0, covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Ray r = cam.pixel_ray(x, y);
            uint64_t best = kEmptyPixel;
            double best_t = INFINITY;
            for (uint32_t p = 0; p < scene.prim_count(); ++p) {
                TriangleHit hit;
                const TriangleVerts& t = scene.tris[p];
                if (intersect_triangle(r, t.a, t.b, t.c, hit) && hit.t < best_t)
                    best_t = hit.t, best = p;
            }
            const uint64_t v = vis[size_t(y) * w + x];
            covered += v != kEmptyPixel;
            const uint32_t rp = v == kEmptyPixel ? ~0u : vis_prim(v);
            if (rp == uint32_t(best)) continue;
            ++differ;
            // A tie: the rasterised triangle is also under the pixel centre (up to an edge
            // tolerance) at the same distance as the ray-cast one, or both are at an edge.
            constexpr double kEdge = 1e-4, kDepth = 1e-4;
            if (v != kEmptyPixel && best != kEmptyPixel) {
                const Reference rr = reference(r, scene.tris[rp]);
                EXPECT_GT(rr.inside, -kEdge) << name << " pixel " << x << "," << y;
                EXPECT_NEAR(rr.t, best_t, kDepth * best_t) << name << " pixel " << x << "," << y;
            } else if (v != kEmptyPixel) {
                const Reference rr = reference(r, scene.tris[rp]);
                EXPECT_GT(rr.inside, -kEdge) << name << " raster-only pixel " << x << "," << y;
            } else {
                const Reference rr = reference(r, scene.tris[best]);
                EXPECT_LT(rr.inside, kEdge) << name << " ray-only pixel " << x << "," << y;
            }
        }
    EXPECT_GT(covered, 0) << name;
    EXPECT_LT(differ, w * h / 50) << name; // ties are rare
}

TEST(Rasterizer, AgreesWithRayCastingOnTheBuiltinScenes) {
    for (const std::string& name : builtin_scene_names())
        compare(prepare_scene(make_builtin_scene(name)), 48, 40, name);
}

TEST(Rasterizer, AgreesWithRayCastingOnRandomTrianglesCrossingTheNearPlane) {
    std::mt19937 g(9);
    std::uniform_real_distribution<float> u(-3, 3);
    Scene s;
    s.add_material(Material{});
    Mesh m;
    for (int t = 0; t < 300; ++t) {
        for (int k = 0; k < 3; ++k) m.positions.push_back(Vec3(u(g), u(g), u(g) * 2));
        for (int k = 0; k < 3; ++k) m.indices.push_back(uint32_t(m.positions.size() - 3 + k));
    }
    s.add_mesh_object("soup", std::move(m), 0);
    s.camera.position =
        Vec3(0.3f, 0.2f, 1.0f); // inside the soup: many triangles pass behind the eye
    s.camera.look_at = Vec3(0, 0, -3);
    compare(prepare_scene(s), 64, 48, "soup");
}

// Found by the C ABI fuzzer: under a narrow field of view a triangle off to the side projects
// to screen bounds beyond int's range, whose conversion was undefined behaviour. Such a
// triangle covers nothing; the one in view is drawn as before.
TEST(Rasterizer, TrianglesProjectingFarOffTheScreenCoverNothing) {
    Scene s;
    s.add_material(Material{});
    Mesh m;
    m.positions = {{1000, 0, -3},        {1000, 1, -3},       {1001, 0, -3},
                   {-1001, 0, -3},       {-1000, 1, -3},      {-1000, 0, -3},
                   {-1e-5f, -1e-5f, -3}, {1e-5f, -1e-5f, -3}, {0, 1e-5f, -3}};
    m.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    s.add_mesh_object("far", std::move(m), 0);
    s.camera.position = Vec3(0.0f);
    s.camera.look_at = Vec3(0, 0, -1);
    s.camera.fov_y_degrees = 1e-4f; // 1000 to the side is 6e9 pixels off the screen
    compare(prepare_scene(s), 32, 24, "far");
}

// Found while testing a C ABI fuzzer finding: the near plane lay at 1e-7 of the scene's
// extent, so one mesh at 1e11 clipped every triangle nearer than 1e4 to the eye: the triangle
// at 3 units was lost. Each triangle's near plane now follows its own extent.
TEST(Rasterizer, FarGeometryClipsNothingNearTheEye) {
    Scene s;
    s.add_material(Material{});
    Mesh m;
    m.positions = {{-1, -1, -3},        {1, -1, -3},        {0, 1, -3},
                   {-1e11f, 0, -1e11f}, {1e11f, 0, -1e11f}, {0, 1e11f, -1e11f}};
    m.indices = {0, 1, 2, 3, 4, 5};
    s.add_mesh_object("near and far", std::move(m), 0);
    s.camera.position = Vec3(0.0f);
    s.camera.look_at = Vec3(0, 0, -1);
    const PreparedScene scene = prepare_scene(s);
    const CameraFrame cam = make_camera_frame(scene.camera, 32, 24);
    std::vector<uint64_t> vis;
    rasterize(scene, cam, vis);
    const uint64_t centre = vis[size_t(12) * 32 + 16];
    ASSERT_NE(centre, kEmptyPixel);
    EXPECT_TRUE(scene.tris[vis_prim(centre)].a.z == -3.0f);
    compare(scene, 32, 24, "near and far");
}

// More triangles than the rasterizer sets up at once (kChunk, 65,536): a tilted plane of
// 151,250 small triangles filling the view, every chunk (a region of it: prepare_scene puts a
// mesh's triangles in Morton order) drawing its own pixels, and a random cloud in front of it,
// whose nearest triangle wins each pixel it covers whatever chunk it is in.
TEST(Rasterizer, AgreesWithRayCastingOverManyChunksOfTriangles) {
    Scene s;
    s.add_material(Material{});
    Mesh plane;
    const int n = 275;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -6.0f + 12.0f * float(i) / n, y = -5.0f + 10.0f * float(j) / n;
            plane.positions.push_back(Vec3(x, y, -4.0f + 0.1f * x));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1);
            for (uint32_t v : {a, b, c, b, c + 1, c}) plane.indices.push_back(v);
        }
    s.add_mesh_object("plane", std::move(plane), 0);
    std::mt19937 g(5);
    std::uniform_real_distribution<float> u(-1, 1);
    Mesh cloud;
    for (int t = 0; t < 2000; ++t) {
        const Vec3 c(u(g) * 2.0f, u(g) * 1.5f, -2.5f + u(g));
        for (int k = 0; k < 3; ++k) cloud.positions.push_back(c + Vec3(u(g), u(g), u(g)) * 0.2f);
        for (int k = 0; k < 3; ++k)
            cloud.indices.push_back(uint32_t(cloud.positions.size() - 3 + k));
    }
    s.add_mesh_object("cloud", std::move(cloud), 0);
    s.camera.position = Vec3(0, 0, 1);
    s.camera.look_at = Vec3(0, 0, -3);
    const PreparedScene scene = prepare_scene(s);
    ASSERT_GT(scene.triangle_count(), 2 * (size_t(1) << 16));
    compare(scene, 32, 24, "plane and cloud");
}

TEST(Rasterizer, AgreesWithRayCastingThroughOrthographicAndShiftedCameras) {
    Scene s = make_builtin_scene("office");
    s.camera.shift_x = 0.2f, s.camera.shift_y = -0.1f;
    compare(prepare_scene(s), 40, 30, "office shifted");
    s.camera.projection = Projection::Orthographic;
    s.camera.ortho_height = 6.0f;
    compare(prepare_scene(s), 40, 30, "office orthographic");
}

TEST(Rasterizer, SharedEdgesAreCoveredExactlyOnce) {
    // A fan of triangles around a centre: every pixel is owned by exactly one of them, so the
    // visibility buffer has no hole along the shared edges.
    Scene s;
    s.add_material(Material{});
    s.add_mesh_object("quad", make_quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), 7, 5), 0);
    s.camera.position = Vec3(0, 0, 1.2f);
    const PreparedScene scene = prepare_scene(s);
    const CameraFrame cam = make_camera_frame(scene.camera, 64, 64);
    std::vector<uint64_t> vis;
    rasterize(scene, cam, vis);
    for (uint64_t v : vis) EXPECT_NE(v, kEmptyPixel); // the quad fills the view
}

} // namespace
} // namespace sheaf

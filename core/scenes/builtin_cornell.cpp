// The built-in "cornell" scene: one reflective object (a sphere ringed by a torus, 778
// triangles) inside a closed box of six tinted mirrors, 790 triangles in all, traced with two
// bounces as in the paper's first test scene.
#include "core/scenes/shapes.h"

namespace sheaf::builtin_detail {

namespace {

constexpr float kHalf = 3.0f; // the box spans [-kHalf, kHalf] on every axis

Material mirror(Vec3 tint) {
    Material m;
    m.color = tint;
    m.ambient = 0.1f;
    m.diffuse = 0.2f;
    m.specular = 0.3f;
    m.mirror = 0.85f;
    return m;
}

} // namespace

Scene make_cornell() {
    Scene scene;
    const float s = 2 * kHalf;
    const Vec3 lo(-kHalf, -kHalf, -kHalf);
    // Each wall faces into the box: its normal cross(edge_u, edge_v) points inward.
    struct Wall {
        const char* name;
        Vec3 corner, edge_u, edge_v, tint;
    };
    const Wall walls[] = {
        {"mirror floor", lo, {0, 0, s}, {s, 0, 0}, {0.85f, 0.85f, 0.85f}},
        {"mirror ceiling", {-kHalf, kHalf, -kHalf}, {s, 0, 0}, {0, 0, s}, {0.85f, 0.85f, 0.85f}},
        {"mirror left", lo, {0, s, 0}, {0, 0, s}, {0.9f, 0.35f, 0.3f}},
        {"mirror right", {kHalf, -kHalf, -kHalf}, {0, 0, s}, {0, s, 0}, {0.3f, 0.85f, 0.35f}},
        {"mirror back", lo, {s, 0, 0}, {0, s, 0}, {0.4f, 0.5f, 0.95f}},
        {"mirror front", {-kHalf, -kHalf, kHalf}, {0, s, 0}, {s, 0, 0}, {0.95f, 0.85f, 0.4f}},
    };
    for (const Wall& w : walls)
        scene.add_mesh_object(w.name, make_quad(w.corner, w.edge_u, w.edge_v),
                              scene.add_material(mirror(w.tint)));

    // The central object: a sphere with a tilted ring, one mesh and one object.
    Mesh centre = make_uv_sphere({0, 0, 0}, 0.75f, 11, 22); // 440 triangles
    append_mesh(centre, make_torus({0, 0, 0}, {0.35f, 1.0f, 0.2f}, 1.2f, 0.17f, 13, 13)); // 338
    Material gold;
    gold.color = {0.95f, 0.75f, 0.35f};
    gold.ambient = 0.1f;
    gold.diffuse = 0.7f;
    gold.specular = 0.5f;
    gold.phong_exponent = 60.0f;
    gold.mirror = 0.4f;
    scene.add_mesh_object("sphere and ring", std::move(centre), scene.add_material(gold));

    scene.add_light({{-1.6f, 2.3f, 1.8f}, {1, 1, 1}});
    scene.camera.position = {0.6f, 0.7f, 2.6f};
    scene.camera.look_at = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.fov_y_degrees = 55.0f;
    scene.background = {0, 0, 0};
    scene.settings.emplace("trace.depth", "2"); // the paper's two bounces
    return scene;
}

} // namespace sheaf::builtin_detail

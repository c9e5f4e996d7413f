// The built-in "colonnade" scene: a Sponza-like courtyard of about 66,000 triangles in one
// single mesh object: a paved floor, two storeys of arcades on both long sides (turned columns
// with bases and capitals, arches, a balustrade), gallery floors and roofs, end walls, and an
// open sky over the courtyard's centre, like the paper's third test scene.
#include "core/scenes/shapes.h"

#include <vector>

namespace sheaf::builtin_detail {

namespace {

// The courtyard spans x in [-kHalfX, kHalfX] and z in [-kHalfZ, kHalfZ]; the arcades stand on
// x = +-kArcadeX, with bays of kBay between column centres.
constexpr float kHalfX = 10.0f, kHalfZ = 20.0f, kArcadeX = 6.0f, kBay = 4.0f;
constexpr int kColumns = 10; // per arcade line
constexpr float kWall = 0.3f, kAbacus = 0.35f, kArchDepth = 0.7f;
constexpr int kColumnSegments = 24, kArchSegments = 24, kBalusterSegments = 10;

float column_z(int k) {
    return -kBay * float(kColumns - 1) * 0.5f + kBay * float(k);
}

/// A column standing at `foot`, `height` tall: a square plinth, a turned body and an abacus.
void add_column(Mesh& m, Vec3 foot, float height) {
    const float plinth = 0.2f, abacus = 0.15f, l = height - plinth - abacus;
    append_mesh(m, make_box(foot + Vec3(-0.4f, 0, -0.4f), foot + Vec3(0.4f, plinth, 0.4f)));
    const std::vector<ProfilePoint> profile{
        {0.34f, 0.0f},       {0.36f, 0.04f},     {0.36f, 0.10f},     {0.31f, 0.14f},
        {0.27f, 0.20f},      {0.26f, 0.5f * l},  {0.24f, l - 0.35f}, {0.265f, l - 0.32f},
        {0.265f, l - 0.28f}, {0.24f, l - 0.25f}, {0.30f, l - 0.12f}, {0.38f, l - 0.02f},
        {0.38f, l}};
    append_mesh(m, make_lathe(foot + Vec3(0, plinth, 0), {0, 1, 0}, profile, kColumnSegments));
    append_mesh(m, make_box(foot + Vec3(-kAbacus, height - abacus, -kAbacus),
                            foot + Vec3(kAbacus, height, kAbacus)));
}

/// One storey of an arcade on x = x0: columns from y0 to y0 + column_height, arches above
/// them up to y0 + column_height + arch_height, and piers that join the ends to the end walls.
void add_arcade(Mesh& m, float x0, float y0, float column_height, float arch_height) {
    const float spring = y0 + column_height;
    for (int k = 0; k < kColumns; ++k) add_column(m, {x0, y0, column_z(k)}, column_height);
    // make_arch builds in the x-y plane, extruded along z; turn it so that it runs along z.
    const Affine turn = Affine::rotate({0, 1, 0}, 0.5f * kPi);
    const Mesh arch = make_arch({0, 0, 0}, kBay * 0.5f - kAbacus, kBay * 0.5f, arch_height,
                                kArchDepth, kArchSegments);
    for (int k = 0; k + 1 < kColumns; ++k)
        append_mesh(m, arch, Affine::translate({x0, spring, column_z(k) + kBay * 0.5f}) * turn);
    const float last = column_z(kColumns - 1), h = kArchDepth * 0.5f;
    for (float s : {-1.0f, 1.0f}) {
        const float z0 = s * last, z1 = s * (kHalfZ - kWall);
        append_mesh(m, make_box({x0 - h, y0, std::min(z0, z1)},
                                {x0 + h, spring + arch_height, std::max(z0, z1)}));
    }
}

/// A balustrade along x = x0 on the floor at y0: in each bay a bottom rail, turned balusters
/// and a hand rail.
void add_balustrade(Mesh& m, float x0, float y0) {
    const float rail = 0.1f, height = 0.8f, spacing = 0.25f;
    const std::vector<ProfilePoint> profile{{0.05f, 0.0f},  {0.05f, 0.06f},  {0.035f, 0.1f},
                                            {0.07f, 0.3f},  {0.045f, 0.55f}, {0.03f, 0.68f},
                                            {0.05f, 0.74f}, {0.05f, height}};
    const Mesh baluster = make_lathe({0, 0, 0}, {0, 1, 0}, profile, kBalusterSegments);
    for (int k = 0; k + 1 < kColumns; ++k) {
        const float z0 = column_z(k) + kAbacus, z1 = column_z(k + 1) - kAbacus;
        append_mesh(m, make_box({x0 - 0.12f, y0, z0}, {x0 + 0.12f, y0 + rail, z1}));
        append_mesh(m, make_box({x0 - 0.14f, y0 + rail + height, z0},
                                {x0 + 0.14f, y0 + 2 * rail + height, z1}));
        const int count = int((z1 - z0) / spacing);
        const float step = (z1 - z0) / float(count);
        for (int i = 0; i < count; ++i)
            append_mesh(m, baluster,
                        Affine::translate({x0, y0 + rail, z0 + step * (float(i) + 0.5f)}));
    }
}

} // namespace

Scene make_colonnade() {
    const float ground = 4.0f, ground_arch = 2.0f, slab = 0.35f, upper = 3.2f, upper_arch = 1.8f;
    const float floor2 = ground + ground_arch + slab; // the upper gallery's floor
    const float top = floor2 + upper + upper_arch + slab;

    Mesh m = make_quad({-kHalfX, 0, -kHalfZ}, {0, 0, 2 * kHalfZ}, {2 * kHalfX, 0, 0}, 64, 24);
    for (float s : {-1.0f, 1.0f}) {
        const float x0 = s * kArcadeX;
        add_arcade(m, x0, 0, ground, ground_arch);
        // The upper gallery's floor, which is the lower one's ceiling.
        const float inner = s * (kArcadeX - kArchDepth * 0.5f - 0.1f), outer = s * (kHalfX - kWall);
        append_mesh(m, make_box({std::min(inner, outer), ground + ground_arch, -kHalfZ + kWall},
                                {std::max(inner, outer), floor2, kHalfZ - kWall}));
        add_balustrade(m, x0, floor2);
        add_arcade(m, x0, floor2, upper, upper_arch);
        // The galleries' roof and the back wall.
        append_mesh(m, make_box({std::min(inner, outer), top - slab, -kHalfZ + kWall},
                                {std::max(inner, outer), top, kHalfZ - kWall}));
        append_mesh(m, make_box({std::min(s * kHalfX, outer), 0, -kHalfZ},
                                {std::max(s * kHalfX, outer), top, kHalfZ}));
        // The end walls.
        append_mesh(m, make_box({-kHalfX + kWall, 0, s > 0 ? kHalfZ - kWall : -kHalfZ},
                                {kHalfX - kWall, top, s > 0 ? kHalfZ : -kHalfZ + kWall}));
    }

    Scene scene;
    Material stone;
    stone.color = {0.78f, 0.72f, 0.62f};
    stone.ambient = 0.1f;
    stone.diffuse = 0.7f;
    stone.specular = 0.05f;
    scene.add_mesh_object("courtyard", std::move(m), scene.add_material(stone));
    scene.add_light({{2.0f, top - 0.5f, -4.0f}, {1, 1, 1}});
    scene.camera.position = {0.0f, 1.7f, -17.0f};
    scene.camera.look_at = {0.0f, 4.0f, 20.0f};
    scene.camera.up = {0, 1, 0};
    scene.camera.fov_y_degrees = 55.0f;
    scene.background = {0, 0, 0};
    return scene;
}

} // namespace sheaf::builtin_detail

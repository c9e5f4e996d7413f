// The built-in "office" scene: a furnished room of about 36,000 triangles in many small objects
// (desks, chairs, monitors, keyboards, desk lamps, bookcases, rows of books, plants), diffuse
// materials lit by two pendant lights, like the paper's second test scene.
#include "core/scenes/shapes.h"

#include <cstdint>
#include <string>

namespace sheaf::builtin_detail {

namespace {

// The room spans x in [-kRoomX, kRoomX], y in [0, kRoomY], z in [-kRoomZ, kRoomZ].
constexpr float kRoomX = 10.0f, kRoomY = 3.2f, kRoomZ = 7.0f;

/// A small fixed-seed generator, so the scene is the same on every platform.
struct Lcg {
    uint32_t state = 12345u;
    float next() { // in [0, 1)
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    }
    float range(float lo, float hi) { return lo + (hi - lo) * next(); }
};

Material diffuse(Vec3 color, float specular = 0.1f) {
    Material m;
    m.color = color;
    m.ambient = 0.1f;
    m.diffuse = 0.7f;
    m.specular = specular;
    m.phong_exponent = 30.0f;
    return m;
}

struct Office {
    Scene scene;
    Lcg rng;
    uint32_t wood, metal, fabric, plastic, screen, wall, floor, ceiling, shade, bulb, pot, leaf;
    uint32_t books[6];

    Office() {
        wood = scene.add_material(diffuse({0.6f, 0.42f, 0.25f}, 0.15f));
        metal = scene.add_material(diffuse({0.55f, 0.57f, 0.6f}, 0.4f));
        fabric = scene.add_material(diffuse({0.2f, 0.3f, 0.55f}, 0.02f));
        plastic = scene.add_material(diffuse({0.15f, 0.15f, 0.17f}, 0.25f));
        screen = scene.add_material(diffuse({0.05f, 0.08f, 0.12f}, 0.5f));
        wall = scene.add_material(diffuse({0.85f, 0.82f, 0.75f}, 0.0f));
        floor = scene.add_material(diffuse({0.45f, 0.4f, 0.36f}, 0.05f));
        ceiling = scene.add_material(diffuse({0.92f, 0.92f, 0.9f}, 0.0f));
        shade = scene.add_material(diffuse({0.8f, 0.15f, 0.1f}, 0.3f));
        bulb = scene.add_material(diffuse({1.0f, 0.97f, 0.85f}, 0.2f));
        pot = scene.add_material(diffuse({0.6f, 0.3f, 0.18f}, 0.1f));
        leaf = scene.add_material(diffuse({0.2f, 0.55f, 0.2f}, 0.05f));
        const Vec3 book_colors[6] = {{0.6f, 0.1f, 0.1f}, {0.1f, 0.3f, 0.6f}, {0.15f, 0.5f, 0.2f},
                                     {0.8f, 0.7f, 0.3f}, {0.4f, 0.2f, 0.5f}, {0.85f, 0.85f, 0.8f}};
        for (int i = 0; i < 6; ++i) books[i] = scene.add_material(diffuse(book_colors[i], 0.1f));
    }

    void add(std::string name, Mesh mesh, uint32_t material) {
        scene.add_mesh_object(std::move(name), std::move(mesh), material);
    }

    void room(int floor_tiles_x, int floor_tiles_z) {
        const float w = 2 * kRoomX, h = kRoomY, d = 2 * kRoomZ;
        // Every surface faces into the room.
        add("floor",
            make_quad({-kRoomX, 0, -kRoomZ}, {0, 0, d}, {w, 0, 0}, floor_tiles_z, floor_tiles_x),
            floor);
        add("ceiling", make_quad({-kRoomX, h, -kRoomZ}, {w, 0, 0}, {0, 0, d}, 4, 4), ceiling);
        add("wall west", make_quad({-kRoomX, 0, -kRoomZ}, {0, h, 0}, {0, 0, d}, 2, 4), wall);
        add("wall east", make_quad({kRoomX, 0, -kRoomZ}, {0, 0, d}, {0, h, 0}, 4, 2), wall);
        add("wall north", make_quad({-kRoomX, 0, -kRoomZ}, {w, 0, 0}, {0, h, 0}, 4, 2), wall);
        add("wall south", make_quad({-kRoomX, 0, kRoomZ}, {0, h, 0}, {w, 0, 0}, 2, 4), wall);
        add("whiteboard", make_box({-kRoomX, 1.0f, -2.0f}, {-kRoomX + 0.04f, 2.2f, 1.5f}), ceiling);
        add("door", make_box({kRoomX - 0.05f, 0, 2.5f}, {kRoomX, 2.1f, 3.5f}), wood);
        for (int i = 0; i < 4; ++i) {
            const float x = -6.0f + 4.0f * float(i);
            add("ceiling panel " + std::to_string(i),
                make_box({x - 0.6f, h - 0.03f, 3.5f}, {x + 0.6f, h, 4.1f}), bulb);
        }
    }

    // A workplace whose desk is centred at (x, z); its user sits on the +z side.
    void workplace(int id, float x, float z) {
        const std::string n = " " + std::to_string(id);
        const float top = 0.74f, hw = 0.7f, hd = 0.4f;
        Mesh desk = make_box({x - hw, top - 0.04f, z - hd}, {x + hw, top, z + hd});
        for (float sx : {-1.0f, 1.0f})
            for (float sz : {-1.0f, 1.0f}) {
                const float lx = x + sx * (hw - 0.05f), lz = z + sz * (hd - 0.05f);
                append_mesh(desk, make_box({lx - 0.03f, 0, lz - 0.03f},
                                           {lx + 0.03f, top - 0.04f, lz + 0.03f}));
            }
        append_mesh(desk, make_box({x - hw + 0.05f, 0.3f, z - hd + 0.03f},
                                   {x + hw - 0.05f, top - 0.04f, z - hd + 0.05f}));
        add("desk" + n, std::move(desk), wood);

        // The chair: seat, back, two back posts and four round legs.
        const float cz = z + hd + 0.35f, seat = 0.45f;
        Mesh chair = make_box({x - 0.22f, seat - 0.04f, cz - 0.22f}, {x + 0.22f, seat, cz + 0.22f});
        append_mesh(chair, make_box({x - 0.22f, seat + 0.15f, cz + 0.2f},
                                    {x + 0.22f, seat + 0.5f, cz + 0.23f}));
        for (float sx : {-1.0f, 1.0f}) {
            append_mesh(chair, make_box({x + sx * 0.18f - 0.015f, seat, cz + 0.2f},
                                        {x + sx * 0.18f + 0.015f, seat + 0.15f, cz + 0.23f}));
            for (float sz : {-1.0f, 1.0f}) {
                const Vec3 foot(x + sx * 0.19f, 0, cz + sz * 0.19f);
                append_mesh(chair,
                            make_cylinder(foot, foot + Vec3(0, seat - 0.04f, 0), 0.018f, 16, true));
            }
        }
        add("chair" + n, std::move(chair), fabric);

        // The monitor: a screen on a round stand and foot.
        const Vec3 mbase(x, top, z - 0.22f);
        Mesh monitor = make_cylinder(mbase, mbase + Vec3(0, 0.012f, 0), 0.11f, 24, true);
        append_mesh(monitor, make_cylinder(mbase, mbase + Vec3(0, 0.2f, 0), 0.02f, 16, true));
        append_mesh(monitor, make_box({x - 0.27f, top + 0.16f, z - 0.215f},
                                      {x + 0.27f, top + 0.48f, z - 0.185f}));
        add("monitor" + n, std::move(monitor), screen);
        add("keyboard" + n,
            make_box({x - 0.22f, top, z + 0.02f}, {x + 0.22f, top + 0.02f, z + 0.17f}), plastic);

        // The desk lamp: a round foot, two arms with a joint, a conical shade and a bulb.
        const Vec3 lb(x + hw - 0.15f, top, z - hd + 0.15f);
        const Vec3 joint = lb + Vec3(-0.05f, 0.32f, 0.05f), head = joint + Vec3(-0.2f, 0.08f, 0.1f);
        Mesh lamp = make_cylinder(lb, lb + Vec3(0, 0.02f, 0), 0.08f, 32, true);
        append_mesh(lamp, make_cylinder(lb, joint, 0.01f, 16, true));
        append_mesh(lamp, make_uv_sphere(joint, 0.018f, 8, 12));
        append_mesh(lamp, make_cylinder(joint, head, 0.01f, 16, true));
        append_mesh(lamp, make_cone(head + Vec3(0, -0.13f, 0), head, 0.08f, 0.03f, 32, false));
        append_mesh(lamp, make_uv_sphere(head + Vec3(0, -0.08f, 0), 0.025f, 8, 12));
        add("desk lamp" + n, std::move(lamp), metal);
    }

    // A bookcase against the north wall with its left side at x, and a row of books per shelf.
    void bookcase(int id, float x) {
        const std::string n = " " + std::to_string(id);
        const float w = 1.6f, h = 2.0f, d = 0.35f, t = 0.025f, z0 = -kRoomZ, z1 = -kRoomZ + d;
        const int shelves = 5;
        Mesh frame = make_box({x, 0, z0}, {x + t, h, z1});
        append_mesh(frame, make_box({x + w - t, 0, z0}, {x + w, h, z1}));
        append_mesh(frame, make_box({x + t, 0, z0}, {x + w - t, h, z0 + t}));
        for (int s = 0; s <= shelves; ++s) {
            const float y = s == shelves ? h - t : float(s) * h / shelves;
            append_mesh(frame, make_box({x + t, y, z0 + t}, {x + w - t, y + t, z1}));
        }
        add("bookcase" + n, std::move(frame), wood);
        for (int s = 0; s < shelves; ++s) {
            const float y = float(s) * h / shelves + t;
            Mesh row;
            float bx = x + t + 0.01f;
            uint32_t material = books[(id + s) % 6];
            while (true) {
                const float bw = rng.range(0.035f, 0.075f), bh = rng.range(0.2f, 0.34f);
                const float bd = rng.range(0.2f, 0.3f);
                if (bx + bw > x + w - t - 0.01f) break;
                append_mesh(row, make_box({bx, y, z0 + t}, {bx + bw, y + bh, z0 + t + bd}));
                bx += bw + 0.002f;
            }
            add("books" + n + "." + std::to_string(s), std::move(row), material);
        }
    }

    void plant(int id, Vec3 at) {
        const std::string n = " " + std::to_string(id);
        add("pot" + n, make_cone(at, at + Vec3(0, 0.45f, 0), 0.16f, 0.22f, 24, true), pot);
        Mesh leaves = make_uv_sphere(at + Vec3(0, 0.8f, 0), 0.35f, 10, 14);
        append_mesh(leaves, make_uv_sphere(at + Vec3(0.15f, 1.05f, 0.05f), 0.25f, 8, 12));
        append_mesh(leaves, make_uv_sphere(at + Vec3(-0.1f, 1.1f, -0.1f), 0.22f, 8, 12));
        add("plant" + n, std::move(leaves), leaf);
    }

    void pendant(int id, Vec3 at) { // `at` is the light's position, just below the shade
        const std::string n = " " + std::to_string(id);
        Mesh fixture =
            make_cylinder({at.x, kRoomY - 0.4f, at.z}, {at.x, kRoomY, at.z}, 0.01f, 16, true);
        append_mesh(fixture, make_cone(at + Vec3(0, 0.1f, 0), {at.x, kRoomY - 0.4f, at.z}, 0.4f,
                                       0.1f, 48, false));
        add("pendant" + n, std::move(fixture), shade);
        add("bulb" + n, make_uv_sphere(at + Vec3(0, 0.22f, 0), 0.07f, 10, 16), bulb);
        scene.add_light({at, {0.6f, 0.6f, 0.6f}});
    }
};

} // namespace

Scene make_office() {
    Office o;
    o.room(22, 15); // floor tiles, chosen so that the total is the paper's 36,308
    int id = 0;
    for (float z : {-3.2f, -0.4f, 2.4f})
        for (float x : {-7.0f, -3.5f, 0.0f, 3.5f, 7.0f}) o.workplace(id++, x, z);
    for (int i = 0; i < 8; ++i) o.bookcase(i, -9.6f + 1.65f * float(i));
    o.plant(0, {-9.4f, 0, -5.8f});
    o.plant(1, {9.4f, 0, -6.4f});
    o.plant(2, {9.3f, 0, 6.3f});
    o.plant(3, {9.3f, 0, 0.5f});
    o.pendant(0, {-3.5f, kRoomY - 0.75f, 0.6f});
    o.pendant(1, {3.5f, kRoomY - 0.75f, -1.2f});

    Scene& s = o.scene;
    s.camera.position = {-9.2f, 1.8f, 6.3f};
    s.camera.look_at = {1.5f, 0.7f, -3.0f};
    s.camera.up = {0, 1, 0};
    s.camera.fov_y_degrees = 55.0f;
    s.background = {0, 0, 0};
    return std::move(o.scene);
}

} // namespace sheaf::builtin_detail

// The C ABI's scenes: creation, built-in scenes and files, meshes, materials, objects, lights,
// the camera, and the commit that validates and prepares them.
#include "capi_internal.h"

#include "core/base/error.h"
#include "core/scenes/builtin.h"
#include "io/scene/scene_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>


using namespace sheaf::capi;

namespace {

sheaf::Vec3 vec3(const float* v, const char* name) {
    require(v, name);
    return {v[0], v[1], v[2]};
}

/// Runs `edit` on the scene under its lock and marks it changed since the last commit.
template <class Edit> void modify(SheafScene handle, Edit&& edit) {
    SheafSceneT& s = *require(handle, "scene");
    std::lock_guard<std::mutex> lock(s.mutex);
    edit(s.scene);
    s.prepared.reset();
}

} // namespace

extern "C" {

SHEAF_API void sheafMaterialDescInit(SheafMaterialDesc* desc) {
    if (!desc) return;
    const sheaf::Material m;
    desc->color[0] = m.color.x, desc->color[1] = m.color.y, desc->color[2] = m.color.z;
    desc->ambient = m.ambient;
    desc->diffuse = m.diffuse;
    desc->specular = m.specular;
    desc->phong_exponent = m.phong_exponent;
    desc->mirror = m.mirror;
    desc->transmission = m.transmission;
    desc->ior = m.ior;
    desc->emission[0] = m.emission.x, desc->emission[1] = m.emission.y,
    desc->emission[2] = m.emission.z;
    desc->texture = m.texture;
}

SHEAF_API void sheafLightDescInit(SheafLightDesc* desc) {
    if (!desc) return;
    const sheaf::Light l;
    desc->type = SHEAF_LIGHT_POINT;
    for (int i = 0; i < 3; ++i)
        desc->position[i] = l.position[i], desc->direction[i] = l.direction[i],
        desc->color[i] = l.color[i];
    desc->spot_radius = l.spot_radius;
    desc->spot_falloff = l.spot_falloff;
    desc->spot_tightness = l.spot_tightness;
    desc->fade_distance = l.fade_distance;
    desc->fade_power = l.fade_power;
    desc->shadowless = l.shadowless ? 1 : 0;
}

SHEAF_API void sheafCameraDescInit(SheafCameraDesc* desc) {
    if (!desc) return;
    const sheaf::Camera c;
    desc->projection = SHEAF_PROJECTION_PERSPECTIVE;
    for (int i = 0; i < 3; ++i)
        desc->position[i] = c.position[i], desc->look_at[i] = c.look_at[i], desc->up[i] = c.up[i];
    desc->fov_y_degrees = c.fov_y_degrees;
    desc->ortho_height = c.ortho_height;
    desc->shift[0] = c.shift_x, desc->shift[1] = c.shift_y;
}

SHEAF_API SheafError sheafSceneNew(SheafScene* out) {
    return barrier([&] {
        require(out, "out");
        *out = nullptr;
        *out = new SheafSceneT;
    });
}

SHEAF_API SheafError sheafSceneRetain(SheafScene scene) {
    return barrier([&] { sheaf_retain(require(scene, "scene")); });
}

SHEAF_API SheafError sheafSceneRelease(SheafScene scene) {
    return barrier([&] { sheaf_release(require(scene, "scene")); });
}

SHEAF_API SheafError sheafSceneLoadBuiltin(SheafScene scene, const char* name) {
    return barrier([&] {
        require(scene, "scene");
        sheaf::Scene loaded = sheaf::make_builtin_scene(require(name, "name"));
        modify(scene, [&](sheaf::Scene& s) { s = std::move(loaded); });
        std::lock_guard<std::mutex> lock(scene->mutex);
        scene->warnings.clear();
        scene->limits.clear();
    });
}

SHEAF_API SheafError sheafSceneLoadFile(SheafScene scene, const char* path) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        require(path, "path");
        sheaf::io::SceneFileOptions options;
        {
            std::lock_guard<std::mutex> lock(s.mutex);
            options = s.load_options;
        }
        if (const std::string problem = sheaf::io::pov::animation_problem(options.animation);
            !problem.empty())
            throw InvalidArgument("load options: " + problem);
        sheaf::io::SceneFile loaded = sheaf::io::load_scene_file(path, options);
        std::lock_guard<std::mutex> lock(s.mutex);
        s.scene = std::move(loaded.scene);
        s.warnings = std::move(loaded.warnings);
        s.limits = std::move(loaded.limits);
        s.prepared.reset();
    });
}

SHEAF_API SheafError sheafSceneSetLoadOption(SheafScene scene, const char* key,
                                             const char* value) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        const std::string k = require(key, "key"), v = require(value, "value");
        std::lock_guard<std::mutex> lock(s.mutex);
        if (k == "include_path") {
            if (v.empty())
                s.load_options.include_paths.clear();
            else
                s.load_options.include_paths.push_back(v);
        } else if (k == "strict") {
            if (v == "1" || v == "true" || v == "on")
                s.load_options.strict = true;
            else if (v == "0" || v == "false" || v == "off")
                s.load_options.strict = false;
            else
                throw InvalidArgument("load option 'strict': '" + v +
                                      "' is not allowed; expected 0 or 1");
        } else if (k == "image_width" || k == "image_height") {
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || n < 1 || n > 16384)
                throw InvalidArgument("load option '" + k + "': '" + v +
                                      "' is not allowed; expected an integer in 1..16384");
            (k == "image_width" ? s.load_options.image_width : s.load_options.image_height) =
                int(n);
        } else if (k == "initial_frame" || k == "final_frame" || k == "frame") {
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || n < -1000000000L || n > 1000000000L)
                throw InvalidArgument("load option '" + k + "': '" + v +
                                      "' is not allowed; expected an integer");
            sheaf::io::pov::Animation& a = s.load_options.animation;
            (k == "initial_frame" ? a.initial_frame
             : k == "final_frame" ? a.final_frame
                                  : a.frame.emplace()) = int(n);
        } else if (k == "initial_clock" || k == "final_clock" || k == "clock") {
            sheaf::io::pov::Animation& a = s.load_options.animation;
            if (k == "clock" && v.empty()) {
                a.clock.reset();
                return;
            }
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            if (v.empty() || *end != '\0' || !std::isfinite(x))
                throw InvalidArgument("load option '" + k + "': '" + v +
                                      "' is not allowed; expected a number");
            (k == "initial_clock" ? a.initial_clock
             : k == "final_clock" ? a.final_clock
                                  : a.clock.emplace()) = x;
        } else if (k == "cyclic_animation") {
            if (v != "0" && v != "1")
                throw InvalidArgument("load option 'cyclic_animation': '" + v +
                                      "' is not allowed; expected 0 or 1");
            s.load_options.animation.cyclic = v == "1";
        } else if (k == "declare") {
            if (v.empty()) {
                s.load_options.declares.clear();
                return;
            }
            const size_t eq = v.find('=');
            const std::string name = v.substr(0, std::min(eq, v.size()));
            bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
            for (char c : name)
                identifier =
                    identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            char* end = nullptr;
            const std::string text = eq == std::string::npos ? "" : v.substr(eq + 1);
            const double x = std::strtod(text.c_str(), &end);
            if (!identifier || text.empty() || *end != '\0' || !std::isfinite(x))
                throw InvalidArgument("load option 'declare': '" + v +
                                      "' is not allowed; expected NAME=NUMBER, e.g. Quality=2");
            s.load_options.declares.emplace_back(name, x);
        } else if (k.compare(0, 6, "limit.") == 0) {
            const std::string name = k.substr(6);
            char* end = nullptr;
            errno = 0;
            const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
            const bool number = !v.empty() && v[0] != '-' && *end == '\0' && errno == 0;
            sheaf::io::pov::PovLimits limits = s.load_options.limits;
            if (!sheaf::io::pov::reset_limit(limits, name)) // "": the default
                throw InvalidArgument("unknown load option '" + k +
                                      "'; known limits: limit.parse_steps, limit.objects, "
                                      "limit.data_mib, limit.loop_iterations, "
                                      "limit.macro_calls, limit.function_terms");
            if (!v.empty() && (!number || !sheaf::io::pov::set_limit(limits, name, n)))
                throw InvalidArgument("load option '" + k + "': '" + v +
                                      "' is not allowed; expected an integer in 1..2^50, or \"\" "
                                      "for the default");
            s.load_options.limits = limits;
        } else if (k == "subdivision.limit") {
            if (v != "0" && v != "1")
                throw InvalidArgument("option 'subdivision.limit': '" + v +
                                      "' is not allowed; expected 0 or 1");
            s.subdivision_limit = v == "1";
        } else if (k == "subdivision.boundary") {
            static const char* const kRules[] = {"edge_only", "edge_and_corner", "none"};
            int rule = -1;
            for (int i = 0; i < 3; ++i)
                if (v == kRules[i]) rule = i;
            if (rule < 0)
                throw InvalidArgument("option 'subdivision.boundary': '" + v +
                                      "' is not allowed; expected edge_only, edge_and_corner or "
                                      "none");
            s.subdivision_boundary = rule;
        } else {
            throw InvalidArgument("unknown load option '" + k +
                                  "'; known options: include_path, strict, image_width, "
                                  "image_height, initial_frame, final_frame, initial_clock, "
                                  "final_clock, cyclic_animation, frame, clock, declare, "
                                  "subdivision.limit, subdivision.boundary, limit.parse_steps, "
                                  "limit.objects, limit.data_mib, limit.loop_iterations, "
                                  "limit.macro_calls, limit.function_terms");
        }
    });
}

SHEAF_API SheafError sheafSceneGetWarningCount(SheafScene scene, size_t* count) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        require(count, "count");
        std::lock_guard<std::mutex> lock(s.mutex);
        *count = s.warnings.size();
    });
}

SHEAF_API SheafError sheafSceneGetWarning(SheafScene scene, size_t index, const char** message) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        require(message, "message");
        std::lock_guard<std::mutex> lock(s.mutex);
        if (index >= s.warnings.size())
            throw InvalidArgument("warning " + std::to_string(index) + " does not exist (the scene has " +
                                  std::to_string(s.warnings.size()) + " warnings)");
        *message = s.warnings[index].c_str();
    });
}

SHEAF_API SheafError sheafSceneGetLimitCount(SheafScene scene, size_t* count) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        require(count, "count");
        std::lock_guard<std::mutex> lock(s.mutex);
        *count = s.limits.size();
    });
}

SHEAF_API SheafError sheafSceneGetLimitUse(SheafScene scene, size_t index, const char** name,
                                           double* used, double* limit) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        require(name, "name");
        require(used, "used");
        require(limit, "limit");
        std::lock_guard<std::mutex> lock(s.mutex);
        if (index >= s.limits.size())
            throw InvalidArgument("limit " + std::to_string(index) +
                                  " does not exist (the last load has " +
                                  std::to_string(s.limits.size()) + " limits)");
        *name = s.limits[index].name.c_str();
        *used = s.limits[index].used;
        *limit = s.limits[index].limit;
    });
}

SHEAF_API SheafError sheafSceneAddMaterial(SheafScene scene, const SheafMaterialDesc* desc,
                                           uint32_t* out_material_id) {
    return barrier([&] {
        require(scene, "scene");
        require(desc, "desc");
        sheaf::Material m;
        m.color = {desc->color[0], desc->color[1], desc->color[2]};
        m.ambient = desc->ambient;
        m.diffuse = desc->diffuse;
        m.specular = desc->specular;
        m.phong_exponent = desc->phong_exponent;
        m.mirror = desc->mirror;
        m.transmission = desc->transmission;
        m.ior = desc->ior;
        m.emission = {desc->emission[0], desc->emission[1], desc->emission[2]};
        m.texture = desc->texture;
        uint32_t id = 0;
        modify(scene, [&](sheaf::Scene& s) { id = s.add_material(m); });
        if (out_material_id) *out_material_id = id;
    });
}

SHEAF_API SheafError sheafSceneAddMesh(SheafScene scene, const float* positions,
                                       uint32_t vertex_count, const uint32_t* indices,
                                       uint32_t triangle_count, const float* normals,
                                       uint32_t* out_mesh_id) {
    return barrier([&] {
        require(scene, "scene");
        if (vertex_count > 0) require(positions, "positions");
        if (triangle_count > 0) require(indices, "indices");
        sheaf::Mesh mesh;
        mesh.positions.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i)
            mesh.positions[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        if (normals) {
            mesh.normals.resize(vertex_count);
            for (size_t i = 0; i < vertex_count; ++i)
                mesh.normals[i] = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
        }
        mesh.indices.assign(indices, indices + size_t(triangle_count) * 3);
        uint32_t id = 0;
        modify(scene, [&](sheaf::Scene& s) { id = s.add_mesh(std::move(mesh)); });
        if (out_mesh_id) *out_mesh_id = id;
    });
}

SHEAF_API SheafError sheafSceneAddObject(SheafScene scene, uint32_t mesh_id, uint32_t material_id,
                                         const float* transform_3x4, const char* name,
                                         uint32_t* out_object_id) {
    return barrier([&] {
        require(scene, "scene");
        sheaf::Object o;
        o.mesh = mesh_id;
        o.material = material_id;
        if (name) o.name = name;
        if (transform_3x4)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c) o.transform.m[r][c] = transform_3x4[r * 4 + c];
        uint32_t id = 0;
        modify(scene, [&](sheaf::Scene& s) {
            if (mesh_id >= s.meshes.size())
                throw sheaf::SceneError("mesh id " + std::to_string(mesh_id) +
                                        " does not exist (the scene has " +
                                        std::to_string(s.meshes.size()) + " meshes)");
            if (material_id >= s.materials.size())
                throw sheaf::SceneError("material id " + std::to_string(material_id) +
                                        " does not exist (the scene has " +
                                        std::to_string(s.materials.size()) + " materials)");
            id = s.add_object(std::move(o));
        });
        if (out_object_id) *out_object_id = id;
    });
}

SHEAF_API SheafError sheafSceneSetObjectFlags(SheafScene scene, uint32_t object_id,
                                              uint32_t flags) {
    return barrier([&] {
        require(scene, "scene");
        constexpr uint32_t kKnown =
            SHEAF_OBJECT_NO_SHADOW | SHEAF_OBJECT_NO_REFLECTION | SHEAF_OBJECT_NO_IMAGE;
        if (flags & ~kKnown)
            throw InvalidArgument("object flags " + std::to_string(flags) +
                                  " name unknown bits; known: SHEAF_OBJECT_NO_SHADOW, "
                                  "SHEAF_OBJECT_NO_REFLECTION, SHEAF_OBJECT_NO_IMAGE");
        modify(scene, [&](sheaf::Scene& s) {
            if (object_id >= s.objects.size())
                throw InvalidArgument("object " + std::to_string(object_id) +
                                      " does not exist (the scene has " +
                                      std::to_string(s.objects.size()) + " objects)");
            s.objects[object_id].flags = uint8_t(flags);
        });
    });
}

SHEAF_API SheafError sheafSceneAddPointLight(SheafScene scene, const float position[3],
                                             const float color[3]) {
    return barrier([&] {
        require(scene, "scene");
        sheaf::Light light;
        light.position = vec3(position, "position");
        light.color = vec3(color, "color");
        modify(scene, [&](sheaf::Scene& s) { s.add_light(light); });
    });
}

SHEAF_API SheafError sheafSceneSetCamera(SheafScene scene, const float position[3],
                                         const float look_at[3], const float up[3],
                                         float fov_y_degrees) {
    return barrier([&] {
        require(scene, "scene");
        sheaf::Camera camera;
        camera.position = vec3(position, "position");
        camera.look_at = vec3(look_at, "look_at");
        camera.up = vec3(up, "up");
        camera.fov_y_degrees = fov_y_degrees;
        modify(scene, [&](sheaf::Scene& s) { s.camera = camera; });
    });
}

SHEAF_API SheafError sheafSceneAddTexture(SheafScene scene, const char* path,
                                          int mapping,
                                          const float* world_to_texture_3x4, const char* colorspace,
                                          uint32_t* out_texture_id) {
    return barrier([&] {
        require(scene, "scene");
        sheaf::Texture t;
        t.path = require(path, "path");
        switch (mapping) {
        case SHEAF_MAPPING_UV:
            t.mapping = sheaf::TextureMapping::Uv;
            break;
        case SHEAF_MAPPING_PLANAR:
            t.mapping = sheaf::TextureMapping::Planar;
            break;
        case SHEAF_MAPPING_SPHERICAL:
            t.mapping = sheaf::TextureMapping::Spherical;
            break;
        case SHEAF_MAPPING_CYLINDRICAL:
            t.mapping = sheaf::TextureMapping::Cylindrical;
            break;
        case SHEAF_MAPPING_TORUS:
            t.mapping = sheaf::TextureMapping::Torus;
            break;
        default:
            throw InvalidArgument("texture mapping " + std::to_string(mapping) +
                                  " is not a SheafTextureMapping");
        }
        if (world_to_texture_3x4)
            for (int i = 0; i < 12; ++i) t.transform.m[i / 4][i % 4] = world_to_texture_3x4[i];
        t.colorspace = colorspace ? colorspace : "";
        if (!t.colorspace.empty() && t.colorspace != "srgb" && t.colorspace != "linear")
            throw InvalidArgument("texture colorspace '" + t.colorspace +
                                  "' is not one of srgb, linear (or empty)");
        uint32_t id = 0;
        modify(scene, [&](sheaf::Scene& s) {
            s.textures.push_back(t);
            id = uint32_t(s.textures.size() - 1);
        });
        if (out_texture_id) *out_texture_id = id;
    });
}

SHEAF_API SheafError sheafSceneSetMeshUvs(SheafScene scene, uint32_t mesh_id, const float* uvs,
                                          uint32_t vertex_count) {
    return barrier([&] {
        require(scene, "scene");
        require(uvs, "uvs");
        modify(scene, [&](sheaf::Scene& s) {
            if (mesh_id >= s.meshes.size())
                throw InvalidArgument("mesh " + std::to_string(mesh_id) + " does not exist");
            sheaf::Mesh& m = s.meshes[mesh_id];
            if (vertex_count != m.positions.size())
                throw InvalidArgument("mesh " + std::to_string(mesh_id) + " has " +
                                      std::to_string(m.positions.size()) + " vertices; " +
                                      std::to_string(vertex_count) + " texture coordinates given");
            m.uvs.assign(uvs, uvs + 2 * size_t(vertex_count));
        });
    });
}

SHEAF_API SheafError sheafSceneAddLight(SheafScene scene, const SheafLightDesc* desc,
                                        uint32_t* out_light_id) {
    return barrier([&] {
        require(scene, "scene");
        require(desc, "desc");
        sheaf::Light l;
        switch (desc->type) {
        case SHEAF_LIGHT_POINT:
            l.type = sheaf::LightType::Point;
            break;
        case SHEAF_LIGHT_SPOT:
            l.type = sheaf::LightType::Spot;
            break;
        case SHEAF_LIGHT_PARALLEL:
            l.type = sheaf::LightType::Parallel;
            break;
        default:
            throw InvalidArgument(
                "light type " + std::to_string(desc->type) +
                " is not one of SHEAF_LIGHT_POINT, SHEAF_LIGHT_SPOT, SHEAF_LIGHT_PARALLEL");
        }
        l.position = vec3(desc->position, "position");
        l.direction = vec3(desc->direction, "direction");
        l.color = vec3(desc->color, "color");
        l.spot_radius = desc->spot_radius;
        l.spot_falloff = desc->spot_falloff;
        l.spot_tightness = desc->spot_tightness;
        l.fade_distance = desc->fade_distance;
        l.fade_power = desc->fade_power;
        l.shadowless = desc->shadowless != 0;
        uint32_t id = 0;
        modify(scene, [&](sheaf::Scene& s) { id = s.add_light(l); });
        if (out_light_id) *out_light_id = id;
    });
}

SHEAF_API SheafError sheafSceneSetCameraDesc(SheafScene scene, const SheafCameraDesc* desc) {
    return barrier([&] {
        require(scene, "scene");
        require(desc, "desc");
        sheaf::Camera c;
        // SheafProjection's values are Projection's, in the same order.
        if (!(desc->projection >= 0 && desc->projection < sheaf::kProjectionCount))
            throw InvalidArgument("projection " + std::to_string(desc->projection) +
                                  " is not a SheafProjection (SHEAF_PROJECTION_PERSPECTIVE .. "
                                  "SHEAF_PROJECTION_SPHERICAL)");
        c.projection = sheaf::Projection(desc->projection);
        if (c.projection == sheaf::Projection::Spherical) c.angle_degrees = 360;
        c.position = vec3(desc->position, "position");
        c.look_at = vec3(desc->look_at, "look_at");
        c.up = vec3(desc->up, "up");
        c.fov_y_degrees = desc->fov_y_degrees;
        c.ortho_height = desc->ortho_height;
        c.shift_x = desc->shift[0], c.shift_y = desc->shift[1];
        modify(scene, [&](sheaf::Scene& s) { s.camera = c; });
    });
}

SHEAF_API SheafError sheafSceneSetCameraLens(SheafScene scene, float angle_degrees,
                                             float v_angle_degrees, const float lengths[3]) {
    return barrier([&] {
        require(scene, "scene");
        for (float a : {angle_degrees, v_angle_degrees})
            if (!sheaf::camera_angle_ok(a))
                throw InvalidArgument("a camera angle of " + std::to_string(a) +
                                      " degrees; expected (0, 3600]");
        sheaf::Vec3 l(-1.0f);
        if (lengths) {
            l = vec3(lengths, "lengths");
            if (!(sheaf::camera_length_ok(l.x) && sheaf::camera_length_ok(l.y) &&
                  sheaf::camera_length_ok(l.z)))
                throw InvalidArgument(
                    "the lengths of right, up and direction must be > 0 and below 1e6");
        }
        modify(scene, [&](sheaf::Scene& s) {
            s.camera.angle_degrees = angle_degrees;
            s.camera.v_angle_degrees = v_angle_degrees;
            if (lengths)
                s.camera.right_length = l.x, s.camera.up_length = l.y,
                s.camera.direction_length = l.z;
        });
    });
}

SHEAF_API SheafError sheafSceneSetCameraFocus(SheafScene scene, float lens_radius,
                                              float focal_distance) {
    return barrier([&] {
        require(scene, "scene");
        if (!(lens_radius >= 0 && lens_radius < 1e30f))
            throw InvalidArgument("a lens radius of " + std::to_string(lens_radius) +
                                  "; expected a finite number >= 0");
        if (lens_radius > 0 && !(focal_distance > 0 && focal_distance < 1e30f))
            throw InvalidArgument("a focal distance of " + std::to_string(focal_distance) +
                                  "; a lens needs a finite one > 0");
        modify(scene, [&](sheaf::Scene& s) {
            s.camera.lens_radius = lens_radius;
            s.camera.focal_distance = lens_radius > 0 ? focal_distance : 0;
        });
    });
}

SHEAF_API SheafError sheafSceneSetBackground(SheafScene scene, const float rgb[3]) {
    return barrier([&] {
        require(scene, "scene");
        const sheaf::Vec3 background = vec3(rgb, "rgb");
        modify(scene, [&](sheaf::Scene& s) { s.background = background; });
    });
}

SHEAF_API SheafError sheafSceneCommit(SheafScene scene) {
    return barrier([&] { require(scene, "scene")->commit(); });
}

} // extern "C"

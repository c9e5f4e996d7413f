// read_mesh_scene: see mesh_scene.h.
#include "io/mesh/mesh_scene.h"

#include "io/mesh/default_view.h"
#include "io/mesh/mesh_file.h"

#include <map>
#include <tuple>

namespace sheaf::io {

SceneFile read_mesh_scene(const std::string& path, const SceneFileOptions&) {
    std::vector<MeshPart> parts = read_mesh_parts(path);
    SceneFile out;
    Scene& scene = out.scene;
    std::map<std::tuple<float, float, float>, uint32_t> by_color; // one material per colour
    for (MeshPart& part : parts) {
        Material m;
        if (part.has_color) m.color = part.color;
        const auto key = std::make_tuple(m.color.x, m.color.y, m.color.z);
        auto it = by_color.find(key);
        if (it == by_color.end()) it = by_color.emplace(key, scene.add_material(m)).first;
        scene.add_mesh_object(part.name, std::move(part.mesh), it->second);
    }
    add_default_view(scene);
    scene.background = Vec3(0.05f);
    return out;
}

} // namespace sheaf::io

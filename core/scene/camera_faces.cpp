// The mesh camera's faces, transforms and uv grid (see camera_faces.h).
#include "core/scene/camera_faces.h"

#include "core/base/error.h"
#include "core/scene/prepared_scene.h"

#include <algorithm>
#include <cmath>

namespace sheaf {

namespace {

/// The grid cells [lo, hi] a face's uv bounds cover along one axis (clamped to the square).
void cell_span(const float* c, uint32_t& lo, uint32_t& hi) {
    const float mn = std::min({c[0], c[1], c[2]}), mx = std::max({c[0], c[1], c[2]});
    auto cell = [](float v) {
        const float g = std::floor(v * float(kCameraUvGrid));
        return uint32_t(std::clamp(g, 0.0f, float(kCameraUvGrid - 1)));
    };
    lo = cell(mn), hi = cell(mx);
}

} // namespace

void prepare_camera_faces(const Scene& scene, PreparedScene& p) {
    p.camera_faces.clear();
    p.camera_meshes.clear();
    p.camera_uv_cells.clear();
    p.camera_uv_faces.clear();
    if (scene.camera.projection != Projection::Mesh) return;
    for (const CameraMesh& cm : scene.camera_meshes) {
        const Mesh& m = cm.mesh;
        CameraMeshRef ref;
        ref.to_world = cm.transform;
        ref.normal_to_world = cm.transform.normal_matrix();
        ref.first = uint32_t(p.camera_faces.size());
        for (size_t t = 0; t < m.triangle_count(); ++t) {
            const uint32_t i[3] = {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
            CameraFace f{};
            f.a = m.positions[i[0]], f.b = m.positions[i[1]], f.c = m.positions[i[2]];
            const Vec3 n = cross(f.b - f.a, f.c - f.a);
            const float len = length(n);
            if (!(len > 0)) continue; // degenerate: not a face
            f.n = n / len;
            if (!m.normals.empty()) {
                Vec3* out[3] = {&f.na, &f.nb, &f.nc};
                for (int k = 0; k < 3; ++k) {
                    const Vec3 v = m.normals[i[k]];
                    *out[k] = length(v) > 0 ? normalize(v) : Vec3(0.0f);
                }
            }
            if (!m.uvs.empty())
                for (int k = 0; k < 3; ++k) f.s[k] = m.uvs[2 * i[k]], f.t[k] = m.uvs[2 * i[k] + 1];
            f.mesh = uint32_t(p.camera_meshes.size());
            p.camera_faces.push_back(f);
        }
        ref.count = uint32_t(p.camera_faces.size()) - ref.first;
        p.camera_meshes.push_back(ref);
    }
    if (scene.camera.mesh_distribution != 3 || p.camera_meshes.empty()) return;
    // The first mesh's faces by the uv cells their bounds cover, each cell's in face order (so
    // the first face found holding a point is the first in the mesh, as POV-Ray takes it).
    const CameraMeshRef& first = p.camera_meshes[0];
    constexpr uint32_t kCells = kCameraUvGrid * kCameraUvGrid;
    std::vector<uint32_t> count(kCells + 1, 0);
    auto each_cell = [&](const CameraFace& f, auto&& visit) {
        uint32_t u0, u1, v0, v1;
        cell_span(f.s, u0, u1);
        cell_span(f.t, v0, v1);
        for (uint32_t v = v0; v <= v1; ++v)
            for (uint32_t u = u0; u <= u1; ++u) visit(v * kCameraUvGrid + u);
    };
    // A uv layout covers its square about once; faces piled over it many times over would
    // make the grid's lists grow as faces times cells: an error before they do.
    const size_t limit = 64 * (size_t(first.count) + kCells);
    size_t total = 0;
    for (uint32_t f = first.first; f < first.first + first.count; ++f)
        each_cell(p.camera_faces[f], [&](uint32_t cell) {
            if (++total > limit)
                throw SceneError("the mesh camera's first mesh covers its uv square more than " +
                                 std::to_string(limit / kCells) +
                                 " times over (distribution 3 finds a pixel's face by its uv "
                                 "coordinates: give the faces a layout that covers it about once)");
            ++count[cell + 1];
        });
    for (uint32_t c = 0; c < kCells; ++c) count[c + 1] += count[c];
    p.camera_uv_cells = count;
    p.camera_uv_faces.resize(count[kCells]);
    for (uint32_t f = first.first; f < first.first + first.count; ++f)
        each_cell(p.camera_faces[f], [&](uint32_t cell) { p.camera_uv_faces[count[cell]++] = f; });
}

} // namespace sheaf

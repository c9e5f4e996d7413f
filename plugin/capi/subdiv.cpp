// The C ABI's subdivision surfaces: a polygon cage refined by OpenSubdiv (io/subdiv) and added
// to the scene as a triangle mesh.
#include "capi_internal.h"

#include "core/base/error.h"
#include "io/subdiv/subdivide.h"

using namespace sheaf::capi;

extern "C" {

SHEAF_API SheafError sheafSceneAddSubdivisionMesh(
    SheafScene scene, const float* positions, uint32_t vertex_count, const uint32_t* face_sizes,
    uint32_t face_count, const uint32_t* face_indices, const uint32_t* crease_edges,
    const float* crease_sharpness, uint32_t crease_count, const float* uvs,
    int scheme, int level, uint32_t* out_mesh_id) {
    return barrier([&] {
        SheafSceneT& s = *require(scene, "scene");
        if (vertex_count > 0) require(positions, "positions");
        if (face_count > 0) require(face_sizes, "face_sizes");
        if (crease_count > 0) {
            require(crease_edges, "crease_edges");
            require(crease_sharpness, "crease_sharpness");
        }
        sheaf::io::SubdivOptions options;
        switch (scheme) {
        case SHEAF_SUBDIV_CATMULL_CLARK:
            options.scheme = sheaf::io::SubdivScheme::CatmullClark;
            break;
        case SHEAF_SUBDIV_LOOP:
            options.scheme = sheaf::io::SubdivScheme::Loop;
            break;
        default:
            throw InvalidArgument("subdivision scheme " + std::to_string(scheme) +
                                  " is not one of SHEAF_SUBDIV_CATMULL_CLARK, SHEAF_SUBDIV_LOOP");
        }
        if (level < 0 || level > sheaf::io::kMaxSubdivLevel)
            throw InvalidArgument("subdivision level " + std::to_string(level) +
                                  " is out of range; expected 0.." +
                                  std::to_string(sheaf::io::kMaxSubdivLevel));
        options.level = level;

        sheaf::io::SubdivCage cage;
        cage.positions.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i)
            cage.positions[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        cage.face_sizes.assign(face_sizes, face_sizes + face_count);
        // The sizes say how many indices to read: a face size that cannot be right is reported
        // before face_indices is touched.
        size_t corners = 0;
        for (uint32_t f = 0; f < face_count; ++f) {
            if (face_sizes[f] < 3 || face_sizes[f] > 65535)
                throw sheaf::SceneError("subdivision cage: face " + std::to_string(f) + " has " +
                                        std::to_string(face_sizes[f]) +
                                        " vertices; expected 3..65535");
            corners += face_sizes[f];
        }
        if (corners > 0) require(face_indices, "face_indices");
        cage.face_indices.assign(face_indices, face_indices + corners);
        cage.crease_edges.assign(crease_edges, crease_edges + 2 * size_t(crease_count));
        cage.crease_sharpness.assign(crease_sharpness, crease_sharpness + crease_count);
        if (uvs) cage.uvs.assign(uvs, uvs + 2 * size_t(vertex_count));

        {
            std::lock_guard<std::mutex> lock(s.mutex); // sheafSceneSetLoadOption's
            options.limit = s.subdivision_limit && level >= 1;
            options.boundary = sheaf::io::SubdivBoundary(s.subdivision_boundary);
        }
        sheaf::Mesh mesh = sheaf::io::subdivide(cage, options);
        uint32_t id = 0;
        {
            std::lock_guard<std::mutex> lock(s.mutex);
            id = s.scene.add_mesh(std::move(mesh));
            s.prepared.reset();
        }
        if (out_mesh_id) *out_mesh_id = id;
    });
}

} // extern "C"

// A flat view of a prepared scene: raw pointers and counts, no containers, so the same
// per-element functions read it on the host (pointers into PreparedScene's vectors) and on the
// device (pointers into device memory, filled by the wavefront pipeline's upload). Trivially
// copyable: kernels take it by value.
#pragma once

#include "core/scene/photon_gather.h"
#include "core/scene/prepared_scene.h"

#include <cstdint>

namespace sheaf {

/// The arrays the exact tests of analytic shapes read (ShapeTables: polys, glyphs, profiles,
/// blobs, isosurfaces and their functions, julias) are its base, held once.
struct SceneView : ShapeTables {
    // Primitives: triangles [0, tri_count), then one per analytic object.
    const TriangleVerts* tris = nullptr;
    const TriangleNormals* normals = nullptr; // null when no mesh has vertex normals
    const TriangleUvs* uvs = nullptr;         // null when no mesh has texture coordinates
    uint32_t tri_count = 0;
    uint32_t analytic_count = 0;
    const uint32_t* prim_object = nullptr;
    const Sphere* prim_sphere = nullptr;
    const WorldBox* analytic_box = nullptr; // per analytic primitive (csg_box)
    const uint8_t* prim_flags = nullptr;
    uint32_t prim_flag_count = 0;

    const uint32_t* object_begin = nullptr; // object_count + 1 entries
    const Sphere* object_sphere = nullptr;
    const uint32_t* object_material = nullptr;
    uint32_t object_count = 0;

    const PlacedShape* shapes = nullptr;
    const uint32_t* shape_material = nullptr;
    const PreparedCsgNode* csg = nullptr;
    const uint32_t* csg_children = nullptr;
    const uint32_t* analytic_root = nullptr;

    const Material* materials = nullptr;
    const Pigment* pigments = nullptr;
    const PigmentEntry* pigment_entries = nullptr;
    const NormalPattern* normal_patterns = nullptr;
    const SlopeEntry* slope_entries = nullptr;
    const NormalMapEntry* normal_map_entries = nullptr;
    const MaterialSwitch* material_switches = nullptr;
    const Warp* warps = nullptr;
    const MaterialEntry* material_entries = nullptr;
    const Medium* media = nullptr;
    const uint32_t* medium_densities = nullptr;
    const DensityGrid* density_grids = nullptr;
    const float* density_voxels = nullptr;
    const uint32_t* media_containers = nullptr; // PreparedScene::media_containers
    uint32_t media_container_count = 0;
    BvhView media_solid_bvh; // PreparedScene::media_solid_bvh (empty: none)
    int32_t atmosphere = -1; // PreparedScene::atmosphere
    int32_t sky = -1;
    bool sky_untinted = false;
    Fogs fog;
    const Rainbow* rainbows = nullptr;
    uint32_t rainbow_count = 0;
    // The frame's photon map (core/frame/photon_pass.h); empty unless the frame shot photons.
    PhotonMapView photon_map;
    const Light* lights = nullptr;
    uint32_t light_count = 0;
    // Projection::Mesh (PreparedScene::camera_faces ...).
    const CameraFace* camera_faces = nullptr;
    uint32_t camera_face_count = 0;
    const CameraMeshRef* camera_meshes = nullptr;
    uint32_t camera_mesh_count = 0;
    const uint32_t* camera_uv_cells = nullptr; // empty unless distribution 3
    const uint32_t* camera_uv_faces = nullptr;
    Vec3 background;
    float working_gamma = 1; // the frame's value v is light v^working_gamma

    // Image textures: host only (OpenImageIO); a device view has none (the backend choice
    // keeps scenes with image textures on the CPU).
    const Texture* textures = nullptr;
    const TextureSampler* sampler = nullptr;

    SceneView() = default;
    /// A view of `p` (host pointers). Implicit, so host code may pass a PreparedScene where a
    /// view is expected; hot loops build one view and pass it on.
    SceneView(const PreparedScene& p) // NOLINT(google-explicit-constructor)
        : ShapeTables{p.polys.data(),
                      p.glyphs.data(),
                      p.glyph_segments.data(),
                      p.revolutions.data(),
                      p.revolution_segments.data(),
                      p.blobs.data(),
                      p.blob_elements.data(),
                      p.isosurfaces.data(),
                      {p.fn_programs.data(), p.fn_code.data(), p.fn_patterns.data(),
                       p.fn_pigments.data(), p.fn_pigment_entries.data(), p.warps.data()},
                      p.julias.data()},
          tris(p.tris.data()), normals(p.normals.empty() ? nullptr : p.normals.data()),
          uvs(p.uvs.empty() ? nullptr : p.uvs.data()), tri_count(uint32_t(p.tris.size())),
          analytic_count(uint32_t(p.analytic_root.size())), prim_object(p.prim_object.data()),
          prim_sphere(p.prim_sphere.data()), analytic_box(p.analytic_box.data()),
          prim_flags(p.prim_flags.data()), prim_flag_count(uint32_t(p.prim_flags.size())),
          object_begin(p.object_begin.data()), object_sphere(p.object_sphere.data()),
          object_material(p.object_material.data()), object_count(uint32_t(p.object_sphere.size())),
          shapes(p.shapes.data()), shape_material(p.shape_material.data()), csg(p.csg.data()),
          csg_children(p.csg_children.data()), analytic_root(p.analytic_root.data()),
          materials(p.materials.data()), pigments(p.pigments.data()),
          pigment_entries(p.pigment_entries.data()), normal_patterns(p.normal_patterns.data()),
          slope_entries(p.slope_entries.data()), normal_map_entries(p.normal_map_entries.data()),
          material_switches(p.material_switches.data()), warps(p.warps.data()),
          material_entries(p.material_entries.data()), media(p.media.data()),
          medium_densities(p.medium_densities.data()), density_grids(p.density_grids.data()),
          density_voxels(p.density_voxels.data()), media_containers(p.media_containers.data()),
          media_container_count(uint32_t(p.media_containers.size())),
          media_solid_bvh(p.media_solid_bvh.view()), atmosphere(p.atmosphere), sky(p.sky),
          sky_untinted(p.sky_untinted), fog(p.fog), rainbows(p.rainbows.data()),
          rainbow_count(uint32_t(p.rainbows.size())), lights(p.lights.data()),
          light_count(uint32_t(p.lights.size())), camera_faces(p.camera_faces.data()),
          camera_face_count(uint32_t(p.camera_faces.size())), camera_meshes(p.camera_meshes.data()),
          camera_mesh_count(uint32_t(p.camera_meshes.size())),
          camera_uv_cells(p.camera_uv_cells.empty() ? nullptr : p.camera_uv_cells.data()),
          camera_uv_faces(p.camera_uv_faces.data()), background(p.background),
          working_gamma(p.working_gamma), textures(p.textures.data()), sampler(p.sampler.get()) {}

    /// What poly, glyph, revolution, blob, isosurface and julia shapes read beside their
    /// Shape.
    SHEAF_HD const ShapeTables& shape_tables() const { return *this; }
    SHEAF_HD uint32_t prim_count() const { return tri_count + analytic_count; }
    /// Whether rays cross media: containers' or the atmosphere's (core/shading/media.h).
    SHEAF_HD bool has_media() const { return media_container_count > 0 || atmosphere >= 0; }
    SHEAF_HD bool is_triangle(uint32_t prim) const { return prim < tri_count; }
    /// Whether primitive `prim`'s object has ObjectFlag `flag` (or kPrimMayPass).
    SHEAF_HD bool prim_flag(uint32_t prim, uint8_t flag) const {
        return prim < prim_flag_count && (prim_flags[prim] & flag) != 0;
    }
};

} // namespace sheaf

// The committed scene: every primitive in world space, grouped by object, with the bounding
// spheres the ray hierarchy tests against. Built once by prepare_scene(); read by every stage.
#pragma once

#include "core/accel/bvh.h"
#include "core/geometry/sphere.h"
#include "core/geometry/world_box.h"
#include "core/scene/camera_faces.h"
#include "core/scene/scene.h"
#include "core/texture/texture.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sheaf {

struct TriangleVerts {
    Vec3 a, b, c;
};

struct TriangleUvs {
    float s[3], t[3]; // texture coordinates of the three vertices (zero when the mesh has none)
};

struct TriangleNormals {
    Vec3 na, nb, nc; // unit vertex normals; all zero when the mesh has none
};

/// A CSG node in flat arrays: a leaf names its placed shape in `first`; an operation owns
/// csg_children[first, first + count). `box` holds the node's solid (csg_box; infinite where
/// unbounded): a ray whose line misses it has no spans in the node, so csg_spans skips it, as
/// POV-Ray tests a CSG member's bounding box before the member.
struct PreparedCsgNode {
    CsgOp op = CsgOp::Leaf;
    bool inverse = false;
    uint32_t first = 0, count = 0;
    WorldBox box;
};

/// A prim_flags bit beside the ObjectFlag ones: a material of the primitive may let light
/// through somewhere (filter, transmit), so shadow rays evaluate it where they cross it.
constexpr uint8_t kPrimMayPass = 0x80;
/// A prim_flags bit: the primitive's surface is not closed (clipped_by opens it), so a ray
/// that meets its far side need not have been inside it (way_in_solid,
/// core/shading/frame_kernels.h).
constexpr uint8_t kPrimOpen = 0x40;

/// Culling units already computed for a prepared scene, by cull.cluster (core/rsh/cull_units.h).
struct CullUnitsCache;
std::shared_ptr<CullUnitsCache> new_cull_units_cache();
/// The BVH of a prepared scene, built on first use (core/accel/bvh.h).
struct BvhCache;
std::shared_ptr<BvhCache> new_bvh_cache();
/// The strips of a prepared scene, built on first use (core/accel/strips.h).
struct StripsCache;
std::shared_ptr<StripsCache> new_strips_cache();

struct PreparedScene {
    // Primitives (triangles for now), object by object: object o owns
    // [object_begin[o], object_begin[o + 1]).
    // Primitive ids: triangles first, [0, tris.size()); then analytic objects, one primitive
    // each (a shape or a CSG tree), [tris.size(), prim_count()).
    std::vector<TriangleVerts> tris;
    std::vector<TriangleNormals> normals; // empty when no mesh has vertex normals
    std::vector<TriangleUvs> uvs;         // empty when no mesh has texture coordinates
    std::vector<uint32_t> prim_object;
    std::vector<Sphere> prim_sphere;

    std::vector<uint32_t> object_begin; // objects + 1 entries
    std::vector<Sphere> object_sphere;  // minimal enclosing sphere (Welzl/Gaertner)
    std::vector<uint32_t> object_material;
    std::vector<std::string> object_name;
    std::vector<PhotonObject> object_photons; // what each object does with photons

    std::vector<PlacedShape> shapes;          // every leaf of every analytic object
    std::vector<PolyCoeffs> polys;            // of the poly leaves, indexed by Shape::index
    std::vector<GlyphRef> glyphs;             // of the glyph leaves, indexed by Shape::index
    std::vector<GlyphSegment> glyph_segments; // the glyphs' outlines
    std::vector<RevolutionRef> revolutions;   // of the revolution leaves, by Shape::index
    std::vector<RevolutionSegment> revolution_segments; // their profiles
    std::vector<BlobRef> blobs;                         // of the blob leaves, by Shape::index
    std::vector<BlobElement> blob_elements;             // their components
    std::vector<IsoRef> isosurfaces;                    // of the isosurface leaves
    std::vector<JuliaFractal> julias;                   // of the julia leaves, by Shape::index
    std::vector<uint32_t> shape_material;               // per placed shape
    std::vector<PreparedCsgNode> csg;
    std::vector<uint32_t> csg_children;
    std::vector<uint32_t> analytic_root; // per analytic primitive: its root node in csg
    std::vector<WorldBox> analytic_box;  // per analytic primitive: its box (csg_box), which
                                         // the BVH bounds it by

    std::vector<uint8_t> prim_flags; // ObjectFlag bits of each primitive's object, and
                                     // kPrimMayPass

    std::vector<Material> materials;
    std::vector<Pigment> pigments;
    std::vector<PigmentEntry> pigment_entries;
    std::vector<NormalPattern> normal_patterns;
    std::vector<SlopeEntry> slope_entries;
    std::vector<NormalMapEntry> normal_map_entries;
    std::vector<MaterialSwitch> material_switches;
    std::vector<Warp> warps;
    std::vector<MaterialEntry> material_entries;
    std::vector<Medium> media;
    std::vector<uint32_t> medium_densities;
    std::vector<DensityGrid> density_grids;
    std::vector<float> density_voxels;
    // The analytic primitives some of whose shapes hold media (0-based among the analytic
    // ones; core/shading/media.h), and the solid ones (kSolid) that media leave out: all of
    // them with an atmosphere or a fog that fades lights (fog_transmittance), else those
    // whose bounds meet a container's.
    std::vector<uint32_t> media_containers, media_solids;
    // A BVH over the media solids (their primitive ids), which the media walk.
    Bvh media_solid_bvh;
    int32_t atmosphere = -1;            // Scene::atmosphere
    std::vector<FnProgram> fn_programs; // user functions (Scene::fn_programs ...)
    std::vector<FnInstr> fn_code;
    std::vector<Pattern> fn_patterns;
    std::vector<FnPigment> fn_pigments;
    std::vector<PigmentEntry> fn_pigment_entries;
    int32_t sky = -1;
    bool sky_untinted = false; // Scene::sky_untinted
    Fogs fog;
    std::vector<Rainbow> rainbows;
    PhotonSettings photons; // Scene::photons
    std::vector<Texture> textures;
    std::shared_ptr<const TextureSampler> sampler; // set by the IO layer when there are textures
    // Set by prepare_scene: the culling units of this geometry, computed once per
    // cull.cluster value and shared by its frames (and copies).
    std::shared_ptr<CullUnitsCache> cull_units_cache;
    // Set by prepare_scene: the BVH of this geometry (accel=bvh), built once and shared alike.
    std::shared_ptr<BvhCache> bvh_cache;
    // Set by prepare_scene: the strips of this geometry (accel=strips), likewise.
    std::shared_ptr<StripsCache> strips_cache;
    std::vector<Light> lights;
    Camera camera;
    // Projection::Mesh: the camera meshes' faces, the meshes, and the distribution-3 uv grid
    // (kCameraUvGrid^2 + 1 offsets into camera_uv_faces); core/scene/camera_faces.h.
    std::vector<CameraFace> camera_faces;
    std::vector<CameraMeshRef> camera_meshes;
    std::vector<uint32_t> camera_uv_cells, camera_uv_faces;
    Vec3 background;
    float working_gamma = 1; // Scene::working_gamma
    std::map<std::string, std::string> settings;

    size_t triangle_count() const { return tris.size(); }
    size_t prim_count() const { return tris.size() + analytic_root.size(); }
    bool is_triangle(uint32_t prim) const { return prim < tris.size(); }
    size_t object_count() const { return object_sphere.size(); }
    /// Whether primitive `prim`'s object has ObjectFlag `flag`.
    bool prim_flag(uint32_t prim, uint8_t flag) const {
        return prim < prim_flags.size() && (prim_flags[prim] & flag) != 0;
    }
    /// Whether rays cross media: containers' or the atmosphere's.
    bool has_media() const { return !media_containers.empty() || atmosphere >= 0; }
    /// Whether frames shoot photons: photons are on and some object is their target.
    bool has_photons() const {
        if (!photons.enabled()) return false;
        for (const PhotonObject& o : object_photons)
            if (o.target > 0) return true;
        return false;
    }
    /// Whether rays that meet surfaces bring light of their own from the way: fog, media,
    /// rainbows (summed in ray order, so that every accel gives the same sums).
    bool lights_the_way() const { return fog.any() || has_media() || !rainbows.empty(); }
    /// Whether frames send media shadow rays (core/shading/media_light.h): a medium of a
    /// container or of the atmosphere scatters and a light that casts shadows interacts with
    /// media.
    bool media_scatter_light() const {
        bool scatters = false, lit = false;
        for (const Medium& md : media) scatters = scatters || md.scatters();
        for (const Light& l : lights) lit = lit || (!l.shadowless && l.media_interaction);
        return scatters && lit && has_media();
    }
};

/// Validates and flattens. Throws SceneError.
PreparedScene prepare_scene(const Scene& scene);

/// Copies what materials, pigments, patterns, media and functions read (their tables, the
/// image textures' list, the working gamma) from `scene`, as prepare_scene does: a
/// PreparedScene with only these evaluates pigments (the POV reader's pigment functions at
/// parse time). Not validated: prepare_scene validates the whole scene.
void copy_texture_tables(const Scene& scene, PreparedScene& p);

/// Whether material m of `scene` may let light through somewhere (filter or transmit), or a
/// material its texture maps lead to.
bool material_may_pass(const Scene& scene, uint32_t m);

} // namespace sheaf

// The scene as hosts describe it: meshes, materials, lights, a camera, and objects that place
// a mesh with a material and a transform. Objects keep their identity through the pipeline,
// because whole objects are culled by their bounding spheres.
#pragma once

#include "core/geometry/shape.h"
#include "core/geometry/world_box.h"
#include "core/math/affine.h"
#include "core/scene/pattern.h"
#include "core/scene/photon_settings.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sheaf {

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;     // empty, or one per position (smooth shading)
    std::vector<uint32_t> indices; // three per triangle, into positions
    std::vector<float> uvs;        // empty, or two per position (texture coordinates)
    size_t triangle_count() const { return indices.size() / 3; }
};

/// How far from the origin a mesh's vertex (in its object's place), a light and the camera may
/// lie: the squares of their differences stay far within a float's range, so no direction or
/// distance between them overflows to infinity and then NaN (found by the C ABI fuzzer: a point
/// light at 1e30 made every shadow ray's direction NaN).
constexpr float kMaxCoordinate = 1e12f;
/// Whether each coordinate of `p` lies within ±kMaxCoordinate (false for NaN).
inline bool within_reach(Vec3 p) {
    return std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
           std::fabs(p.z) <= kMaxCoordinate;
}

/// Throws SceneError "WHAT: ..." naming the first vertex, normal, texture coordinate or index
/// of `mesh` that is wrong, or that it has no faces: Scene::validate's check of each mesh, and
/// the readers' of a mesh from a file or a cage, where `what` names the file or the element.
void validate_mesh(const Mesh& mesh, const std::string& what);

struct Material {
    Vec3 color{0.8f, 0.8f, 0.8f};
    Vec3 emission{0.0f, 0.0f, 0.0f}; // radiance the surface gives off by itself
    float ambient = 0.1f;
    float diffuse = 0.7f;
    float specular = 0.0f; // Phong highlight strength
    float phong_exponent = 40.0f;
    float mirror = 0.0f;       // mirror reflection weight
    float transmission = 0.0f; // refracted share, split with reflection by Fresnel
    float ior = 1.5f;
    int32_t texture = -1; // >= 0: an image texture (Scene::textures) multiplies `color`

    // Procedural textures and POV-Ray's finish (the defaults keep the plain model above).
    int32_t pigment = -1; // >= 0: Scene::pigments gives colour, filter and transmit at each
                          // point, replacing color, texture and transmission (as filter)
    int32_t normal = -1;  // >= 0: Scene::normal_patterns tilts the shading normal
    int32_t select = -1;  // >= 0: Scene::material_switches picks the material at each point
    // >= 0: the material the surface shows where a ray meets it from inside (POV-Ray's
    // interior_texture): that whole material, ior and fade included, so it should share this
    // one's; one without an `inside` of its own. Shadow rays see this one.
    int32_t inside = -1;
    float brilliance = 1.0f;                    // the diffuse term is cos^brilliance
    float blinn = 0.0f, blinn_exponent = 20.0f; // half-vector highlight (POV-Ray's specular)
    float metallic = 0.0f;                      // highlights tinted by the surface colour
    Vec3 mirror_color{1.0f, 1.0f, 1.0f};        // mirror reflection is mirror * mirror_color
    float mirror_min = -1.0f;     // >= 0: reflection varies from mirror_min (facing) to mirror
    float mirror_falloff = 1.0f;  //   (grazing) as (1 - cos)^falloff,
    bool mirror_fresnel = false;  //   or by Fresnel's law with `ior`
    bool mirror_metallic = false; // reflection tinted by the surface colour
    bool conserve_energy = false; // diffuse and transmission keep what reflection leaves,
    bool conserve_diffuse = true; //   the diffuse only where this is set (POV-Ray: transmission)
    bool fresnel_split = true;    // transmission splits into reflection and refraction by Fresnel
                                  // (POV-Ray: reflection only from the finish)
    Vec3 fade_color{0.0f, 0.0f, 0.0f};             // light inside fades to this colour:
    float fade_distance = 0.0f, fade_power = 0.0f; //   1 / (1 + (d / fade_distance)^fade_power)
    uint32_t media_first = 0, media_count = 0;     // the media inside: Scene::media
    // POV-Ray's light groups: 0, lit by the lights in no group; g (1 .. kMaxLightGroup), lit
    // by group g's lights only, and with kGlobalLights set also by the lights in no group.
    uint16_t light_group = 0;
    // POV-Ray's fake caustics (interior { caustics c }, here 45 c): light a shadow ray carries
    // across this surface is scaled by 1 + |n.d|^caustics, n the shading normal and d the
    // ray's direction, so curved or bumpy glass casts bright spots; 0: none.
    float caustics = 0.0f;
    // Iridescence (POV-Ray's irid): light from each light and from the mirror is scaled per
    // channel by 1 + irid cos(2 pi thickness (|n.l| + |n.v|) / wavelength), the thickness
    // varied by `irid_turbulence` times noise (core/shading/shade.h).
    float irid = 0, irid_thickness = 0, irid_turbulence = 0;
    Vec3 irid_wavelength{0.25f, 0.18f, 0.14f};
};

/// How a medium scatters light towards the viewer, POV-Ray's `scattering { type, … }`: the
/// phase function of the angle between the way to the light and the way the ray goes.
enum class ScatterType : uint8_t {
    Isotropic = 1,        // the same every way
    MieHazy = 2,          // small particles: 0.577 (1 + 9 ((1 + cos) / 2)^8)
    MieMurky = 3,         // larger particles: 0.496 (1 + 50 ((1 + cos) / 2)^32)
    Rayleigh = 4,         // very small particles: 0.799 (1 + cos^2)
    HenyeyGreenstein = 5, // (1 - g^2) / (1 + g^2 - 2 g cos)^1.5, g the eccentricity
};

/// A participating medium inside an object (POV-Ray's interior media): the light it gives off
/// (emission) and takes away (absorption) per unit length, each times the product of its
/// densities' colours at the point (Scene::medium_densities: pigment indices), integrated
/// along the part of a ray inside the object at `samples` evenly spaced points
/// (core/shading/media.h).
struct Medium {
    Vec3 emission{0.0f, 0.0f, 0.0f}, absorption{0.0f, 0.0f, 0.0f};
    /// Light scattered towards the ray per unit length; it also takes `extinction` times
    /// itself away from the light passing through (POV-Ray's extinction, 1 by default).
    Vec3 scattering{0.0f, 0.0f, 0.0f};
    ScatterType scatter_type = ScatterType::Isotropic;
    float eccentricity = 0.0f; // HenyeyGreenstein's g, in (-1, 1)
    float extinction = 1.0f;
    uint32_t density_first = 0, density_count = 0;
    uint32_t samples = 32;      // steps along each part of a ray inside
    uint32_t light_samples = 8; // steps along a shadow ray's part inside (with densities)

    SHEAF_HD bool scatters() const {
        return scattering.x > 0 || scattering.y > 0 || scattering.z > 0;
    }
    /// What the medium takes away per unit length at density 1: absorption and extinction.
    SHEAF_HD Vec3 attenuation() const { return absorption + scattering * extinction; }
};

/// What an object takes part in: bits of Object::flags and ShapeObject::flags.
enum ObjectFlag : uint8_t {
    kNoShadow = 1,         // casts no shadow (shadow and ambient-occlusion rays pass)
    kNoReflection = 2,     // not seen in reflections
    kNoImage = 4,          // not seen by the camera (still in shadows and reflections)
    kSolid = 8,            // media of objects around it do not fill it (POV-Ray's objects without
                           // `hollow`; analytic objects only)
    kPassPhotons = 16,     // photons pass it unchanged (POV-Ray's pass_through)
    kNoPhotonCollect = 32, // keeps no photons and gathers none (POV-Ray's collect off)
};

/// How a texture finds its (s, t) coordinates at a surface point.
enum class TextureMapping {
    Uv,          // the mesh's texture coordinates (analytic shapes: planar)
    Planar,      // (x, y) of the point in texture space, repeated every unit
    Spherical,   // longitude and latitude around the texture-space origin
    Cylindrical, // angle around texture-space y, and y
    Torus,       // angle around texture-space y, and angle around the unit circle in the xz plane
};

/// An image texture. The image is read by the IO layer (OpenImageIO); the core only asks for
/// colours at (s, t).
struct Texture {
    std::string path;
    TextureMapping mapping = TextureMapping::Uv;
    Affine transform; // world -> texture space, for the projections
    // "", "srgb", "linear" or "data"; empty: from the file (8-bit sRGB, float linear); data:
    // the values as stored, not in the working gamma either (a bump map's heights)
    std::string colorspace;
    std::string origin; // where the scene asked for it ("scene.pov:12:3"), for messages
    bool once = false;  // seen once: nothing outside s, t in [0, 1] (a clear pigment there, a
                        // bump map's normal unchanged), not repeated
};

enum class LightType { Point, Spot, Parallel };

/// A light. Position and colour come first so that `Light{position, color}` is a point light.
struct Light {
    Vec3 position;
    Vec3 color{1, 1, 1};
    LightType type = LightType::Point;
    Vec3 direction{0, -1, 0};    // spot: the cone's axis; parallel: the way the light travels
    float spot_radius = 30.0f;   // spot: degrees from the axis at full intensity
    float spot_falloff = 45.0f;  // spot: degrees from the axis where it reaches zero
    float spot_tightness = 0.0f; // spot: intensity times cos(angle)^tightness
    float fade_distance = 0.0f;  // > 0: intensity 2 / (1 + (d / fade_distance)^fade_power)
    float fade_power = 0.0f;
    bool shadowless = false;        // lights without shadow rays
    bool highlights = true;         // false: diffuse light only (POV-Ray's shadowless lights)
    bool media_interaction = true;  // false: media do not scatter this light
    bool media_attenuation = false; // true: the atmosphere's media fade its light on its way
    uint16_t group = 0; // > 0: lights only materials of that light group (Material::light_group)
    // Photons it sends reflect and refract where the object's switches allow
    // (photon_switch_on); photons are off unless the scene's PhotonSettings are on.
    PhotonSwitch photon_reflection = PhotonSwitch::Unset, photon_refraction = PhotonSwitch::Unset;
    float photon_weight = 1.0f; // its photons carry color x this (an area light's one shooter)
    // One sample of an area light, as POV-Ray lights without area_illumination: the spot cone
    // and the fade are taken from the area light's centre, the rest (direction, shadow) from
    // this sample's position.
    bool centred = false;
    Vec3 centre;
};

constexpr uint16_t kMaxLightGroup = 0x7fff;
constexpr uint16_t kGlobalLights = 0x8000; // Material::light_group: also the ungrouped lights

/// Whether light l lights a surface of light group `group` (Material::light_group).
SHEAF_HD_INLINE bool light_reaches_group(const Light& l, uint16_t group) {
    const uint16_t g = uint16_t(group & kMaxLightGroup);
    return l.group == 0 ? g == 0 || (group & kGlobalLights) != 0 : l.group == g;
}

/// Perspective and orthographic views are rasterised. The others are POV-Ray's camera types
/// whose pixels do not map to a plane: their primary rays are traced (core/raster/camera.h).
enum class Projection {
    Perspective,
    Orthographic,
    Fisheye,        // angle: the field of view across the image circle
    UltraWideAngle, // angle: horizontal; vertical angle * up / right
    Omnimax,        // a 180-degree fisheye squeezed for a dome
    Panoramic,      // 180 degrees across, tangent up and down
    Cylinder1,      // vertical cylinder, fixed eye; angle: horizontal
    Cylinder2,      // horizontal cylinder, fixed eye; angle: vertical
    Cylinder3,      // vertical cylinder, eye moving along it
    Cylinder4,      // horizontal cylinder, eye moving along it
    Spherical,      // angle: horizontal, v_angle: vertical
    Mesh,           // rays leave the faces of Scene::camera_meshes (POV-Ray's mesh_camera)
};
/// The projections a camera's own parameters define (every one but Mesh, which needs
/// Scene::camera_meshes): what hosts choose from by number.
constexpr int kProjectionCount = 11;

/// The projections whose primary visibility is traced rather than rasterised.
SHEAF_HD_INLINE bool traced_projection(Projection p) {
    return p != Projection::Perspective && p != Projection::Orthographic;
}

/// The traced projections' limits, which Scene::validate and every reader enforce: an angle
/// in (0, 3600] degrees, and lengths of right, up and direction in (0, 1e6).
inline bool camera_angle_ok(double degrees) {
    return degrees > 0 && degrees <= 3600;
}
inline bool camera_length_ok(double length) {
    return length > 0 && length < 1e6;
}

struct Camera {
    Vec3 position{0, 0, 5};
    Vec3 look_at{0, 0, 0};
    Vec3 up{0, 1, 0};
    float fov_y_degrees = 45.0f; // perspective: vertical field of view
    Projection projection = Projection::Perspective;
    float ortho_height = 2.0f;      // orthographic: height of the view in scene units
    float shift_x = 0, shift_y = 0; // lens shift in image widths / heights (off-axis views)
    // > 0: the view's width over its height whatever the image's shape (POV-Ray's
    // |right| / |up|: an image of another shape shows it stretched, as POV-Ray does); 0: the
    // image's own width over height.
    float aspect = 0;
    // The image mirrored left to right (POV-Ray's right-handed cameras: right -x).
    bool mirror = false;
    // Traced projections only. The angles in degrees (POV-Ray's camera `angle`: 90 by default;
    // spherical: 360 across and 180 up and down), and POV-Ray's lengths of right, up and
    // direction, which these projections read as the shape of the view.
    float angle_degrees = 90.0f;
    float v_angle_degrees = 180.0f;
    float right_length = 1.0f, up_length = 1.0f, direction_length = 1.0f;
    // >= 0: Scene::normal_patterns tilts every primary ray's direction as it tilts a surface
    // normal, the pattern evaluated at (u, v, 0), u and v across and up the image from -1/2
    // to 1/2 (POV-Ray's camera normal). Primary visibility is then traced.
    int32_t normal = -1;
    // > 0 (perspective and orthographic cameras): depth of field (POV-Ray's focal blur). Each
    // of a pixel's anti-aliasing samples leaves from its own point of a lens of this radius
    // across the view, through the point its pixel sees on the plane `focal_distance` ahead,
    // which stays sharp. Primary visibility is then traced.
    float lens_radius = 0;
    float focal_distance = 0;
    // Projection::Mesh (POV-Ray's mesh_camera). Each pixel's primary rays leave faces of
    // Scene::camera_meshes along the face's normal, normalize(cross(b - a, c - a)) in the
    // mesh's space, mapped to the world by the mesh's transform (origins as points, normals
    // by the inverse transpose). mesh_distribution picks the faces:
    // Pixel rows are counted as POV-Ray 3.7 counts them for this camera, one row up: pixel
    // (x, y) is pixel x + (y - 1) * width (row 0 its own row).
    //   0: pixel i is face i of mesh k for its anti-aliasing sample k of s: k
    //      modulo mesh_rays when s >= mesh_rays, else k * mesh_rays / s (an even share of the
    //      meshes): several meshes are several rays averaged in a pixel;
    //   1: pixel i is face i of the meshes' faces counted one mesh after another;
    //   2: the meshes side by side across the image, each taking a band of columns; pixel
    //      (x, y) is face y * (width / meshes) + x of its band's mesh (POV-Ray's indexing);
    //   3: the first mesh's uv coordinates: (u, v) = (x / width, 1 - y / height) at the
    //      pixel's top left corner (x, y) (its samples spread around it) finds the first face
    //      holding it, the origin the point there (texture baking).
    // A pixel or sample without a face is black. The origin moves mesh_offset along the
    // normal (POV-Ray's location z); mesh_reverse shoots against it (direction z < 0);
    // mesh_smooth (distribution 3) interpolates the vertex normals.
    uint32_t mesh_rays = 1;
    uint8_t mesh_distribution = 0;
    bool mesh_smooth = false;
    bool mesh_reverse = false;
    float mesh_offset = 0;
};

/// The most rays a mesh camera may name per pixel (a pixel's anti-aliasing samples, at most
/// 8 x 8, take them: see Camera::mesh_distribution).
constexpr uint32_t kMaxMeshCameraRays = 65536;

/// A mesh of a mesh camera (Camera::mesh_distribution): its faces in its own space and the
/// transform to the world.
struct CameraMesh {
    Mesh mesh;
    Affine transform;
};

struct Object {
    std::string name;
    uint32_t mesh = 0;
    uint32_t material = 0;
    Affine transform;
    uint8_t flags = 0; // ObjectFlag bits
    PhotonObject photons;
};

/// Clip: the surface of the first child where it lies inside all the others (POV-Ray's
/// clipped_by): an open surface, the clipping objects' own surfaces are not seen.
enum class CsgOp : uint8_t { Leaf, Union, Merge, Intersection, Difference, Clip };

/// A node of an analytic object: a shape (leaf) or a CSG operation over other nodes of the
/// same object. `inverse` swaps inside and outside (POV-Ray's `inverse`).
struct CsgNode {
    CsgOp op = CsgOp::Leaf;
    Shape shape;                                         // leaf
    std::shared_ptr<const PolyCoeffs> poly;              // leaf of kind Poly: its coefficients
    std::shared_ptr<const GlyphOutline> glyph;           // leaf of kind Glyph: its outline
    std::shared_ptr<const RevolutionProfile> revolution; // leaf of kind Revolution: its profile
    std::shared_ptr<const BlobModel> blob;               // leaf of kind Blob: its components
    std::shared_ptr<const IsoRef> iso; // leaf of kind Isosurface (bound computed by prepare)
    std::shared_ptr<const JuliaFractal> julia; // leaf of kind Julia: its parameters
    Affine transform;                          // leaf: shape space -> object space
    uint32_t material = 0;                     // leaf
    bool inverse = false;
    std::vector<uint32_t> children; // operation: indices into the object's nodes
};

/// The deepest nesting of CSG operations over a shape that a scene may have: both backends
/// evaluate CSG recursively (the CUDA one with a stack reserved for every resident thread).
constexpr int kMaxCsgNesting = 64;

/// An object made of analytic shapes: one shape, or a CSG tree whose root is `root`.
struct ShapeObject {
    std::string name;
    std::vector<CsgNode> nodes;
    uint32_t root = 0;
    Affine transform;  // object space -> world
    uint8_t flags = 0; // ObjectFlag bits
    PhotonObject photons;
    /// A bound the scene gives (POV-Ray's bounded_by), in world space: where it is smaller
    /// than the one its shapes give (none for a polynomial surface), rays that miss it skip
    /// the object. Infinite: none; empty: nothing shows.
    WorldBox bound;
};

/// The deepest nesting of CSG operations in `o` (a lone shape: 0), against kMaxCsgNesting.
/// Its nodes must be in the core's order: children after their parents.
int csg_nesting(const ShapeObject& o);

class Scene {
  public:
    /// Adds an object of one analytic shape.
    uint32_t add_shape(std::string name, const Shape& shape, uint32_t material,
                       const Affine& transform = {});
    uint32_t add_shape_object(ShapeObject o);
    uint32_t add_mesh(Mesh mesh);
    uint32_t add_material(const Material& m);
    uint32_t add_object(Object o);
    uint32_t add_light(const Light& l);
    /// Adds a mesh and one object that uses it (the common case of a unique mesh).
    uint32_t add_mesh_object(std::string name, Mesh mesh, uint32_t material, const Affine& t = {});

    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Object> objects;
    std::vector<ShapeObject> shape_objects; // rendered after the mesh objects
    std::vector<Light> lights;
    std::vector<CameraMesh> camera_meshes; // Projection::Mesh: the faces rays leave
    // Procedural textures (core/scene/pattern.h), indexed by materials and each other.
    std::vector<Pigment> pigments;
    std::vector<PigmentEntry> pigment_entries;
    std::vector<NormalPattern> normal_patterns;
    std::vector<SlopeEntry> slope_entries;          // the normal patterns' slope maps
    std::vector<NormalMapEntry> normal_map_entries; // and their normal maps
    std::vector<MaterialSwitch> material_switches;
    std::vector<MaterialEntry> material_entries;
    std::vector<Warp> warps;                // the patterns' warps (Pattern::warp_first)
    std::vector<Medium> media;              // indexed by Material::media_first
    std::vector<uint32_t> medium_densities; // pigments, indexed by Medium::density_first
    std::vector<DensityGrid> density_grids; // the density_file patterns' grids (Pattern::grid)
    std::vector<float> density_voxels;      // and their values
    // User functions (core/scene/function.h), run by function patterns and isosurfaces:
    // programs, their code, and the patterns and pigments their instructions read.
    std::vector<FnProgram> fn_programs;
    std::vector<FnInstr> fn_code;
    std::vector<Pattern> fn_patterns;
    std::vector<FnPigment> fn_pigments;           // the pigments they read
    std::vector<PigmentEntry> fn_pigment_entries; // and those pigments' colours
    Camera camera;
    Vec3 background{0, 0, 0};
    int32_t sky = -1; // >= 0: a pigment over directions seen where rays leave the scene
    /// How the sky's layers (a layered pigment, bottom first) weigh what lies below them:
    /// POV-Ray 3.7 tints it by each layer's transmitted colour; before 3.7 it weighed it by
    /// the layers' filter and transmit alone, untinted (core/shading/surface_texture.h).
    bool sky_untinted = false;
    Fogs fog;
    std::vector<Rainbow> rainbows; // core/shading/rainbow.h
    /// >= 0: the material whose media fill the space outside solid objects (POV-Ray's
    /// atmospheric `media`; only its media are read). Rays that leave the scene cross
    /// kAtmosphereFar units of it (core/shading/media.h).
    int32_t atmosphere = -1;
    /// Photon mapping (caustics): on when photons.spacing > 0 (core/frame/photon_pass.h).
    PhotonSettings photons;
    /// The gamma of the space colours are given and computed in (POV-Ray's assumed_gamma): the
    /// frame's value v is light v^working_gamma, and image textures are read into that space.
    /// 1: linear light (the default; every format but legacy POV-Ray scenes).
    float working_gamma = 1.0f;
    /// Settings the scene itself asks for (e.g. trace.depth); a host's explicit settings win.
    std::map<std::string, std::string> settings;

    size_t triangle_count() const;
    /// Throws SceneError naming the offending mesh, object or value.
    void validate() const;

  private:
    void validate_patterns() const;
    void validate_functions() const;
    void validate_photons() const;
};

} // namespace sheaf

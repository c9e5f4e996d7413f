// The reader's intermediate scene, in POV-Ray's own (left-handed) coordinates: objects with
// their shapes, meshes and CSG children, textures (pigments, normals, finishes, maps and layers,
// each with its own transform), lights and the camera. builder.cpp turns it into a sheaf::Scene.
#pragma once

#include "core/geometry/shape.h"
#include "core/math/affine.h"
#include "core/scene/scene.h"
#include "io/pov/function.h"
#include "io/pov/lexer.h"

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sheaf::io::pov {

/// A POV-Ray colour: red, green, blue, filter, transmit.
using Color5 = std::array<double, 5>;

struct PovFinish {
    std::array<double, 3> ambient{0.1, 0.1, 0.1};
    std::array<double, 3> emission{0, 0, 0};
    double diffuse = 0.6, brilliance = 1;
    double specular = 0, roughness = 0.05;
    double phong = 0, phong_size = 40;
    double metallic = 0;
    // reflection { [min,] max [fresnel] [falloff F] [metallic] } or reflection COLOUR
    std::array<double, 3> reflection{0, 0, 0};     // the maximum (or only) reflection
    std::array<double, 3> reflection_min{0, 0, 0}; // with `variable`: at facing angles
    bool reflection_variable = false;              // a min and a max were given
    bool fresnel = false;
    double reflection_falloff = 1;
    bool reflection_metallic = false;
    bool conserve_energy = false;
    double irid = 0, irid_thickness = 0,
           irid_turbulence = 0; // irid { amount thickness turbulence }
    bool operator==(const PovFinish&) const = default;
};

/// A density_file's voxels (io/pov/density_file.cpp): nx x ny x nz values in [0, 1], x
/// fastest, and how the pattern reads between them (`interpolate`: 0 none, 1 trilinear,
/// 2 tricubic).
struct PovDensity {
    uint32_t nx = 0, ny = 0, nz = 0;
    std::shared_ptr<const std::vector<float>> values; // shared by the patterns of one file
    int interpolation = 0;
};

/// An image for image_map (and the image pattern): the file and how it is wrapped.
struct PovImage {
    std::string path; // resolved against the scene's folder and the include paths
    int map_type = 0; // 0 planar, 1 spherical, 2 cylindrical, 5 torus
    double filter_all = 0, transmit_all = 0;
    bool once = false; // bump_map once: no change outside the image
    Token where;       // where the scene asked for it, for errors
};

/// A pattern as parsed: its kind and modifiers. It lives in the space of the pigment, normal or
/// texture that holds it.
struct PovPigment;

struct PovPattern {
    PatternKind kind = PatternKind::Gradient;
    Wave wave = Wave::Ramp;
    bool wave_given = false;
    bool has_turbulence = false;
    Vec3 turbulence{0, 0, 0};
    int octaves = 6;
    double omega = 0.5, lambda = 2;
    int noise_generator = 0; // 1..3; 0: the scene's (PovModel::scene_noise_generator)
    double frequency = 1, phase = 0, wave_exponent = 1;
    Vec3 vector{0, 1, 0}; // gradient
    double param[4] = {0, 0, 0, 0};
    std::shared_ptr<const PovImage> image;
    bool bump_map = false; // kind Image in a normal: its image's heights tilt the normal
    std::shared_ptr<const PovFunction> function; // kind Function
    FractalParams fractal;                       // kinds Mandel and Julia
    // Slope: `vector` is its direction (or point, point_at) in POV-Ray's world, param[0..3]
    // the slope's and the altitude's low and high ends.
    Vec3 slope_altitude{0, 0, 0};
    bool slope_point_at = false;
    // Warps in the order declared, each with the pattern's transforms declared before it
    // (`at`: the pattern's local transform then; Warp::to_inner is set when lowered).
    struct DeclaredWarp {
        Warp warp;
        Affine at;
    };
    std::vector<DeclaredWarp> warps;
    std::shared_ptr<const PovPigment> pigment; // kind PigmentPattern
    std::shared_ptr<const PovDensity> density; // kind DensityFile
};

/// An entry of a colour map, pigment map or list: a colour, or a pigment.
struct PovMapEntry {
    double value = 0;
    Color5 color{0, 0, 0, 0, 0};
    std::shared_ptr<const PovPigment> pigment; // null: `color`
};

/// A pigment: a solid colour, or a pattern with its entries. `local` maps the pigment's space
/// to the space of what holds it (transforms inside the pigment and after it).
struct PovPigment {
    bool patterned = false;
    bool average = false; // POV-Ray's average: the mean of the entries
    Color5 color{0, 0, 0, 0, 0};
    PovPattern pattern;
    std::vector<PovMapEntry> entries;
    Affine local;
    // uv_mapping: evaluated at the surface's uv coordinates (u, v, 0), placed by `local` only
    // (what holds the pigment does not move it, as in POV-Ray).
    bool uv = false;
};

/// A normal: a pattern and its bump size.
struct PovNormal {
    PovPattern pattern;
    double amount = 0.5;
    /// Bumps, dents, wrinkles, ripples and waves: POV-Ray's own normal functions; every other
    /// pattern tilts by its slope, sampled `accuracy` around the point.
    NormalForm form = NormalForm::Slope;
    double accuracy = 0.02;
    bool no_bump_scale = false;
    /// Bumps, dents, ripples, waves, wrinkles, quilted and facets: POV-Ray draws them with
    /// their own normal functions, which ignore a slope map.
    bool own_normal = false;
    /// slope_map entries {value, height, slope}, sorted by value: the pattern's value becomes
    /// a height along cubic curves, and that height's slope tilts the normal.
    std::vector<std::array<double, 3>> slope_map;
    /// A normal map: {value, normal} entries (null: the surface's own normal). Continuous
    /// patterns blend the two entries around their value (sorted by value); list patterns
    /// index them; with `average` the values are weights.
    std::vector<std::pair<double, std::shared_ptr<const PovNormal>>> map;
    bool average = false;
    Affine local;
};

struct PovTexture;
using PovTextureRef = std::shared_ptr<const PovTexture>;

/// A texture: pigment, normal and finish, or a choice between textures by pattern (texture_map,
/// checker texture ...). Layered textures are a top layer with the layers below it.
struct PovTexture {
    std::shared_ptr<const PovPigment> pigment; // null: black
    std::shared_ptr<const PovNormal> normal;   // null: none
    PovFinish finish;
    Affine local; // texture space -> the space of what holds it
    // uv_mapping: its patterns are evaluated at the surface's uv coordinates (u, v, 0), placed
    // by the texture's own transforms (`uv_local`); the object's transforms do not move them.
    bool uv = false;
    Affine uv_local;
    std::vector<PovTextureRef> below; // layered: the layers under this one, bottom first
    bool is_map = false;              // chosen by `map_pattern` among `map_entries`
    PovPattern map_pattern;
    std::vector<std::pair<double, PovTextureRef>> map_entries;
};

/// Whether a texture_map over a continuous pattern has neighbouring entries (by value) of two
/// textures at two values, between which POV-Ray blends the textures (Sheaf does not).
bool texture_map_blends(const std::vector<std::pair<double, PovTextureRef>>& entries);

/// Whether the layers of a layered texture that show (some light passes the layers above
/// them, and some of theirs is not clear) are lit alike: the same ambient, emission, diffuse,
/// brilliance, metallic, reflection and iridescence (highlights are added layer by layer).
/// Sheaf lights a layered texture with one finish (io/pov/materials.cpp).
bool layers_lit_alike(const PovTexture& t);

/// A texture moved by a transform applied after it (the object's, or the texture's own).
PovTextureRef transformed(const PovTextureRef& t, const Affine& m);
/// `t` uv-mapped (an object's uv_mapping), placed by the transforms it has now (one that is
/// already keeps its placement).
PovTextureRef uv_mapped(const PovTextureRef& t);

/// Whether two textures are the same one: the same object, or copies of one (the same pigment
/// and normal, equal finishes and placements, the same layers); texture maps only as the same
/// object.
bool same_texture(const PovTextureRef& a, const PovTextureRef& b);

/// media { emission absorption density { ... } samples transforms }: an interior's medium, or
/// the atmosphere's (PovModel::atmosphere).
struct PovMedia {
    std::array<double, 3> emission{0, 0, 0}, absorption{0, 0, 0}, scattering{0, 0, 0};
    int scatter_type = 1; // POV-Ray's scattering types 1..5 (ScatterType)
    double eccentricity = 0, extinction = 1;
    std::vector<std::shared_ptr<const PovPigment>> densities; // multiplied
    int samples = 32;      // steps along each ray inside (core/shading/media.h)
    int light_samples = 8; // intervals x samples: steps along a shadow ray inside
    Affine local;          // the medium's own transforms, applied to its densities
};

/// interior { ior caustics fade_distance fade_power fade_color media }.
struct PovInterior {
    double ior = 0;      // 0: not set (1)
    double caustics = 0; // POV-Ray's fake caustics, as written (Material::caustics is 45 times)
    double fade_distance = 0, fade_power = 0;
    std::array<double, 3> fade_color{0, 0, 0};
    std::vector<PovMedia> media;
    Affine local; // the object's transforms after the interior was given (its media's space)
};

/// material { texture interior }: what a declared material carries.
struct PovMaterial {
    PovTextureRef texture;
    std::shared_ptr<const PovInterior> interior;
};

/// A light source (POV-Ray coordinates). Area lights become jittered samples in the builder.
struct PovLight {
    Light light; // position, colour, type, spot parameters, fade, shadowless
    Vec3 point_at{0, 0, 0};
    bool area = false;
    Vec3 axis1, axis2;
    int n1 = 1, n2 = 1;
    bool area_illumination = false; // each sample its own cone and fade (else the centre's)
};

enum class PovKind { Shape, Mesh, Csg, Light };

/// An object. Transforms are applied as they are parsed: `local` maps the shape's canonical
/// space (shape.h), a mesh's own coordinates, or nothing (CSG) to POV-Ray world space.
struct PovObject {
    PovKind kind = PovKind::Shape;
    Shape shape;
    std::shared_ptr<const PolyCoeffs> poly;              // shape of kind Poly: its coefficients
    std::shared_ptr<const GlyphOutline> glyph;           // shape of kind Glyph: its outline
    std::shared_ptr<const RevolutionProfile> revolution; // shape of kind Revolution
    std::shared_ptr<const BlobModel> blob;               // shape of kind Blob
    std::shared_ptr<const IsoRef> iso; // shape of kind Isosurface (its program set when built)
    std::shared_ptr<const PovFunction> iso_function; // and its function
    std::shared_ptr<const JuliaFractal> julia;       // shape of kind Julia: its parameters
    std::shared_ptr<const Mesh> mesh;
    // mesh2's texture_list: the textures faces name (moved with the object), and each
    // triangle's index into them (-1: the object's texture); null when no face names one.
    std::vector<PovTextureRef> face_textures;
    std::shared_ptr<const std::vector<int32_t>> face_texture;
    CsgOp op = CsgOp::Union;
    std::vector<PovObject> children;
    /// bounded_by's objects (a union of them), moved with the object: a ray that misses them
    /// may skip it (null: none given).
    std::shared_ptr<const PovObject> bounded_by;
    Affine local;
    PovTextureRef texture;                       // null: inherited (or the default texture)
    std::shared_ptr<const PovInterior> interior; // null: inherited (or none)
    PovTextureRef interior_texture; // what it shows from inside; null: inherited (or none)
    bool inverse = false;
    bool hollow = false;     // media around it fill it (`hollow`; set on a CSG, on its members too)
    bool uv_mapping = false; // its textures are uv-mapped (the object's uv_mapping)
    uint8_t flags = 0;       // ObjectFlag bits: no_shadow, no_reflection, no_image, photons'
    PhotonObject photons;    // its photons block (a union's passes to its parts)
    // A light_group (a union whose lights light only its objects, and its objects only its
    // lights, and with global_lights also the lights in no group).
    bool light_group = false, global_lights = false;
    PovLight light;
    Token where; // the keyword that started it, for warnings
};

struct PovCamera {
    Projection projection = Projection::Perspective;
    Vec3 location{0, 0, 0}, direction{0, 0, 1}, right{1.33f, 0, 0}, up{0, 1, 0}, sky{0, 1, 0};
    Vec3 look_at{0, 0, 1};
    bool has_look_at = false;
    bool has_up = false, has_right = false; // given: an orthographic view keeps their size
    double angle = 0;                       // degrees, 0: not given
    double v_angle = -1;                    // spherical: the vertical angle; < 0: not given
    Token type_at;                          // the camera type's keyword, for errors
    Token where;                            // its opening brace, for warnings
    Affine transform;                       // applied after everything else
    /// Tilts each primary ray as a surface normal, in screen space (x and y from -1/2 to 1/2).
    std::shared_ptr<const PovNormal> normal;
    /// Focal blur: the aperture (0: none), the point in focus and the samples a pixel takes.
    double aperture = 0;
    Vec3 focal_point{0, 0, 0};
    int blur_samples = 0; // 0: not given
    Token aperture_at;
    /// mesh_camera: rays per pixel, the distribution, smooth, and its meshes (with their
    /// transforms, in POV-Ray's space).
    int mesh_rays = 1, mesh_distribution = 0;
    bool mesh_smooth = false;
    std::vector<PovObject> meshes;
};

/// sky_sphere { pigments transforms }: its pigments bottom first, in the sky's space.
struct PovSky {
    std::vector<std::shared_ptr<const PovPigment>> pigments;
    Affine local;
};

/// Everything the parser collected.
/// What a scene's global settings give its patterns: the noise generator of those that name
/// none, and the number of waves of ripples and waves.
struct PatternDefaults {
    int noise_generator = 2;
    int waves = 10;
};

struct PovModel {
    std::vector<PovObject> objects;
    bool has_camera = false;
    PovCamera camera;
    Color5 background{0, 0, 0, 0, 0};
    double assumed_gamma = 0; // 0: not given
    double version = 3.7;
    bool version_given = false;
    int noise_generator = 0;  // global_settings' (1..3); 0: not given
    int number_of_waves = 10; // global_settings' (ripples and waves), 1..kPovMostWaves
    /// The generator of patterns that name none: global_settings', else as POV-Ray 3.7
    /// defaults it, 1 before #version 3.5 and 2 from it.
    int scene_noise_generator() const {
        return noise_generator ? noise_generator : version < 3.5 ? 1 : 2;
    }
    /// What the scene's global settings give every pattern (lower_pattern).
    PatternDefaults pattern_defaults() const { return {scene_noise_generator(), number_of_waves}; }
    std::array<double, 3> ambient_light{1, 1, 1};
    // POV-Ray 3.7.0's default, measured from povray: its documentation's <0.25, 0.18, 0.14>
    // is not what it renders (textures/pigments/irid.pov).
    std::array<double, 3> irid_wavelength{0.70, 0.52, 0.48};
    int max_trace_level = -1;
    double adc_bailout = 1.0 / 255; // POV-Ray's default
    /// global_settings { radiosity { ... } }: on, its count (gather rays), recursion_limit
    /// and brightness (POV-Ray 3.7's defaults).
    bool radiosity = false;
    int radiosity_count = 35, radiosity_depth = 2;
    double radiosity_brightness = 1;
    PovTexture default_texture;
    /// What every new normal starts from: #default's normal, pattern or not (its bump size).
    PovNormal normal_defaults;
    PovSky sky; // no pigments: no sky_sphere
    /// The fogs, in the order declared: constant (fog_type 1) or ground fog (fog_type 2: alt
    /// > 0), with their turbulence (turb zero: none).
    struct Fog {
        double distance = 0;
        Color5 color{0, 0, 0, 0, 0};
        double offset = 0, alt = 0;
        Vec3 up{0, 1, 0};
        Vec3 turb{0, 0, 0};
        int octaves = 6;
        double omega = 0.5, lambda = 2, turb_depth = 0.5;
    };
    std::vector<Fog> fogs;
    /// The scene's own `media { … }` statements: the atmosphere (Scene::atmosphere).
    std::vector<PovMedia> atmosphere;
    /// rainbow { … }: as written (degrees, POV-Ray's coordinates); `colors` is a gradient x
    /// over the colour map (none: the rainbow shows nothing, as in POV-Ray).
    struct Rainbow {
        double angle = 0, width = 0, distance = 1e7, jitter = 0;
        double arc = 360, falloff = 360; // degrees
        Vec3 direction{0, 0, 0}, up{0, 1, 0};
        std::shared_ptr<const PovPigment> colors;
    };
    std::vector<Rainbow> rainbows;
    PhotonSettings photons; // global_settings photons
};

/// The object's axis-aligned bounding box in POV-Ray's coordinates (min_extent, max_extent;
/// io/pov/extents.cpp); false when it has none (a light, an empty union).
bool object_extent(const PovObject& o, Vec3& lo, Vec3& hi);

} // namespace sheaf::io::pov

// Procedural textures in the scene model: patterns (a value or a list index at every point of
// space), pigments (a pattern with a colour map, a pigment map or a list, layered or solid),
// normal perturbations, material selection by pattern (texture maps), sky and fog. Plain data
// in flat arrays that index each other, so both backends can evaluate them
// (core/texture/pattern_eval.h, core/shading/surface_texture.h).
#pragma once

#include "core/math/affine.h"

#include <cmath>
#include <cstdint>
#include <string_view>

namespace sheaf {

enum class PatternKind : uint8_t {
    // Continuous patterns: a value in [0, 1], then frequency, phase and the wave.
    Gradient,       // frac(p . vector)
    Marble,         // p.x with a triangle wave (turbulence makes the veins)
    Wood,           // distance from the z axis, triangle wave
    Onion,          // distance from the origin
    Radial,         // angle around the y axis
    Spherical,      // 1 at the origin to 0 at distance 1
    Cylindrical,    // 1 on the y axis to 0 at distance 1
    Planar,         // 1 on the x-z plane to 0 at distance 1
    Boxed,          // 1 at the origin to 0 on the unit cube
    Leopard,        // ((sin x + sin y + sin z) / 3)^2
    Bozo,           // smooth noise (also spotted, bumps)
    Granite,        // fractal sum of |noise|
    Agate,          // noise-bent bands
    Wrinkles,       // fractal sum of noise
    Dents,          // noise cubed
    Crackle,        // cells of random points: `vector` (the form) weighs the nearest three
                    // distances under metric param[0], each raised by param[1] (the offset);
                    // param[2] 1: solid, each cell the noise at its point (POV-Ray's crackle)
    Cells,          // a random value per unit cube
    Ripples,        // concentric waves from fixed random centres
    Waves,          // like ripples, with amplitude falling with distance
    Spiral1,        // spiral bands (param[0] arms) around the z axis
    Spiral2,        // two spirals crossing
    Quilted,        // cushion-shaped cells: POV-Ray's, param[0] control0, param[1] control1
    Mandel,         // the Mandelbrot set in the x-y plane (Pattern::fractal)
    Julia,          // a Julia set in the x-y plane (Pattern::fractal, its c)
    Slope,          // the surface's slope towards a direction, and its altitude (SlopeParams)
    Function,       // a user function's value (core/scene/function.h): Pattern::program
    Image,          // an image's colour (Pigment only): `image` in Scene::textures
    PigmentPattern, // the grey of a pigment (`pigment`) evaluated at the pattern-space point
    ImagePattern,   // the grey of an image (`image`, mapped from pattern space; host only)
    DensityFile,    // a voxel grid's value in the unit cube (`grid` in Scene::density_grids)
    Facets,         // normals only: the normal turned to the nearest of random cell points
                    // (param[0] the cells' size, param[1] `coords`: 0 cells over the normal,
                    // else cells over the point, tilting by noise that much)
    // Discrete patterns: an index into the list of their entries.
    Checker,    // 2 entries
    Hexagon,    // 3 entries, tiles in the x-z plane
    Brick,      // 2 entries: mortar, brick; param = size x, y, z and mortar width
    Square,     // 4 entries, tiles in the x-z plane
    Triangular, // 6 entries, tiles in the x-z plane
};

/// Discrete patterns choose an entry; continuous ones give a value.
/// The patterns whose classic turbulence bends them inside the pattern instead of moving the
/// point (marble, wood): POV-Ray skips their turbulence when it warps the point, so neither
/// their own point nor their maps' entries move by it. (Agate and the spirals bend inside
/// too, but POV-Ray also moves their point, and their entries', as every other pattern's.)
SHEAF_HD_INLINE bool bends_by_own_turbulence(PatternKind k) {
    return k == PatternKind::Marble || k == PatternKind::Wood;
}

/// The entries a list pattern picks from by tile (checker and brick 2, hexagon 3, square 4,
/// triangular 6); 0 for continuous patterns. Every reader checks a list's length by it.
SHEAF_HD_INLINE int pattern_list_size(PatternKind k) {
    switch (k) {
    case PatternKind::Checker:
    case PatternKind::Brick:
        return 2;
    case PatternKind::Hexagon:
        return 3;
    case PatternKind::Square:
        return 4;
    case PatternKind::Triangular:
        return 6;
    default:
        return 0;
    }
}

SHEAF_HD_INLINE bool pattern_is_list(PatternKind k) {
    return pattern_list_size(k) > 0;
}

enum class Wave : uint8_t { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

/// POV-Ray's fractal patterns: z -> z^exponent + c from z = p (x, y), c = p (mandel) or a
/// constant (julia), until |z| > 2 or `iterations`. The magnet patterns iterate
///   magnet 1: z -> ((z^2 + c - 1) / (2z + c - 2))^2,
///   magnet 2: z -> ((z^3 + 3(c-1)z + (c-1)(c-2)) / (3z^2 + 3(c-2)z + (c-1)(c-2) + 1))^2
/// from z = 0 (mandel) or p (julia) until |z| > 100 or z comes within 0.01 of 1.
/// A point that escapes at step i (from 0) takes its exterior value, one that never does its
/// interior value:
///   exterior type 0 factor, 1 i / iterations, 2 Re z * factor, 3 Im z * factor,
///     4 (Re z)^2 * factor, 5 (Im z)^2 * factor, 6 |z| * factor,
///     7 (i mod factor) / factor, 8 (i mod (factor + 1)) / factor;
///   interior type 0 factor, 1 the orbit's least |z| * factor, 2..5 as exterior, 6 |z|^2 * factor.
struct FractalParams {
    uint16_t iterations = 1;
    uint8_t exponent = 2; // 2..33
    uint8_t magnet = 0;   // 0: z^exponent + c; 1, 2: the magnet formulas
    uint8_t interior_type = 0, exterior_type = 1;
    float interior_factor = 1.0f, exterior_factor = 1.0f;
    float c[2] = {0, 0}; // Julia
};

/// POV-Ray's slope pattern: how steeply the surface faces Pattern::vector (a unit world
/// direction, or with `point_at` a world point), as asin(n . d) mapped from [-pi/2, pi/2] to
/// [0, 1], where n is the normal facing the ray (after the surface's own normal pattern);
/// with an altitude, blended with the pattern-space point's height along `altitude`. Each
/// part may be remapped from [lo, lo + width] to [0, 1] (param[0], param[1] for the slope,
/// param[2], param[3] for the altitude; width 0: as it is). The sum wraps into [0, 1), a 1
/// staying 1. Where there is no surface (media, the sky, functions) the value is 0.
struct SlopeParams {
    Vec3 altitude{0, 0, 0}; // unit, in pattern space; zero: no altitude
    float slope_weight = 1; // the slope's share of the value; the altitude's is the rest
    bool point_at = false;
};

/// POV-Ray's ranges of the fractal patterns' values, which both scene readers enforce, each
/// reporting a broken rule at its own position (povray refuses the same values).
constexpr int kFractalMaxIterations = 65535; // FractalParams::iterations' 16 bits
constexpr int kFractalMinExponent = 2, kFractalMaxExponent = 33;

/// Why `type` is not an interior (`inside`) or exterior colouring type, or null when it is.
inline const char* fractal_type_error(bool inside, double type) {
    if (type >= 0 && type <= (inside ? 6 : 8) && type == std::floor(type)) return nullptr;
    return inside ? "the interior type must be a whole number from 0 to 6"
                  : "the exterior type must be a whole number from 0 to 8";
}

/// Why `factor` does not suit colouring type `type` (a valid one), or null when it does:
/// exterior types 7 and 8 divide the step by it (7: modulo its whole part).
inline const char* fractal_factor_error(bool inside, double type, double factor) {
    if (!std::isfinite(factor)) return "the factor must be finite";
    if (!inside && type == 7 && !(factor >= 1))
        return "exterior type 7 needs a factor of 1 or more";
    if (!inside && type == 8 && !(factor > 0)) return "exterior type 8 needs a factor above 0";
    return nullptr;
}

/// POV-Ray's warps: each moves the pattern point in the space where it was declared, in the
/// pattern's chain of transforms and warps (see Pattern::warp_first and warp_point).
enum class WarpKind : uint8_t {
    Turbulence,  // p + a * vector turbulence (octaves, f[0] omega, f[1] lambda)
    Repeat,      // a slab of width f[0] along `axis` repeated: offset a per slab, odd slabs
                 // mirrored where b is -1 (b is 1 elsewhere)
    Planar,      // (x, y) of the point, z = f[0], turned to `orientation` (b)
    Cylindrical, // (angle around y as a fraction of a turn, y, distance from the y axis)
    Spherical,   // (longitude, latitude as fractions, distance from the origin)
    Toroidal,    // a torus of major radius f[1] around y unrolled: (angle, tube angle, distance)
    Cubic,       // a cube's faces unfolded on the x-y plane
    BlackHole,   // points within f[0] of the centre a pushed from it by (1 - d / f[0])^f[1] *
                 // f[2] of their distance (at most all of it; axis 1: pulled, POV-Ray's
                 // inverse); repeated every b along the axes where b > 0, each copy's centre
                 // jittered by up to c
};

/// One warp of a pattern's chain. `to_inner` maps the point, once warped, into the space of the
/// transforms and warps declared before this one. Cylindrical, spherical and toroidal warps
/// multiply their angles by the distance to the power f[0] (dist_exp; 0: not at all) and,
/// like planar, turn their result to the unit `orientation` b (z: as it is).
struct Warp {
    WarpKind kind = WarpKind::Turbulence;
    uint8_t axis = 0;   // Repeat: 0 x, 1 y, 2 z; BlackHole: 1 inverse
    int8_t octaves = 6; // Turbulence
    Affine to_inner;
    Vec3 a{0, 0, 0};        // Turbulence: the amount; Repeat: the offset
    Vec3 b{0, 0, 1};        // Repeat: the flip signs; Planar ... Toroidal: the orientation
    Vec3 c{0, 0, 0};        // BlackHole: the jitter
    float f[3] = {0, 0, 0}; // see WarpKind
};

/// A voxel grid over the unit cube (POV-Ray's density_file): nx x ny x nz values in [0, 1] at
/// Scene::density_voxels[first ...], x fastest, then y, then z; 0 outside the cube.
struct DensityGrid {
    uint32_t first = 0;
    uint32_t nx = 0, ny = 0, nz = 0;
    uint32_t interpolation = 0; // 0 the nearest voxel, 1 trilinear, 2 tricubic
};

struct Pattern {
    PatternKind kind = PatternKind::Gradient;
    Wave wave = Wave::Ramp;
    int8_t octaves = 6; // turbulence
    bool has_turbulence = false;
    // POV-Ray's noise_generator for the noise patterns and turbulence (core/texture/pov_noise.h):
    // 1 the original, 2 range-corrected (POV-Ray's default), 3 Perlin's.
    uint8_t noise_generator = 2;
    // Ripples and waves: POV-Ray's number_of_waves (global_settings), 1..1000.
    uint16_t waves = 10;
    // World -> pattern space (uv: texture coordinates -> pattern space), or with warps world
    // -> the space of the last warp declared; then Scene::warps [warp_first, warp_first +
    // warp_count), the last declared first, each warping and mapping on by its to_inner.
    Affine to_pattern;
    uint32_t warp_first = 0, warp_count = 0;
    // Evaluated at the surface's texture coordinates (u, v, 0) instead of the world point
    // (POV-Ray's uv_mapping): pigments and texture maps; off surfaces (media, the sky) the
    // coordinates are (0, 0).
    bool uv = false;
    Vec3 turbulence{0, 0, 0};
    float omega = 0.5f, lambda = 2.0f;
    float frequency = 1.0f, phase = 0.0f;
    float wave_exponent = 1.0f; // Wave::Poly
    Vec3 vector{0, 1, 0};       // Gradient: the direction
    float param[4] = {0, 0, 0, 0};
    // Image, ImagePattern: index into Scene::textures, whose transform maps from pattern
    // space (after to_pattern and the warps, so warps bend images too)
    int32_t image = -1;
    // PigmentPattern: index into Scene::pigments of a pigment placed in this pattern's space
    // (its transforms map from there, not from the world), whose grey 0.297 red + 0.589
    // green + 0.114 blue is the value.
    int32_t pigment = -1;
    int32_t program = -1;  // Function: index into Scene::fn_programs
    int32_t grid = -1;     // DensityFile: index into Scene::density_grids
    FractalParams fractal; // Mandel, Julia
    SlopeParams slope;     // Slope
};

/// POV-Ray's crackle as it starts: form <-1, 1, 0> (the second nearest distance less the
/// nearest), metric 2, offset 0, not solid.
inline void set_crackle_defaults(Pattern& pt) {
    pt.vector = Vec3(-1, 1, 0);
    pt.param[0] = 2, pt.param[1] = 0, pt.param[2] = 0;
}

/// Sets `pt` to POV-Ray's slope pattern: `direction`'s and `altitude`'s lengths weigh the two
/// parts; (lo, hi) ranges remap them (hi == lo: left as they are). False when both
/// directions are zero (nothing to measure), or when a point_at slope has an altitude.
inline bool set_slope(Pattern& pt, Vec3 direction, float lo, float hi, Vec3 altitude, float alo,
                      float ahi, bool point_at) {
    const float sl = point_at ? 1.0f : length(direction), al = length(altitude);
    if (!(sl + al > 0) || (point_at && al > 0)) return false;
    pt.kind = PatternKind::Slope;
    pt.vector = point_at || !(sl > 0) ? direction : direction / sl;
    pt.slope.point_at = point_at;
    pt.slope.altitude = al > 0 ? altitude / al : Vec3(0.0f);
    pt.slope.slope_weight = sl / (sl + al);
    pt.param[0] = hi != lo ? lo : 0, pt.param[1] = hi != lo ? hi - lo : 0;
    pt.param[2] = ahi != alo ? alo : 0, pt.param[3] = ahi != alo ? ahi - alo : 0;
    return true;
}

/// A pigment: a solid colour, or a pattern whose value picks (continuous) or indexes (list
/// patterns) entries [first, first + count) of Scene::pigment_entries. With `layers`, the
/// entries are layers, bottom first, composed by each layer's filter and transmit.
struct Pigment {
    Pattern pattern;
    bool solid = true;
    bool layers = false;
    bool average = false;             // the mean of the entries (POV-Ray's `average`)
    float color[5] = {0, 0, 0, 0, 0}; // solid: red, green, blue, filter, transmit
    uint32_t first = 0, count = 0;
};

/// A map entry: at pattern value `value`, a colour (pigment < 0) or another pigment.
struct PigmentEntry {
    float value = 0;
    float color[5] = {0, 0, 0, 0, 0};
    int32_t pigment = -1;
};

/// Where a continuous pattern's value falls in a map of `count` (> 0) entries sorted by
/// value: the blend (1 - t) * lo + t * hi, or one entry (lo == hi) below the first entry,
/// above the last, on an entry, or for NaN (the first). One lookup for pigments, pigment
/// functions and normal maps (any entry type with a `value`).
struct MapSpan {
    uint32_t lo, hi;
    float t;
};
template <class Entry> SHEAF_HD_INLINE MapSpan map_span(const Entry* e, uint32_t count, float v) {
    uint32_t hi = 0;
    while (hi < count && e[hi].value < v) ++hi;
    if (hi == 0) return {0, 0, 0.0f};
    if (hi == count) return {count - 1, count - 1, 0.0f};
    const float span = e[hi].value - e[hi - 1].value;
    const float t = span > 0 ? (v - e[hi - 1].value) / span : 1.0f;
    if (t <= 0) return {hi - 1, hi - 1, 0.0f};
    if (t >= 1) return {hi, hi, 0.0f};
    return {hi - 1, hi, t};
}

/// A slope map entry (POV-Ray's slope_map): at pattern value `value`, the surface's height and
/// its slope.
struct SlopeEntry {
    float value = 0, height = 0, slope = 0;
};

/// The height a slope map of `count` (> 0) entries sorted by value gives pattern value v, as
/// POV-Ray computes it: the first or last entry's height outside them, else the cubic Hermite
/// curve between the two entries around v through their heights with their slopes (per unit
/// of the interval's parameter).
SHEAF_HD_INLINE float slope_map_height(const SlopeEntry* e, uint32_t count, float v) {
    if (!(v > e[0].value)) return e[0].height; // also NaN
    if (v >= e[count - 1].value) return e[count - 1].height;
    uint32_t i = 1;
    while (v > e[i].value) ++i;
    const SlopeEntry &a = e[i - 1], &b = e[i];
    const float t = (v - a.value) / (b.value - a.value), tt = t * t;
    return tt * t * (a.slope + b.slope + 2 * (a.height - b.height)) -
           tt * (2 * a.slope + b.slope + 3 * (a.height - b.height)) + t * a.slope + a.height;
}

/// A normal perturbation: the shading normal tilts along the pattern's gradient, `amount`
/// (POV-Ray's bump size) times its slope. With a slope map (entries [slope_first,
/// slope_first + slope_count) of Scene::slope_entries) the pattern's value is first mapped
/// to a height, whose slope tilts the normal.
///
/// With a normal map (entries [map_first, map_first + map_count) of
/// Scene::normal_map_entries) the normal is instead that of other normal patterns: the two
/// entries around the pattern's value blended (continuous patterns, entries sorted by
/// value), the entry a list pattern indexes, or with `average` the mean of all the entries'
/// normals weighted by their values (POV-Ray's normal_map, normal lists and average).
/// How POV-Ray tilts a normal by its pattern: bumps, dents, wrinkles, ripples and waves have
/// normal functions of their own (core/shading/surface_texture.h); every other pattern tilts
/// it by its slope, sampled `delta` (POV-Ray's accuracy) around the point.
enum class NormalForm : uint8_t { Slope, Bumps, Dents, Wrinkles, Ripples, Waves, Quilted };

/// The form POV-Ray gives a normal pattern named `name` (bumps, dents ...; others Slope).
inline NormalForm normal_form_of(std::string_view name) {
    if (name == "bumps") return NormalForm::Bumps;
    if (name == "dents") return NormalForm::Dents;
    if (name == "wrinkles") return NormalForm::Wrinkles;
    if (name == "ripples") return NormalForm::Ripples;
    if (name == "waves") return NormalForm::Waves;
    if (name == "quilted") return NormalForm::Quilted;
    return NormalForm::Slope;
}

struct NormalPattern {
    Pattern pattern;
    float amount = 0.5f; // POV-Ray's bump size
    NormalForm form = NormalForm::Slope;
    bool no_bump_scale = false; // POV-Ray's no_bump_scale: the normal not made unit in between
    float delta = 0.02f;        // Slope: POV-Ray's accuracy
    uint32_t slope_first = 0, slope_count = 0;
    uint32_t map_first = 0, map_count = 0;
    bool average = false;
};

/// A normal map entry: at pattern value (or with the weight) `value`, the normal of normal
/// pattern `normal`, which has no map of its own (< 0: the surface's own normal).
struct NormalMapEntry {
    float value = 0;
    int32_t normal = -1;
};

/// A material chosen by pattern (POV-Ray's texture_map and texture lists): entries
/// [first, first + count) of Scene::material_entries. Continuous patterns take the nearer of
/// the two entries around the pattern's value (no blending between materials).
struct MaterialSwitch {
    Pattern pattern;
    uint32_t first = 0, count = 0;
};

struct MaterialEntry {
    float value = 0;
    uint32_t material = 0;
};

/// One fog. Constant fog (POV-Ray fog_type 1): a surface at distance d keeps
/// a = max(exp(-d / distance), transmit) of its colour, tinted by (1 - filter) + filter *
/// color; the fog's colour fills 1 - a.
struct Fog {
    float distance = 0; // 0: no fog
    Vec3 color{0, 0, 0};
    float filter = 0, transmit = 0;
    // alt > 0: POV-Ray's ground fog (fog_type 2): full density below the height `offset`
    // along `up` (unit), 1 / (1 + Y^2) above it, Y the height over offset in units of alt.
    float offset = 0, alt = 0;
    Vec3 up{0, 1, 0};
    // POV-Ray's fog turbulence (turb not zero): a finite way's depth shrinks by
    // exp(-d / distance) * min(1, turb_depth * turbulence at the way's middle times turb),
    // the turbulence POV-Ray's (octaves, omega, lambda, noise generator 1..3).
    Vec3 turb{0, 0, 0};
    int octaves = 6, noise_generator = 2;
    float omega = 0.5f, lambda = 2.0f, turb_depth = 0.5f;
};

/// A scene's fogs: POV-Ray lays every fog a scene declares over the others (each fades what
/// is behind it and adds its colour), at most kMax of them.
struct Fogs {
    static constexpr uint32_t kMax = 4;
    Fog layer[kMax];
    uint32_t count = 0;
    SHEAF_HD bool any() const { return count > 0; }
};

/// POV-Ray's rainbow: a band of colour around the antisolar direction, added to each ray as a
/// fog of its own (core/shading/rainbow.h). A ray at angle a from `antisolar` takes the colour
/// of pigment `colors` at ((a - start) / width, 0, 0) while that lies in [0, 1); the ray's
/// angle around `antisolar`, from `up`, must not pass `arc` (radians), and beyond `falloff`
/// the band fades out towards it.
struct Rainbow {
    Vec3 antisolar{0, 0, 1};            // unit
    Vec3 up{0, 1, 0}, right{1, 0, 0};   // unit, square to antisolar and to each other
    float start = 0, width = 0;         // radians (a negative width turns the band round)
    float distance = 1e30f;             // its fog: a surface at depth d keeps exp(-d / distance)
    float jitter = 0;                   // the band's index moves by up to this, per sample
    float arc = 1e30f, falloff = 1e30f; // radians from up
    uint32_t colors = 0;                // a pigment
};

} // namespace sheaf

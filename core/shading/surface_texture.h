// Procedural textures at surface points: the material a texture map picks, the pigment's
// colour, filter and transmit, the tilted shading normal, and the sky seen along a direction.
// Host-and-device: image pigments are the one host-only branch (OpenImageIO), and scenes with
// image textures never reach the device.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/function.h"
#include "core/scene/scene_view.h"
#include "core/texture/density_grid.h"
#include "core/texture/pattern_eval.h"
#include "core/texture/texture.h"

#include <cfloat>

namespace sheaf {

/// A POV-Ray colour: linear RGB, filter (light passes tinted by rgb), transmit (passes as is).
struct SurfaceColor {
    Vec3 rgb;
    float filter = 0, transmit = 0;
};

namespace texture_detail {

// Texture maps and pigment maps may nest; scenes do not go deeper than a few levels, and the
// scene's validation forbids cycles, so this only bounds the work.
constexpr int kMaxDepth = 16;

/// POV-Ray's grey of a colour (pigment_pattern, image_pattern, bump maps).
SHEAF_HD_INLINE float pov_grey(Vec3 c) {
    return 0.297f * c.x + 0.589f * c.y + 0.114f * c.z;
}

SHEAF_HD_INLINE SurfaceColor entry_color(const PigmentEntry& e) {
    return {Vec3(e.color[0], e.color[1], e.color[2]), e.color[3], e.color[4]};
}

SHEAF_HD_INLINE SurfaceColor mix(const SurfaceColor& a, const SurfaceColor& b, float t) {
    return {a.rgb * (1.0f - t) + b.rgb * t, a.filter * (1.0f - t) + b.filter * t,
            a.transmit * (1.0f - t) + b.transmit * t};
}

/// (s, t) of image texture `image` at world point p; false where an image seen once does not
/// cover p (s or t outside [0, 1]). Host only: the device never samples images.
SHEAF_HD_INLINE bool image_point(const SceneView& scene, int32_t image, Vec3 p, float uv_s,
                                 float uv_t, float& s, float& t) {
#if SHEAF_DEVICE_PASS
    (void)scene, (void)image, (void)p, (void)uv_s, (void)uv_t;
    s = t = 0;
    return true;
#else
    const Texture& tex = scene.textures[size_t(image)];
    texture_coordinates(tex, p, uv_s, uv_t, s, t);
    return !tex.once || (s >= 0 && s <= 1 && t >= 0 && t <= 1);
#endif
}

/// Image texture `image` at (s, t): the colour from the host's sampler (grey on the device).
SHEAF_HD_INLINE Vec3 sample_at(const SceneView& scene, int32_t image, float s, float t) {
#if SHEAF_DEVICE_PASS
    (void)scene, (void)image, (void)s, (void)t;
    return Vec3(0.5f);
#else
    return scene.sampler->sample(uint32_t(image), s, t);
#endif
}

/// Image texture `image` at world point p (repeated, whether seen once or not).
SHEAF_HD_INLINE Vec3 sample_image(const SceneView& scene, int32_t image, Vec3 p, float uv_s,
                                  float uv_t) {
    float s, t;
    image_point(scene, image, p, uv_s, uv_t, s, t);
    return sample_at(scene, image, s, t);
}

SHEAF_HD_NOINLINE float pigment_grey(const SceneView& scene, uint32_t pigment, Vec3 q, int depth);

/// What a program run on a scene reads (core/scene/function.h): any pattern (warps, pigment
/// patterns) and any pigment (FnPigment::scene_pigment), inside `depth` levels of pigments,
/// patterns and functions.
struct FnSceneContext {
    const SceneView& scene;
    int depth;
    SHEAF_HD double pattern(uint32_t i, double x, double y, double z) const;
    SHEAF_HD double pigment(uint32_t i, int comp, double x, double y, double z) const;
};

/// A continuous pattern's value at pattern-space point q of the surface at world point
/// `world` whose normal, facing the ray, is n (zero where there is no surface: media, the
/// sky); a function pattern runs its program (a value that is not finite counts as 0), a
/// pigment pattern evaluates its pigment at q (`depth`: the pigments around this one).
SHEAF_HD_NOINLINE float pattern_value(const SceneView& scene, const Pattern& pt, Vec3 q,
                                      Vec3 world = Vec3(0.0f), Vec3 n = Vec3(0.0f), int depth = 0) {
    if (pt.kind == PatternKind::PigmentPattern)
        return pattern_detail::shape_value(
            pt, depth < kMaxDepth ? pigment_grey(scene, uint32_t(pt.pigment), q, depth + 1) : 0);
    if (pt.kind == PatternKind::Slope)
        return pattern_detail::shape_value(pt, slope_raw(pt, q, world, n));
    if (pt.kind == PatternKind::DensityFile)
        return pattern_detail::shape_value(
            pt, pt.grid >= 0 && scene.density_grids
                    ? density_value(scene.density_grids[pt.grid], scene.density_voxels, q)
                    : 0.0f);
    if (pt.kind == PatternKind::ImagePattern) { // POV-Ray's image_pattern: 0 off an image seen once
        float s, t;
        if (!scene.sampler || !texture_detail::image_point(scene, pt.image, q, 0, 0, s, t))
            return pattern_detail::shape_value(pt, 0.0f);
        const Vec3 c = texture_detail::sample_at(scene, pt.image, s, t);
        return pattern_detail::shape_value(pt, pattern_detail::clamp01(pov_grey(c)));
    }
    if (pt.kind != PatternKind::Function) return pattern_value_at(pt, q);
    if (!scene.functions.programs || pt.program < 0) return 0.0f;
    const double args[3] = {q.x, q.y, q.z};
    const float raw =
        float(fn_eval(scene.functions, uint32_t(pt.program), args, FnSceneContext{scene, depth}));
    return pattern_detail::shape_value(pt, raw - raw == 0 ? raw : 0.0f);
}

struct Evaluator {
    const SceneView& scene;
    float uv_s, uv_t;
    Vec3 normal; // the surface's, facing the ray (slope patterns); zero off surfaces

    SHEAF_HD_NOINLINE SurfaceColor entry(const PigmentEntry& e, Vec3 p, int depth) const {
        if (e.pigment < 0) return entry_color(e);
        return pigment(uint32_t(e.pigment), p, depth + 1);
    }

    SHEAF_HD_NOINLINE SurfaceColor pigment(uint32_t index, Vec3 p, int depth) const {
        const Pigment& pg = scene.pigments[index];
        if (pg.solid || depth > kMaxDepth || pg.count == 0)
            return {Vec3(pg.color[0], pg.color[1], pg.color[2]), pg.color[3], pg.color[4]};
        const PigmentEntry* entries = &scene.pigment_entries[pg.first];
        if (pg.layers) { // bottom first; each layer shows what is below by filter and transmit
            SurfaceColor c = entry(entries[0], p, depth);
            for (uint32_t i = 1; i < pg.count; ++i) {
                const SurfaceColor top = entry(entries[i], p, depth);
                const float pass = top.filter + top.transmit;
                SurfaceColor out;
                out.rgb = top.rgb * hdm::fmaxf(0.0f, 1.0f - pass) +
                          c.rgb * (top.rgb * top.filter + Vec3(top.transmit));
                out.filter = c.filter * pass;
                out.transmit = c.transmit * pass;
                c = out;
            }
            return c;
        }
        if (pg.average) {
            SurfaceColor sum{Vec3(0.0f), 0, 0};
            for (uint32_t i = 0; i < pg.count; ++i) {
                const SurfaceColor c = entry(entries[i], p, depth);
                sum.rgb += c.rgb, sum.filter += c.filter, sum.transmit += c.transmit;
            }
            const float inv = 1.0f / float(pg.count);
            return {sum.rgb * inv, sum.filter * inv, sum.transmit * inv};
        }
        const Pattern& pt = pg.pattern;
        const Vec3 at = pt.uv ? Vec3(uv_s, uv_t, 0.0f) : p; // where the pattern is evaluated
        if (pt.kind == PatternKind::Image) { // mapped from pattern space: warps bend it
            if (!scene.sampler) return {Vec3(0.5f), 0, 0};
            float s, t;
            const Vec3 q = pattern_point(pt, at, scene.warps);
            if (!texture_detail::image_point(scene, pt.image, q, uv_s, uv_t, s, t))
                return {Vec3(1.0f), 0, 1}; // off an image seen once: clear, as POV-Ray's
            const Vec3 c = texture_detail::sample_at(scene, pt.image, s, t);
            const SurfaceColor tint = entry_color(entries[0]); // filter and transmit of the map
            return {c, tint.filter, tint.transmit};
        }
        const Vec3 q = pattern_point(pt, at, scene.warps);
        if (pattern_is_list(pt.kind)) {
            const int i = pattern_index_at(pt, q);
            return entry(entries[uint32_t(i) < pg.count ? uint32_t(i) : pg.count - 1], p, depth);
        }
        const MapSpan m =
            map_span(entries, pg.count, pattern_value(scene, pt, q, at, normal, depth));
        if (m.lo == m.hi) return entry(entries[m.lo], p, depth);
        return mix(entry(entries[m.lo], p, depth), entry(entries[m.hi], p, depth), m.t);
    }
};

/// The grey of pigment `pigment` (placed in a pattern's space) at that space's point q, as
/// POV-Ray's pigment_pattern weighs it.
SHEAF_HD_NOINLINE float pigment_grey(const SceneView& scene, uint32_t pigment, Vec3 q, int depth) {
    return pov_grey(Evaluator{scene, 0, 0, Vec3(0.0f)}.pigment(pigment, q, depth).rgb);
}

/// A function pattern's value: a list pattern's entry 0 or not (0 or 1), as fn_pattern.
SHEAF_HD_NOINLINE double FnSceneContext::pattern(uint32_t i, double x, double y, double z) const {
    const Pattern& pt = scene.functions.patterns[i];
    const Vec3 q = pattern_point(pt, Vec3(float(x), float(y), float(z)), scene.warps);
    if (pattern_is_list(pt.kind)) return pattern_index_at(pt, q) != 0 ? 1.0 : 0.0;
    return depth < kMaxDepth ? pattern_value(scene, pt, q, Vec3(0.0f), Vec3(0.0f), depth + 1) : 0.0;
}

SHEAF_HD_NOINLINE double FnSceneContext::pigment(uint32_t i, int comp, double x, double y,
                                                 double z) const {
    const FnPigment& fp = scene.functions.pigments[i];
    if (fp.scene_pigment < 0 || depth >= kMaxDepth)
        return fn_pigment(scene.functions, fp, comp, x, y, z);
    const SurfaceColor c = Evaluator{scene, 0, 0, Vec3(0.0f)}.pigment(
        uint32_t(fp.scene_pigment), Vec3(float(x), float(y), float(z)), depth + 1);
    const float rgbft[5] = {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
    return fn_component(rgbft, comp);
}

// The value a pattern gives at a pattern-space point, for slopes: list patterns give their
// index spread over [0, 1].
SHEAF_HD_INLINE float slope_value(const SceneView& scene, const Pattern& pt, Vec3 q, Vec3 world,
                                  Vec3 n) {
    if (pattern_is_list(pt.kind)) return float(pattern_index_at(pt, q)) * 0.5f;
    return pattern_value(scene, pt, q, world, n);
}

} // namespace texture_detail

/// Follows material switches (texture maps) from `material` at world point p, where the
/// surface's normal facing the ray is n (zero off surfaces) and its texture coordinates are
/// (uv_s, uv_t).
SHEAF_HD_INLINE uint32_t resolve_material(const SceneView& scene, uint32_t material, Vec3 p,
                                          Vec3 n = Vec3(0.0f), float uv_s = 0, float uv_t = 0) {
    using namespace texture_detail;
    for (int depth = 0; depth < kMaxDepth; ++depth) {
        const int32_t sw = scene.materials[material].select;
        if (sw < 0) return material;
        const MaterialSwitch& ms = scene.material_switches[size_t(sw)];
        const MaterialEntry* entries = &scene.material_entries[ms.first];
        const Vec3 at = ms.pattern.uv ? Vec3(uv_s, uv_t, 0.0f) : p;
        const Vec3 q = pattern_point(ms.pattern, at, scene.warps);
        if (pattern_is_list(ms.pattern.kind)) {
            const uint32_t i = uint32_t(pattern_index_at(ms.pattern, q));
            material = entries[i < ms.count ? i : ms.count - 1].material;
            continue;
        }
        const float v = pattern_value(scene, ms.pattern, q, at, n);
        uint32_t pick = 0;
        for (uint32_t i = 1; i < ms.count; ++i) {
            // The nearer of the two entries around v.
            if (entries[i].value <= v) {
                pick = i;
            } else {
                if (v - entries[i - 1].value > entries[i].value - v) pick = i;
                break;
            }
        }
        material = entries[pick].material;
    }
    return material;
}

/// Pigment `pigment` at world point p; (uv_s, uv_t) are the surface's texture coordinates,
/// read by image pigments with uv mapping and uv patterns (Pattern::uv), n its normal facing the
/// ray (slope patterns; zero off surfaces).
SHEAF_HD_INLINE SurfaceColor evaluate_pigment(const SceneView& scene, uint32_t pigment, Vec3 p,
                                              float uv_s, float uv_t, Vec3 n = Vec3(0.0f)) {
    return texture_detail::Evaluator{scene, uv_s, uv_t, n}.pigment(pigment, p, 0);
}

/// Function pattern `pattern` (of SceneView::functions) at (x, y, z), as programs run on the
/// scene read it.
SHEAF_HD_INLINE double evaluate_fn_pattern(const SceneView& scene, uint32_t pattern, double x,
                                           double y, double z) {
    return texture_detail::FnSceneContext{scene, 0}.pattern(pattern, x, y, z);
}

namespace texture_detail {

/// POV-Ray's bump_map: the unit normal n at world point p tilted by the grey levels of image
/// np.pattern.image (heights times np.amount) at the point and one pixel down-left and
/// down-right of it, as the plane through those three heights leans, in POV-Ray's frame about
/// the normal and the world's up axis (built in POV-Ray's left-handed world: Sheaf's with z
/// mirrored). Images are sampled on the host only (scenes with them render on the CPU).
SHEAF_HD_INLINE Vec3 bump_map_normal(const SceneView& scene, const NormalPattern& np, Vec3 p,
                                     Vec3 n) {
#if SHEAF_DEVICE_PASS
    (void)scene, (void)np, (void)p;
    return n;
#else
    const int32_t image = np.pattern.image;
    if (!scene.sampler || image < 0) return n;
    float s, t;
    if (!image_point(scene, image, p, 0, 0, s, t)) return n;
    int w = 0, h = 0;
    scene.sampler->size(uint32_t(image), w, h);
    if (w <= 0 || h <= 0) return n;
    auto grey = [&](float ss, float tt) {
        const Vec3 c = scene.sampler->sample(uint32_t(image), ss, tt);
        return pov_grey(c);
    };
    const float a = np.amount, h1 = grey(s, t);
    const float h2 = grey(s - 1.0f / float(w), t - 1.0f / float(h));
    const float h3 = grey(s + 1.0f / float(w), t - 1.0f / float(h));
    // The normal of the triangle (0, a h1, 0), (-1, a h2, 1), (1, a h3, 1).
    const Vec3 b = normalize(Vec3(-a * (h3 - h2), 2.0f, a * (2 * h1 - h2 - h3)));
    const Vec3 up(n.x, n.y, -n.z); // the normal in POV-Ray's world
    Vec3 side = cross(up, Vec3(0, 1, 0)), normal = up;
    float len = length(side);
    if (len < 1e-6f) { // the normal is the up axis: a fixed frame
        normal = Vec3(0, fabsf(up.y - 1) < 1e-6f ? 1.0f : -1.0f, 0);
        side = Vec3(1, 0, 0), len = 1;
    }
    side = side / len;
    const Vec3 ahead = normalize(cross(side, normal));
    const Vec3 r = side * b.x + normal * b.y - ahead * b.z;
    const Vec3 out = normalize(Vec3(r.x, r.y, -r.z));
    return length_squared(out) > 0 ? out : n;
#endif
}

/// POV-Ray's facets, in the pattern's space: one random point per unit cell (pov_cell_point)
/// of space scaled by 1 / size (param[0]); the cell points around the unit normal t (or, with
/// `coords`, param[1], around the point q) are measured under metric param[2], and the nearest
/// becomes the normal (with coords: t tilted by coords times POV-Ray's vector noise at that
/// point, less its part along t). Not yet unit length.
SHEAF_HD_INLINE DVec3 facets_normal(const Pattern& pt, Vec3 q, DVec3 t) {
    const double size = pt.param[0], coords = pt.param[1];
    const double metric = pt.param[2] > 0 ? double(pt.param[2]) : 2.0;
    const double scale = size < 1e-6 ? 1e6 : 1.0 / size;
    const DVec3 tv = (coords != 0 ? DVec3(q) : t) * scale;
    // As POV-Ray: the metric 1 sum has no absolute values.
    auto dist = [&](DVec3 c) {
        const double dx = c.x - tv.x, dy = c.y - tv.y, dz = c.z - tv.z;
        if (metric == 2.0) return dx * dx + dy * dy + dz * dz;
        if (metric == 1.0) return dx + dy + dz;
        return hdm::pow(fabs(dx), metric) + hdm::pow(fabs(dy), metric) + hdm::pow(fabs(dz), metric);
    };
    DVec3 nearest;
    double best = 0;
    bool first = true;
    for (int ax = -2; ax <= 2; ++ax)
        for (int ay = -2; ay <= 2; ++ay)
            for (int az = -2; az <= 2; ++az) {
                if ((ax == 2 || ax == -2) + (ay == 2 || ay == -2) + (az == 2 || az == -2) > 1)
                    continue;
                const DVec3 sv = pattern_detail::clamp_coords(tv + DVec3(ax, ay, az));
                const DVec3 c =
                    pov_cell_point(int(::floor(sv.x - 1e-10)), int(::floor(sv.y - 1e-10)),
                                   int(::floor(sv.z - 1e-10)));
                const double d = dist(c);
                if (first || d < best) best = d, nearest = c, first = false;
            }
    if (coords == 0) return nearest;
    DVec3 pert = pov_dnoise(nearest);
    const double along = pert.x * t.x + pert.y * t.y + pert.z * t.z;
    pert = pert + t * -along;
    return t + pert * coords;
}

// POV-Ray's four directions its slope normal samples a pattern along (a tetrahedron's).
SHEAF_HD_INLINE DVec3 pyramid_direction(int i) {
    switch (i) {
    case 0:
        return {0.942809041, -0.333333333, 0.0};
    case 1:
        return {-0.471404521, -0.333333333, 0.816496581};
    case 2:
        return {-0.471404521, -0.333333333, -0.816496581};
    default:
        return {0.0, 1.0, 0.0};
    }
}

// The displacement POV-Ray's normal pattern np adds to the unit normal in pattern space at
// pattern-space point q (p the world point, n its normal facing the ray, for slope patterns).
SHEAF_HD_INLINE DVec3 normal_displacement(const SceneView& scene, const NormalPattern& np, Vec3 q,
                                          Vec3 p, Vec3 n) {
    const Pattern& pt = np.pattern;
    const DVec3 d(q);
    const double amount = np.amount;
    switch (np.form) {
    case NormalForm::Bumps: // the vector noise
        return pov_dnoise(d) * amount;
    case NormalForm::Dents: // the vector noise times the noise cubed
    {
        const double v = pov_noise(d, pt.noise_generator);
        return pov_dnoise(d) * (v * v * v * amount);
    }
    case NormalForm::Wrinkles: { // ten octaves of the vector noise's size, component by component
        DVec3 r;
        double scale = 1.0;
        for (int i = 0; i < 10; scale *= 2.0, ++i) {
            const DVec3 v = pov_dnoise(d * scale);
            r = r + DVec3(fabs(v.x / scale), fabs(v.y / scale), fabs(v.z / scale));
        }
        return r * amount;
    }
    case NormalForm::Ripples:
    case NormalForm::Waves: { // towards each wave's centre by the sine of its distance
        DVec3 r;
        PovWaveFrequencies freq;
        const int count = pt.waves;
        for (int i = 0; i < count; ++i) {
            const DVec3 s = pov_wave_source(i);
            const DVec3 v(d.x - s.x, d.y - s.y, d.z - s.z);
            double len = ::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            if (len == 0.0) len = 1.0;
            double scalar;
            if (np.form == NormalForm::Waves) {
                const double f = freq.next();
                scalar =
                    pattern_detail::cycloidal(len * double(pt.frequency) * f + double(pt.phase)) *
                    amount / f;
            } else {
                scalar = pattern_detail::cycloidal(len * double(pt.frequency) + double(pt.phase)) *
                         amount;
            }
            r = r + v * (scalar / (len * count));
        }
        return r;
    }
    case NormalForm::Quilted: // by the quilted cell's scaled offset (POV-Ray's own normal)
        return pattern_detail::quilted_offset(pt, d) * amount;
    case NormalForm::Slope:
        break;
    }
    // Every other pattern: its heights (through the slope map) at four points around q, each
    // pushing the normal against its direction.
    auto height = [&](Vec3 at) {
        const float v = slope_value(scene, pt, at, p, n);
        return np.slope_count > 0
                   ? slope_map_height(scene.slope_entries + np.slope_first, np.slope_count, v)
                   : v;
    };
    const double delta = np.delta;
    const double scaled = amount * -5.0 * (0.02 / delta);
    DVec3 r;
    for (int i = 0; i < 4; ++i) {
        const DVec3 dir = pyramid_direction(i);
        const Vec3 at(float(d.x + delta * dir.x), float(d.y + delta * dir.y),
                      float(d.z + delta * dir.z));
        r = r + dir * (double(height(at)) * scaled);
    }
    return r;
}

/// The unit shading normal n tilted by normal pattern np (its map aside), as POV-Ray tilts it:
/// the normal taken into the pattern's space (by the inverse transpose of its transforms, made
/// unit length unless no_bump_scale), displaced there (normal_displacement), and taken back.
SHEAF_HD_NOINLINE Vec3 tilt_normal(const SceneView& scene, const NormalPattern& np, Vec3 p,
                                   Vec3 n) {
    const Pattern& pt = np.pattern;
    if (pt.kind == PatternKind::Image) return bump_map_normal(scene, np, p, n);
    const Vec3 q = pattern_point(pt, p, scene.warps);
    // Pattern space to the world for normals: the transposes of the pattern's transforms
    // (columns a0, a1, a2); the world's normal goes the other way by its inverse.
    const Vec3 a0 = pattern_gradient_to_world(pt, scene.warps, Vec3(1, 0, 0));
    const Vec3 a1 = pattern_gradient_to_world(pt, scene.warps, Vec3(0, 1, 0));
    const Vec3 a2 = pattern_gradient_to_world(pt, scene.warps, Vec3(0, 0, 1));
    const Vec3 c0 = cross(a1, a2), c1 = cross(a2, a0), c2 = cross(a0, a1);
    const float det = dot(a0, c0);
    if (!(fabsf(det) > 0) || !(fabsf(det) <= FLT_MAX)) return n;
    DVec3 t(dot(n, c0) / det, dot(n, c1) / det, dot(n, c2) / det);
    if (!np.no_bump_scale) {
        const double l = ::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
        if (!(l > 0)) return n;
        t = t * (1.0 / l);
    }
    if (pt.kind == PatternKind::Facets) {
        const double l = ::sqrt(t.x * t.x + t.y * t.y + t.z * t.z); // POV-Ray makes it unit
        if (!(l > 0)) return n;
        t = facets_normal(pt, q, t * (1.0 / l));
    } else {
        t = t + normal_displacement(scene, np, q, p, n);
    }
    const Vec3 out = normalize(a0 * float(t.x) + a1 * float(t.y) + a2 * float(t.z));
    return length_squared(out) > 0 && length_squared(out) <= FLT_MAX ? out : n;
}

} // namespace texture_detail

/// The unit shading normal n tilted by normal pattern `normal` at world point p: by its own
/// slope, or as its normal map says (see NormalPattern).
SHEAF_HD_NOINLINE Vec3 perturb_normal(const SceneView& scene, uint32_t normal, Vec3 p, Vec3 n) {
    using texture_detail::pattern_value;
    using texture_detail::tilt_normal;
    const NormalPattern& np = scene.normal_patterns[normal];
    if (np.map_count == 0) return tilt_normal(scene, np, p, n);
    const NormalMapEntry* e = scene.normal_map_entries + np.map_first;
    auto entry = [&](uint32_t i) {
        return e[i].normal < 0 ? n : tilt_normal(scene, scene.normal_patterns[e[i].normal], p, n);
    };
    Vec3 out;
    if (np.average) {
        out = Vec3(0.0f);
        float weights = 0;
        for (uint32_t i = 0; i < np.map_count; ++i) {
            out += entry(i) * e[i].value;
            weights += e[i].value;
        }
        out = out / weights;
    } else {
        const Pattern& pt = np.pattern;
        const Vec3 q = pattern_point(pt, p, scene.warps);
        if (pattern_is_list(pt.kind)) {
            const uint32_t i = uint32_t(pattern_index_at(pt, q));
            return entry(i < np.map_count ? i : np.map_count - 1);
        }
        const MapSpan m = map_span(e, np.map_count, pattern_value(scene, pt, q, p, n));
        if (m.lo == m.hi) return entry(m.lo);
        out = entry(m.lo) * (1 - m.t) + entry(m.hi) * m.t;
    }
    const float l = length(out);
    return l > 0 && l <= FLT_MAX ? out / l : n;
}

/// What a ray leaving the scene along unit `dir` sees: the sky pigment's layers (one, or a
/// layered pigment's, bottom first), each adding its colour by its opacity and letting what
/// lies below through; the background under them all. As POV-Ray 3.7, what lies below is
/// tinted by each layer's transmitted colour (colour times filter, plus transmit); with
/// Scene::sky_untinted, as POV-Ray before 3.7, weighed by the products of the layers'
/// filters and transmits alone.
SHEAF_HD_NOINLINE Vec3 sky_color(const SceneView& scene, Vec3 dir) {
    if (scene.sky < 0) return scene.background;
    const Pigment& pg = scene.pigments[scene.sky];
    const texture_detail::Evaluator ev{scene, 0, 0, Vec3(0.0f)};
    const uint32_t n = pg.layers ? pg.count : 1;
    Vec3 col(0.0f), through(1.0f), tint(1.0f);
    float filter = 1, transmit = 1, pass = 1;
    for (uint32_t i = n; i-- > 0;) { // top first
        const SurfaceColor c = pg.layers ? ev.entry(scene.pigment_entries[pg.first + i], dir, 0)
                                         : ev.pigment(uint32_t(scene.sky), dir, 0);
        const float opacity = 1.0f - c.filter - c.transmit;
        if (scene.sky_untinted) {
            col += c.rgb * (pass * opacity);
            tint = tint * c.rgb, filter *= c.filter, transmit *= c.transmit;
            pass = fabsf(filter) + fabsf(transmit);
        } else {
            col += c.rgb * opacity * through;
            through = through * (c.rgb * c.filter + Vec3(c.transmit));
        }
    }
    if (scene.sky_untinted) through = tint * filter + Vec3(transmit);
    return col + scene.background * through;
}

} // namespace sheaf

// The camera, light sources, global_settings, background and the atmospheric blocks the core
// cannot show (warned), and the top level: statements and declared values.
#include "io/pov/parser.h"

#include "core/base/error.h"
#include "core/settings/settings.h"
#include "core/texture/pov_noise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace sheaf::io::pov {

/// The narrowest camera angle read, in degrees: below it float rays fall on one direction.
constexpr double kMinCameraAngle = 1e-4;

namespace {

/// The projection a camera type keyword names (cylinder: the first of the four), or null.
const Projection* camera_type(const std::string& k) {
    static const std::pair<const char*, Projection> kTypes[] = {
        {"perspective", Projection::Perspective}, {"orthographic", Projection::Orthographic},
        {"fisheye", Projection::Fisheye},         {"ultra_wide_angle", Projection::UltraWideAngle},
        {"omnimax", Projection::Omnimax},         {"panoramic", Projection::Panoramic},
        {"cylinder", Projection::Cylinder1},      {"spherical", Projection::Spherical}};
    for (const auto& [name, type] : kTypes)
        if (k == name) return &type;
    return nullptr;
}

} // namespace

void Parser::parse_camera(PovCamera& c) {
    const Token brace = peek();
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Camera, declared, "a camera")) c = declared.as<PovCamera>();
    c.where = brace;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        Affine m;
        if (parse_transform_item(m)) {
            c.transform = m * c.transform;
            continue;
        }
        if (t.kind != TokKind::Ident) error_expected(t, "a camera item or '}'");
        const std::string& k = t.text;
        advance();
        if (const Projection* type = camera_type(k)) {
            c.projection = *type;
            c.type_at = t;
            if (k == "cylinder") {
                const Token& at = peek();
                const double n = parse_float();
                if (!(n == 1 || n == 2 || n == 3 || n == 4))
                    error_at(at, "a cylinder camera's type must be 1, 2, 3 or 4, not " +
                                     format_number(n));
                c.projection = Projection(int(Projection::Cylinder1) + int(n) - 1);
            }
        } else if (k == "location")
            c.location = parse_vector();
        else if (k == "look_at")
            c.look_at = parse_vector(), c.has_look_at = true;
        else if (k == "right")
            c.right = parse_vector(), c.has_right = true;
        else if (k == "up")
            c.up = parse_vector(), c.has_up = true;
        else if (k == "direction")
            c.direction = parse_vector();
        else if (k == "sky")
            c.sky = parse_vector();
        else if (k == "angle") {
            const Token& at = peek();
            c.angle = parse_float();
            if (!(c.angle == 0 || camera_angle_ok(c.angle))) // 0: not given
                error_at(at, "a camera's angle must lie between 0 and 3600 degrees");
            // Single-precision rays no longer tell the pixels apart (animations/fractalzoom
            // zooms to 2e-13 degrees): an error, not a picture of one colour.
            if (c.angle > 0 && c.angle < kMinCameraAngle) {
                char text[96];
                std::snprintf(text, sizeof text, "a camera's angle of %g degrees is below the %g",
                              c.angle, kMinCameraAngle);
                error_at(at,
                         std::string(text) + " degrees that Sheaf's single-precision rays resolve");
            }
            if (accept_sym(",")) { // spherical: the vertical angle
                const Token& v = peek();
                c.v_angle = parse_float();
                if (!(c.v_angle == 0 || camera_angle_ok(c.v_angle)))
                    error_at(v, "a camera's vertical angle must lie between 0 and 3600 degrees");
            }
        } else if (k == "aperture") {
            const Token& at = peek();
            c.aperture = parse_float();
            c.aperture_at = t;
            if (!(c.aperture >= 0 && c.aperture < 1e30))
                error_at(at, "a camera's aperture must be a finite number >= 0");
        } else if (k == "focal_point") {
            c.focal_point = parse_vector();
        } else if (k == "blur_samples") {
            // blur_samples [MIN,] MAX: Sheaf always takes about MAX (no adaptive stop).
            const Token& at = peek();
            double n = parse_float();
            if (accept_sym(",")) n = parse_float();
            if (!(n >= 1 && n <= 1e6))
                error_at(at, "a camera's blur_samples must be a number from 1 to 1000000");
            c.blur_samples = int(n);
        } else if (k == "confidence" || k == "variance") {
            parse_float(); // POV-Ray's adaptive stop: Sheaf takes every sample
        } else if (k == "bokeh") {
            unsupported(t, "camera bokeh (a round lens is used)");
            skip_block();
        } else if (k == "mesh_camera") {
            c.projection = Projection::Mesh;
            c.type_at = t;
            parse_mesh_camera(t, c);
        } else if (k == "normal") {
            c.normal = parse_normal(c.normal.get());
        } else {
            error_expected(t, "a camera item (location, look_at, angle ...)");
        }
    }
}

void Parser::parse_mesh_camera(const Token& kw, PovCamera& c) {
    expect_sym("{");
    const Token& rays_at = peek();
    const double rays = parse_float();
    if (!(rays >= 1 && rays <= double(kMaxMeshCameraRays)))
        error_at(rays_at, "a mesh camera takes 1 to " + std::to_string(kMaxMeshCameraRays) +
                              " rays per pixel");
    accept_sym(",");
    const Token& dist_at = peek();
    const double dist = parse_float();
    if (!(dist == 0 || dist == 1 || dist == 2 || dist == 3))
        error_at(dist_at, "a mesh camera's distribution must be 0, 1, 2 or 3");
    c.mesh_rays = int(rays), c.mesh_distribution = int(dist);
    if (c.mesh_distribution >= 2 && c.mesh_rays != 1)
        error_at(rays_at, "a mesh camera of distribution 2 or 3 takes 1 ray per pixel");
    accept_sym(",");
    if (starts_expression(peek())) { // the longest ray
        const Token& at = peek();
        if (parse_float() != 0) unsupported(at, "mesh_camera's maximum ray distance (ignored)");
    }
    c.meshes.clear();
    c.mesh_smooth = false;
    for (;;) {
        const Token& t = peek();
        if (accept_kw("mesh") || accept_kw("mesh2")) {
            PovObject m;
            if (t.text == "mesh")
                parse_mesh(t, m);
            else
                parse_mesh2(t, m);
            c.meshes.push_back(std::move(m));
        } else if (accept_kw("smooth")) {
            if (c.mesh_distribution != 3)
                error_at(t, "a mesh camera's smooth needs distribution 3");
            c.mesh_smooth = true;
        } else if (!c.meshes.empty() && accept_sym("}")) {
            break;
        } else {
            error_expected(t, c.meshes.empty() ? "mesh or mesh2" : "mesh, mesh2, smooth or '}'");
        }
    }
    if (c.mesh_distribution == 0 && size_t(c.mesh_rays) > c.meshes.size())
        error_at(rays_at, "a mesh camera of distribution 0 takes at most one ray per pixel per "
                          "mesh (" +
                              std::to_string(c.mesh_rays) + " rays, " +
                              std::to_string(c.meshes.size()) + " meshes)");
    if (c.mesh_distribution == 3 && c.meshes[0].mesh->uvs.empty())
        error_at(kw, "a mesh camera of distribution 3 needs its first mesh's uv_vectors");
}

void Parser::parse_light(const Token& kw, PovObject& o) {
    o.kind = PovKind::Light;
    o.where = kw;
    expect_sym("{");
    Value declared;
    const Token& first = peek();
    if (accept_declared(VType::Object, declared, "a light")) {
        if (declared.as<PovObject>().kind != PovKind::Light) error_expected(first, "a light");
        o = declared.as<PovObject>();
    } else {
        o.light.light.position = parse_vector();
        accept_sym(",");
        const Color5 c = parse_color();
        o.light.light.color = Vec3(float(c[0]), float(c[1]), float(c[2]));
    }
    PovLight& l = o.light;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        Affine m;
        if (parse_transform_item(m)) {
            apply_transform(o, m);
            continue;
        }
        if (t.kind != TokKind::Ident) error_expected(t, "a light item or '}'");
        const std::string& k = t.text;
        advance();
        if (k == "spotlight")
            l.light.type = LightType::Spot;
        else if (k == "parallel")
            l.light.type = LightType::Parallel;
        else if (k == "cylinder") {
            unsupported(t, "cylindrical light (a spotlight is used)");
            l.light.type = LightType::Spot;
        } else if (k == "point_at")
            l.point_at = parse_vector();
        else if (k == "radius")
            l.light.spot_radius = float(parse_float());
        else if (k == "falloff")
            l.light.spot_falloff = float(parse_float());
        else if (k == "tightness")
            l.light.spot_tightness = float(parse_float());
        else if (k == "fade_distance")
            l.light.fade_distance = float(parse_float());
        else if (k == "fade_power")
            l.light.fade_power = float(parse_float());
        else if (k == "shadowless") // POV-Ray's fill light: no shadow and no highlight
            l.light.shadowless = true, l.light.highlights = false;
        else if (k == "area_light") {
            l.area = true;
            l.axis1 = parse_vector();
            accept_sym(",");
            l.axis2 = parse_vector();
            accept_sym(",");
            l.n1 = std::max(1, int(parse_float()));
            accept_sym(",");
            l.n2 = std::max(1, int(parse_float()));
            if (size_t(l.n1) * size_t(l.n2) > 4096)
                error_at(t, "an area light of more than 4096 samples");
        } else if (k == "adaptive") {
            parse_float();
        } else if (k == "area_illumination") {
            l.area_illumination = parse_bool_opt(true);
        } else if (k == "media_interaction") {
            l.light.media_interaction = parse_bool_opt(true);
        } else if (k == "media_attenuation") { // the atmosphere's media fade its light
            l.light.media_attenuation = parse_bool_opt(true);
        } else if (k == "jitter" || k == "circular" || k == "orient") {
            parse_bool_opt(true);
        } else if (k == "looks_like") {
            // Modelled around the origin; the builder places it at the light, casting no
            // shadow (it holds the light).
            PovObject shape;
            const bool ok = parse_object_block(shape);
            o.children.clear();
            if (ok) {
                shape.flags |= kNoShadow;
                o.children.push_back(std::move(shape));
            }
        } else if (k == "projected_through") {
            unsupported(t, k + " (ignored)");
            skip_block();
        } else if (k == "photons") {
            parse_light_photons(l.light);
        } else {
            error_expected(t, "a light item (spotlight, point_at, area_light ...)");
        }
    }
}

void Parser::parse_global_settings() {
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (t.kind != TokKind::Ident) error_expected(t, "a global setting or '}'");
        const std::string& k = t.text;
        advance();
        if (k == "assumed_gamma") {
            const Token& at = peek();
            model.assumed_gamma = parse_float();
            // The working space's gamma (Scene::working_gamma): POV-Ray's range of use.
            if (!(model.assumed_gamma >= 0.1 && model.assumed_gamma <= 10))
                error_at(at, "assumed_gamma must lie between 0.1 and 10");
        } else if (k == "max_trace_level") {
            model.max_trace_level = int(parse_float());
        } else if (k == "ambient_light") {
            const Color5 c = parse_color();
            model.ambient_light = {c[0], c[1], c[2]};
        } else if (k == "radiosity") {
            const Token at = t; // the block's tokens come after it
            parse_radiosity();
            approximated(at, "radiosity: gathered anew at every pixel with " +
                                 std::to_string(model.radiosity_count) +
                                 " rays, where POV-Ray interpolates a cache of samples (the "
                                 "light agrees, its grain and the cache's smoothing do not)");
        } else if (k == "photons") {
            parse_photon_settings();
        } else if (k == "subsurface") {
            unsupported(t, k);
            if (is_sym_tok(peek(), "{")) skip_block();
        } else if (k == "irid_wavelength") {
            const Token& at = peek();
            const Color5 c = parse_color();
            if (!(c[0] > 0 && c[1] > 0 && c[2] > 0) || !std::isfinite(c[0] + c[1] + c[2]))
                error_at(at, "irid_wavelength's components must be positive numbers");
            model.irid_wavelength = {c[0], c[1], c[2]};
        } else if (k == "charset") {
            next();
        } else if (k == "noise_generator") { // as POV-Ray: 1, 2 or 3
            const Token& at = peek();
            const double g = parse_float();
            if (!(g >= 1 && g < 4)) error_at(at, "global noise_generator must be 1, 2 or 3");
            model.noise_generator = int(g);
        } else if (k == "number_of_waves") { // as POV-Ray: below 1 is 1
            const Token& at = peek();
            const double n = parse_float();
            if (!std::isfinite(n)) error_at(at, "number_of_waves must be a number");
            model.number_of_waves = int(std::clamp(n, 1.0, double(kPovMostWaves)));
            if (n < 1 || n >= kPovMostWaves + 1)
                warn(at, "number_of_waves " + format_number(n) + " is clamped to " +
                             std::to_string(model.number_of_waves) + " (1.." +
                             std::to_string(kPovMostWaves) + ")");
        } else if (k == "adc_bailout") {
            const Token& at = peek();
            const double b = parse_float();
            if (!(b >= 0 && b <= 1)) error_at(at, "adc_bailout must lie between 0 and 1");
            model.adc_bailout = b;
        } else if (k == "max_intersections" || k == "hf_gray_16" || k == "mm_per_unit") {
            if (starts_expression(peek())) parse_expr();
        } else {
            error_expected(t, "a global setting (assumed_gamma, max_trace_level ...)");
        }
    }
}

double Parser::radiosity_in_range(const Token& at, const std::string& name, std::string_view key,
                                  double v) {
    // POV-Ray takes any positive count and recursion_limit (and clamps them itself); Sheaf
    // renders what the settings registry allows, so a larger value is clamped with a warning
    // naming the range, and a NaN is an error.
    const SettingSpec* spec = find_setting(key);
    if (!std::isfinite(v)) error_at(at, "a radiosity " + name + " must be a finite number");
    if (v <= spec->max) return v;
    warn(at, "radiosity " + name + " " + format_number(v) + " is clamped to " +
                 format_number(spec->max) + " (" + std::string(key) + " is " +
                 describe_allowed(*spec) + ")");
    return spec->max;
}

void Parser::parse_radiosity() {
    // Sheaf gathers at every point (no irradiance cache), so the cache's settings change
    // nothing and are read and dropped; what changes the picture is kept or warned.
    static const std::set<std::string> cache = {
        "pretrace_start", "pretrace_end",  "error_bound",     "low_error_factor",
        "minimum_reuse",  "maximum_reuse", "nearest_count",   "always_sample",
        "max_sample",     "adc_bailout",   "distance_maximum"};
    model.radiosity = true;
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (t.kind != TokKind::Ident) error_expected(t, "a radiosity setting or '}'");
        const std::string k = t.text;
        advance();
        if (k == "count") {
            const Token& at = peek();
            const double c = parse_float();
            if (!(c >= 1)) error_at(at, "a radiosity count must be a positive number");
            model.radiosity_count = int(radiosity_in_range(at, "count", "radiosity.samples", c));
            if (accept_sym(",")) parse_float(); // the number of directions to draw from
        } else if (k == "recursion_limit") {
            const Token& at = peek();
            const double d = parse_float();
            if (!(d >= 1)) error_at(at, "a radiosity recursion_limit must be a positive number");
            model.radiosity_depth = int(radiosity_in_range(at, k, "radiosity.depth", d));
        } else if (k == "brightness") {
            const Token& at = peek();
            const double v = parse_float();
            if (!(v >= 0)) error_at(at, "a radiosity brightness must not be negative");
            model.radiosity_brightness = radiosity_in_range(at, k, "radiosity.brightness", v);
        } else if (k == "gray_threshold") {
            const Token& at = peek();
            if (parse_float() != 0) unsupported(at, "radiosity gray_threshold (ignored)");
        } else if (k == "normal" || k == "media" || k == "subsurface") {
            if (parse_bool_opt(true)) unsupported(t, "radiosity " + k + " on (ignored)");
        } else if (k == "save_file" || k == "load_file") {
            parse_string();
        } else if (cache.count(k)) {
            if (k == "always_sample") {
                parse_bool_opt(true);
            } else {
                parse_float();
                if (k == "nearest_count" && accept_sym(",")) parse_float();
            }
        } else {
            error_expected(t, "a radiosity setting (count, recursion_limit, brightness ...)");
        }
    }
}

void Parser::parse_background() {
    expect_sym("{");
    model.background = parse_color();
    expect_sym("}");
}

PovSky Parser::parse_sky_sphere() {
    // Its pigments, layered (later ones on top), seen along each ray that leaves the scene.
    expect_sym("{");
    PovSky sky;
    Value declared;
    if (accept_declared(VType::Other, declared, "a sky_sphere")) {
        if (declared.str != "sky_sphere") error_expected(peek(), "a sky_sphere identifier");
        sky = declared.as<PovSky>();
    }
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        Affine m;
        if (parse_transform_item(m)) {
            sky.local = m * sky.local;
            continue;
        }
        if (accept_kw("pigment")) {
            auto pg = std::make_shared<PovPigment>(*parse_pigment(PovPigment{}));
            // Transforms before a pigment do not move it: it starts in the sky's space now.
            if (std::fabs(sky.local.determinant()) > 1e-30f)
                pg->local = sky.local.inverse() * pg->local;
            sky.pigments.push_back(pg);
        } else if (accept_kw("emission")) {
            parse_color();
        } else {
            error_expected(t, "pigment, emission, a transform or '}'");
        }
    }
    return sky;
}

void Parser::parse_atmospheric(const Token& kw) {
    if (kw.text == "sky_sphere") {
        model.sky = parse_sky_sphere();
        return;
    }
    if (kw.text == "fog") {
        expect_sym("{");
        int type = 1;
        PovModel::Fog fog;
        Vec3 up(0, 1, 0);
        Affine transform;
        for (;;) {
            const Token& t = peek();
            if (accept_sym("}")) break;
            Affine m;
            if (parse_transform_item(m)) { // turns the ground fog's up vector
                transform = m * transform;
                continue;
            }
            if (accept_kw("fog_type")) {
                type = int(parse_float());
            } else if (accept_kw("distance")) {
                fog.distance = parse_float();
            } else if (is_color_start(t)) {
                fog.color = parse_color();
            } else if (accept_kw("fog_offset")) {
                fog.offset = parse_float();
            } else if (accept_kw("fog_alt")) {
                const Token& at = peek();
                fog.alt = parse_float();
                if (!(fog.alt > 0)) error_at(at, "fog_alt must be greater than 0");
            } else if (accept_kw("up")) {
                const Token& at = peek();
                up = parse_vector();
                if (!(length(up) > 0)) error_at(at, "the fog's up vector must not be zero");
            } else if (accept_kw("turbulence")) {
                fog.turb = parse_vector();
            } else if (accept_kw("octaves")) {
                fog.octaves = parse_octaves();
            } else if (accept_kw("omega")) {
                fog.omega = parse_float();
            } else if (accept_kw("lambda")) {
                fog.lambda = parse_float();
            } else if (accept_kw("turb_depth")) {
                fog.turb_depth = parse_float();
            } else {
                error_expected(t, "a fog item (distance, color, fog_type ...)");
            }
        }
        if (type != 1 && type != 2)
            error_at(kw, "fog_type " + std::to_string(type) + " is not 1 (constant) or 2 (ground)");
        if (type != 2)
            fog.alt = 0;
        else if (!(fog.alt > 0))
            fog.alt = 1;
        fog.up = normalize(transform.vector(up));
        if (!(length(fog.up) > 0)) error_at(kw, "the fog's up vector must not be zero");
        if (!(fog.distance > 0)) return; // POV-Ray leaves out a fog of no distance
        if (model.fogs.size() == Fogs::kMax)
            unsupported(kw, "fog beyond the " + std::to_string(Fogs::kMax) +
                                " Sheaf lays over each other (left out)");
        else
            model.fogs.push_back(fog);
        return;
    }
    if (kw.text == "rainbow") {
        parse_rainbow(kw);
        return;
    }
    if (kw.text == "media") { // the atmosphere's; several add up, as in POV-Ray
        model.atmosphere.push_back(parse_media());
        return;
    }
    unsupported(kw, kw.text);
    skip_block();
}

void Parser::parse_rainbow(const Token& kw) {
    expect_sym("{");
    PovModel::Rainbow r;
    bool arc = false, falloff = false;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (accept_kw("angle")) {
            r.angle = parse_float();
        } else if (accept_kw("width")) {
            r.width = parse_float();
        } else if (accept_kw("distance")) {
            r.distance = parse_float();
            if (!(r.distance > 0)) error_at(t, "a rainbow's distance must be greater than 0");
        } else if (accept_kw("jitter")) {
            r.jitter = std::fabs(parse_float());
        } else if (accept_kw("direction")) {
            r.direction = parse_vector();
        } else if (accept_kw("up")) {
            r.up = parse_vector();
        } else if (accept_kw("arc_angle") || accept_kw("falloff_angle")) {
            const double a = parse_float();
            if (!(a >= 0 && a <= 360))
                error_at(t, "a rainbow's " + t.text + " must lie between 0 and 360 degrees");
            (t.text == "arc_angle" ? r.arc : r.falloff) = a;
            (t.text == "arc_angle" ? arc : falloff) = true;
        } else if (accept_kw("color_map") || accept_kw("colour_map")) {
            auto pg = std::make_shared<PovPigment>();
            pg->patterned = true;
            pg->pattern.kind = PatternKind::Gradient;
            pg->pattern.vector = Vec3(1, 0, 0);
            pg->entries = parse_color_map();
            r.colors = std::move(pg);
        } else {
            error_expected(t, "a rainbow item (angle, width, distance, direction, color_map ...)");
        }
    }
    if (arc && !falloff) r.falloff = r.arc; // POV-Ray: no fading unless a falloff is given
    if (r.falloff > r.arc) error_at(kw, "a rainbow's arc_angle is smaller than its falloff_angle");
    if (!(length(r.direction) > 0)) error_at(kw, "a rainbow's direction must not be zero");
    if (!(length(r.up) > 0)) error_at(kw, "a rainbow's up vector must not be zero");
    if (length(cross(r.direction, r.up)) <= 1e-6f * length(r.direction) * length(r.up))
        error_at(kw, "a rainbow's up vector must not lie along its direction");
    model.rainbows.push_back(std::move(r));
}

Value Parser::parse_rvalue() {
    const Token& t = peek();
    if (t.kind == TokKind::Ident && !lookup(t)) {
        const std::string& k = t.text;
        if (is_object_start(t)) {
            PovObject o;
            if (!parse_object(o)) { // unsupported: a marker, so that uses are skipped
                Value v;
                v.type = VType::Other;
                v.str = "object";
                return v;
            }
            return Value::boxed(VType::Object, std::move(o));
        }
        if (k == "texture") {
            advance();
            return Value::boxed(VType::Texture,
                                PovTexture(*parse_texture_layers(model.default_texture)));
        }
        if (k == "material") {
            advance();
            PovObject holder;
            holder.kind = PovKind::Csg;
            expect_sym("{");
            bool texture_here = false;
            while (!accept_sym("}"))
                if (!parse_modifier(holder, texture_here))
                    error_expected(peek(), "texture, interior or '}' in material");
            return Value::boxed(VType::Material, PovMaterial{holder.texture, holder.interior});
        }
        if (k == "pigment") {
            advance();
            return Value::boxed(VType::Pigment, PovPigment(*parse_pigment(PovPigment{})));
        }
        if (k == "normal") {
            advance();
            std::shared_ptr<const PovNormal> n = parse_normal(nullptr);
            if (!n) { // a normal that changes nothing (unsupported pattern): declared as flat
                Value v;
                v.type = VType::Other;
                v.str = "normal";
                return v;
            }
            return Value::boxed(VType::Normal, PovNormal(*n));
        }
        if (k == "finish") {
            advance();
            PovFinish f = model.default_texture.finish;
            parse_finish(f);
            return Value::boxed(VType::Finish, f);
        }
        if (k == "interior") {
            advance();
            return Value::boxed(VType::Interior, parse_interior(PovInterior{}));
        }
        if (k == "color_map" || k == "colour_map") {
            advance();
            return Value::boxed(VType::ColorMap, parse_color_map());
        }
        if (k == "pigment_map") {
            advance();
            Value v = Value::boxed(VType::Other, parse_pigment_map());
            v.str = k;
            return v;
        }
        if (k == "normal_map") {
            advance();
            Value v = Value::boxed(VType::Other, parse_normal_map(t, false));
            v.str = k;
            return v;
        }
        if (k == "slope_map") {
            advance();
            Value v = Value::boxed(VType::Other, parse_slope_map());
            v.str = k;
            return v;
        }
        if (k == "media") {
            advance();
            Value v = Value::boxed(VType::Other, parse_media());
            v.str = k;
            return v;
        }
        if (k == "density") { // a pigment whose colour multiplies a medium
            advance();
            return Value::boxed(VType::Pigment, parse_density());
        }
        if (k == "texture_map") {
            advance();
            Value v = Value::boxed(VType::Other, parse_texture_map());
            v.str = k;
            return v;
        }
        if (k == "camera") {
            advance();
            PovCamera c;
            parse_camera(c);
            return Value::boxed(VType::Camera, c);
        }
        if (k == "sky_sphere") {
            advance();
            Value v = Value::boxed(VType::Other, parse_sky_sphere());
            v.str = k;
            return v;
        }
        if (k == "spline") {
            advance();
            Value v = Value::boxed(VType::Other, parse_spline());
            v.str = k;
            return v;
        }
        if (k == "fog" || k == "media" || k == "rainbow" || k == "density" ||
            k == "interior_texture" || k == "density_map" || k == "photons" || k == "radiosity" ||
            k == "material_map") {
            advance();
            Value v;
            v.type = VType::Other;
            v.str = k;
            skip_block(); // declared only; a use is warned where it happens
            return v;
        }
    }
    return parse_expr();
}

bool Parser::parse_statement() {
    const Token& t = peek();
    if (t.kind == TokKind::End) return false;
    if (is_sym_tok(t, ";")) { // stray semicolons after directives
        advance();
        return true;
    }
    if (is_object_start(t)) {
        PovObject o;
        if (parse_object(o)) {
            // Placed objects stay until the scene is built: they count against the data
            // budget (10 million spheres in a loop took 5.6 GB before the loop limit). The
            // objects inside were charged as their CSG took them.
            charge(object_bytes(o), t);
            model.objects.push_back(std::move(o));
        }
        return true;
    }
    if (t.kind != TokKind::Ident) error_expected(t, "an object, camera, light_source or directive");
    const std::string& k = t.text;
    if (k == "camera") {
        advance();
        parse_camera(model.camera);
        model.has_camera = true;
    } else if (k == "global_settings") {
        advance();
        parse_global_settings();
    } else if (k == "default") { // the old spelling of #default
        advance();
        default_directive();
    } else if (k == "background") {
        advance();
        parse_background();
    } else if (k == "sky_sphere" || k == "fog" || k == "rainbow" || k == "media" ||
               k == "photons" || k == "radiosity") {
        advance();
        parse_atmospheric(t);
    } else {
        error_expected(t, "an object, camera, light_source or directive");
    }
    return true;
}

} // namespace sheaf::io::pov

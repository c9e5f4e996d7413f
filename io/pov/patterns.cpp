// Patterns: the pattern keywords of pigments, normals and textures with their arguments, and
// the modifiers every pattern takes (turbulence, octaves, omega, lambda, frequency, phase, the
// waves, the warps, transforms).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <map>

namespace sheaf::io::pov {

namespace {

// The kinds Sheaf shows; a list pattern's entries: pattern_list_size (core/scene/pattern.h).
const std::map<std::string, PatternKind>& supported_patterns() {
    static const std::map<std::string, PatternKind> m = {
        {"agate", PatternKind::Agate},
        {"boxed", PatternKind::Boxed},
        {"bozo", PatternKind::Bozo},
        {"spotted", PatternKind::Bozo},
        {"bumps", PatternKind::Bozo},
        {"brick", PatternKind::Brick},
        {"cells", PatternKind::Cells},
        {"checker", PatternKind::Checker},
        {"crackle", PatternKind::Crackle},
        {"cylindrical", PatternKind::Cylindrical},
        {"dents", PatternKind::Dents},
        {"gradient", PatternKind::Gradient},
        {"granite", PatternKind::Granite},
        {"hexagon", PatternKind::Hexagon},
        {"leopard", PatternKind::Leopard},
        {"marble", PatternKind::Marble},
        {"onion", PatternKind::Onion},
        {"planar", PatternKind::Planar},
        {"quilted", PatternKind::Quilted},
        {"radial", PatternKind::Radial},
        {"ripples", PatternKind::Ripples},
        {"spherical", PatternKind::Spherical},
        {"spiral1", PatternKind::Spiral1},
        {"spiral2", PatternKind::Spiral2},
        {"square", PatternKind::Square},
        {"triangular", PatternKind::Triangular},
        {"waves", PatternKind::Waves},
        {"wood", PatternKind::Wood},
        {"wrinkles", PatternKind::Wrinkles},
        {"function", PatternKind::Function},
        {"mandel", PatternKind::Mandel},
        {"julia", PatternKind::Julia},
        {"magnet", PatternKind::Mandel}, // magnet 1 mandel 50, magnet 2 julia <c>, 50
        {"slope", PatternKind::Slope},
        {"pigment_pattern", PatternKind::PigmentPattern},
        {"image_pattern", PatternKind::ImagePattern},
        {"density_file", PatternKind::DensityFile},
        {"facets", PatternKind::Facets},
    };
    return m;
}

// Patterns Sheaf reads but cannot show; the number of list entries they take.
const std::map<std::string, int>& unsupported_patterns() {
    static const std::map<std::string, int> m = {
        {"aoi", 0}, {"cubic", 6}, {"object", 2}, {"pavement", 0}, {"tiling", 0}, {"fractal", 0},
    };
    return m;
}

} // namespace

bool Parser::is_pattern_name(const Token& t) const {
    return t.kind == TokKind::Ident &&
           (supported_patterns().count(t.text) || unsupported_patterns().count(t.text));
}

bool Parser::parse_pattern_name(PovPattern& pt, int& list, bool& supported) {
    const Token& t = peek();
    if (!is_pattern_name(t)) return false;
    advance();
    const std::string& k = t.text;
    if (auto it = supported_patterns().find(k); it != supported_patterns().end()) {
        supported = true;
        pt.kind = it->second;
        list = pattern_list_size(pt.kind);
        // Marble, wood and the spirals are triangle-waved unless the scene says otherwise.
        if (!pt.wave_given)
            pt.wave = (pt.kind == PatternKind::Marble || pt.kind == PatternKind::Wood ||
                       pt.kind == PatternKind::Spiral1 || pt.kind == PatternKind::Spiral2)
                          ? Wave::Triangle
                          : Wave::Ramp;
        if (k == "gradient") pt.vector = parse_vector();
        if (k == "crackle") { // POV-Ray's defaults: form <-1, 1, 0>, metric 2, offset 0
            pt.vector = Vec3(-1, 1, 0);
            pt.param[0] = 2, pt.param[1] = 0, pt.param[2] = 0;
        }
        if (k == "function") { // its body, or a declared function called over x, y, z
            const Value f = parse_function(t);
            pt.function = std::static_pointer_cast<const PovFunction>(f.ptr);
            if (pt.function->params.size() != 3 && pt.function->scene_unsupported.empty())
                error_at(t, "a function pattern's function must take x, y and z");
            supported = pt.function->scene_unsupported.empty();
        }
        if (k == "spiral1" || k == "spiral2") pt.param[0] = parse_float();
        if (k == "pigment_pattern") pt.pigment = parse_pigment(PovPigment{});
        if (k == "image_pattern") pt.image = parse_image_pattern(t);
        if (k == "density_file") pt.density = parse_density_file(t);
        if (k == "facets") { // POV-Ray's defaults: size 0.1, over the normal, metric 2
            pt.param[0] = 0.1, pt.param[2] = 2;
            for (;;) {
                const Token& m = peek();
                if (accept_kw("coords")) {
                    pt.param[1] = parse_float();
                } else if (accept_kw("size")) {
                    pt.param[0] = parse_float();
                    if (!(pt.param[0] > 0)) error_at(m, "a facets size must be above 0");
                } else if (accept_kw("metric")) { // a vector, of which POV-Ray takes x
                    const Value v = parse_expr();
                    if (!v.numeric()) error_expected(m, "a number or a vector after 'metric'");
                    pt.param[2] = v.v[0];
                    if (!(pt.param[2] > 0 && std::isfinite(pt.param[2])))
                        error_at(m, "facets' metric must be a positive number");
                } else {
                    break;
                }
            }
        }
        if (k == "mandel" || k == "julia" || k == "magnet") parse_fractal(pt, k);
        if (k == "slope") parse_slope(pt, t);
        if (k == "quilted") { // POV-Ray's: control points 1 and 1, and no frequency
            pt.param[0] = 1, pt.param[1] = 1;
            pt.frequency = 0;
        }
        return true;
    }
    supported = false;
    list = unsupported_patterns().at(k);
    // Their arguments: a block (function, object, pigment_pattern ...) or numbers.
    if (is_sym_tok(peek(), "{")) {
        skip_block();
    } else if (k == "tiling" || k == "pavement") {
        if (starts_expression(peek())) parse_float();
    } else if (k == "aoi") {
        if (starts_expression(peek())) parse_expr();
    }
    if (k == "object" && is_sym_tok(peek(), "{")) skip_block();
    return true;
}

void Parser::only_in_normals(const Token& t, const PovPattern& pt) const {
    if (pt.kind == PatternKind::Facets)
        error_at(t, "facets is a normal pattern; a pigment, texture, density or function "
                    "cannot take it (nor can POV-Ray's)");
}

int Parser::parse_octaves() {
    const double n = parse_float();
    return n > 10 ? 10 : n >= 1 ? int(n) : 1; // NaN: 1
}

bool Parser::parse_pattern_modifier(PovPattern& pt, Affine& local) {
    Affine m;
    if (parse_transform_item(m)) {
        local = m * local;
        return true;
    }
    const Token& t = peek();
    if (t.kind != TokKind::Ident) return false;
    const std::string& k = t.text;
    auto turbulence = [&]() {
        const Value v = parse_expr();
        pt.turbulence = v.type == VType::Float ? Vec3(float(v.v[0]))
                                               : Vec3(float(v.v[0]), float(v.v[1]), float(v.v[2]));
        pt.has_turbulence = pt.turbulence.x != 0 || pt.turbulence.y != 0 || pt.turbulence.z != 0;
    };
    if (k == "turbulence") {
        advance();
        turbulence();
    } else if (k == "octaves") {
        advance();
        pt.octaves = parse_octaves();
    } else if (k == "omega") {
        advance();
        pt.omega = parse_float();
    } else if (k == "lambda") {
        advance();
        pt.lambda = parse_float();
    } else if (k == "interpolate" && pt.kind == PatternKind::DensityFile && pt.density) {
        advance();
        const double v = parse_float();
        if (v != 0 && v != 1 && v != 2)
            error_at(t, "a density_file's interpolate is 0 (none), 1 (trilinear) or 2 "
                        "(tricubic)");
        auto d = std::make_shared<PovDensity>(*pt.density);
        d->interpolation = int(v);
        pt.density = std::move(d);
    } else if (k == "frequency") {
        advance();
        pt.frequency = parse_float();
    } else if (k == "phase") {
        advance();
        pt.phase = parse_float();
    } else if (k == "ramp_wave" || k == "triangle_wave" || k == "sine_wave" ||
               k == "scallop_wave" || k == "cubic_wave" || k == "poly_wave") {
        advance();
        pt.wave_given = true;
        pt.wave = k == "ramp_wave"       ? Wave::Ramp
                  : k == "triangle_wave" ? Wave::Triangle
                  : k == "sine_wave"     ? Wave::Sine
                  : k == "scallop_wave"  ? Wave::Scallop
                  : k == "cubic_wave"    ? Wave::Cubic
                                         : Wave::Poly;
        if (pt.wave == Wave::Poly && starts_expression(peek())) pt.wave_exponent = parse_float();
    } else if (k == "agate_turb") {
        advance();
        pt.param[0] = parse_float();
    } else if (k == "brick_size") {
        advance();
        const Vec3 s = parse_vector();
        pt.param[0] = s.x, pt.param[1] = s.y, pt.param[2] = s.z;
    } else if (k == "mortar") {
        advance();
        pt.param[3] = parse_float();
    } else if (k == "warp") {
        advance();
        parse_warp(pt, local);
    } else if (k == "exponent" || k == "interior" || k == "exterior") {
        advance();
        parse_fractal_modifier(t, pt.fractal);
    } else if (k == "noise_generator") { // 0: the scene's, as POV-Ray reads it
        advance();
        const Token& at = peek();
        const double g = parse_float();
        if (!(g >= 0 && g < 4)) error_at(at, "noise_generator must be 0, 1, 2 or 3");
        pt.noise_generator = int(g);
    } else if (pt.kind == PatternKind::Crackle && (k == "form" || k == "metric")) {
        advance(); // form: the weights of the nearest three distances; metric: its x
        const Value v = parse_expr();
        if (v.type != VType::Float && v.type != VType::Vector)
            error_expected(t, "a number or a vector after '" + k + "'");
        const Vec3 w = v.type == VType::Float ? Vec3(float(v.v[0]))
                                              : Vec3(float(v.v[0]), float(v.v[1]), float(v.v[2]));
        if (k == "form")
            pt.vector = w;
        else
            pt.param[0] = w.x;
        if (k == "metric" && !(w.x > 0 && std::isfinite(w.x)))
            error_at(t, "crackle's metric must be a positive number");
    } else if (pt.kind == PatternKind::Crackle && k == "offset") {
        advance();
        pt.param[1] = parse_float();
    } else if (pt.kind == PatternKind::Quilted && (k == "control0" || k == "control1")) {
        advance();
        pt.param[k == "control0" ? 0 : 1] = parse_float();
    } else if (k == "form" || k == "metric" || k == "offset" || k == "control0" ||
               k == "control1" || k == "orientation" || k == "dist_exp" || k == "max_iteration" ||
               k == "interpolate") {
        // Shape details of patterns Sheaf draws its own way: read and not used.
        advance();
        if (starts_expression(peek())) parse_expr();
    } else if (k == "solid") { // crackle: each cell one value, the noise at its point
        advance();
        if (pt.kind == PatternKind::Crackle) pt.param[2] = 1;
    } else {
        return false;
    }
    return true;
}

void Parser::parse_warp(PovPattern& pt, const Affine& local) {
    expect_sym("{");
    const Token& w = peek();
    Warp out;
    auto unit = [&](const Token& at, Vec3 v) { // an orientation
        const float l = length(v);
        if (!(l > 0) || !std::isfinite(l)) error_at(at, "a warp's orientation must not be zero");
        return v / l;
    };
    if (accept_kw("turbulence")) { // warp { turbulence amount [octaves n] [omega w] [lambda l] }
        out.kind = WarpKind::Turbulence;
        const Value v = parse_expr();
        out.a = v.type == VType::Float ? Vec3(float(v.v[0]))
                                       : Vec3(float(v.v[0]), float(v.v[1]), float(v.v[2]));
        out.f[0] = 0.5f, out.f[1] = 2.0f;
        for (;;) {
            if (accept_kw("octaves"))
                out.octaves = int8_t(parse_octaves());
            else if (accept_kw("omega"))
                out.f[0] = parse_float();
            else if (accept_kw("lambda"))
                out.f[1] = parse_float();
            else
                break;
        }
    } else if (accept_kw("repeat")) { // repeat <width along one axis> [offset v] [flip v]
        out.kind = WarpKind::Repeat;
        const Token& at = peek();
        const Vec3 v = parse_vector();
        const int axes = (v.x != 0) + (v.y != 0) + (v.z != 0);
        if (axes != 1)
            error_at(at, axes == 0 ? "a repeat warp needs an axis: one component other than 0"
                                   : "a repeat warp repeats along one axis only");
        out.axis = v.x != 0 ? 0 : v.y != 0 ? 1 : 2;
        out.f[0] = v.x != 0 ? v.x : v.y != 0 ? v.y : v.z;
        out.b = Vec3(1.0f);
        for (;;) {
            if (accept_kw("offset")) {
                out.a = parse_vector();
            } else if (accept_kw("flip")) {
                const Vec3 f = parse_vector();
                out.b =
                    Vec3(f.x != 0 ? -1.0f : 1.0f, f.y != 0 ? -1.0f : 1.0f, f.z != 0 ? -1.0f : 1.0f);
            } else {
                break;
            }
        }
    } else if (accept_kw("planar")) { // planar [orientation [, offset]]
        out.kind = WarpKind::Planar;
        if (starts_expression(peek())) {
            const Token& at = peek();
            out.b = unit(at, parse_vector());
            accept_sym(",");
            if (starts_expression(peek())) out.f[0] = parse_float();
        }
    } else if (is_kw("cylindrical") || is_kw("spherical") || is_kw("toroidal") || is_kw("cubic")) {
        advance();
        out.kind = w.text == "cylindrical" ? WarpKind::Cylindrical
                   : w.text == "spherical" ? WarpKind::Spherical
                   : w.text == "toroidal"  ? WarpKind::Toroidal
                                           : WarpKind::Cubic;
        for (;;) {
            const Token& m = peek();
            if (out.kind != WarpKind::Cubic && accept_kw("orientation")) {
                out.b = unit(m, parse_vector());
            } else if (out.kind != WarpKind::Cubic && accept_kw("dist_exp")) {
                out.f[0] = parse_float();
            } else if (out.kind == WarpKind::Toroidal && accept_kw("major_radius")) {
                out.f[1] = parse_float();
            } else {
                break;
            }
        }
    } else if (accept_kw("black_hole")) { // black_hole <centre>, radius [modifiers]
        out.kind = WarpKind::BlackHole;
        out.a = parse_vector();
        accept_sym(",");
        const Token& at = peek();
        out.f[0] = parse_float();
        if (!(out.f[0] > 0)) error_at(at, "a black hole's radius must be above 0");
        out.f[1] = 2, out.f[2] = 1; // falloff, strength
        out.b = Vec3(0.0f);
        bool repeat = false;
        int type = 0;
        // POV-Ray's checks, run each time repeat or turbulence is read: a repeated hole's
        // centre is at least its radius from the block's edge, and a block holds it whole.
        auto check = [&] {
            if (!repeat) return;
            for (int i = 0; i < 3; ++i) {
                if (!(out.b[i] > 0)) continue;
                if (out.a[i] < out.f[0]) out.a[i] = out.f[0];
                out.b[i] = std::max(out.b[i], out.a[i] + out.f[0] + out.c[i]);
                if (out.b[i] < 1e-6f) out.b[i] = 0;
            }
        };
        for (;;) {
            if (accept_kw("strength")) {
                out.f[2] = parse_float();
            } else if (accept_kw("falloff")) {
                out.f[1] = parse_float();
            } else if (accept_kw("inverse")) {
                out.axis = 1;
            } else if (accept_kw("type")) {
                type = int(parse_float());
            } else if (accept_kw("repeat")) {
                out.b = parse_vector();
                repeat = true;
                check();
            } else if (accept_kw("turbulence")) {
                out.c = parse_vector();
                check();
            } else {
                break;
            }
        }
        if (!repeat) out.b = Vec3(0.0f);
        if (type != 0) out.f[2] = 0; // POV-Ray moves points for type 0 only
    } else {
        error_expected(w, "a warp (turbulence, repeat, planar, cylindrical, spherical, "
                          "toroidal, cubic or black_hole)");
    }
    expect_sym("}");
    if (pt.bump_map) {
        unsupported(w, "warp of a bump_map (ignored)");
        return;
    }
    pt.warps.push_back({out, local});
}

void Parser::skip_to_block_end() {
    int depth = 1;
    for (;;) {
        const Token& t = peek();
        if (t.kind == TokKind::End) error_expected(t, "'}'");
        advance();
        if (is_sym_tok(t, "{")) ++depth;
        if (is_sym_tok(t, "}") && --depth == 0) return;
    }
}

} // namespace sheaf::io::pov

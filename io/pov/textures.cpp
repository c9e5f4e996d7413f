// Textures: pigment, normal and finish with the texture's own transforms; texture patterns
// (texture_map, checker texture ...), layers, material_map (warned); finishes and interiors.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace sheaf::io::pov {

PovTextureRef uv_mapped(const PovTextureRef& t) {
    if (!t) return t;
    if (t->uv) return t; // placed where it became uv-mapped
    auto copy = std::make_shared<PovTexture>(*t);
    copy->uv = true;
    copy->uv_local = copy->local;
    for (PovTextureRef& layer : copy->below) layer = uv_mapped(layer);
    return copy;
}

PovTextureRef transformed(const PovTextureRef& t, const Affine& m) {
    if (!t) return t;
    auto copy = std::make_shared<PovTexture>(*t);
    copy->local = m * copy->local;
    for (PovTextureRef& layer : copy->below) layer = transformed(layer, m); // they share its space
    return copy;
}

bool same_texture(const PovTextureRef& a, const PovTextureRef& b) {
    if (a == b) return true;
    if (!a || !b || a->is_map || b->is_map || a->pigment != b->pigment || a->normal != b->normal ||
        !(a->finish == b->finish) || a->below.size() != b->below.size())
        return false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            if (a->local.m[i][j] != b->local.m[i][j]) return false;
    for (size_t i = 0; i < a->below.size(); ++i)
        if (!same_texture(a->below[i], b->below[i])) return false;
    return true;
}

bool Parser::starts_expression(const Token& t) const {
    switch (t.kind) {
    case TokKind::Number:
    case TokKind::String:
        return true;
    case TokKind::Symbol:
        return t.text == "<" || t.text == "(" || t.text == "-" || t.text == "+" || t.text == "!";
    case TokKind::Ident: {
        if (const Value* v = lookup(t))
            return v->numeric() || v->type == VType::String || v->type == VType::Function ||
                   v->type == VType::Array;
        static const std::set<std::string> k = {
            "x",    "y",     "z",     "t",     "u",     "v",      "pi",    "on",
            "off",  "true",  "false", "yes",   "no",    "clock",  "rgb",   "rgbf",
            "rgbt", "rgbft", "srgb",  "srgbf", "srgbt", "srgbft", "color", "colour"};
        return k.count(t.text) || is_float_builtin(t.text);
    }
    default:
        return false;
    }
}

PovTextureRef Parser::parse_texture_block(const PovTexture& base) {
    expect_sym("{");
    return std::make_shared<const PovTexture>(parse_texture_body(base, "}"));
}

void Parser::warn_layers_lit_alike(const Token& t) {
    approximated(t, "layered texture whose layers' finishes differ: lit with one finish, the "
                    "top-most mostly opaque layer's");
}

PovTextureRef Parser::parse_texture_layers(const PovTexture& base) {
    PovTextureRef top = parse_texture_block(base);
    while (is_kw_tok(peek_cont(), "texture")) {
        const Token layer = peek_cont();
        advance();
        PovTextureRef next = parse_texture_block(base);
        auto layered = std::make_shared<PovTexture>(*next);
        layered->below.insert(layered->below.begin(), top->below.begin(), top->below.end());
        auto lower = std::make_shared<PovTexture>(*top);
        lower->below.clear();
        layered->below.insert(layered->below.begin() + top->below.size(), lower);
        top = layered;
        if (!layers_lit_alike(*top)) warn_layers_lit_alike(layer);
    }
    return top;
}

// POV-Ray applies a texture's transforms to its pigment and normal as they come, so a pigment
// or normal block that modifies them after the texture's transforms (texture { T_Stone1
// pigment { rotate 90*z } }, interior/ballbox1.pov) adds its own after the texture's. Sheaf
// keeps the texture's transforms in PovTexture::local, applied after the pigment's: such a
// block is parsed with them applied, then they are taken out again (only where the texture
// moved, by an invertible transform: elsewhere nothing changes, rounding included).
static bool moved(const Affine& local) {
    const Affine none;
    bool identity = true;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) identity = identity && local.m[r][c] == none.m[r][c];
    return !identity && std::fabs(local.determinant()) > 1e-30f;
}

// `part` (a pigment or a normal, with its `local`) modified by parse(base) in the space of a
// texture moved by `local`.
template <class Part, class Parse>
static std::shared_ptr<const Part> modify_in_texture_space(const Affine& local, const Part& part,
                                                           Parse parse) {
    Part base = part;
    base.local = local * base.local;
    auto out = std::make_shared<Part>(*parse(base));
    out->local = local.inverse() * out->local;
    return out;
}

PovTexture Parser::parse_texture_body(const PovTexture& base, const char* close) {
    const Nest nest(*this, peek()); // texture maps hold textures
    PovTexture tx = base;
    tx.local = Affine();
    Value declared;
    if (accept_declared(VType::Texture, declared, "a texture")) tx = declared.as<PovTexture>();
    // A declared layered texture's top layer modified here: whether it still lights its
    // layers alike (the declaration warned if it did not).
    const bool layers_alike = tx.below.empty() || layers_lit_alike(tx);
    Token modified_at;
    int list = 0;
    bool list_given = false;
    Token pattern_at;
    bool unsupported_pattern = false;
    bool uv = tx.uv;
    Token uv_at;
    // A uv-mapped texture is placed by its own transforms only (PovTexture::uv_local).
    auto done = [&](PovTexture& out) -> PovTexture& {
        out.uv = uv;
        if (uv) out.uv_local = out.local;
        if (uv && out.normal && !uv_at.text.empty())
            unsupported(uv_at, "uv_mapping of the texture's normal (the normal pattern is "
                               "evaluated in space)");
        return out;
    };
    for (;;) {
        const Token& t = peek();
        if (accept_sym(close)) break;
        if (tx.is_map) {
            if (parse_pattern_modifier(tx.map_pattern, tx.local)) continue;
        } else if (Affine m; parse_transform_item(m)) {
            tx.local = m * tx.local;
            // A declared layered texture's layers below move with it, as in POV-Ray.
            for (PovTextureRef& layer : tx.below) layer = transformed(layer, m);
            continue;
        }
        if (t.kind != TokKind::Ident) error_expected(t, "pigment, normal, finish or '}'");
        const std::string& k = t.text;
        if (k == "tiles") { // tiles { texture {...} tile2 texture {...} }: a checker of two
            advance();
            expect_sym("{");
            const Token& first = peek();
            if (!accept_kw("texture")) error_expected(first, "texture");
            PovTextureRef a = parse_texture_layers(PovTexture{});
            const Token& between = peek();
            if (!accept_kw("tile2")) error_expected(between, "tile2");
            const Token& second = peek();
            if (!accept_kw("texture")) error_expected(second, "texture");
            PovTextureRef b = parse_texture_layers(PovTexture{});
            expect_sym("}");
            tx = PovTexture{};
            tx.is_map = true;
            tx.map_pattern.kind = PatternKind::Checker;
            tx.map_entries = {{0.0, a}, {0.0, b}};
            list = 2;
            list_given = true;
            continue;
        }
        PovPattern pt;
        bool supported = true;
        if (parse_pattern_name(pt, list, supported)) { // a texture pattern
            only_in_normals(t, pt);
            pattern_at = t;
            tx = PovTexture{};
            tx.is_map = true;
            tx.map_pattern = pt;
            list_given = false;
            if (!supported) unsupported_pattern = true;
            continue;
        }
        advance();
        if (k == "pigment") {
            if (tx.pigment && !tx.pigment->uv && moved(tx.local))
                tx.pigment = modify_in_texture_space(
                    tx.local, *tx.pigment, [&](const PovPigment& b) { return parse_pigment(b); });
            else
                tx.pigment = parse_pigment(tx.pigment ? *tx.pigment : PovPigment{});
            if (modified_at.text.empty()) modified_at = t;
        } else if (k == "finish") {
            parse_finish(tx.finish);
            if (modified_at.text.empty()) modified_at = t;
        } else if (k == "normal") {
            if (tx.normal && moved(tx.local))
                tx.normal = modify_in_texture_space( // parse_normal keeps a given base
                    tx.local, *tx.normal, [&](const PovNormal& b) { return parse_normal(&b); });
            else
                tx.normal = parse_normal(tx.normal.get());
        } else if (k == "texture_map") {
            if (!tx.is_map) error_at(t, "texture_map needs a pattern before it");
            tx.map_entries = parse_texture_map();
            if (list == 0 && texture_map_blends(tx.map_entries))
                approximated(t, "texture_map blending: a point takes the nearer entry's texture, "
                                "where POV-Ray mixes the two around the pattern's value");
        } else if (k == "texture" && tx.is_map && list > 0) {
            if (!list_given) tx.map_entries.clear(), list_given = true;
            tx.map_entries.push_back({0.0, parse_texture_block(PovTexture{})});
            accept_sym(",");
        } else if (k == "average") { // of a texture_map: not supported, the first texture is used
            pattern_at = t;
            tx = PovTexture{};
            tx.is_map = true;
            unsupported_pattern = true;
        } else if (k == "material_map") {
            unsupported(t, "material_map (ignored)");
            skip_block();
        } else if (k == "uv_mapping") {
            uv = true;
            uv_at = t;
        } else if (k == "quick_color" || k == "quick_colour") {
            parse_color();
        } else {
            error_expected(t, "a texture item (pigment, normal, finish, a pattern ...)");
        }
    }
    if (!tx.is_map && !tx.below.empty() && layers_alike && !layers_lit_alike(tx))
        warn_layers_lit_alike(modified_at);
    if (tx.is_map) {
        if (unsupported_pattern || tx.map_entries.empty()) {
            if (unsupported_pattern)
                unsupported(pattern_at, "texture pattern '" + pattern_at.text + "' (" +
                                            (tx.map_entries.empty() ? "the default texture"
                                                                    : "its first texture") +
                                            " is used)");
            PovTextureRef first = tx.map_entries.empty() ? nullptr : tx.map_entries.front().second;
            const Affine local = tx.local;
            tx = first ? *first : base;
            tx.local = local * tx.local;
            return done(tx);
        }
        // Missing list entries: POV-Ray leaves them to the default texture.
        if (pattern_is_list(tx.map_pattern.kind))
            while (int(tx.map_entries.size()) < list)
                tx.map_entries.push_back({0.0, std::make_shared<const PovTexture>(base)});
    }
    return done(tx);
}

bool texture_map_blends(const std::vector<std::pair<double, PovTextureRef>>& entries) {
    std::vector<std::pair<double, PovTextureRef>> sorted = entries;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t i = 0; i + 1 < sorted.size(); ++i)
        if (sorted[i].first < sorted[i + 1].first &&
            !same_texture(sorted[i].second, sorted[i + 1].second))
            return true;
    return false;
}

std::vector<std::pair<double, PovTextureRef>> Parser::parse_texture_map() {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Other, declared, "a texture map")) {
        expect_sym("}");
        if (declared.str == "texture_map")
            return declared.as<std::vector<std::pair<double, PovTextureRef>>>();
    }
    std::vector<std::pair<double, PovTextureRef>> entries;
    while (!accept_sym("}")) {
        const Token& e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        double v = 1; // average maps may leave the weight out
        if (starts_map_value(peek())) v = parse_float();
        accept_sym(",");
        PovTextureRef tex;
        if (accept_kw("texture")) {
            tex = parse_texture_layers(PovTexture{});
            expect_sym("]");
        } else { // [v Ident] or [v pigment {...} finish {...}]
            tex = std::make_shared<const PovTexture>(parse_texture_body(PovTexture{}, "]"));
        }
        entries.push_back({v, tex});
    }
    if (entries.size() > 256) error_at(peek(), "a texture map of more than 256 entries");
    return entries;
}

void Parser::parse_finish(PovFinish& f) {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Finish, declared, "a finish")) f = declared.as<PovFinish>();
    auto rgb3 = [&](std::array<double, 3>& out) {
        const Color5 c = parse_color();
        out = {c[0], c[1], c[2]};
    };
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (t.kind != TokKind::Ident) error_expected(t, "a finish item or '}'");
        const std::string& k = t.text;
        advance();
        if (k == "ambient") {
            rgb3(f.ambient);
        } else if (k == "emission") {
            rgb3(f.emission);
        } else if (k == "diffuse") {
            accept_kw("albedo");
            f.diffuse = parse_float();
            if (accept_sym(",")) parse_float(); // backside
        } else if (k == "brilliance") {
            f.brilliance = parse_float();
        } else if (k == "specular") {
            accept_kw("albedo");
            f.specular = parse_float();
        } else if (k == "phong") {
            accept_kw("albedo");
            f.phong = parse_float();
        } else if (k == "phong_size") {
            f.phong_size = parse_float();
        } else if (k == "roughness") {
            f.roughness = parse_float();
        } else if (k == "metallic") {
            f.metallic = starts_expression(peek()) ? parse_float() : 1.0;
        } else if (k == "conserve_energy") {
            f.conserve_energy = parse_bool_opt(true);
        } else if (k == "crand" || k == "reflection_exponent" || k == "refraction" || k == "ior" ||
                   k == "caustics" || k == "fade_distance" || k == "fade_power") {
            parse_float(); // old or noise-only items
        } else if (k == "reflection") {
            if (accept_sym("{")) {
                std::vector<Color5> values;
                for (;;) {
                    const Token& r = peek();
                    if (accept_sym("}")) break;
                    if (accept_kw("fresnel")) {
                        f.fresnel = parse_bool_opt(true);
                    } else if (accept_kw("falloff")) {
                        f.reflection_falloff = parse_float();
                    } else if (accept_kw("exponent")) {
                        parse_float(); // POV-Ray's reflection_exponent: not modelled
                    } else if (accept_kw("metallic")) {
                        f.reflection_metallic =
                            starts_expression(peek()) ? parse_float() > 0 : true;
                    } else if (is_color_start(r)) {
                        values.push_back(parse_color());
                        accept_sym(",");
                    } else {
                        error_expected(r, "a reflection item (colours, fresnel, falloff ...)");
                    }
                }
                if (values.size() >= 2) {
                    f.reflection_min = {values[0][0], values[0][1], values[0][2]};
                    f.reflection = {values[1][0], values[1][1], values[1][2]};
                    f.reflection_variable = true;
                } else if (values.size() == 1) {
                    f.reflection = {values[0][0], values[0][1], values[0][2]};
                    f.reflection_min = f.fresnel ? std::array<double, 3>{0, 0, 0} : f.reflection;
                    f.reflection_variable = f.fresnel;
                }
            } else {
                rgb3(f.reflection);
                f.reflection_min = f.reflection;
                f.reflection_variable = false;
            }
        } else if (k == "irid") {
            expect_sym("{");
            const Token& at = peek();
            f.irid = parse_float();
            if (!std::isfinite(f.irid)) error_at(at, "the irid amount is not finite");
            for (;;) {
                const Token& i = peek();
                if (accept_sym("}")) break;
                if (accept_kw("thickness"))
                    f.irid_thickness = parse_float();
                else if (accept_kw("turbulence"))
                    f.irid_turbulence = parse_float();
                else
                    error_expected(i, "thickness, turbulence or '}'");
                if (!std::isfinite(f.irid_thickness) || !std::isfinite(f.irid_turbulence))
                    error_at(i, "the irid value is not finite");
            }
        } else if (k == "subsurface") {
            unsupported(t, k + " (ignored)");
            skip_block();
        } else if (k == "phong_size") {
            f.phong_size = parse_float();
        } else {
            error_expected(t, "a finish item (ambient, diffuse, phong, reflection ...)");
        }
    }
}

PovPigment Parser::parse_density() {
    PovPigment d;
    d.color = {1, 1, 1, 0, 0}; // white: the medium as it is
    expect_sym("{");
    parse_pigment_body(d, "}");
    return d;
}

// scattering { TYPE, COLOUR [eccentricity G] [extinction E] }
void Parser::parse_scattering(PovMedia& m) {
    expect_sym("{");
    const Token& at = peek();
    const double type = parse_float();
    if (!(type >= 1 && type <= 5) || type != std::floor(type))
        error_at(at, "a scattering type must be 1 (isotropic), 2 (Mie hazy), 3 (Mie murky), 4 "
                     "(Rayleigh) or 5 (Henyey-Greenstein)");
    m.scatter_type = int(type);
    accept_sym(",");
    const Token& ct = peek();
    const Color5 c = parse_color();
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(c[i]) <= 1e30) || c[i] < 0)
            error_at(ct, "a medium's scattering must be finite and not negative");
    m.scattering = {c[0], c[1], c[2]};
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        if (accept_kw("eccentricity")) {
            m.eccentricity = parse_float();
            if (!(m.eccentricity > -1 && m.eccentricity < 1))
                error_at(t, "eccentricity must lie strictly between -1 and 1");
        } else if (accept_kw("extinction")) {
            m.extinction = parse_float();
            if (!(m.extinction >= 0 && m.extinction <= 1e30))
                error_at(t, "extinction must be finite and not negative");
        } else {
            error_expected(t, "eccentricity, extinction or '}'");
        }
    }
}

PovMedia Parser::parse_media() {
    expect_sym("{");
    PovMedia m;
    Value declared;
    if (accept_declared(VType::Other, declared, "a media") && declared.str == "media")
        m = declared.as<PovMedia>();
    int intervals = 1, samples = 1;
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        Affine tr;
        if (parse_transform_item(tr)) {
            m.local = tr * m.local;
            continue;
        }
        if (t.kind != TokKind::Ident) error_expected(t, "a media item or '}'");
        const std::string& k = t.text;
        advance();
        if (k == "emission" || k == "absorption") {
            const Token& at = peek();
            const Color5 c = parse_color();
            for (int i = 0; i < 3; ++i)
                if (!(std::fabs(c[i]) <= 1e30) || (k == "absorption" && c[i] < 0))
                    error_at(at, "a medium's " + k + " must be finite" +
                                     (k == "absorption" ? " and not negative" : ""));
            (k == "emission" ? m.emission : m.absorption) = {c[0], c[1], c[2]};
        } else if (k == "density") {
            m.densities.push_back(std::make_shared<const PovPigment>(parse_density()));
        } else if (k == "intervals") {
            intervals = int(std::clamp(parse_float(), 1.0, 1024.0));
        } else if (k == "samples") {
            samples = int(std::clamp(parse_float(), 1.0, 1024.0));
            if (accept_sym(",")) parse_float(); // method 1 and 2's maximum
        } else if (k == "method" || k == "confidence" || k == "variance" || k == "ratio" ||
                   k == "jitter" || k == "aa_threshold" || k == "aa_level") {
            parse_float(); // Sheaf's steps are fixed (core/shading/media.h)
        } else if (k == "scattering") {
            parse_scattering(m);
        } else {
            error_expected(t, "a media item (emission, absorption, density, samples ...)");
        }
    }
    // POV-Ray's method 3 takes `samples` per interval and refines where they differ; fixed
    // steps need more: at least 32 along each crossing.
    m.samples = std::clamp(intervals * samples, 32, 1024);
    m.light_samples = std::clamp(intervals * samples, 1, 1024);
    return m;
}

PovInterior Parser::parse_interior(const PovInterior& base) {
    expect_sym("{");
    PovInterior in = base;
    Value declared;
    if (accept_declared(VType::Interior, declared, "an interior")) in = declared.as<PovInterior>();
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return in;
        if (accept_kw("ior")) {
            in.ior = parse_float();
        } else if (accept_kw("fade_distance")) {
            in.fade_distance = parse_float();
        } else if (accept_kw("fade_power")) {
            in.fade_power = parse_float();
        } else if (accept_kw("fade_color") || accept_kw("fade_colour")) {
            const Color5 c = parse_color();
            in.fade_color = {c[0], c[1], c[2]};
        } else if (accept_kw("caustics")) {
            in.caustics = parse_float();
        } else if (accept_kw("dispersion")) {
            // Dispersion splits refracted light by wavelength; not rendered, so warned where
            // it would show.
            if (parse_float() != 1) unsupported(t, "interior dispersion (ignored)");
        } else if (accept_kw("dispersion_samples")) {
            parse_float();
        } else if (accept_kw("media")) {
            in.media.push_back(parse_media());
        } else {
            error_expected(t, "ior, caustics, fade_distance, media or '}'");
        }
    }
}

} // namespace sheaf::io::pov

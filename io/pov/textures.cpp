// Textures reduced to the core Material: a solid pigment colour (a patterned pigment gives
// the average of its colour map, with a warning naming the pattern), the finish, the
// interior's ior. Normals, texture maps and layers are warned.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <set>

namespace sheaf::io::pov {

namespace {

const std::set<std::string>& patterns() {
    static const std::set<std::string> s = {
        "agate",      "aoi",         "average",      "boxed",           "bozo",
        "brick",      "bumps",       "cells",        "checker",         "crackle",
        "cubic",      "cylindrical", "density_file", "dents",           "facets",
        "function",   "gradient",    "granite",      "hexagon",         "image_pattern",
        "julia",      "leopard",     "magnet",       "mandel",          "marble",
        "object",     "onion",       "pavement",     "pigment_pattern", "planar",
        "quilted",    "radial",      "ripples",      "slope",           "spherical",
        "spiral1",    "spiral2",     "spotted",      "square",          "tiling",
        "triangular", "waves",       "wood",         "wrinkles"};
    return s;
}

// Patterns that take their colours or pigments as a list (checker c1, c2).
int list_size(const std::string& p) {
    if (p == "checker" || p == "brick" || p == "object") return 2;
    if (p == "hexagon") return 3;
    if (p == "square") return 4;
    if (p == "triangular") return 6;
    return 0;
}

Color5 average(const std::vector<Color5>& cs) {
    Color5 a{0, 0, 0, 0, 0};
    if (cs.empty()) return {0.5, 0.5, 0.5, 0, 0}; // the default gray ramp
    for (const Color5& c : cs)
        for (int i = 0; i < 5; ++i) a[i] += c[i] / double(cs.size());
    return a;
}

bool is_color_keyword(const Token& t) {
    static const std::set<std::string> k = {"color", "colour", "rgb",   "rgbf",  "rgbt",
                                            "rgbft", "srgb",   "srgbf", "srgbt", "srgbft"};
    return t.kind == TokKind::Ident && k.count(t.text);
}

} // namespace

bool Parser::starts_expression(const Token& t) const {
    switch (t.kind) {
    case TokKind::Number:
    case TokKind::String:
        return true;
    case TokKind::Symbol:
        return t.text == "<" || t.text == "(" || t.text == "-" || t.text == "+" || t.text == "!";
    case TokKind::Ident: {
        if (const Value* v = lookup(t.text))
            return v->numeric() || v->type == VType::String || v->type == VType::Function ||
                   v->type == VType::Array;
        static const std::set<std::string> k = {"x",  "y",   "z",    "t",     "u",   "v",  "pi",
                                                "on", "off", "true", "false", "yes", "no", "clock"};
        return k.count(t.text) || is_float_builtin(t.text) || is_color_keyword(t);
    }
    default:
        return false;
    }
}

void Parser::skip_pattern_modifier(const Token& t) {
    (void)t;
    advance();
    if (is_sym_tok(peek(), "{")) {
        skip_block();
        return;
    }
    while (starts_expression(peek())) {
        if (is_color_keyword(peek()))
            parse_color();
        else
            parse_expr();
        accept_sym(",");
    }
}

PovTexture Parser::parse_texture(const PovTexture& base) {
    expect_sym("{");
    return parse_texture_body(base, "}");
}

PovTexture Parser::parse_texture_body(const PovTexture& base, const char* close) {
    PovTexture tx = base;
    const Token first = peek();
    Value declared;
    if (accept_declared(VType::Texture, declared, "a texture")) {
        const Value* v = &declared;
        tx = v->as<PovTexture>();
        if (v->v[1] != 0)
            unsupported(first, "layered texture '" + first.text + "' (its first layer is used)");
    }
    bool patterned = false, have_entry = false;
    for (;;) {
        const Token t = peek();
        if (accept_sym(close)) return tx;
        Affine ignored;
        if (parse_transform_item(ignored)) continue;
        if (t.kind != TokKind::Ident) error_expected(t, "pigment, finish, normal or '}'");
        const std::string& k = t.text;
        if (k == "pigment") {
            advance();
            parse_pigment(tx.pigment);
        } else if (k == "finish") {
            advance();
            parse_finish(tx.finish);
        } else if (k == "normal") {
            advance();
            unsupported(t, "normal");
            if (is_sym_tok(peek(), "{"))
                skip_block();
            else
                next();
        } else if (k == "material_map") {
            advance();
            unsupported(t, "material_map");
            skip_block();
        } else if (k == "texture_map") {
            advance();
            if (!patterned) unsupported(t, k + " (its first texture is used)");
            expect_sym("{");
            while (!accept_sym("}")) {
                const Token e = peek();
                if (!accept_sym("[")) error_expected(e, "'[' or '}'");
                if (starts_expression(peek()) && !is_color_keyword(peek())) parse_float();
                accept_sym(",");
                PovTexture inner = model.default_texture;
                if (is_kw_tok(peek(), "texture")) {
                    advance();
                    inner = parse_texture(model.default_texture);
                    expect_sym("]");
                } else { // [v Ident] or [v pigment {...} finish {...}]
                    inner = parse_texture_body(model.default_texture, "]");
                }
                if (!have_entry) tx = inner, have_entry = true;
            }
        } else if (k == "texture") { // a texture list of a pattern (checker texture{} texture{})
            advance();
            const PovTexture inner = parse_texture(model.default_texture);
            if (!have_entry) tx = inner, have_entry = true;
            accept_sym(",");
        } else if (patterns().count(k)) {
            if (!patterned)
                unsupported(t, "texture pattern '" + k + "' (its first texture is used)");
            patterned = true;
            skip_pattern_modifier(t);
        } else if (k == "uv_mapping") {
            advance();
        } else {
            skip_pattern_modifier(t);
        }
    }
}

void Parser::parse_pigment(Color5& c) {
    expect_sym("{");
    parse_pigment_body(c, "}");
}

void Parser::parse_pigment_body(Color5& c, const char* close) {
    Token pattern;
    bool has_pattern = false, has_map = false;
    Color5 map{0.5, 0.5, 0.5, 0, 0};
    std::vector<Color5> list;
    Value declared;
    if (accept_declared(VType::Pigment, declared, "a pigment")) c = to_color(declared);
    for (;;) {
        const Token t = peek();
        if (accept_sym(close)) break;
        Affine ignored;
        if (parse_transform_item(ignored)) continue;
        if (is_color_keyword(t) || (t.kind != TokKind::Ident && starts_expression(t)) ||
            (t.kind == TokKind::Ident && lookup(t.text) && lookup(t.text)->numeric())) {
            const Color5 col = parse_color();
            if (has_pattern && list_size(pattern.text))
                list.push_back(col);
            else
                c = col;
            accept_sym(",");
            continue;
        }
        if (t.kind != TokKind::Ident) error_expected(t, "a colour, a pattern or '}'");
        const std::string& k = t.text;
        if (k == "color_map" || k == "colour_map") {
            advance();
            map = parse_color_map();
            has_map = true;
        } else if (k == "pigment_map") {
            advance();
            expect_sym("{");
            std::vector<Color5> entries;
            while (!accept_sym("}")) {
                const Token e = peek();
                if (!accept_sym("[")) error_expected(e, "'[' or '}'");
                if (starts_expression(peek()) && !is_color_keyword(peek())) parse_float();
                accept_sym(",");
                Color5 p = map;
                if (accept_kw("pigment")) {
                    parse_pigment(p);
                    expect_sym("]");
                } else {
                    parse_pigment_body(p, "]"); // [v Ident], [v color c], [v bozo color_map{}]
                }
                entries.push_back(p);
            }
            map = average(entries);
            has_map = true;
        } else if (k == "pigment" && has_pattern && list_size(pattern.text)) {
            advance();
            Color5 p = c;
            parse_pigment(p);
            list.push_back(p);
            accept_sym(",");
        } else if (k == "image_map") {
            advance();
            unsupported(t, "image_map (a gray pigment is used)");
            skip_block();
            c = {0.5, 0.5, 0.5, 0, 0};
        } else if (k == "quick_color" || k == "quick_colour") {
            advance();
            parse_color();
        } else if (patterns().count(k)) {
            pattern = t;
            has_pattern = true;
            advance();
            if (list_size(k)) { // colours follow, parsed above; an object pattern has a block
                if (k == "object") skip_block();
                continue;
            }
            if (is_sym_tok(peek(), "{"))
                skip_block();
            else
                while (starts_expression(peek()) && !is_color_keyword(peek())) {
                    parse_expr();
                    accept_sym(",");
                }
        } else {
            skip_pattern_modifier(t);
        }
    }
    if (has_pattern) {
        unsupported(pattern, "pigment pattern '" + pattern.text + "' (its average colour is used)");
        if (list_size(pattern.text)) {
            if (list.empty()) list = {{0, 0, 1, 0, 0}, {0, 1, 0, 0, 0}}; // POV-Ray's defaults
            c = average(list);
        } else {
            c = map;
        }
    } else if (has_map) {
        c = map; // a map without a pattern: POV-Ray uses the map at 0; close enough
    }
}

Color5 Parser::parse_color_map() {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::ColorMap, declared, "a colour map")) {
        expect_sym("}");
        return to_color(declared);
    }
    std::vector<Color5> entries;
    while (!accept_sym("}")) {
        const Token e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        parse_float();
        accept_sym(",");
        if (peek().kind == TokKind::Number) { // [a, b color c1 color c2]
            parse_float();
            accept_sym(",");
        }
        while (!accept_sym("]")) {
            entries.push_back(parse_color());
            accept_sym(",");
        }
    }
    return average(entries);
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
        const Token t = peek();
        if (accept_sym("}")) return;
        if (t.kind != TokKind::Ident) error_expected(t, "a finish item or '}'");
        const std::string& k = t.text;
        advance();
        if (k == "ambient")
            rgb3(f.ambient);
        else if (k == "emission")
            rgb3(f.emission);
        else if (k == "diffuse") {
            accept_kw("albedo");
            f.diffuse = parse_float();
            if (accept_sym(",")) parse_float(); // backside
        } else if (k == "specular") {
            accept_kw("albedo");
            f.specular = parse_float();
        } else if (k == "phong") {
            accept_kw("albedo");
            f.phong = parse_float();
        } else if (k == "phong_size")
            f.phong_size = parse_float();
        else if (k == "roughness")
            f.roughness = parse_float();
        else if (k == "brilliance" || k == "crand" || k == "reflection_exponent" ||
                 k == "refraction" || k == "ior" || k == "caustics" || k == "fade_distance" ||
                 k == "fade_power")
            parse_float();
        else if (k == "metallic" || k == "conserve_energy")
            parse_bool_opt(true);
        else if (k == "reflection") {
            if (accept_sym("{")) {
                Color5 lo{0, 0, 0, 0, 0}, hi{0, 0, 0, 0, 0};
                int n = 0;
                for (;;) {
                    const Token r = peek();
                    if (accept_sym("}")) break;
                    if (accept_kw("fresnel")) {
                        if (parse_bool_opt(true)) unsupported(r, "fresnel reflection (ignored)");
                    } else if (accept_kw("falloff") || accept_kw("exponent")) {
                        parse_float();
                    } else if (accept_kw("metallic")) {
                        parse_bool_opt(true);
                    } else {
                        (n++ == 0 ? lo : hi) = parse_color();
                        accept_sym(",");
                    }
                }
                const Color5& use = n >= 2 ? hi : lo; // the maximum (facing) reflection
                f.reflection = {use[0], use[1], use[2]};
                if (n >= 2) unsupported(t, "variable reflection (the maximum is used)");
            } else {
                rgb3(f.reflection);
            }
        } else if (k == "irid" || k == "subsurface") {
            unsupported(t, k);
            skip_block();
        } else {
            error_expected(t, "a finish item (ambient, diffuse, phong, reflection ...)");
        }
    }
}

double Parser::parse_interior() {
    expect_sym("{");
    double ior = 0;
    Value declared;
    if (accept_declared(VType::Interior, declared, "an interior")) ior = declared.v[0];
    for (;;) {
        const Token t = peek();
        if (accept_sym("}")) return ior;
        if (accept_kw("ior"))
            ior = parse_float();
        else if (accept_kw("caustics") || accept_kw("dispersion") ||
                 accept_kw("dispersion_samples") || accept_kw("fade_distance") ||
                 accept_kw("fade_power"))
            parse_float();
        else if (accept_kw("fade_color") || accept_kw("fade_colour"))
            parse_color();
        else if (accept_kw("media")) {
            unsupported(t, "media");
            skip_block();
        } else
            error_expected(t, "ior, caustics, fade_distance, media or '}'");
    }
}

} // namespace sheaf::io::pov

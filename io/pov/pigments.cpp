// Pigments: solid colours, patterns with colour maps, pigment maps or colour and pigment
// lists, image maps, `average`, and declared pigments and colour maps.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <set>

namespace sheaf::io::pov {

namespace {

// POV-Ray's colours for list patterns the scene gives no colours for.
std::vector<Color5> default_list(PatternKind k) {
    const Color5 blue{0, 0, 1, 0, 0}, green{0, 1, 0, 0, 0}, red{1, 0, 0, 0, 0},
        white{1, 1, 1, 0, 0}, gray{0.5, 0.5, 0.5, 0, 0};
    switch (k) {
    case PatternKind::Brick:
        return {{0.5, 0.5, 0.5, 0, 0}, {0.6, 0.15, 0.15, 0, 0}};
    case PatternKind::Hexagon:
        return {blue, green, red};
    case PatternKind::Square:
        return {blue, green, red, white};
    case PatternKind::Triangular:
        return {blue, green, red, white, gray, {1, 1, 0, 0, 0}};
    default:
        return {blue, green};
    }
}

// POV-Ray's colour map for a continuous pattern the scene gives no colours for: its own for
// agate, bozo, marble, radial, wood and mandel (of exponent 2), else a grey ramp.
std::vector<PovMapEntry> default_map(const std::string& keyword, const PovPattern& pt) {
    auto rgb = [](double v, double r, double g, double b) {
        return PovMapEntry{v, {r, g, b, 0, 0}, {}};
    };
    if (keyword == "agate")
        return {rgb(0, 1, 1, 1),         rgb(0.5, 0.95, 0.75, 0.5), rgb(0.5, 0.9, 0.7, 0.5),
                rgb(0.6, 0.9, 0.7, 0.4), rgb(0.6, 1, 0.7, 0.4),     rgb(1, 0.6, 0.3, 0)};
    if (keyword == "bozo")
        return {rgb(0.4, 1, 1, 1), rgb(0.4, 0, 1, 0), rgb(0.6, 0, 1, 0),
                rgb(0.6, 0, 0, 1), rgb(0.8, 0, 0, 1), rgb(0.8, 1, 0, 0)};
    if (keyword == "marble")
        return {rgb(0, 0.9, 0.8, 0.8), rgb(0.9, 0.9, 0.08, 0.08), rgb(0.9, 0, 0, 0)};
    if (keyword == "radial")
        return {rgb(0, 0, 1, 1), rgb(0.333, 1, 1, 0), rgb(0.666, 1, 0, 1), rgb(1, 0, 1, 1)};
    if (keyword == "wood") return {rgb(0.6, 0.666, 0.312, 0.2), rgb(0.6, 0.4, 0.1333, 0.066)};
    if (keyword == "mandel" && pt.fractal.exponent == 2 && pt.fractal.magnet == 0)
        return {rgb(0.001, 0, 0, 0), rgb(0.001, 0, 1, 1), rgb(0.012, 1, 1, 0), rgb(0.015, 1, 0, 1),
                rgb(0.1, 0, 1, 1)};
    return {rgb(0, 0, 0, 0), rgb(1, 1, 1, 1)};
}

Color5 mean(const std::vector<PovMapEntry>& entries) {
    Color5 a{0.5, 0.5, 0.5, 0, 0};
    int n = 0;
    for (const PovMapEntry& e : entries) {
        const Color5& c = e.pigment ? e.pigment->color : e.color;
        if (n++ == 0) a = {0, 0, 0, 0, 0};
        for (int i = 0; i < 5; ++i) a[i] += c[i];
    }
    if (n > 0)
        for (double& v : a) v /= n;
    return a;
}

} // namespace

bool Parser::is_color_start(const Token& t) {
    static const std::set<std::string> k = {"color", "colour", "rgb",   "rgbf",  "rgbt",
                                            "rgbft", "srgb",   "srgbf", "srgbt", "srgbft"};
    if (t.kind == TokKind::Ident && k.count(t.text)) return true;
    // Components alone: `red 1 green 0.5`.
    if (is_kw_tok(t, "red") || is_kw_tok(t, "green") || is_kw_tok(t, "blue") ||
        is_kw_tok(t, "filter") || is_kw_tok(t, "transmit"))
        return !lookup(t);
    if (t.kind != TokKind::Ident) return starts_expression(t);
    const Value* v = lookup(t);
    if (v && v->type == VType::Array) // an array of colours or numbers
        for (const Value& e : static_cast<const ArrayValue*>(v->ptr.get())->elements)
            if (e.type != VType::None) return e.numeric();
    return v && v->numeric();
}

bool Parser::starts_map_value(const Token& t) {
    if (t.kind == TokKind::Number) return true;
    if (t.kind == TokKind::Ident)
        if (const Value* v = lookup(t)) return v->type == VType::Float;
    if (is_sym_tok(t, "<")) return false; // a colour vector
    return starts_expression(t) && (t.kind != TokKind::Ident || !is_color_start(t));
}

std::shared_ptr<const PovPigment> Parser::parse_pigment(const PovPigment& base) {
    expect_sym("{");
    PovPigment pg = base;
    parse_pigment_body(pg, "}");
    return std::make_shared<const PovPigment>(std::move(pg));
}

void Parser::parse_pigment_body(PovPigment& pg, const char* close) {
    const Nest nest(*this, peek()); // pigment maps hold pigments
    Value declared;
    if (accept_declared(VType::Pigment, declared, "a pigment")) pg = declared.as<PovPigment>();
    Token pattern_at;
    bool unsupported_pattern = false;
    int list = pg.patterned && pattern_is_list(pg.pattern.kind) ? int(pg.entries.size()) : 0;
    bool list_given = false; // the scene named its own list entries
    for (;;) {
        const Token& t = peek();
        if (accept_sym(close)) break;
        if (parse_pattern_modifier(pg.pattern, pg.local)) continue;
        if (is_color_start(t)) {
            const Color5 c = parse_color();
            if (pg.patterned && list > 0) {
                if (!list_given) pg.entries.clear(), list_given = true;
                pg.entries.push_back({0, c, nullptr});
            } else {
                pg.color = c;
            }
            accept_sym(",");
            continue;
        }
        if (t.kind != TokKind::Ident)
            error_expected(t, "a colour, a pattern or '" + std::string(close) + "'");
        const std::string& k = t.text;
        bool supported = true;
        if (parse_pattern_name(pg.pattern, list, supported)) {
            only_in_normals(t, pg.pattern);
            pattern_at = t;
            pg.patterned = true;
            pg.average = false;
            pg.entries.clear();
            list_given = false;
            if (!supported) unsupported_pattern = true;
            continue;
        }
        advance();
        if (k == "color_map" || k == "colour_map") {
            pg.entries = parse_color_map();
        } else if (k == "pigment_map" || k == "density_map") { // colours or declared densities
            pg.entries = parse_pigment_map();
        } else if (k == "pigment" && pg.patterned && list > 0) {
            if (!list_given) pg.entries.clear(), list_given = true;
            PovMapEntry e;
            e.pigment = parse_pigment(PovPigment{});
            if (!e.pigment->patterned) e.color = e.pigment->color, e.pigment = nullptr;
            pg.entries.push_back(std::move(e));
            accept_sym(",");
        } else if (k == "average") {
            pattern_at = t;
            pg.patterned = true;
            pg.average = true;
            list = 0;
        } else if (k == "image_map") {
            pattern_at = t;
            parse_image_map(t, pg);
            list = 0;
        } else if (k == "quick_color" || k == "quick_colour") {
            parse_color();
        } else if (k == "uv_mapping") {
            pg.uv = true;
        } else if (k == "color" || k == "colour") {
            error_expected(t, "a colour");
        } else {
            error_expected(t, "a pigment item (a colour, a pattern, color_map, turbulence ...)");
        }
    }
    if (!pg.patterned) return;
    if (unsupported_pattern) {
        unsupported(pattern_at,
                    "pigment pattern '" + pattern_at.text + "' (its average colour is used)");
        pg.color = mean(pg.entries);
        pg.patterned = false;
        pg.entries.clear();
        return;
    }
    if (pg.pattern.kind == PatternKind::Image) return;
    if (pattern_is_list(pg.pattern.kind)) {
        // Missing entries take POV-Ray's default colours.
        const std::vector<Color5> d = default_list(pg.pattern.kind);
        for (size_t i = pg.entries.size(); i < d.size(); ++i) pg.entries.push_back({0, d[i], {}});
    } else if (pg.entries.empty()) {
        if (pg.average) {
            pg.patterned = false; // an average of nothing: the colour as it was
            return;
        }
        pg.entries = default_map(pattern_at.text, pg.pattern);
    }
}

std::vector<PovMapEntry> Parser::parse_color_map() {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::ColorMap, declared, "a colour map")) {
        expect_sym("}");
        return declared.as<std::vector<PovMapEntry>>();
    }
    std::vector<PovMapEntry> entries;
    while (!accept_sym("}")) {
        const Token& e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        const double a = parse_float();
        accept_sym(",");
        if (!is_color_start(peek()) || peek().kind == TokKind::Number) {
            // The old form [a, b color c1 color c2]: two entries.
            const double b = parse_float();
            accept_sym(",");
            const Color5 c1 = parse_color();
            accept_sym(",");
            const Color5 c2 = parse_color();
            expect_sym("]");
            entries.push_back({a, c1, {}});
            entries.push_back({b, c2, {}});
            continue;
        }
        const Color5 c = parse_color();
        accept_sym(",");
        expect_sym("]");
        entries.push_back({a, c, {}});
    }
    if (entries.size() > 256) error_at(peek(), "a colour map of more than 256 entries");
    return entries;
}

std::vector<PovMapEntry> Parser::parse_pigment_map() {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Other, declared, "a pigment map")) {
        expect_sym("}");
        if (declared.str == "pigment_map") return declared.as<std::vector<PovMapEntry>>();
    }
    std::vector<PovMapEntry> entries;
    while (!accept_sym("}")) {
        const Token& e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        PovMapEntry entry;
        entry.value = 1; // average maps may leave the weight out
        if (starts_map_value(peek())) entry.value = parse_float();
        accept_sym(",");
        PovPigment p;
        if (accept_kw("pigment")) {
            p = *parse_pigment(PovPigment{});
            expect_sym("]");
        } else {
            parse_pigment_body(p, "]"); // [v Ident], [v color c], [v bozo color_map {...}]
        }
        if (p.patterned)
            entry.pigment = std::make_shared<const PovPigment>(std::move(p));
        else
            entry.color = p.color;
        entries.push_back(std::move(entry));
    }
    if (entries.size() > 256) error_at(peek(), "a pigment map of more than 256 entries");
    return entries;
}

std::shared_ptr<PovImage> Parser::parse_image_file(const Token& kw) {
    auto img = std::make_shared<PovImage>();
    img->where = kw;
    static const std::set<std::string> types = {"gif",  "tga",  "iff", "ppm", "pgm", "png",
                                                "jpeg", "tiff", "sys", "exr", "hdr", "bmp"};
    if (peek().kind == TokKind::Ident && types.count(peek().text)) advance();
    const Token& name = peek();
    const std::string file = parse_string();
    img->path = find_file(file, name, "image file",
                          {".tga", ".png", ".jpg", ".jpeg", ".ppm", ".pgm", ".bmp", ".tif", ".tiff",
                           ".exr", ".hdr", ".gif"});
    return img;
}

bool Parser::parse_image_item(PovImage& img) {
    const Token& t = peek();
    if (accept_kw("map_type")) {
        img.map_type = int(parse_float());
        if (img.map_type != 0 && img.map_type != 1 && img.map_type != 2 && img.map_type != 5) {
            unsupported(t, "image map_type " + std::to_string(img.map_type) + " (planar is used)");
            img.map_type = 0;
        }
    } else if (accept_kw("once")) {
        img.once = true;
    } else if (accept_kw("interpolate")) {
        parse_float(); // Sheaf's images are always sampled bilinearly
    } else if (!accept_kw("use_color") && !accept_kw("use_colour")) {
        return false;
    }
    return true;
}

std::shared_ptr<const PovImage> Parser::parse_image_pattern(const Token& kw) {
    expect_sym("{");
    const std::shared_ptr<PovImage> img = parse_image_file(kw);
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (parse_image_item(*img) || accept_kw("use_index")) {
        } else if (accept_kw("use_alpha")) {
            unsupported(t, "image_pattern use_alpha (the grey is used)");
        } else if (accept_kw("gamma")) {
            parse_float();
        } else if (accept_kw("premultiplied")) {
            parse_bool_opt(true);
        } else {
            error_expected(t, "an image_pattern item (map_type, once, interpolate, use_alpha "
                              "...) or '}'");
        }
    }
    return img;
}

void Parser::parse_image_map(const Token& kw, PovPigment& pg) {
    expect_sym("{");
    const std::shared_ptr<PovImage> img = parse_image_file(kw);
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (parse_image_item(*img)) {
        } else if (accept_kw("use_index") || accept_kw("use_alpha")) {
        } else if (accept_kw("gamma")) {
            parse_float();
        } else if (accept_kw("premultiplied")) {
            parse_bool_opt(true);
        } else if (accept_kw("filter") || accept_kw("transmit")) {
            const bool filter = t.text == "filter";
            if (accept_kw("all")) {
                (filter ? img->filter_all : img->transmit_all) = parse_float();
            } else { // a palette index: OpenImageIO gives the palette's colours, not indices
                parse_float();
                accept_sym(",");
                parse_float();
                unsupported(t, std::string(filter ? "filter" : "transmit") +
                                   " of a palette index (ignored)");
            }
        } else if (!parse_pattern_modifier(pg.pattern, pg.local)) {
            error_expected(t, "an image_map item (map_type, once, interpolate, filter ...)");
        }
    }
    pg.patterned = true;
    pg.average = false;
    pg.pattern.kind = PatternKind::Image;
    pg.pattern.image = img;
    pg.entries = {{0, {1, 1, 1, img->filter_all, img->transmit_all}, {}}};
}

} // namespace sheaf::io::pov

// Normals: a pattern with its bump size (`bumps 0.4`, `ripples 0.5 frequency 3`,
// `granite 0.3`, `bump_size`), its modifiers and transforms, and declared normals.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>

namespace sheaf::io::pov {

namespace {

// The patterns POV-Ray draws with normal functions of their own, which ignore a slope map.
bool has_own_normal(const std::string& name) {
    return name == "bumps" || name == "dents" || name == "ripples" || name == "waves" ||
           name == "wrinkles" || name == "quilted" || name == "facets";
}

} // namespace

std::shared_ptr<const PovNormal> Parser::parse_normal(const PovNormal* base) {
    expect_sym("{");
    PovNormal n = base ? *base : model.normal_defaults;
    bool have = base != nullptr;
    parse_normal_body(n, have, "}");
    if (!have) return nullptr;
    return std::make_shared<const PovNormal>(std::move(n));
}

void Parser::parse_normal_body(PovNormal& n, bool& have, const char* close) {
    const Nest nest(*this, peek()); // normal maps hold normals
    Value declared;
    const Value* named = peek().kind == TokKind::Ident ? lookup(peek()) : nullptr;
    // Arrays take the path below: their elements may mix normals and flat ones.
    if (named && named->type == VType::Normal &&
        accept_declared(VType::Normal, declared, "a normal")) {
        n = declared.as<PovNormal>();
        have = true;
    } else if (const Token& t = peek(); t.kind == TokKind::Ident) {
        // A normal declared flat (its pattern unsupported, warned where it is used), alone or
        // as an element of an array of normals (the portfolio's normal { normalArr[i] }).
        const Value* v = lookup(t);
        if (v && ((v->type == VType::Other && v->str == "normal") || v->type == VType::Array)) {
            accept_declared_any(declared);
            if (declared.type == VType::Normal) {
                n = declared.as<PovNormal>();
                have = true;
            } else if (declared.type != VType::Other || declared.str != "normal") {
                error_expected(t, std::string("a normal, not ") + type_name(declared.type));
            }
        }
    }
    int list = pattern_is_list(n.pattern.kind) ? int(n.map.size()) : 0;
    bool list_given = false; // the scene named its own list entries
    for (;;) {
        const Token& t = peek();
        if (accept_sym(close)) break;
        if (parse_pattern_modifier(n.pattern, n.local)) continue;
        if (t.kind != TokKind::Ident)
            error_expected(t, "a normal pattern or '" + std::string(close) + "'");
        bool supported = true;
        if (parse_pattern_name(n.pattern, list, supported)) {
            if (!supported) unsupported(t, "normal pattern '" + t.text + "' (no normal change)");
            have = supported;
            n.form = normal_form_of(t.text);
            n.own_normal = has_own_normal(t.text);
            n.average = false;
            n.map.clear();
            list_given = false;
            // The bump size may follow the pattern (and its own arguments), after a comma too.
            if (accept_sym(",") || (starts_expression(peek()) && !is_sym_tok(peek(), "<")))
                n.amount = parse_float();
            continue;
        }
        const std::string& k = t.text;
        advance();
        if (k == "bump_size") {
            n.amount = parse_float();
        } else if (k == "average") {
            n.average = true;
            have = true;
        } else if (k == "slope_map") {
            n.slope_map = parse_slope_map();
        } else if (k == "normal_map") {
            n.map = parse_normal_map(t, n.average);
        } else if (k == "normal" && list > 0) { // a list pattern's entries, in order
            if (!list_given) n.map.clear(), list_given = true;
            const Token& e = peek();
            if (int(n.map.size()) == list)
                error_at(t, "a list pattern of " + std::to_string(list) + " entries takes " +
                                std::to_string(list) + " normals");
            n.map.push_back({0, map_entry(e, parse_normal(nullptr))});
        } else if (k == "bump_map") {
            parse_bump_map(t, n);
            have = true;
        } else if (k == "uv_mapping") {
            unsupported(t, "uv_mapping of a normal (the normal pattern is evaluated in space)");
        } else if (k == "accuracy") { // how far apart the slope is sampled
            const Token& at = peek();
            n.accuracy = parse_float();
            if (!(n.accuracy > 0 && std::isfinite(n.accuracy)))
                error_at(at, "accuracy must be a positive number");
        } else if (k == "no_bump_scale") {
            n.no_bump_scale = true;
            if (starts_expression(peek()) && parse_float() == 0) n.no_bump_scale = false;
        } else {
            error_expected(t, "a normal item (bumps, ripples, bump_size, turbulence ...)");
        }
    }
    if (n.own_normal) n.slope_map.clear();        // as POV-Ray: their own normals take no slope map
    if (n.average && n.map.empty()) have = false; // an average of nothing: no change
    // A list pattern's entries that were not given leave the surface's normal as it is.
    if (list > 0 && !n.map.empty())
        while (int(n.map.size()) < list) n.map.push_back({0, nullptr});
}

void Parser::parse_bump_map(const Token& kw, PovNormal& n) {
    expect_sym("{");
    const std::shared_ptr<PovImage> img = parse_image_file(kw);
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (parse_image_item(*img)) {
        } else if (accept_kw("use_index")) {
            unsupported(t, "bump_map use_index (the grey level is used, not the palette index)");
        } else if (accept_kw("bump_size")) {
            n.amount = parse_float();
        } else {
            error_expected(t, "a bump_map item (map_type, once, interpolate, use_color, "
                              "use_index, bump_size)");
        }
    }
    n.pattern.kind = PatternKind::Image;
    n.pattern.bump_map = true;
    n.pattern.image = img;
    n.form = NormalForm::Slope; // the image's heights tilt the normal (bump_map_normal)
    n.own_normal = true;
}

std::shared_ptr<const PovNormal> Parser::map_entry(const Token& at,
                                                   std::shared_ptr<const PovNormal> entry) {
    if (entry && !entry->map.empty()) {
        unsupported(at, "a normal map inside a normal map (the inner map is left out)");
        PovNormal leaf = *entry;
        leaf.map.clear();
        leaf.average = false;
        entry = std::make_shared<const PovNormal>(std::move(leaf));
    }
    return entry;
}

std::vector<std::pair<double, std::shared_ptr<const PovNormal>>>
Parser::parse_normal_map(const Token& kw, bool weights) {
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Other, declared, "a normal map")) {
        expect_sym("}");
        if (declared.str != "normal_map") error_at(kw, "a declared normal map expected");
        return declared.as<std::vector<std::pair<double, std::shared_ptr<const PovNormal>>>>();
    }
    std::vector<std::pair<double, std::shared_ptr<const PovNormal>>> entries;
    while (!accept_sym("}")) {
        const Token& e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        double value = 1; // an average's weight may be left out
        if (starts_map_value(peek())) {
            const Token& vt = peek();
            const Value v = parse_additive();
            if (v.type != VType::Float) error_expected(vt, "a float (the entry's value)");
            value = v.v[0];
        } else if (!weights) {
            error_expected(peek(), "the entry's value (a float)");
        }
        accept_sym(",");
        const Token& body = peek();
        PovNormal n = model.normal_defaults;
        bool have = false;
        if (accept_kw("normal")) {
            const auto inner = parse_normal(nullptr);
            expect_sym("]");
            if (inner) n = *inner, have = true;
        } else {
            parse_normal_body(n, have, "]"); // [v Ident], [v bumps 0.5 scale 2]
        }
        entries.push_back(
            {value,
             map_entry(body, have ? std::make_shared<const PovNormal>(std::move(n)) : nullptr)});
    }
    if (entries.empty()) error_at(kw, "an empty normal map");
    if (entries.size() > 256) error_at(kw, "a normal map of more than 256 entries");
    if (!weights) // POV-Ray searches the entries in order; sorted, equal values keep it
        std::stable_sort(entries.begin(), entries.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
    return entries;
}

std::vector<std::array<double, 3>> Parser::parse_slope_map() {
    const Token& open = peek();
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Other, declared, "a slope map")) {
        expect_sym("}");
        if (declared.str != "slope_map") error_at(peek(), "a declared slope map expected");
        return declared.as<std::vector<std::array<double, 3>>>();
    }
    std::vector<std::array<double, 3>> entries;
    while (!accept_sym("}")) {
        const Token& e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        const Token& vt = peek();
        const Value v = parse_additive(); // no comparison: `[0 <0, 1>]` is a value and a vector
        if (v.type != VType::Float) error_expected(vt, "a float (the entry's value)");
        const double value = v.v[0];
        accept_sym(",");
        const Token& at = peek();
        const Value hs = parse_expr(); // <height, slope>
        double height = 0, slope = 0;
        if (hs.type == VType::Float) {
            height = slope = hs.v[0]; // a float promotes to <f, f>
        } else if (hs.type == VType::Vector && hs.dim >= 2) {
            height = hs.v[0], slope = hs.v[1];
        } else {
            error_expected(at, "<height, slope>");
        }
        if (!std::isfinite(value) || !std::isfinite(height) || !std::isfinite(slope))
            error_at(at, "a slope map entry that is not finite");
        expect_sym("]");
        entries.push_back({value, height, slope});
    }
    if (entries.empty()) error_at(open, "an empty slope map");
    if (entries.size() > 256) error_at(open, "a slope map of more than 256 entries");
    // POV-Ray searches its entries in the order given; sorted, equal values keep that order.
    std::stable_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a[0] < b[0]; });
    return entries;
}

} // namespace sheaf::io::pov

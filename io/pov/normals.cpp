// Normals: a pattern with its bump size (`bumps 0.4`, `ripples 0.5 frequency 3`,
// `granite 0.3`, `bump_size`), its modifiers and transforms, and declared normals.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>

namespace sheaf::io::pov {

namespace {

// How strongly a normal pattern tilts, relative to its slope: measured as the spread of a lit
// plane's shading against povray's (normal { NAME 0.5 }, 128x128, tests in docs/pov.md).
double normal_slope_scale(const std::string& name) {
    if (name == "bumps") return 1.0;
    if (name == "waves") return 0.8;
    if (name == "ripples") return 0.35;
    if (name == "wrinkles") return 0.28;
    if (name == "dents") return 0.3;
    return 0.15; // every other pattern: POV-Ray's generic slope normal
}

// The patterns POV-Ray draws with normal functions of their own, which ignore a slope map.
bool has_own_normal(const std::string& name) {
    return name == "bumps" || name == "dents" || name == "ripples" || name == "waves" ||
           name == "wrinkles" || name == "quilted" || name == "facets";
}

} // namespace

std::shared_ptr<const PovNormal> Parser::parse_normal(const PovNormal* base) {
    const Token at = peek();
    const Nest nest(*this, at); // normal maps hold normals
    expect_sym("{");
    PovNormal n = base ? *base : PovNormal{};
    bool have = base != nullptr;
    Value declared;
    if (accept_declared(VType::Normal, declared, "a normal")) {
        n = declared.as<PovNormal>();
        have = true;
    }
    for (;;) {
        const Token t = peek();
        if (accept_sym("}")) break;
        if (parse_pattern_modifier(n.pattern, n.local)) continue;
        if (t.kind != TokKind::Ident) error_expected(t, "a normal pattern or '}'");
        int list = 0;
        bool supported = true;
        if (parse_pattern_name(n.pattern, list, supported)) {
            if (!supported) unsupported(t, "normal pattern '" + t.text + "' (no normal change)");
            have = supported;
            n.slope_scale = normal_slope_scale(t.text);
            n.own_normal = has_own_normal(t.text);
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
            unsupported(t, "normal average (no normal change)");
            have = false;
        } else if (k == "slope_map") {
            n.slope_map = parse_slope_map();
        } else if (k == "normal_map") {
            unsupported(t, k + " (the pattern's own slope is used)");
            skip_block();
        } else if (k == "bump_map") {
            unsupported(t, "bump_map (no normal change)");
            skip_block();
            have = false;
        } else if (k == "uv_mapping") {
            unsupported(t, "uv_mapping (surfaces carry no POV-Ray uv coordinates; the pattern is "
                           "evaluated in space)");
        } else if (k == "accuracy" || k == "no_bump_scale") {
            if (starts_expression(peek())) parse_expr();
        } else if (k == "normal") { // a list entry of a list pattern: the first is kept
            unsupported(t, "normal list (the pattern's own slope is used)");
            skip_block();
        } else {
            error_expected(t, "a normal item (bumps, ripples, bump_size, turbulence ...)");
        }
    }
    (void)at;
    if (!have) return nullptr;
    if (n.own_normal) n.slope_map.clear(); // as POV-Ray: their own normals take no slope map
    return std::make_shared<const PovNormal>(std::move(n));
}

std::vector<std::array<double, 3>> Parser::parse_slope_map() {
    const Token open = peek();
    expect_sym("{");
    Value declared;
    if (accept_declared(VType::Other, declared, "a slope map")) {
        expect_sym("}");
        if (declared.str != "slope_map") error_at(peek(), "a declared slope map expected");
        return declared.as<std::vector<std::array<double, 3>>>();
    }
    std::vector<std::array<double, 3>> entries;
    while (!accept_sym("}")) {
        const Token e = peek();
        if (!accept_sym("[")) error_expected(e, "'[' or '}'");
        const Token vt = peek();
        const Value v = parse_additive(); // no comparison: `[0 <0, 1>]` is a value and a vector
        if (v.type != VType::Float) error_expected(vt, "a float (the entry's value)");
        const double value = v.v[0];
        accept_sym(",");
        const Token at = peek();
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

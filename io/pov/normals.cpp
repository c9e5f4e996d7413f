// Normals: a pattern with its bump size (`bumps 0.4`, `ripples 0.5 frequency 3`,
// `granite 0.3`, `bump_size`), its modifiers and transforms, and declared normals.
#include "io/pov/parser.h"

#include "core/base/error.h"

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
        } else if (k == "slope_map" || k == "normal_map") {
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
        } else if (k == "normal" ) { // a list entry of a list pattern: the first is kept
            unsupported(t, "normal list (the pattern's own slope is used)");
            skip_block();
        } else {
            error_expected(t, "a normal item (bumps, ripples, bump_size, turbulence ...)");
        }
    }
    (void)at;
    if (!have) return nullptr;
    return std::make_shared<const PovNormal>(std::move(n));
}

} // namespace sheaf::io::pov

// POV-Ray's photon blocks: the scene's (global_settings photons), an object's and a light's.
#include "io/pov/parser.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

PhotonSwitch switch_of(bool on) {
    return on ? PhotonSwitch::On : PhotonSwitch::Off;
}

} // namespace

void Parser::parse_photon_settings() {
    PhotonSettings& ps = model.photons;
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (t.kind != TokKind::Ident) error_expected(t, "a photons setting or '}'");
        const std::string k = t.text;
        advance();
        if (k == "spacing") {
            const Token& at = peek();
            const double s = parse_float();
            if (!(s > 0) || !std::isfinite(s)) error_at(at, "photons need a spacing above 0");
            ps.spacing = float(s), ps.count = 0;
        } else if (k == "count") {
            const Token& at = peek();
            const double c = parse_float();
            if (!(c >= 1 && c <= 20e6))
                error_at(at, "a photon count must lie between 1 and 20 million");
            ps.count = uint32_t(c), ps.spacing = 0;
        } else if (k == "gather") {
            const Token& at = peek();
            const double lo = parse_float();
            expect_sym(",");
            const double hi = parse_float();
            if (!(lo >= 0 && hi >= 1 && lo <= hi && hi <= 10000))
                error_at(at, "gather needs 0 <= min <= max, and max from 1 to 10000");
            ps.gather_min = uint32_t(lo), ps.gather_max = uint32_t(hi);
        } else if (k == "radius") {
            // radius GATHER [, MULTIPLIER [, MEDIA_GATHER [, MEDIA_MULTIPLIER]]]
            const Token& at = peek();
            double r = 0, scale = 1;
            if (starts_expression(peek())) r = parse_float();
            if (accept_sym(",")) {
                if (starts_expression(peek())) scale = parse_float();
                if (accept_sym(",")) {
                    if (starts_expression(peek())) parse_float();
                    if (accept_sym(",") && starts_expression(peek())) parse_float();
                }
            }
            if (!(r >= 0) || !std::isfinite(r) || !(scale > 0) || !std::isfinite(scale))
                error_at(at, "a photon gather radius must be 0 (estimated) or more, and its "
                             "multiplier above 0");
            ps.radius = float(r), ps.radius_scale = float(scale);
        } else if (k == "jitter") {
            const Token& at = peek();
            const double j = parse_float();
            if (!(j >= 0 && j <= 1)) error_at(at, "photons' jitter must lie between 0 and 1");
            ps.jitter = float(j);
        } else if (k == "max_trace_level") {
            const Token& at = peek();
            const double l = parse_float();
            if (!(l >= 1 && l <= 256))
                error_at(at, "photons' max_trace_level must lie between 1 and 256");
            ps.max_trace_level = uint32_t(l);
        } else if (k == "adc_bailout") {
            const Token& at = peek();
            const double a = parse_float();
            if (!(a >= 0 && a < 1)) error_at(at, "photons' adc_bailout must lie in [0, 1)");
            ps.adc_bailout = float(a);
        } else if (k == "expand_thresholds") {
            const Token& at = peek();
            const double tol = parse_float();
            expect_sym(",");
            const double n = parse_float();
            if (!(tol >= 0) || !(n >= 0 && n <= 1e6))
                error_at(at, "expand_thresholds needs a share of 0 or more and a count");
            ps.expand_tolerance = float(tol), ps.expand_min = uint32_t(n);
        } else if (k == "steps") {
            const Token& at = peek();
            const double n = parse_float();
            if (!(n >= 1 && n <= 16)) error_at(at, "photons' steps must lie between 1 and 16");
            ps.steps = uint32_t(n);
        } else if (k == "media") {
            const double steps = parse_float();
            if (accept_sym(",")) parse_float();
            if (steps > 0) unsupported(t, "photons in media (ignored)");
        } else if (k == "autostop") { // a speed-up of POV-Ray's shooting: the same photons
            parse_float();
        } else if (k == "save_file") { // POV-Ray's own file format: not written
            parse_string();
        } else if (k == "load_file") {
            const Token& at = peek();
            parse_string();
            unsupported(at, "photons' load_file (the photons are shot instead)");
        } else {
            error_expected(t, "a photons setting (spacing, count, gather, radius, jitter ...)");
        }
    }
}

void Parser::parse_object_photons(PovObject& o) {
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (t.kind != TokKind::Ident) error_expected(t, "an object's photons setting or '}'");
        const std::string k = t.text;
        advance();
        if (k == "target") {
            double m = 1;
            const Token& at = peek();
            if (starts_expression(peek())) m = parse_float();
            if (!(m > 0) || !std::isfinite(m))
                error_at(at, "a photon target's spacing multiplier must be above 0");
            o.photons.target = float(m);
        } else if (k == "refraction") {
            o.photons.refraction = switch_of(parse_bool_opt(true));
        } else if (k == "reflection") {
            o.photons.reflection = switch_of(parse_bool_opt(true));
        } else if (k == "collect") {
            if (parse_bool_opt(true))
                o.flags = uint8_t(o.flags & ~kNoPhotonCollect);
            else
                o.flags |= kNoPhotonCollect;
        } else if (k == "pass_through") {
            if (parse_bool_opt(true))
                o.flags |= kPassPhotons;
            else
                o.flags = uint8_t(o.flags & ~kPassPhotons);
        } else if (k == "split_union") { // how POV-Ray aims at a union's parts
            parse_bool_opt(true);
        } else {
            error_expected(t, "target, refraction, reflection, collect, pass_through or '}'");
        }
    }
}

void Parser::parse_light_photons(Light& l) {
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) break;
        if (t.kind != TokKind::Ident) error_expected(t, "a light's photons setting or '}'");
        const std::string k = t.text;
        advance();
        if (k == "refraction") {
            l.photon_refraction = switch_of(parse_bool_opt(true));
        } else if (k == "reflection") {
            l.photon_reflection = switch_of(parse_bool_opt(true));
        } else if (k == "area_light") { // area lights shoot as one light here
            parse_bool_opt(true);
        } else {
            error_expected(t, "refraction, reflection, area_light or '}'");
        }
    }
}

} // namespace sheaf::io::pov

// Built-in functions of the scene language: float math (shared with user functions),
// vectors (vlength, vcross, vrotate ...), strings (concat, str, substr ...), random streams,
// arrays (dimension_size) and defined().
#include "io/pov/parser.h"

#include "core/base/error.h"
#include "core/texture/pov_noise.h"
#include "io/pov/probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace sheaf::io::pov {

namespace {

const std::set<std::string>& names() {
    static const std::set<std::string> s = {"vlength",     "vnormalize", "vdot",
                                            "vcross",      "vrotate",    "vaxis_rotate",
                                            "vturbulence", "concat",     "str",
                                            "vstr",        "chr",        "strlen",
                                            "substr",      "strupr",     "strlwr",
                                            "val",         "asc",        "file_exists",
                                            "rand",        "seed",       "dimension_size",
                                            "dimensions",  "defined",    "inside",
                                            "trace",       "min_extent", "max_extent",
                                            "bitwise_and", "bitwise_or", "bitwise_xor",
                                            "prod",        "sum",        "datetime",
                                            "now"};
    return s;
}

std::string format_float(double d, int width, int precision) {
    char buf[128];
    const bool zero = width < 0;
    const int w = std::min(std::abs(width), 60);
    if (precision < 0) {
        std::snprintf(buf, sizeof buf, zero ? "%0*g" : "%*g", w, d);
    } else {
        std::snprintf(buf, sizeof buf, zero ? "%0*.*f" : "%*.*f", w, std::min(precision, 40), d);
    }
    return buf;
}

Vec3 rotate_xyz(Vec3 v, Vec3 deg) {
    const Affine r = Affine::rotate({0, 0, 1}, deg.z * float(M_PI / 180)) *
                     Affine::rotate({0, 1, 0}, deg.y * float(M_PI / 180)) *
                     Affine::rotate({1, 0, 0}, deg.x * float(M_PI / 180));
    return r.vector(v);
}

} // namespace

Parser::Word Parser::word(const Token& t) {
    auto classify = [&] {
        static const std::set<std::string> colours = {
            "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "color", "colour"};
        if (colours.count(t.text)) return Word::Colour;
        if (is_float_builtin(t.text)) return Word::MathBuiltin;
        if (names().count(t.text)) return Word::Builtin;
        return Word::Other;
    };
    const uint32_t id = name_of(t);
    if (id == Scopes::kNoName) return classify();
    if (id >= words_.size()) words_.resize(size_t(id) + 1, Word::Unknown);
    if (words_[id] == Word::Unknown) words_[id] = classify();
    return words_[id];
}

bool Parser::builtin_call(const Token& t, Value& out) {
    const std::string& n = t.text;
    const Word w = word(t);
    const bool math = w == Word::MathBuiltin;
    if (!math && w != Word::Builtin) return false;
    advance();
    if (same_text(n, "now")) {
        out = Value::number(0);
        return true;
    }
    if (!is_sym("(")) error_expected(peek(), "'(' after " + n);
    advance();
    if (same_text(n, "defined")) {
        const Token& id = raw();
        if (id.kind != TokKind::Ident) error_expected(id, "an identifier");
        advance();
        bool d = lookup(id) != nullptr || find_macro(id.text) != nullptr;
        if (is_sym_tok(raw(), "[")) { // defined(A[i])
            const Value* a = lookup(id);
            if (!a) error_at(id, "'" + id.text + "' is not declared");
            Value probe = *a;
            const ArrayValue& arr = a->as<ArrayValue>();
            size_t flat = 0;
            for (size_t k = 0; k < arr.sizes.size(); ++k) {
                expect_sym("[");
                const double i = parse_float();
                expect_sym("]");
                flat = flat * arr.sizes[k] + size_t(std::clamp(i, 0.0, double(arr.sizes[k] - 1)));
            }
            d = arr.elements[flat].type != VType::None;
        }
        expect_sym(")");
        out = Value::number(d);
        return true;
    }
    std::vector<Value> args;
    std::vector<const Token*> at; // where each argument starts (tokens of files the reader holds)
    Token normal_var;             // trace's fourth argument: the variable its normal is put in
    if (!accept_sym(")")) {
        for (;;) {
            at.push_back(&peek());
            if (same_text(n, "trace") && at.size() == 4) {
                normal_var = peek();
                if (normal_var.kind != TokKind::Ident)
                    error_expected(normal_var, "an identifier for the surface's normal");
                advance();
                args.emplace_back();
                expect_sym(")", "')' after trace's normal variable");
                break;
            }
            args.push_back(parse_rvalue());
            if (accept_sym(")")) break;
            expect_sym(",", "',' or ')'");
        }
    }
    auto need = [&](size_t k) {
        if (args.size() != k)
            error_at(t, n + " takes " + std::to_string(k) + " arguments, not " +
                            std::to_string(args.size()));
    };
    auto num = [&](size_t i) {
        if (args[i].type != VType::Float) error_expected(*at[i], "a float");
        return args[i].v[0];
    };
    auto vec = [&](size_t i) {
        const Value& v = args[i];
        if (!v.numeric()) error_expected(*at[i], "a vector");
        if (v.type == VType::Float) return Vec3(float(v.v[0]));
        return Vec3(float(v.v[0]), float(v.v[1]), float(v.dim > 2 ? v.v[2] : 0));
    };
    auto str = [&](size_t i) -> const std::string& {
        if (args[i].type != VType::String) error_expected(*at[i], "a string");
        return args[i].str;
    };
    auto vout = [](Vec3 v) { return Value::vec3(v.x, v.y, v.z); };
    auto set_normal = [&](Vec3 v) { // as #declare, or into the local of that name
        if (normal_var.kind != TokKind::Ident) return;
        if (Value* existing = lookup_mut(normal_var))
            *existing = vout(v);
        else
            declare(normal_var.text, vout(v), false);
    };
    if (math) {
        std::vector<double> a;
        for (size_t i = 0; i < args.size(); ++i) a.push_back(num(i));
        double r = 0;
        if (!eval_builtin(n, a, r))
            error_at(t, n + " does not take " + std::to_string(a.size()) + " arguments");
        out = Value::number(r);
    } else if (same_text(n, "vlength")) {
        need(1);
        out = Value::number(length(vec(0)));
    } else if (same_text(n, "vnormalize")) {
        need(1);
        const Vec3 v = vec(0);
        out = length(v) > 0 ? vout(v / length(v)) : vout(v);
    } else if (same_text(n, "vdot")) {
        need(2);
        out = Value::number(dot(vec(0), vec(1)));
    } else if (same_text(n, "vcross")) {
        need(2);
        out = vout(cross(vec(0), vec(1)));
    } else if (same_text(n, "vrotate")) {
        need(2);
        out = vout(rotate_xyz(vec(0), vec(1)));
    } else if (same_text(n, "vaxis_rotate")) {
        need(3);
        out = vout(Affine::rotate(vec(1), float(num(2) * M_PI / 180)).vector(vec(0)));
    } else if (same_text(n, "vturbulence")) { // vturbulence(lambda, omega, octaves, point)
        need(4);
        // POV-Ray's DTurbulence, its omega and lambda in single precision as POV-Ray keeps them.
        const int octaves = std::isfinite(num(2)) ? int(std::clamp(num(2), 1.0, 10.0)) : 6;
        const Value& p = args[3];
        if (!p.numeric()) error_expected(*at[3], "a vector");
        const DVec3 q = p.type == VType::Float ? DVec3(p.v[0], p.v[0], p.v[0])
                                               : DVec3(p.v[0], p.v[1], p.dim > 2 ? p.v[2] : 0);
        const DVec3 t = pov_dturbulence(q, octaves, double(float(num(1))), double(float(num(0))));
        out = Value::vec3(t.x, t.y, t.z);
    } else if (same_text(n, "concat")) {
        // A string lives in the variables and values that hold it, which the data budget does
        // not follow: one string may take a sixteenth of the budget, checked before it is built.
        size_t size = 0;
        for (size_t i = 0; i < args.size(); ++i) size += str(i).size();
        const uint64_t most = options_.limits.data_bytes / 16;
        if (size > most)
            error_at(t, "a string longer than " + std::to_string(most >> 10) +
                            " KiB (a sixteenth of the data limit; render --limit data_mib=N "
                            "raises it)");
        std::string s;
        s.reserve(size);
        for (size_t i = 0; i < args.size(); ++i) s += str(i);
        out = Value::string(std::move(s));
    } else if (same_text(n, "str")) {
        need(3);
        out = Value::string(format_float(num(0), int(num(1)), int(num(2))));
    } else if (same_text(n, "vstr")) {
        need(5);
        const Value& v = args[1];
        std::string s;
        for (int i = 0; i < int(num(0)) && i < 5; ++i)
            s += (i ? str(2) : "") +
                 format_float(v.dim == 1 ? v.v[0] : v.v[i], int(num(3)), int(num(4)));
        out = Value::string(s);
    } else if (same_text(n, "chr")) {
        need(1);
        out = Value::string(std::string(1, char(int(num(0)))));
    } else if (same_text(n, "strlen")) {
        need(1);
        out = Value::number(double(str(0).size()));
    } else if (same_text(n, "substr")) {
        need(3);
        const std::string& s = str(0);
        const double p = num(1), l = num(2);
        if (p < 1 || l < 0 || p - 1 + l > double(s.size()))
            error_at(t, "substr outside the string (length " + std::to_string(s.size()) + ")");
        out = Value::string(s.substr(size_t(p) - 1, size_t(l)));
    } else if (same_text(n, "strupr") || same_text(n, "strlwr")) {
        need(1);
        std::string s = str(0);
        for (char& c : s) c = char(same_text(n, "strupr") ? toupper(c) : tolower(c));
        out = Value::string(s);
    } else if (same_text(n, "val")) {
        need(1);
        out = Value::number(std::atof(str(0).c_str()));
    } else if (same_text(n, "asc")) {
        need(1);
        out = Value::number(str(0).empty() ? 0 : double((unsigned char)str(0)[0]));
    } else if (same_text(n, "file_exists")) {
        need(1);
        namespace fs = std::filesystem;
        const fs::path p = str(0);
        std::error_code ec; // a name the system refuses (too long ...) does not exist
        bool e = fs::exists(p.is_absolute() ? p : fs::path(scene_dir_) / p, ec);
        for (const std::string& d : options_.include_paths)
            e = e || fs::exists(fs::path(d) / p, ec);
        out = Value::number(e);
    } else if (same_text(n, "seed")) {
        need(1);
        // POV-Ray's stream: the seed's whole part as 32 bits of state; one out of an int's
        // range (or NaN) becomes INT_MIN, as POV-Ray's conversion gives on x86.
        const double s = num(0);
        const int32_t seed = s > -2147483649.0 && s < 2147483648.0 ? int32_t(s) : INT32_MIN;
        rand_streams_.push_back(uint32_t(seed));
        out = Value::number(double(rand_streams_.size() - 1));
    } else if (same_text(n, "rand")) {
        need(1);
        const double s = num(0);
        if (s < 0 || size_t(s) >= rand_streams_.size())
            error_at(*at[0], "rand of a stream that seed() did not make");
        // POV-Ray's generator: the classic 32-bit step, the state over 2^32 - 1.
        uint32_t& x = rand_streams_[size_t(s)];
        x = x * 1812433253u + 12345u;
        out = Value::number(double(x) / 4294967295.0);
    } else if (same_text(n, "dimension_size") || same_text(n, "dimensions")) {
        if (args.empty() || args[0].type != VType::Array) error_expected(*at[0], "an array");
        const ArrayValue& a = args[0].as<ArrayValue>();
        if (same_text(n, "dimensions")) {
            out = Value::number(double(a.sizes.size()));
        } else {
            need(2);
            const double d = num(1);
            out = Value::number(
                d >= 1 && size_t(d) <= a.sizes.size() ? double(a.sizes[size_t(d) - 1]) : 0.0);
        }
    } else if (same_text(n, "bitwise_and") || same_text(n, "bitwise_or") ||
               same_text(n, "bitwise_xor")) {
        long r = long(num(0));
        for (size_t i = 1; i < args.size(); ++i) {
            const long b = long(num(i));
            r = same_text(n, "bitwise_and")  ? (r & b)
                : same_text(n, "bitwise_or") ? (r | b)
                                             : (r ^ b);
        }
        out = Value::number(double(r));
    } else if (same_text(n, "min_extent") || same_text(n, "max_extent")) {
        need(1);
        Vec3 lo(0.0f), hi(0.0f); // an unsupported object (warned where declared) or none
        if (args[0].type == VType::Object)
            object_extent(args[0].as<PovObject>(), lo, hi);
        else if (!(args[0].type == VType::Other && args[0].str == "object"))
            error_expected(*at[0], "an object identifier");
        const Vec3 v = same_text(n, "min_extent") ? lo : hi;
        out = Value::vec3(v.x, v.y, v.z);
    } else if (same_text(n, "trace") || same_text(n, "inside")) {
        // trace(OBJECT, FROM, DIRECTION [, NORMAL]): the first surface's point (<0,0,0> when
        // none) and its normal put in NORMAL (<0,0,0> when none); inside(OBJECT, POINT).
        if (same_text(n, "inside"))
            need(2);
        else if (args.size() != 3 && args.size() != 4)
            error_at(t, "trace takes 3 or 4 arguments, not " + std::to_string(args.size()));
        if (args[0].type == VType::Other && args[0].str == "object") {
            out = same_text(n, "inside") ? Value::number(0)
                                         : Value::vec3(0, 0, 0); // warned when declared
            set_normal(Vec3(0.0f));
            return true;
        }
        if (args[0].type != VType::Object) error_expected(*at[0], "an object identifier");
        const ObjectProbe& q = probe(args[0], t);
        if (same_text(n, "inside")) {
            out = Value::number(probe_inside(q, vec(1)) ? 1 : 0);
        } else {
            Vec3 hit(0.0f), normal(0.0f);
            if (!probe_trace(q, vec(1), vec(2), hit, normal)) hit = normal = Vec3(0.0f);
            out = vout(hit);
            set_normal(normal);
        }
    } else { // prod, sum, datetime
        unsupported(t, n + " (gives 0)");
        out = same_text(n, "datetime") ? Value::string("") : Value::number(0);
    }
    return true;
}

const ObjectProbe& Parser::probe(const Value& v, const Token& at) {
    for (auto it = probes_.begin(); it != probes_.end(); ++it)
        if (it->first == v.ptr) {
            std::rotate(it, it + 1, probes_.end()); // most recent last
            return *probes_.back().second;
        }
    constexpr size_t kMaxProbes = 8; // the objects a loop queries in turn
    if (probes_.size() == kMaxProbes) probes_.erase(probes_.begin());
    probes_.emplace_back(v.ptr, make_probe(*this, v.as<PovObject>(), at));
    return *probes_.back().second;
}

} // namespace sheaf::io::pov

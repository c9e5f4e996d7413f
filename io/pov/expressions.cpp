// Expressions with POV-Ray's precedence (lowest first): ?:, |, &, comparisons, + -, * /,
// unary + - !, then members (.x, .red ...). Vectors promote floats; colours have five
// components (r, g, b, filter, transmit).
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>
#include <set>

namespace sheaf::io::pov {

namespace {

Value arith(const Parser& p, const Value& a, const Value& b, char op, const Token& t) {
    if (!a.numeric() || !b.numeric())
        p.error_at(t, std::string("cannot apply '") + op + "' to " + type_name(a.type) + " and " +
                          type_name(b.type));
    Value r;
    if (a.type == VType::Color || b.type == VType::Color) {
        r.type = VType::Color, r.dim = 5;
    } else {
        r.dim = std::max(a.dim, b.dim);
        r.type = r.dim == 1 ? VType::Float : VType::Vector;
    }
    for (int i = 0; i < r.dim; ++i) {
        const double x = a.dim == 1 ? a.v[0] : (i < a.dim ? a.v[i] : 0.0);
        const double y = b.dim == 1 ? b.v[0] : (i < b.dim ? b.v[i] : 0.0);
        switch (op) {
        case '+':
            r.v[i] = x + y;
            break;
        case '-':
            r.v[i] = x - y;
            break;
        case '*':
            r.v[i] = x * y;
            break;
        default:
            r.v[i] = x / y;
            break;
        }
    }
    return r;
}

bool truth(const Value& v) {
    return std::fabs(v.v[0]) > 1e-10;
}

double scalar(const Parser& p, const Value& v, const Token& t) {
    if (!v.numeric()) p.error_expected(t, std::string("a float, not ") + type_name(v.type));
    return v.v[0];
}

} // namespace

Value Parser::parse_expr() {
    return parse_ternary();
}

double Parser::parse_float() {
    const Token& t = peek();
    const Value v = parse_expr();
    if (v.type != VType::Float) error_expected(t, std::string("a float, not ") + type_name(v.type));
    return v.v[0];
}

Vec3 Parser::parse_vector() {
    const Token& t = peek();
    const Value v = parse_expr();
    if (v.type == VType::Float) return Vec3(float(v.v[0]));
    if (!v.numeric()) error_expected(t, std::string("a vector, not ") + type_name(v.type));
    return Vec3(float(v.v[0]), float(v.v[1]), float(v.dim >= 3 ? v.v[2] : 0.0));
}

std::string Parser::parse_string() {
    const Token& t = peek();
    const Value v = parse_expr();
    if (v.type != VType::String) error_expected(t, "a string");
    return v.str;
}

bool Parser::parse_bool_opt(bool dflt) {
    const Token& t = peek();
    if (t.kind == TokKind::Number || is_kw_tok(t, "on") || is_kw_tok(t, "off") ||
        is_kw_tok(t, "true") || is_kw_tok(t, "false") || is_kw_tok(t, "yes") ||
        is_kw_tok(t, "no") || is_sym_tok(t, "(") || is_sym_tok(t, "!"))
        return truth(parse_expr());
    if (t.kind == TokKind::Ident) {
        const Value* v = lookup(t);
        if (v && v->type == VType::Float) return truth(parse_expr());
    }
    return dflt;
}

Color5 Parser::parse_color() {
    const Token& t = peek();
    Color5 c{0, 0, 0, 0, 0};
    const bool keyword = is_kw_tok(t, "color") || is_kw_tok(t, "colour");
    if (keyword) advance();
    const Token& n = peek();
    const bool component = is_kw_tok(n, "red") || is_kw_tok(n, "green") || is_kw_tok(n, "blue") ||
                           is_kw_tok(n, "filter") || is_kw_tok(n, "transmit");
    if (!component) {
        const Value v = parse_additive();
        if (!v.numeric()) error_expected(t, std::string("a colour, not ") + type_name(v.type));
        c = to_color(v);
    }
    for (;;) { // component modifiers: color Red filter 0.5, color red 1 green 0.5
        const Token& m = peek_cont();
        int k = -1;
        if (is_kw_tok(m, "red"))
            k = 0;
        else if (is_kw_tok(m, "green"))
            k = 1;
        else if (is_kw_tok(m, "blue"))
            k = 2;
        else if (is_kw_tok(m, "filter"))
            k = 3;
        else if (is_kw_tok(m, "transmit"))
            k = 4;
        if (k < 0) break;
        advance();
        c[k] = parse_float();
    }
    return c;
}

Value Parser::parse_color_keyword(const Token& t) {
    const std::string& k = t.text;
    if (k == "color" || k == "colour") return Value::color(parse_color());
    const bool srgb = k.rfind("srgb", 0) == 0;
    const std::string kind = srgb ? k.substr(1) : k; // rgb, rgbf, rgbt, rgbft
    const Token& at = peek();
    // The whole expression after the keyword is its vector, as in POV-Ray: `rgb 0.6 + 0.5 * x`
    // is grey (0.6 + 0.5x), where a colour `rgb 0.6` plus a float would add the float to its
    // filter and transmit too (incdemo/screen.pov's buildings came out half clear).
    const Value v = parse_additive();
    if (!v.numeric()) error_expected(at, std::string("a colour vector, not ") + type_name(v.type));
    Color5 c{0, 0, 0, 0, 0};
    const int want = kind == "rgb" ? 3 : kind == "rgbft" ? 5 : 4;
    double in[5];
    for (int i = 0; i < 5; ++i) in[i] = v.dim == 1 ? v.v[0] : (i < v.dim ? v.v[i] : 0.0);
    for (int i = 0; i < 3; ++i) c[i] = srgb ? srgb_to_linear(in[i]) : in[i];
    if (kind == "rgbf") c[3] = in[3];
    if (kind == "rgbt") c[4] = in[3];
    if (kind == "rgbft") c[3] = in[3], c[4] = in[4];
    (void)want;
    Value out = Value::color(c);
    for (;;) {
        const Token& m = peek_cont();
        int i = -1;
        if (is_kw_tok(m, "red"))
            i = 0;
        else if (is_kw_tok(m, "green"))
            i = 1;
        else if (is_kw_tok(m, "blue"))
            i = 2;
        else if (is_kw_tok(m, "filter"))
            i = 3;
        else if (is_kw_tok(m, "transmit"))
            i = 4;
        if (i < 0) break;
        advance();
        out.v[i] = parse_float();
    }
    return out;
}

Value Parser::parse_ternary() {
    Value c = parse_or();
    if (!is_sym_tok(peek_cont(), "?")) return c;
    const Token& q = raw();
    advance();
    const bool cond = truth(c);
    const int saved = no_gt_;
    no_gt_ = 0;
    Value a = parse_ternary();
    no_gt_ = saved;
    if (!is_sym_tok(peek_cont(), ":")) error_expected(raw(), "':'");
    advance();
    Value b = parse_ternary();
    (void)q;
    return cond ? a : b;
}

Value Parser::parse_or() {
    Value a = parse_and();
    while (is_sym_tok(peek_cont(), "|")) {
        advance();
        const Value b = parse_and();
        a = Value::number(truth(a) || truth(b));
    }
    return a;
}

Value Parser::parse_and() {
    Value a = parse_compare();
    while (is_sym_tok(peek_cont(), "&")) {
        advance();
        const Value b = parse_compare();
        a = Value::number(truth(a) && truth(b));
    }
    return a;
}

Value Parser::parse_compare() {
    Value a = parse_additive();
    for (;;) {
        const Token& t = peek_cont();
        if (t.kind != TokKind::Symbol) return a;
        const std::string& o = t.text;
        if (!((same_text(o, "<") && no_lt_ == 0) || same_text(o, "<=") || same_text(o, "=") ||
              same_text(o, "!=") || same_text(o, ">=") || (same_text(o, ">") && no_gt_ == 0)))
            return a;
        if (a.type != VType::Float && a.type != VType::String) return a; // <1,2,3> <4,5,6>
        advance();
        const Value b = parse_additive();
        if (a.type == VType::String && b.type == VType::String) { // 3.7 compares strings too
            const int c = a.str.compare(b.str);
            a = Value::number(same_text(o, "<")    ? c < 0
                              : same_text(o, "<=") ? c <= 0
                              : same_text(o, "=")  ? c == 0
                              : same_text(o, "!=") ? c != 0
                              : same_text(o, ">=") ? c >= 0
                                                   : c > 0);
            continue;
        }
        const double x = scalar(*this, a, t), y = scalar(*this, b, t);
        bool r;
        if (same_text(o, "<"))
            r = x < y;
        else if (same_text(o, "<="))
            r = x <= y;
        else if (same_text(o, "="))
            r = std::fabs(x - y) <= 1e-10;
        else if (same_text(o, "!="))
            r = std::fabs(x - y) > 1e-10;
        else if (same_text(o, ">="))
            r = x >= y;
        else
            r = x > y;
        a = Value::number(r);
    }
}

Value Parser::parse_additive() {
    Value a = parse_term();
    for (;;) {
        const Token& t = peek_cont();
        if (!is_sym_tok(t, "+") && !is_sym_tok(t, "-")) return a;
        advance();
        a = arith(*this, a, parse_term(), t.text[0], t);
    }
}

Value Parser::parse_term() {
    Value a = parse_unary();
    for (;;) {
        const Token& t = peek_cont();
        if (!is_sym_tok(t, "*") && !is_sym_tok(t, "/")) return a;
        advance();
        a = arith(*this, a, parse_unary(), t.text[0], t);
    }
}

Value Parser::parse_unary() {
    const Token& t = peek();
    const Nest nest(*this, t); // every nested expression comes through here
    if (is_sym_tok(t, "-") || is_sym_tok(t, "+")) {
        advance();
        Value v = parse_unary();
        if (!v.numeric()) error_expected(t, "a number after the sign");
        if (t.text == "-")
            for (int i = 0; i < v.dim; ++i) v.v[i] = -v.v[i];
        return v;
    }
    if (is_sym_tok(t, "!")) {
        advance();
        const Value v = parse_unary();
        return Value::number(!truth(v));
    }
    return parse_postfix();
}

Value Parser::parse_postfix() {
    Value v = parse_primary();
    while (is_sym_tok(peek_cont(), ".")) {
        advance();
        const Token& m = raw();
        if (m.kind != TokKind::Ident) error_expected(m, "a component (x, y, z, red ...)");
        advance();
        if (!v.numeric()) error_at(m, std::string("'.") + m.text + "' of " + type_name(v.type));
        const std::string& n = m.text;
        int i = -1;
        if (n == "x" || n == "u" || n == "red")
            i = 0;
        else if (n == "y" || n == "v" || n == "green")
            i = 1;
        else if (n == "z" || n == "blue")
            i = 2;
        else if (n == "t" || n == "filter")
            i = 3;
        else if (n == "transmit")
            i = 4;
        if (n == "gray" || n == "grey") {
            v = Value::number(0.297 * v.v[0] + 0.589 * v.v[1] + 0.114 * v.v[2]);
            continue;
        }
        if (i < 0) error_expected(m, "a component (x, y, z, t, u, v, red, green, blue ...)");
        if (v.type != VType::Color && i >= v.dim && v.dim > 1)
            error_at(m, "'." + n + "' of a " + std::to_string(v.dim) + "-component vector");
        v = Value::number(v.dim == 1 ? v.v[0] : v.v[i]);
    }
    return v;
}

Value Parser::parse_primary() {
    const Token& t = peek();
    switch (t.kind) {
    case TokKind::Number:
        advance();
        return Value::number(t.number);
    case TokKind::String:
        advance();
        return Value::string(t.text);
    case TokKind::Ident:
        return parse_identifier(t);
    case TokKind::Symbol:
        if (t.text == "(") {
            advance();
            const int saved = no_gt_, saved_lt = no_lt_;
            no_gt_ = no_lt_ = 0;
            Value v = parse_expr();
            no_gt_ = saved, no_lt_ = saved_lt;
            expect_sym(")", "')'");
            return v;
        }
        if (t.text == "<") {
            advance();
            double c[5];
            int n = 0;
            ++no_gt_;
            for (;;) {
                const Token& at = peek();
                const Value e = parse_expr();
                if (e.type != VType::Float)
                    error_expected(at, std::string("a float component, not ") + type_name(e.type));
                if (n == 5) error_expected(at, "'>' (at most 5 components)");
                c[n++] = e.v[0];
                if (accept_sym(",")) {
                    if (is_sym_tok(peek(), ">")) break; // <1, 2, 3,>
                    continue;
                }
                if (!is_sym_tok(peek(), ">") && starts_expression(peek())) continue; // < -1 0 0 >
                break;
            }
            --no_gt_;
            expect_sym(">", "',' or '>'");
            if (n < 2) error_at(t, "a vector needs at least 2 components");
            return Value::vec(n, c);
        }
        break;
    default:
        break;
    }
    error_expected(t, "a float, vector, colour or string expression");
}

Value Parser::index_value(const Value& base, const Token& t) {
    if (base.type != VType::Array) error_at(t, "'" + t.text + "' is not an array");
    const ArrayValue& a = base.as<ArrayValue>();
    size_t flat = 0;
    for (size_t k = 0; k < a.sizes.size(); ++k) {
        if (!is_sym_tok(peek_cont(), "[")) error_expected(raw(), "'[' (more array indices)");
        advance();
        const Token& at = peek();
        const double i = parse_float();
        expect_sym("]");
        if (i < 0 || size_t(i) >= a.sizes[k])
            error_at(at, "index " + std::to_string(long(i)) + " is out of range for '" + t.text +
                             "' (size " + std::to_string(a.sizes[k]) + ")");
        flat = flat * a.sizes[k] + size_t(i);
    }
    const Value& e = a.elements[flat];
    if (e.type == VType::None) error_at(t, "element of '" + t.text + "' used before it was set");
    return e;
}

Value Parser::parse_identifier(const Token& t) {
    if (const Value* found = lookup(t)) {
        advance();
        // A copy before peek_cont, which may close the macro whose local it is.
        Value v = *found;
        if (v.type == VType::Array && is_sym_tok(peek_cont(), "[")) v = index_value(v, t);
        raise_pending(v);
        if (v.type == VType::Other && v.str == "spline" && is_sym_tok(peek_cont(), "("))
            return call_spline(v.as<PovSpline>());
        if (v.type == VType::Function && is_sym_tok(peek_cont(), "(")) {
            const auto fn = std::static_pointer_cast<PovFunction>(v.ptr);
            return call_function(t, *fn);
        }
        return v;
    }
    const std::string& k = t.text;
    const Word w = word(t);
    if (w == Word::Colour) {
        advance();
        return parse_color_keyword(t);
    }
    Value out;
    if ((w == Word::MathBuiltin || w == Word::Builtin) && builtin_call(t, out)) return out;
    advance();
    if (k == "x") return Value::vec3(1, 0, 0);
    if (k == "y") return Value::vec3(0, 1, 0);
    if (k == "z") return Value::vec3(0, 0, 1);
    if (k == "t") {
        const double c[4] = {0, 0, 0, 1};
        return Value::vec(4, c);
    }
    if (k == "u" || k == "v") {
        const double c[2] = {k == "u" ? 1.0 : 0.0, k == "v" ? 1.0 : 0.0};
        return Value::vec(2, c);
    }
    if (k == "pi") return Value::number(M_PI);
    if (k == "tau") return Value::number(2 * M_PI);
    if (k == "true" || k == "on" || k == "yes") return Value::number(1);
    if (k == "false" || k == "off" || k == "no") return Value::number(0);
    if (std::optional<double> c = clock_identifier(options_.clock, k)) return Value::number(*c);
    if (k == "version") return Value::number(model.version);
    if (k == "image_width") return Value::number(options_.image_width);
    if (k == "image_height") return Value::number(options_.image_height);
    if (k == "function") return parse_function(t);
    if (k == "array") return parse_array_literal(t);
    if (k == "transform") {
        Value v;
        v.type = VType::Transform;
        v.ptr = std::make_shared<Affine>(parse_transform_block());
        return v;
    }
    error_at(t, "found '" + k +
                    "', expected a float, vector, colour or string expression "
                    "(undeclared identifier?)");
}

Value Parser::parse_array_literal(const Token& t) {
    std::vector<size_t> sizes;
    size_t count = 1;
    while (is_sym_tok(peek_cont(), "[")) {
        advance();
        const Token& at = peek();
        const double n = parse_float();
        expect_sym("]");
        if (n < 1) error_at(at, "an array needs at least one element per dimension");
        if (sizes.size() == kMaxArrayDimensions)
            error_at(at,
                     "an array has at most " + std::to_string(kMaxArrayDimensions) + " dimensions");
        if (n > double(kMaxArrayElements) || count * size_t(n) > kMaxArrayElements)
            error_at(at,
                     "an array of more than " + std::to_string(kMaxArrayElements) + " elements");
        sizes.push_back(size_t(n));
        count *= size_t(n);
    }
    if (sizes.empty()) error_expected(peek(), "'[' and the array's size");
    return parse_array_init(sizes, t);
}

Value Parser::parse_array_init(const std::vector<size_t>& sizes, const Token& t) {
    size_t count = 1;
    for (size_t s : sizes) count *= s;
    auto a = std::make_shared<ArrayValue>();
    a->sizes = sizes;
    charge(count * sizeof(Value), t);
    a->budget = &data_bytes_;
    a->bytes = count * sizeof(Value);
    a->elements.resize(count);
    if (is_sym_tok(peek_cont(), "{")) {
        size_t flat = 0;
        // Nested braces, one level per dimension.
        std::function<void(size_t)> level = [&](size_t d) {
            expect_sym("{");
            size_t n = 0;
            while (!is_sym_tok(peek(), "}")) {
                if (n == sizes[d]) error_expected(peek(), "'}' (more initialisers than elements)");
                if (d + 1 < sizes.size()) {
                    level(d + 1);
                } else {
                    a->elements[flat++] = parse_rvalue();
                }
                ++n;
                accept_sym(","); // commas between initialisers may be left out
            }
            expect_sym("}", "',' or '}'");
            if (n != sizes[d])
                error_at(t, "the array has " + std::to_string(sizes[d]) + " elements but " +
                                std::to_string(n) + " initialisers");
        };
        level(0);
    }
    Value v;
    v.type = VType::Array;
    v.ptr = a;
    return v;
}

Value Parser::call_function(const Token& t, const PovFunction& f) {
    if (f.spline) return call_spline(*f.spline); // the spline's point, a vector
    if (!f.scene_unsupported.empty() && !f.transform) unsupported(t, f.scene_unsupported);
    expect_sym("(");
    std::vector<double> args;
    if (!accept_sym(")")) {
        for (;;) {
            args.push_back(parse_float());
            if (accept_sym(")")) break;
            expect_sym(",", "',' or ')'");
        }
    }
    if (args.size() != f.params.size() && f.scene_unsupported.empty())
        error_at(t, "'" + t.text + "' takes " + std::to_string(f.params.size()) +
                        " arguments, not " + std::to_string(args.size()));
    if (f.transform) { // a transform function gives the point transformed
        if (args.size() != 3) error_at(t, "a transform function takes 3 arguments");
        const Vec3 p = f.transform->point(Vec3(float(args[0]), float(args[1]), float(args[2])));
        return Value::vec3(p.x, p.y, p.z);
    }
    if (f.pigment && args.size() == 3) { // a pigment function gives its colour
        ++steps_;
        Color5 c;
        for (int i = 0; i < 5; ++i) c[size_t(i)] = f.pigment->at(i, args[0], args[1], args[2]);
        return Value::color(c);
    }
    uint64_t left = function_terms_left();
    const uint64_t had = left;
    try {
        const double v = f.eval(args.data(), int(args.size()), left);
        count_function_terms(had - left);
        return Value::number(v);
    } catch (const FnStepsExceeded&) {
        too_many_function_terms(t);
    }
}

} // namespace sheaf::io::pov

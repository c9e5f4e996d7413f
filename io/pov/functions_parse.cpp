// `function { ... }` and `function(a, b) { ... }`: the body compiled to an FnNode tree over the
// parameters; declared floats become constants, declared functions calls. `internal(N)` of the
// internal functions Sheaf knows (core/scene/function.h) and `pattern { ... }` of its
// patterns are functions too, and pigment functions; a transform function gives the point
// transformed when the scene language calls it; spline and image functions are accepted and
// marked unsupported (they evaluate to 0).
#include "io/pov/function_scene.h"
#include "io/pov/materials.h"
#include "io/pov/parser.h"

#include "core/base/error.h"
#include "core/scene/function.h"

#include <algorithm>
#include <map>

namespace sheaf::io::pov {

Value Parser::parse_function(const Token& t) {
    auto f = std::make_shared<PovFunction>();
    f->where = t;
    if (accept_sym("(")) {
        if (!accept_sym(")")) {
            for (;;) {
                f->params.push_back(expect_ident("a parameter name"));
                if (accept_sym(")")) break;
                expect_sym(",", "',' or ')'");
            }
        }
    } else {
        f->params = {"x", "y", "z"};
    }
    const Token& first = peek();
    if (!is_sym_tok(first, "{")) error_expected(first, "'{'");
    advance();
    const Token& b = peek();
    if (is_kw_tok(b, "internal")) {
        parse_internal_function(*f);
        expect_sym("}", "'}'");
    } else if (is_kw_tok(b, "pattern")) {
        parse_pattern_function(*f);
        expect_sym("}", "'}'");
    } else if (is_kw_tok(b, "pigment")) {
        parse_pigment_function(*f);
        expect_sym("}", "'}'");
    } else if (is_kw_tok(b, "transform")) {
        Affine m;
        parse_transform_item(m); // transform { ... } or transform NAME
        f->transform = std::make_shared<const Affine>(m);
        f->unsupported = f->scene_unsupported = "transform function in a function";
        expect_sym("}", "'}'");
    } else if (is_kw_tok(b, "spline")) {
        advance();
        f->spline = std::make_shared<const PovSpline>(parse_spline());
        f->unsupported = f->scene_unsupported = "spline function in a function";
        expect_sym("}", "'}'");
    } else if (is_kw_tok(b, "image_map")) {
        f->unsupported = f->scene_unsupported = b.text + " function";
        int depth = 1;
        while (depth > 0) {
            const Token& s = peek();
            if (s.kind == TokKind::End) error_expected(s, "'}'");
            if (is_sym_tok(s, "{")) ++depth;
            if (is_sym_tok(s, "}")) --depth;
            advance();
        }
    } else {
        const std::string saved = fn_unsupported_, saved_scene = fn_scene_unsupported_;
        fn_unsupported_.clear();
        fn_scene_unsupported_.clear();
        f->body = parse_fn(f->params, 0);
        f->unsupported = fn_unsupported_;
        f->scene_unsupported = fn_scene_unsupported_;
        fn_unsupported_ = saved;
        fn_scene_unsupported_ = saved_scene;
        expect_sym("}", "'}' or an operator");
    }
    Value v;
    v.type = VType::Function;
    v.ptr = f;
    return v;
}

void Parser::parse_internal_function(PovFunction& f) {
    advance();
    expect_sym("(");
    const double id = parse_float();
    expect_sym(")");
    const int extra = id >= 0 && id < 256 ? fn_internal_extra(int(id)) : -1;
    if (extra < 0) {
        f.unsupported = f.scene_unsupported = "internal function " + std::to_string(int(id));
        return;
    }
    f.internal = int(id);
    f.params = {"x", "y", "z"};
    for (int i = 0; i < extra; ++i) f.params.push_back("p" + std::to_string(i));
}

void Parser::parse_pattern_function(PovFunction& f) {
    advance();
    expect_sym("{");
    PovPattern pt;
    Affine local;
    int list = 0;
    bool supported = false;
    const Token& name = peek();
    if (!parse_pattern_name(pt, list, supported)) error_expected(name, "a pattern");
    only_in_normals(name, pt);
    while (!accept_sym("}"))
        if (!parse_pattern_modifier(pt, local)) error_expected(peek(), "a pattern modifier or '}'");
    if (!supported || pt.kind == PatternKind::Image || pt.kind == PatternKind::ImagePattern ||
        pt.kind == PatternKind::Function) {
        f.unsupported = f.scene_unsupported = "pattern function '" + name.text + "'";
        return;
    }
    // Programs run without a scene (isosurfaces) read no pigments.
    if (pt.kind == PatternKind::PigmentPattern)
        f.unsupported = "pattern function '" + name.text + "'";
    auto pf = std::make_shared<PatternFunction>();
    pf->source = std::make_shared<const PovPattern>(std::move(pt));
    pf->local = local;
    pf->scene = function_scene(name, nullptr, pf.get());
    f.pattern = std::move(pf);
}

void Parser::parse_pigment_function(PovFunction& f) {
    const Token& at = peek(); // `pigment`
    advance();
    const std::shared_ptr<const PovPigment> pg = parse_pigment(PovPigment());
    auto pf = std::make_shared<PigmentFunction>();
    pf->source = pg;
    pf->scene = function_scene(at, pg.get(), nullptr);
    f.pigment = pf;
    // Programs run without a scene read a solid colour or a colour map or list over a pattern.
    for (int i = 0; i < 5; ++i) pf->pigment.color[i] = float(pg->color[i]);
    if (pg->patterned) {
        const PatternKind k = pg->pattern.kind;
        if (pg->average || k == PatternKind::Image || k == PatternKind::ImagePattern ||
            k == PatternKind::Function || k == PatternKind::PigmentPattern || pg->entries.empty()) {
            f.unsupported =
                "pigment function (of an average, image, function or pigment_pattern pigment)";
            return;
        }
        for (const PovMapEntry& e : pg->entries) {
            if (e.pigment && e.pigment->patterned) {
                f.unsupported = "pigment function (of a pigment map)";
                return;
            }
            PigmentEntry out;
            out.value = float(e.value);
            const Color5& c = e.pigment ? e.pigment->color : e.color;
            for (int i = 0; i < 5; ++i) out.color[i] = float(c[i]);
            pf->entries.push_back(out);
        }
        if (!pg->pattern.warps.empty()) {
            f.unsupported = "warp in a pigment function";
            return;
        }
        pf->pattern = lower_pattern(pg->pattern, pg->local, nullptr, model.pattern_defaults());
        pf->pigment.count = uint32_t(pf->entries.size());
        pf->pigment.list = pattern_is_list(k) ? 1 : 0;
    }
}

std::shared_ptr<const FunctionScene>
Parser::function_scene(const Token& at, const PovPigment* pigment, const PatternFunction* pattern) {
    auto fs = std::make_shared<FunctionScene>();
    MaterialBuilder builder(*this, fs->scene);
    if (pigment) fs->pigment = builder.function_pigment(*pigment);
    if (pattern) {
        // Lowering it may compile functions its pigment reads, which add patterns first.
        const Pattern p = builder.function_pattern(*pattern->source, pattern->local);
        fs->scene.fn_patterns.push_back(p);
        fs->pattern = int32_t(fs->scene.fn_patterns.size() - 1);
    }
    copy_texture_tables(fs->scene, fs->tables);
    if (!fs->tables.textures.empty()) {
        if (!options_.attach_sampler)
            error_at(at, "an image in a function's pigment: this program reads no images");
        options_.attach_sampler(fs->tables);
    }
    return fs;
}

namespace {

void set_height(FnNode& n) {
    for (const FnNode& a : n.args) n.height = std::max(n.height, a.height + 1);
}

/// An operation over its operands, moved in (a long chain would otherwise be copied at each
/// operator: quadratic in its length).
template <class... Kids> FnNode node(FnOp op, Kids&&... kids) {
    FnNode n;
    n.kind = FnNode::Operator;
    n.op = op;
    n.args.reserve(sizeof...(kids));
    (n.args.push_back(std::forward<Kids>(kids)), ...);
    set_height(n);
    return n;
}

} // namespace

// Levels: 0 ?:, 1 |, 2 &, 3 comparisons, 4 + -, 5 * /, 6 unary.
FnNode Parser::parse_fn(const std::vector<std::string>& params, int level) {
    if (level == 6) {
        const Token& t = peek();
        const Nest nest(*this, t); // every nested term of the body comes through here
        if (is_sym_tok(t, "-")) {
            advance();
            return node(FnOp::Neg, parse_fn(params, 6));
        }
        if (is_sym_tok(t, "+")) {
            advance();
            return parse_fn(params, 6);
        }
        if (is_sym_tok(t, "!")) {
            advance();
            return node(FnOp::Not, parse_fn(params, 6));
        }
        return parse_fn_primary(params);
    }
    FnNode a = parse_fn(params, level + 1);
    for (;;) {
        const Token& t = peek();
        if (t.kind != TokKind::Symbol) return a;
        const std::string& o = t.text;
        FnOp op;
        if (level == 0 && o == "?") {
            advance();
            FnNode b = parse_fn(params, 0);
            expect_sym(":");
            FnNode c = parse_fn(params, 0);
            return node(FnOp::Cond, std::move(a), std::move(b), std::move(c));
        } else if (level == 1 && o == "|")
            op = FnOp::Or;
        else if (level == 2 && o == "&")
            op = FnOp::And;
        else if (level == 3 && o == "<")
            op = FnOp::Lt;
        else if (level == 3 && o == "<=")
            op = FnOp::Le;
        else if (level == 3 && o == ">")
            op = FnOp::Gt;
        else if (level == 3 && o == ">=")
            op = FnOp::Ge;
        else if (level == 3 && o == "=")
            op = FnOp::Eq;
        else if (level == 3 && o == "!=")
            op = FnOp::Ne;
        else if (level == 4 && o == "+")
            op = FnOp::Add;
        else if (level == 4 && o == "-")
            op = FnOp::Sub;
        else if (level == 5 && o == "*")
            op = FnOp::Mul;
        else if (level == 5 && o == "/")
            op = FnOp::Div;
        else
            return a;
        advance();
        FnNode b = parse_fn(params, level + 1);
        a = node(op, std::move(a), std::move(b));
        if (a.height > kMaxFunctionHeight)
            error_at(t, "a function body more than " + std::to_string(kMaxFunctionHeight) +
                            " operations deep");
    }
}

FnNode Parser::parse_fn_primary(const std::vector<std::string>& params) {
    FnNode n = parse_fn_atom(params);
    while (is_sym_tok(peek(), ".")) { // F(x, y, z).red of a pigment function
        advance();
        const Token& c = peek();
        const std::string name = expect_ident("a component");
        if (n.kind != FnNode::Call || !n.fn || !n.fn->pigment) continue; // of a vector: unsupported
        static const std::map<std::string, FnComponent> components = {
            {"x", FnComponent::Red},
            {"u", FnComponent::Red},
            {"red", FnComponent::Red},
            {"y", FnComponent::Green},
            {"v", FnComponent::Green},
            {"green", FnComponent::Green},
            {"z", FnComponent::Blue},
            {"blue", FnComponent::Blue},
            {"filter", FnComponent::Filter},
            {"t", FnComponent::Transmit},
            {"transmit", FnComponent::Transmit},
            {"gray", FnComponent::Gray},
            {"grey", FnComponent::Gray},
            {"hf", FnComponent::Gray}};
        const auto it = components.find(name);
        if (it == components.end())
            error_at(c, "found '" + name +
                            "', expected a colour component (red, green, blue, "
                            "filter, transmit, gray, x, y, z, t)");
        n.component = int(it->second);
    }
    return n;
}

FnNode Parser::parse_fn_atom(const std::vector<std::string>& params) {
    const Token& t = peek();
    FnNode n;
    if (t.kind == TokKind::Number) {
        advance();
        n.value = t.number;
        return n;
    }
    if (is_sym_tok(t, "(")) {
        advance();
        n = parse_fn(params, 0);
        expect_sym(")");
        return n;
    }
    if (t.kind != TokKind::Ident) error_expected(t, "a function expression");
    advance();
    auto args = [&]() {
        std::vector<FnNode> a;
        expect_sym("(", "'(' after " + t.text);
        if (accept_sym(")")) return a;
        for (;;) {
            a.push_back(parse_fn(params, 0));
            if (accept_sym(")")) return a;
            expect_sym(",", "',' or ')'");
        }
    };
    if (auto it = std::find(params.begin(), params.end(), t.text); it != params.end()) {
        n.kind = FnNode::Param;
        n.param = int(it - params.begin());
        return n;
    }
    if (const Value* v = lookup(t)) {
        if (v->type == VType::Float) {
            n.value = v->v[0];
            return n;
        }
        if (v->type == VType::Function) {
            // What its declaration met that is unsupported (a pigment function's pigment of
            // an unsupported pattern) is warned where it is used, as in expressions.
            raise_pending(*v);
            n.kind = FnNode::Call;
            n.fn = std::static_pointer_cast<const PovFunction>(v->ptr);
            if (!n.fn->unsupported.empty() && fn_unsupported_.empty()) // warned when called
                fn_unsupported_ = n.fn->unsupported + " ('" + t.text + "')";
            if (!n.fn->scene_unsupported.empty() && fn_scene_unsupported_.empty())
                fn_scene_unsupported_ = n.fn->scene_unsupported + " ('" + t.text + "')";
            n.args = args();
            set_height(n);
            if (n.args.size() != n.fn->params.size() && n.fn->scene_unsupported.empty())
                error_at(t, "'" + t.text + "' takes " + std::to_string(n.fn->params.size()) +
                                " arguments");
            // Evaluation recurses through the called body too.
            n.height = std::max(n.height, n.fn->body.height + 1);
            if (n.height > kMaxFunctionHeight)
                error_at(t, "'" + t.text + "' calls functions nested more than " +
                                std::to_string(kMaxFunctionHeight) + " operations deep");
            return n;
        }
        error_at(t, "'" + t.text + "' (" + type_name(v->type) + ") in a function");
    }
    if (t.text == "pi") {
        n.value = M_PI;
        return n;
    }
    if (t.text == "true" || t.text == "on" || t.text == "yes") {
        n.value = 1;
        return n;
    }
    if (t.text == "false" || t.text == "off" || t.text == "no") return n;
    if (std::optional<double> c = clock_identifier(options_.clock, t.text)) {
        n.value = *c;
        return n;
    }
    if (t.text == "tau") {
        n.value = 2 * M_PI;
        return n;
    }
    if (t.text == "image_width" || t.text == "image_height" || t.text == "version") {
        n.value = t.text == "image_width"    ? options_.image_width
                  : t.text == "image_height" ? options_.image_height
                                             : model.version;
        return n;
    }
    if (is_float_builtin(t.text)) {
        n.kind = FnNode::Builtin;
        n.name = t.text;
        n.args = args();
        set_height(n);
        double out;
        if (!eval_builtin(n.name, std::vector<double>(n.args.size(), 0.5), out))
            error_at(t, t.text + " does not take " + std::to_string(n.args.size()) + " arguments");
        return n;
    }
    error_at(t, "found '" + t.text +
                    "', expected a parameter, number or function in a function "
                    "body");
}

} // namespace sheaf::io::pov

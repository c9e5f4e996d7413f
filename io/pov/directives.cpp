// Directives: #declare/#local/#undef, #if/#ifdef/#ifndef/#else/#elseif, #while, #for,
// #switch/#case/#range/#break, #end, #version, #default, #debug/#warning/#error.
// (#macro is in macros.cpp, #include and the #fopen family in files.cpp.)
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>
#include <iostream>

namespace sheaf::io::pov {

namespace {

bool opens_block(const std::string& d) {
    return d == "if" || d == "ifdef" || d == "ifndef" || d == "while" || d == "for" ||
           d == "switch" || d == "macro";
}

bool truthy(const Value& v) {
    return std::fabs(v.v[0]) > 1e-10;
}

} // namespace

bool Parser::directive(bool continuation) {
    // A directive reads its expressions afresh: '<' and '>' there compare, whatever vector or
    // macro argument list the directive stands in (a #while in a macro called as an argument).
    struct Fresh {
        int &lt, &gt;
        const int saved_lt, saved_gt;
        Fresh(int& l, int& g) : lt(l), gt(g), saved_lt(l), saved_gt(g) { lt = gt = 0; }
        ~Fresh() { lt = saved_lt, gt = saved_gt; }
    } fresh(no_lt_, no_gt_);
    Frame& f = frames_.back();
    const Token hash = f.file->tokens[f.pos];
    const Token name = f.file->tokens[f.pos + 1 < f.file->tokens.size() ? f.pos + 1 : f.pos];
    if (name.kind != TokKind::Ident) { // a stray '#': POV-Ray ignores it
        if (continuation) return false;
        advance();
        return true;
    }
    const std::string_view d = name.text; // compared with many names: sizes first
    if (continuation) {
        const Cond* top = f.conds.empty() ? nullptr : &f.conds.back();
        bool ok = false;
        if (d == "end")
            ok = top ? (top->kind == Cond::If || top->kind == Cond::Switch) : f.macro;
        else if (d == "else" || d == "elseif")
            ok = top && (top->kind == Cond::If || top->kind == Cond::Switch);
        else if (d == "break" || d == "case" || d == "range")
            ok = top && top->kind == Cond::Switch;
        if (!ok) return false;
    }
    advance();
    advance();
    if (d == "declare" || d == "local") {
        declare_directive(d == "local");
    } else if (d == "undef") {
        undef_directive();
    } else if (d == "include") {
        include_directive(name);
    } else if (d == "macro") {
        define_macro(name);
    } else if (d == "if") {
        if (truthy(parse_condition())) {
            Cond c;
            c.kind = Cond::If, c.where = name;
            frames_.back().conds.push_back(c);
        } else {
            skip_to_branch(name);
        }
    } else if (d == "ifdef" || d == "ifndef") {
        ifdef_directive(d == "ifdef");
    } else if (d == "else" || d == "elseif") {
        Frame& cur = frames_.back();
        if (cur.conds.empty()) error_at(name, "#" + name.text + " without #if");
        if (cur.conds.back().kind == Cond::Switch) {
            if (d == "elseif") parse_condition(); // falls through, like #case
        } else if (cur.conds.back().kind == Cond::If) {
            cur.conds.pop_back();
            skip_raw_to_end(1, name);
        } else {
            error_at(name, "#" + name.text + " without #if");
        }
    } else if (d == "end") {
        end_directive(name);
    } else if (d == "while") {
        Cond c;
        c.kind = Cond::While, c.where = name, c.pos = frames_.back().pos;
        if (truthy(parse_condition()))
            frames_.back().conds.push_back(c);
        else
            skip_raw_to_end(1, name);
    } else if (d == "for") {
        expect_sym("(");
        Cond c;
        c.kind = Cond::For, c.where = name;
        const Token& var = peek();
        if (var.kind != TokKind::Ident) error_expected(var, "the loop variable");
        c.var = intern_of(var);
        advance();
        expect_sym(",");
        const double start = parse_float();
        expect_sym(",");
        c.end = parse_float();
        if (accept_sym(",")) c.step = parse_float();
        expect_sym(")");
        if (c.step == 0) error_at(name, "#for with a step of 0 never ends");
        // As POV-Ray: the loop variable is #local, so a loop inside a macro never changes the
        // caller's variable of the same name.
        declare(c.var, Value::number(start), true);
        c.pos = frames_.back().pos;
        if (c.step > 0 ? start <= c.end : start >= c.end)
            frames_.back().conds.push_back(c);
        else
            skip_raw_to_end(1, name);
    } else if (d == "switch") {
        Cond c;
        c.kind = Cond::Switch, c.where = name;
        const Value v = parse_condition();
        c.end = v.v[0];
        frames_.back().conds.push_back(c);
        switch_scan(name);
    } else if (d == "case" || d == "range") {
        Frame& cur = frames_.back();
        if (cur.conds.empty() || cur.conds.back().kind != Cond::Switch)
            error_at(name, "#" + name.text + " outside #switch");
        expect_sym("(");
        parse_float();
        if (d == "range") {
            expect_sym(",");
            parse_float();
        }
        expect_sym(")"); // a matched clause runs on into the next one
    } else if (d == "break") {
        break_directive(name);
    } else if (d == "version") {
        version_directive();
    } else if (d == "default") {
        default_directive();
    } else if (d == "debug" || d == "warning" || d == "error" || d == "render" ||
               d == "statistics") {
        const std::string msg = parse_string();
        if (d == "error") error_at(name, msg);
        if (d == "warning")
            warn(name, msg);
        else
            std::cerr << msg;
    } else if (d == "fopen") {
        fopen_directive(name);
    } else if (d == "read") {
        read_directive(name);
    } else if (d == "write") {
        write_directive(name);
    } else if (d == "fclose") {
        const std::string id = expect_ident("a file identifier");
        Value* v = lookup_mut(id);
        if (v && v->type == VType::File) {
            scopes_.erase_everywhere(scopes_.find(id));
        }
    } else {
        error_expected(name, "a directive");
    }
    return true;
}

Value Parser::parse_condition() {
    ++directive_args_;
    try {
        // POV-Ray reads a parenthesised condition and stops at its ')': in
        // "#while (I < 3) <I, 0, 0>, ..." the vector that follows is the loop's first item,
        // not "(I < 3) < I".
        Value v;
        if (accept_sym("(")) {
            // Inside the parentheses the expression may run on through a macro's #end (a
            // macro called in it) up to the ')'.
            --directive_args_;
            try {
                v = parse_expr();
            } catch (...) {
                ++directive_args_;
                throw;
            }
            ++directive_args_;
            expect_sym(")", "')' closing the condition");
        } else {
            v = parse_expr();
        }
        --directive_args_;
        return v;
    } catch (...) {
        --directive_args_;
        throw;
    }
}

void Parser::declare_directive(bool local) {
    if (is_kw_tok(raw(), "deprecated")) { // #declare deprecated [once] "message" NAME = ...
        advance();
        if (is_kw_tok(raw(), "once")) advance();
        if (raw().kind == TokKind::String) advance();
    }
    const Token& name = raw();
    if (name.kind != TokKind::Ident) error_expected(name, "an identifier");
    advance();
    // A #local belongs to the scope it is written in, though a macro the value calls may
    // still be open when the value ends (its body ends with the value and the ';').
    const size_t scope = scopes_.size() - 1;
    std::vector<size_t> index;
    while (is_sym_tok(raw(), "[")) {
        advance();
        const double i = parse_float();
        expect_sym("]");
        index.push_back(size_t(std::max(0.0, i)));
    }
    expect_sym("=", "'='");
    captures_.emplace_back();
    Value v;
    try {
        v = parse_rvalue();
    } catch (...) {
        captures_.pop_back();
        throw;
    }
    if (!captures_.back().empty())
        v.pending =
            std::make_shared<const std::vector<PendingWarning>>(std::move(captures_.back()));
    captures_.pop_back();
    if (is_sym_tok(peek_cont(), ";")) advance();
    if (v.type == VType::Array) { // arrays are copied on assignment
        auto copy = std::make_shared<ArrayValue>();
        const ArrayValue& src = v.as<ArrayValue>();
        copy->sizes = src.sizes;
        charge(src.bytes, name);
        copy->elements = src.elements;
        copy->budget = &data_bytes_, copy->bytes = src.bytes;
        v.ptr = copy;
    }
    if (index.empty()) {
        if (local)
            scopes_.set(scope, intern_of(name), std::move(v));
        else
            declare(intern_of(name), std::move(v), false);
        return;
    }
    Value* arr = lookup_mut(name);
    if (!arr || arr->type != VType::Array) error_at(name, "'" + name.text + "' is not an array");
    ArrayValue& a = arr->as<ArrayValue>();
    if (index.size() != a.sizes.size())
        error_at(name, "'" + name.text + "' has " + std::to_string(a.sizes.size()) +
                           " dimensions, not " + std::to_string(index.size()));
    size_t flat = 0;
    for (size_t k = 0; k < index.size(); ++k) {
        if (index[k] >= a.sizes[k])
            error_at(name, "index " + std::to_string(index[k]) + " is out of range for '" +
                               name.text + "' (size " + std::to_string(a.sizes[k]) + ")");
        flat = flat * a.sizes[k] + index[k];
    }
    a.elements[flat] = std::move(v);
}

void Parser::undef_directive() {
    const Token& name = raw();
    if (name.kind != TokKind::Ident) error_expected(name, "an identifier");
    advance();
    if (scopes_.erase_innermost(name_of(name))) return;
    macros_.erase(name.text);
}

void Parser::ifdef_directive(bool want_defined) {
    const Token& where = raw();
    expect_sym("(");
    const Token& name = raw();
    if (name.kind != TokKind::Ident) error_expected(name, "an identifier");
    advance();
    bool defined = lookup(name) != nullptr || find_macro(name.text) != nullptr;
    if (defined && is_sym_tok(raw(), "[")) { // an array element
        const Value* a = lookup(name);
        std::vector<size_t> index;
        while (accept_sym("[")) {
            index.push_back(size_t(std::max(0.0, parse_float())));
            expect_sym("]");
        }
        if (a->type != VType::Array) error_at(name, "'" + name.text + "' is not an array");
        const ArrayValue& arr = a->as<ArrayValue>();
        size_t flat = 0;
        for (size_t k = 0; k < index.size() && k < arr.sizes.size(); ++k)
            flat = flat * arr.sizes[k] + std::min(index[k], arr.sizes[k] - 1);
        defined = flat < arr.elements.size() && arr.elements[flat].type != VType::None;
    }
    expect_sym(")");
    if (defined == want_defined) {
        Cond c;
        c.kind = Cond::If, c.where = where;
        frames_.back().conds.push_back(c);
    } else {
        skip_to_branch(where);
    }
}

// Skips raw tokens until `levels` unmatched #end directives have been passed.
void Parser::skip_raw_to_end(int levels, const Token& from) {
    int depth = levels;
    for (;;) {
        const Token& t = raw();
        if (t.kind == TokKind::End) error_at(from, "this block has no #end");
        advance();
        if (!is_sym_tok(t, "#")) continue;
        const Token& d = raw();
        if (opens_block(d.text))
            ++depth;
        else if (d.text == "end" && --depth == 0) {
            advance();
            return;
        }
    }
}

// Skips tokens, and nested blocks whole, to the next directive of the block `from` opened;
// returns its name token, not yet consumed. `missing_end` is the error at the end of input.
Token Parser::next_directive_in_block(const Token& from, const char* missing_end) {
    int depth = 0;
    for (;;) {
        const Token& t = raw();
        if (t.kind == TokKind::End) error_at(from, missing_end);
        advance();
        if (!is_sym_tok(t, "#")) continue;
        const Token& d = raw();
        if (opens_block(d.text))
            ++depth;
        else if (d.text == "end" && depth > 0)
            --depth;
        else if (depth == 0)
            return d;
    }
}

// After a false #if/#ifdef/#elseif: skips to the #else, a true #elseif or the #end.
void Parser::skip_to_branch(const Token& from) {
    for (;;) {
        const Token d = next_directive_in_block(from, "this block has no #end");
        if (d.text == "end") {
            advance();
            return;
        }
        if (d.text == "else" || d.text == "elseif") {
            advance();
            if (d.text == "elseif" && !truthy(parse_condition())) continue;
            Cond c;
            c.kind = Cond::If, c.where = d;
            frames_.back().conds.push_back(c);
            return;
        }
    }
}

// Positions the stream at the clause of the #switch on top that matches, or past its #end.
void Parser::switch_scan(const Token& from) {
    const double value = frames_.back().conds.back().end;
    for (;;) {
        const Token d = next_directive_in_block(from, "this #switch has no #end");
        if (d.text == "end") {
            advance();
            frames_.back().conds.pop_back();
            return;
        }
        if (d.text == "case" || d.text == "range") {
            advance();
            expect_sym("(");
            const double a = parse_float();
            bool match = std::fabs(a - value) <= 1e-10;
            if (d.text == "range") {
                expect_sym(",");
                const double b = parse_float();
                match = value >= a && value <= b;
            }
            expect_sym(")");
            if (match) return;
        } else if (d.text == "else") {
            advance();
            return;
        }
    }
}

void Parser::end_directive(const Token& where) {
    Frame& f = frames_.back();
    if (f.conds.empty()) {
        if (f.macro) {
            pop_frame();
            return;
        }
        error_at(where, "#end without a block to close");
    }
    Cond& c = f.conds.back();
    if (c.kind == Cond::If || c.kind == Cond::Switch) {
        f.conds.pop_back();
        return;
    }
    ++c.iterations;
    if (++loop_runs_ > options_.limits.loop_iterations)
        error_at(c.where, "the scene's loops ran more than " +
                              std::to_string(options_.limits.loop_iterations) +
                              " times in all (this one " + std::to_string(c.iterations) +
                              "); if they are meant to, raise the limit: render --limit "
                              "loop_iterations=N, load option limit.loop_iterations");
    if (c.kind == Cond::While) {
        const Token loop = c.where;
        f.pos = c.pos;
        if (!truthy(parse_condition())) {
            frames_.back().conds.pop_back();
            skip_raw_to_end(1, loop);
        }
        return;
    }
    // #for
    Value* v = scopes_.lookup(c.var);
    const double next = (v && v->type == VType::Float ? v->v[0] : c.end) + c.step;
    declare(c.var, Value::number(next), true); // after the loop it holds End + Step
    if (c.step > 0 ? next <= c.end + 1e-10 : next >= c.end - 1e-10)
        f.pos = c.pos;
    else
        f.conds.pop_back();
}

void Parser::break_directive(const Token& where) {
    Frame& f = frames_.back();
    int levels = 0;
    for (size_t i = f.conds.size(); i-- > 0;) {
        ++levels;
        if (f.conds[i].kind != Cond::If) {
            f.conds.resize(i);
            skip_raw_to_end(levels, where);
            return;
        }
    }
    error_at(where, "#break outside #switch, #while or #for");
}

void Parser::version_directive() {
    const Token& t = peek();
    const double v = parse_float();
    if (v < 1 || v > 10) error_at(t, "#version " + std::to_string(v) + " is not a version");
    model.version = v;
    model.version_given = true;
    if (is_sym_tok(peek_cont(), ";")) advance();
}

void Parser::default_directive() {
    expect_sym("{");
    for (;;) {
        const Token& t = peek();
        if (accept_sym("}")) return;
        PovTexture& d = model.default_texture;
        if (accept_kw("texture")) {
            d = *parse_texture_layers(d);
        } else if (accept_kw("pigment")) {
            d.pigment = parse_pigment(d.pigment ? *d.pigment : PovPigment{});
        } else if (accept_kw("finish")) {
            parse_finish(d.finish);
        } else if (accept_kw("normal")) {
            // New normals start from this one, bump size and all, even without a pattern.
            expect_sym("{");
            PovNormal n = d.normal ? *d.normal : model.normal_defaults;
            bool have = d.normal != nullptr;
            parse_normal_body(n, have, "}");
            model.normal_defaults = n;
            d.normal = have ? std::make_shared<const PovNormal>(std::move(n)) : nullptr;
        } else if (t.kind == TokKind::Ident && (t.text == "interior" || t.text == "radiosity")) {
            advance();
            unsupported(t, "#default " + t.text);
            skip_block();
        } else {
            error_expected(t, "texture, pigment, normal or finish in #default");
        }
    }
}

} // namespace sheaf::io::pov

// The token stream: tokens of the current file or macro body, with directives run and macros
// expanded as they come (peek), messages with positions, warnings and the symbol tables.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sheaf::io::pov {

Parser::Parser(const PovOptions& options) : options_(options) {}

std::string Parser::where(const Token& t) const {
    const std::string file =
        t.file >= 0 && size_t(t.file) < file_names_.size() ? file_names_[t.file] : std::string("?");
    return file + ":" + std::to_string(t.line) + ":" + std::to_string(t.col);
}

std::string Parser::context() const {
    constexpr int kShown = 8; // lines, innermost first; a recursion is one line with a count
    std::string out, line, previous;
    int shown = 0, repeats = 0;
    size_t more = 0;
    auto flush = [&] {
        if (previous.empty()) return;
        if (shown == kShown) {
            more += size_t(repeats);
        } else {
            ++shown;
            out += "\n  " + previous +
                   (repeats > 1 ? " (" + std::to_string(repeats) + " times)" : std::string());
        }
    };
    for (size_t i = frames_.size(); i-- > 1;) {
        const Frame& f = frames_[i];
        line = f.macro ? "in macro '" + f.where.text + "' called at " + where(f.where)
                       : "in '" + std::filesystem::path(f.file->path).filename().string() +
                             "' included at " + where(f.where);
        if (line == previous) {
            ++repeats;
            continue;
        }
        flush();
        previous = line, repeats = 1;
    }
    flush();
    if (more > 0) out += "\n  (and " + std::to_string(more) + " more)";
    return out;
}

void Parser::error_expected(const Token& found, const std::string& expected) const {
    throw SceneError(where(found) + ": error: found '" + describe(found) + "', expected " +
                     expected + context());
}

void Parser::error_at(const Token& t, const std::string& msg) const {
    // A scene's string may hold a NUL byte, which would end the message a host reads (the C
    // ABI's messages are C strings) before the place and the reason (found by the POV fuzzer).
    std::string text = where(t) + ": error: " + msg + context();
    for (size_t i = 0; (i = text.find('\0', i)) != std::string::npos; i += 2)
        text.replace(i, 1, "\\0");
    throw SceneError(text);
}

void Parser::warn(const Token& t, const std::string& msg) {
    std::string w = where(t) + ": warning: " + msg;
    if (warned_.emplace(w, true).second) warnings.push_back(std::move(w));
}

void Parser::unsupported(const Token& t, const std::string& what) {
    if (!captures_.empty()) {
        captures_.back().push_back({t, what});
        return;
    }
    if (options_.strict) throw SceneError(where(t) + ": error: unsupported " + what + context());
    warn(t, "unsupported " + what);
}

void Parser::approximated(const Token& t, const std::string& what) {
    if (!captures_.empty()) {
        captures_.back().push_back({t, what, true});
        return;
    }
    if (options_.strict) throw SceneError(where(t) + ": error: approximated " + what + context());
    warn(t, "approximated " + what);
}

void Parser::raise_pending(const Value& v) {
    if (!v.pending) return;
    const auto pending = v.pending; // unsupported() may add to the same declaration's list
    for (const PendingWarning& p : *pending)
        p.approximation ? approximated(p.where, p.what) : unsupported(p.where, p.what);
}

void Parser::charge(size_t bytes, const Token& t) {
    const uint64_t limit = options_.limits.data_bytes;
    if (bytes > limit || data_bytes_ > limit - bytes)
        error_at(t, "the scene's data would exceed " + std::to_string(limit >> 20) +
                        " MiB (arrays, strings and objects); if it is meant to, raise the limit: "
                        "render --limit data_mib=N, load option limit.data_mib");
    data_bytes_ += bytes;
    peak_data_bytes_ = std::max(peak_data_bytes_, data_bytes_);
}

void Parser::count_objects(const Token& at, size_t count) {
    objects_made_ += count;
    if (objects_made_ > options_.limits.objects)
        error_at(at, "more than " + std::to_string(options_.limits.objects) +
                         " objects parsed (an endless loop?); if it is meant to, raise the "
                         "limit: render --limit objects=N, load option limit.objects");
}

std::shared_ptr<const TokenFile> Parser::load_tokens(const std::string& path, const Token* where) {
    if (auto it = file_cache_.find(path); it != file_cache_.end()) return it->second;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (where) error_at(*where, "cannot read '" + path + "'");
        throw SceneError(path + ": error: cannot read the file");
    }
    std::stringstream ss;
    ss << in.rdbuf();
    file_names_.push_back(path);
    auto tf = tokenize(ss.str(), path, int(file_names_.size() - 1));
    for (Token& t : tf->tokens)
        if (t.kind == TokKind::Ident) t.name = scopes_.intern(t.text);
    file_cache_[path] = tf;
    return tf;
}

void Parser::push_file(const std::string& path, const Token& where) {
    Frame f;
    f.file = load_tokens(path, frames_.empty() ? nullptr : &where);
    f.where = where;
    f.own_scope = !frames_.empty();
    if (f.own_scope) scopes_.push();
    frames_.push_back(std::move(f));
}

void Parser::pop_frame() {
    Frame& f = frames_.back();
    if (f.own_scope) scopes_.pop();
    if (f.macro) --macro_depth_;
    frames_.pop_back();
}

void Parser::advance() {
    Frame& f = frames_.back();
    if (f.file->tokens[f.pos].kind != TokKind::End) ++f.pos;
    if (++steps_ > options_.limits.parse_steps) too_many_steps(f.file->tokens[f.pos]);
}

void Parser::too_many_steps(const Token& at) const {
    error_at(at, "the scene takes more than " + std::to_string(options_.limits.parse_steps) +
                     " parse steps (tokens read and function terms evaluated): loops within "
                     "loops, or a macro that calls itself without end? If it is meant to, raise "
                     "the limit: render --limit parse_steps=N, load option limit.parse_steps");
}

uint64_t Parser::function_terms_left() const {
    const uint64_t limit = options_.limits.function_terms;
    return std::min(steps_left(), limit - std::min(function_terms_, limit));
}

void Parser::too_many_function_terms(const Token& at) const {
    const uint64_t limit = options_.limits.function_terms;
    if (steps_left() < limit - std::min(function_terms_, limit)) too_many_steps(at);
    error_at(at, "the scene evaluates more than " + std::to_string(limit) +
                     " function terms while it is read: a function that calls itself many "
                     "times over? If it is meant to, raise the limit: render --limit "
                     "function_terms=N, load option limit.function_terms");
}

const Token& Parser::peek() {
    // Asked again and again for the same token (every accept_ and is_ asks): the answer
    // stands while no token was read and no file or macro opened or closed.
    if (peeked_ && peeked_.steps == steps_ && peeked_.depth == frames_.size() &&
        peeked_.pos == frames_.back().pos && peeked_.file == frames_.back().file.get())
        return *peeked_.token;
    const Token& t = peek_expanded();
    peeked_ = {&t, steps_, frames_.size(), frames_.back().pos, frames_.back().file.get(), 0};
    return t;
}

const Token& Parser::peek_expanded() {
    for (;;) {
        const Token& t = raw();
        if (t.kind == TokKind::End) {
            Frame& f = frames_.back();
            if (!f.conds.empty()) error_at(f.conds.back().where, "this block has no #end");
            if (frames_.size() == 1) return t;
            pop_frame();
            continue;
        }
        if (t.kind == TokKind::Symbol && same_text(t.text, "#")) {
            directive(false);
            continue;
        }
        if (t.kind == TokKind::Ident && !lookup(t)) {
            if (const Macro* m = find_macro(t)) {
                const Token name = t;
                advance();
                call_macro(name, *m);
                continue;
            }
        }
        return t;
    }
}

const Token& Parser::peek_cont() {
    // As peek: every level of an expression asks whether its operator follows.
    if (peeked_cont_ && peeked_cont_.steps == steps_ && peeked_cont_.depth == frames_.size() &&
        peeked_cont_.pos == frames_.back().pos && peeked_cont_.file == frames_.back().file.get() &&
        peeked_cont_.directive_args == directive_args_)
        return *peeked_cont_.token;
    const Token& t = peek_cont_expanded();
    peeked_cont_ = {
        &t, steps_, frames_.size(), frames_.back().pos, frames_.back().file.get(), directive_args_};
    return t;
}

const Token& Parser::peek_cont_expanded() {
    for (;;) {
        const Token& t = raw();
        if (t.kind == TokKind::End && frames_.size() > 1 && frames_.back().conds.empty() &&
            !frames_.back().macro && directive_args_ == 0) {
            pop_frame();
            continue;
        }
        if (t.kind == TokKind::Symbol && same_text(t.text, "#") && directive_args_ == 0 &&
            directive(true))
            continue;
        return t;
    }
}

Token Parser::next() {
    Token t = peek();
    advance();
    return t;
}

bool Parser::accept_sym(const char* s) {
    if (!is_sym(s)) return false;
    advance();
    return true;
}

bool Parser::accept_kw(const char* s) {
    if (!is_kw(s)) return false;
    advance();
    return true;
}

void Parser::expect_sym(const char* s, const std::string& expected) {
    const Token& t = peek();
    if (!is_sym_tok(t, s))
        error_expected(t, expected.empty() ? "'" + std::string(s) + "'" : expected);
    advance();
}

std::string Parser::expect_ident(const std::string& expected) {
    const Token& t = peek();
    if (t.kind != TokKind::Ident) error_expected(t, expected);
    std::string s = t.text;
    advance();
    return s;
}

void Parser::skip_block() {
    expect_sym("{");
    skip_rest_of_block();
}

void Parser::skip_rest_of_block() {
    int depth = 1;
    while (depth > 0) {
        const Token& t = peek();
        if (t.kind == TokKind::End) error_expected(t, "'}'");
        if (is_sym_tok(t, "{")) ++depth;
        if (is_sym_tok(t, "}")) --depth;
        advance();
    }
}

Value* Parser::lookup_mut(const std::string& name) {
    return scopes_.lookup(scopes_.find(name));
}

const Value* Parser::lookup(const std::string& name) const {
    return const_cast<Parser*>(this)->lookup_mut(name);
}

Value* Parser::lookup_mut(const Token& t) {
    return scopes_.lookup(name_of(t));
}

const Value* Parser::lookup(const Token& t) const {
    return const_cast<Parser*>(this)->lookup_mut(t);
}

void Parser::declare(const std::string& name, Value v, bool local) {
    declare(scopes_.intern(name), std::move(v), local);
}

void Parser::declare(uint32_t id, Value v, bool local) {
    if (local) {
        scopes_.set(scopes_.size() - 1, id, std::move(v));
        return;
    }
    if (Value* existing = scopes_.lookup(id)) {
        *existing = std::move(v);
        return;
    }
    scopes_.set(0, id, std::move(v));
}

void Parser::declare_in(size_t scope, const std::string& name, Value v) {
    scopes_.set(scope, scopes_.intern(name), std::move(v));
}

bool Parser::accept_declared(VType type, Value& out, const std::string& expected) {
    const Token& t = peek();
    if (t.kind != TokKind::Ident) return false;
    const Value* v = lookup(t);
    if (!v) return false;
    if (v->type != type && v->type != VType::Array) return false;
    if (v->type == VType::Array) // an array of other values (colours ...) is not one of these
        for (const Value& e : static_cast<const ArrayValue*>(v->ptr.get())->elements)
            if (e.type != VType::None) {
                if (e.type != type) return false;
                break;
            }
    advance();
    Value got = *v;
    if (got.type == VType::Array) {
        if (!is_sym_tok(peek_cont(), "[")) error_expected(t, expected);
        got = index_value(got, t);
    }
    if (got.type != type) error_expected(t, expected + ", not " + type_name(got.type));
    raise_pending(got);
    out = std::move(got);
    return true;
}

bool Parser::accept_declared_any(Value& out) {
    const Token& t = peek();
    if (t.kind != TokKind::Ident) return false;
    const Value* v = lookup(t);
    if (!v) return false;
    advance();
    out = *v;
    if (out.type == VType::Array && is_sym_tok(peek_cont(), "[")) out = index_value(out, t);
    raise_pending(out);
    return true;
}

const Macro* Parser::find_macro(const Token& t) const {
    // Every keyword comes here: most names never named a macro.
    const uint32_t id = name_of(t);
    if (id == Scopes::kNoName || id >= macro_named_.size() || !macro_named_[id]) return nullptr;
    return find_macro(t.text);
}

const Macro* Parser::find_macro(const std::string& name) const {
    auto it = macros_.find(name);
    return it == macros_.end() ? nullptr : &it->second;
}

} // namespace sheaf::io::pov

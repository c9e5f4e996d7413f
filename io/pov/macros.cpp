// #macro definitions and calls: a call parses its arguments, opens a scope holding the
// parameters, and continues reading tokens from the macro's body until its #end.
#include "io/pov/parser.h"

#include "core/base/error.h"

namespace sheaf::io::pov {

void Parser::define_macro(const Token& where) {
    const Token& name = raw();
    if (name.kind != TokKind::Ident) error_expected(name, "the macro's name");
    advance();
    Macro m;
    std::vector<uint32_t> params;
    expect_sym("(");
    if (!is_sym_tok(raw(), ")")) {
        for (;;) {
            const Token& p = raw();
            if (p.kind != TokKind::Ident) error_expected(p, "a parameter name");
            advance();
            params.push_back(name_of(p));
            if (is_sym_tok(raw(), ")")) break;
            if (!is_sym_tok(raw(), ",")) error_expected(raw(), "',' or ')'");
            advance();
        }
    }
    advance(); // ')'
    m.params = std::make_shared<const std::vector<uint32_t>>(std::move(params));
    m.file = frames_.back().file;
    m.body = frames_.back().pos;
    skip_raw_to_end(1, where);
    const uint32_t id = intern_of(name);
    if (id >= macro_named_.size()) macro_named_.resize(size_t(id) + 1, false);
    macro_named_[id] = true; // never cleared: find_macro looks the name up when it is set
    macros_[name.text] = std::move(m);
}

void Parser::call_macro(const Token& name, const Macro& macro) {
    const Nest nest(*this, name); // an argument may call a macro while its '(' is read
    // The table may change while the arguments are parsed: what the call needs, held.
    const std::shared_ptr<const TokenFile> file = macro.file;
    const size_t body = macro.body;
    const std::shared_ptr<const std::vector<uint32_t>> holder = macro.params;
    const std::vector<uint32_t>& params = *holder;
    std::vector<Value> args;
    // Arguments that are a declared variable alone are passed by reference, as in POV-Ray:
    // the macro's assignments to the parameter reach the variable.
    std::vector<std::pair<size_t, Scopes::Ref>> by_ref;
    if (!is_sym("(")) error_expected(peek(), "'(' after macro " + name.text);
    advance();
    if (!accept_sym(")")) {
        for (;;) {
            const Token& t = peek();
            const Frame& fr = frames_.back();
            if (t.kind == TokKind::Ident && fr.pos + 1 < fr.file->tokens.size()) {
                const Token& after = fr.file->tokens[fr.pos + 1];
                Scopes::Ref target;
                if ((is_sym_tok(after, ",") || is_sym_tok(after, ")")) &&
                    scopes_.find_variable(name_of(t), scopes_.size() - 1, target))
                    by_ref.push_back({args.size(), target});
            }
            // As in POV-Ray, '<' outside parentheses is not a comparison: "off <100, 100>"
            // is two arguments, the comma between them left out.
            ++no_lt_;
            args.push_back(parse_rvalue());
            --no_lt_;
            if (accept_sym(")")) break;
            accept_sym(","); // POV-Ray lets the comma out between arguments
        }
    }
    if (args.size() != params.size())
        error_at(name, "macro '" + name.text + "' takes " + std::to_string(params.size()) +
                           " arguments, not " + std::to_string(args.size()));
    if (++macro_calls_ > options_.limits.macro_calls)
        error_at(name, "more than " + std::to_string(options_.limits.macro_calls) +
                           " macro calls (a macro that calls itself many times over?); if it is "
                           "meant to, raise the limit: render --limit macro_calls=N, load option "
                           "limit.macro_calls");
    if (macro_depth_ >= kMaxMacroDepth)
        error_at(name, "macro calls nested deeper than " + std::to_string(kMaxMacroDepth) +
                           " (endless recursion?)");
    std::vector<std::pair<uint32_t, Value>> vars;
    std::vector<std::pair<uint32_t, Scopes::Ref>> refs;
    vars.reserve(args.size());
    for (size_t i = 0; i < args.size(); ++i) vars.emplace_back(params[i], std::move(args[i]));
    for (const auto& [i, var] : by_ref) refs.emplace_back(params[i], var);
    Frame f;
    f.file = file;
    f.pos = body;
    f.macro = true;
    f.own_scope = true;
    f.where = name;
    scopes_.push(std::move(vars), std::move(refs));
    frames_.push_back(std::move(f));
    ++macro_depth_;
}

} // namespace sheaf::io::pov

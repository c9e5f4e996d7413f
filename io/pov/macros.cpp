// #macro definitions and calls: a call parses its arguments, opens a scope holding the
// parameters, and continues reading tokens from the macro's body until its #end.
#include "io/pov/parser.h"

#include "core/base/error.h"

namespace sheaf::io::pov {

void Parser::define_macro(const Token& where) {
    const Token name = raw();
    if (name.kind != TokKind::Ident) error_expected(name, "the macro's name");
    advance();
    Macro m;
    expect_sym("(");
    if (!is_sym_tok(raw(), ")")) {
        for (;;) {
            const Token p = raw();
            if (p.kind != TokKind::Ident) error_expected(p, "a parameter name");
            advance();
            m.params.push_back(p.text);
            if (is_sym_tok(raw(), ")")) break;
            if (!is_sym_tok(raw(), ",")) error_expected(raw(), "',' or ')'");
            advance();
        }
    }
    advance(); // ')'
    m.file = frames_.back().file;
    m.body = frames_.back().pos;
    skip_raw_to_end(1, where);
    macros_[name.text] = std::move(m);
}

void Parser::call_macro(const Token& name, const Macro& macro) {
    const Nest nest(*this, name); // an argument may call a macro while its '(' is read
    const Macro m = macro; // the table may change while the arguments are parsed
    std::vector<Value> args;
    expect_sym("(", "'(' after macro " + name.text);
    if (!accept_sym(")")) {
        for (;;) {
            args.push_back(parse_rvalue());
            if (accept_sym(")")) break;
            accept_sym(","); // POV-Ray lets the comma out after an object argument
        }
    }
    if (args.size() != m.params.size())
        error_at(name, "macro '" + name.text + "' takes " + std::to_string(m.params.size()) +
                           " arguments, not " + std::to_string(args.size()));
    if (macro_depth_ >= kMaxMacroDepth)
        error_at(name, "macro calls nested deeper than " + std::to_string(kMaxMacroDepth) +
                           " (endless recursion?)");
    std::unordered_map<std::string, Value> scope;
    for (size_t i = 0; i < args.size(); ++i) scope[m.params[i]] = std::move(args[i]);
    Frame f;
    f.file = m.file;
    f.pos = m.body;
    f.macro = true;
    f.own_scope = true;
    f.where = name;
    scopes_.push_back(std::move(scope));
    frames_.push_back(std::move(f));
    ++macro_depth_;
}

} // namespace sheaf::io::pov

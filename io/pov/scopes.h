// The reader's variables: every name interned to a number once (the tokenizer's identifiers
// carry theirs), a stack of scopes (the scene's, each include's and each macro call's), and
// macro parameters that stand for a caller's variable. Each name holds its bindings, one per
// scope that declares it, innermost last (shallow binding): a lookup reads the last one
// however deep the macro calls are, without hashing, and a name nothing binds (every keyword)
// is known undeclared at once.
#pragma once

#include "io/pov/value.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sheaf::io::pov {

class Scopes {
  public:
    static constexpr uint32_t kNoName = 0xFFFFFFFFu;
    /// A macro parameter passed by reference: the variable `name` of scope `scope`.
    struct Ref {
        size_t scope = 0;
        uint32_t name = kNoName;
    };

    Scopes() { push(); }

    /// The name's number, given it on first sight.
    uint32_t intern(std::string_view name);
    /// The name's number, kNoName when it was never interned (so never declared).
    uint32_t find(std::string_view name) const;
    const std::string& text(uint32_t name) const { return names_[name]; }

    size_t size() const { return stack_.size(); }
    void push() { stack_.emplace_back(); }
    /// A macro call's scope: its parameters' values and the ones passed by reference (which
    /// win over a value of the same name).
    void push(std::vector<std::pair<uint32_t, Value>> vars,
              std::vector<std::pair<uint32_t, Ref>> refs);
    void pop();

    /// The variable `name` as seen from the innermost scope, references followed; nullptr
    /// when it is not declared. The pointer stays valid until the variable is removed.
    Value* lookup(uint32_t name);
    /// Where `name` lives as seen from scope `top` down, references followed; false when it
    /// is not declared.
    bool find_variable(uint32_t name, size_t top, Ref& where) const;
    /// #local in scope `scope`: its own variable, or the one a reference of that name stands
    /// for.
    void set(size_t scope, uint32_t name, Value v);
    /// Removes the variable from the innermost scope that holds it as a variable; false when
    /// none does.
    bool erase_innermost(uint32_t name);
    /// Removes the variable from every scope.
    void erase_everywhere(uint32_t name);

  private:
    /// A name in one scope: a variable (its value, which keeps its address) or a reference.
    struct Binding {
        uint32_t scope = 0;
        bool is_ref = false;
        Ref ref;
        std::unique_ptr<Value> value;
    };
    /// The names a scope binds, for its pop (a name may repeat after an erase).
    struct Scope {
        std::vector<uint32_t> names;
    };
    /// The binding of `name` in exactly scope `scope`, nullptr when there is none.
    Binding* in_scope(uint32_t name, size_t scope);
    const Binding* in_scope(uint32_t name, size_t scope) const;
    /// A new binding in scope `scope`, kept in scope order.
    Binding& bind(uint32_t name, size_t scope);
    bool unbound(uint32_t name) const { return name >= held_.size() || held_[name].empty(); }

    std::vector<Scope> stack_;
    std::unordered_map<std::string, uint32_t> ids_;
    std::vector<std::string> names_;
    std::vector<std::vector<Binding>> held_; // per name, in scope order
};

} // namespace sheaf::io::pov

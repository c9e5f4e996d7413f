#include "io/pov/scopes.h"

namespace sheaf::io::pov {

uint32_t Scopes::intern(std::string_view name) {
    if (auto it = ids_.find(std::string(name)); it != ids_.end()) return it->second;
    const uint32_t id = uint32_t(names_.size());
    names_.emplace_back(name);
    ids_.emplace(names_.back(), id);
    held_.emplace_back();
    return id;
}

uint32_t Scopes::find(std::string_view name) const {
    const auto it = ids_.find(std::string(name));
    return it == ids_.end() ? kNoName : it->second;
}

void Scopes::bind(uint32_t name, size_t scope) {
    std::vector<uint32_t>& h = held_[name];
    // Mostly the innermost scope (a #local, a parameter) or the outermost (a #declare).
    auto at = h.end();
    while (at != h.begin() && *(at - 1) > scope) --at;
    h.insert(at, uint32_t(scope));
}

void Scopes::unbind(uint32_t name, size_t scope) {
    std::vector<uint32_t>& h = held_[name];
    for (auto at = h.end(); at != h.begin();)
        if (*--at == scope) {
            h.erase(at);
            return;
        }
}

bool Scopes::holder(uint32_t name, size_t top, size_t& scope) const {
    if (unbound(name)) return false;
    const std::vector<uint32_t>& h = held_[name];
    for (auto at = h.end(); at != h.begin();)
        if (*--at <= top) {
            scope = *at;
            return true;
        }
    return false;
}

void Scopes::push(std::vector<std::pair<uint32_t, Value>> vars,
                  std::vector<std::pair<uint32_t, Ref>> refs) {
    Scope s;
    for (auto& [name, v] : vars) s.vars.insert_or_assign(name, std::move(v));
    for (auto& [name, r] : refs) {
        s.vars.erase(name);
        s.refs.insert_or_assign(name, r);
    }
    const size_t at = stack_.size();
    for (const auto& [name, v] : s.vars) bind(name, at);
    for (const auto& [name, r] : s.refs) bind(name, at);
    stack_.push_back(std::move(s));
}

void Scopes::pop() {
    const size_t at = stack_.size() - 1;
    for (const auto& [name, v] : stack_.back().vars) unbind(name, at);
    for (const auto& [name, r] : stack_.back().refs) unbind(name, at);
    stack_.pop_back();
}

Value* Scopes::lookup(uint32_t name) {
    size_t i;
    if (stack_.empty() || !holder(name, stack_.size() - 1, i)) return nullptr;
    Scope& s = stack_[i];
    if (!s.refs.empty())
        if (auto r = s.refs.find(name); r != s.refs.end()) {
            auto& bound = stack_[r->second.scope].vars;
            auto v = bound.find(r->second.name);
            return v == bound.end() ? nullptr : &v->second;
        }
    return &s.vars.find(name)->second;
}

bool Scopes::find_variable(uint32_t name, size_t top, Ref& where) const {
    size_t i;
    if (!holder(name, top, i)) return false;
    const Scope& s = stack_[i];
    if (auto r = s.refs.find(name); r != s.refs.end()) {
        where = r->second; // resolved when bound
        return stack_[where.scope].vars.count(where.name) != 0;
    }
    where = {i, name};
    return true;
}

void Scopes::set(size_t scope, uint32_t name, Value v) {
    if (auto r = stack_[scope].refs.find(name); r != stack_[scope].refs.end()) {
        const Ref to = r->second;
        if (stack_[to.scope].vars.insert_or_assign(to.name, std::move(v)).second)
            bind(to.name, to.scope);
        return;
    }
    if (stack_[scope].vars.insert_or_assign(name, std::move(v)).second) bind(name, scope);
}

bool Scopes::erase_innermost(uint32_t name) {
    if (unbound(name)) return false;
    for (size_t i = stack_.size(); i-- > 0;)
        if (stack_[i].vars.erase(name)) {
            unbind(name, i);
            return true;
        }
    return false;
}

void Scopes::erase_everywhere(uint32_t name) {
    if (unbound(name)) return;
    for (size_t i = 0; i < stack_.size(); ++i)
        if (stack_[i].vars.erase(name)) unbind(name, i);
}

} // namespace sheaf::io::pov

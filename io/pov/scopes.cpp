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

Scopes::Binding* Scopes::in_scope(uint32_t name, size_t scope) {
    return const_cast<Binding*>(std::as_const(*this).in_scope(name, scope));
}

const Scopes::Binding* Scopes::in_scope(uint32_t name, size_t scope) const {
    if (unbound(name)) return nullptr;
    const std::vector<Binding>& h = held_[name];
    for (size_t i = h.size(); i-- > 0;) {
        if (h[i].scope == scope) return &h[i];
        if (h[i].scope < scope) break;
    }
    return nullptr;
}

Scopes::Binding& Scopes::bind(uint32_t name, size_t scope) {
    std::vector<Binding>& h = held_[name];
    // Mostly the innermost scope (a #local, a parameter) or the outermost (a #declare).
    size_t at = h.size();
    while (at > 0 && h[at - 1].scope > scope) --at;
    Binding& b = *h.insert(h.begin() + ptrdiff_t(at), Binding{});
    b.scope = uint32_t(scope);
    stack_[scope].names.push_back(name);
    return b;
}

void Scopes::push(std::vector<std::pair<uint32_t, Value>> vars,
                  std::vector<std::pair<uint32_t, Ref>> refs) {
    const size_t at = stack_.size();
    stack_.emplace_back();
    for (auto& [name, r] : refs) {
        Binding* b = in_scope(name, at);
        if (!b) b = &bind(name, at);
        b->is_ref = true, b->ref = r, b->value.reset();
    }
    for (auto& [name, v] : vars) {
        Binding* b = in_scope(name, at);
        if (!b) {
            b = &bind(name, at);
            b->value = std::make_unique<Value>(std::move(v));
        } else if (!b->is_ref) {
            *b->value = std::move(v);
        }
    }
}

void Scopes::pop() {
    const size_t at = stack_.size() - 1;
    for (uint32_t name : stack_.back().names) {
        std::vector<Binding>& h = held_[name];
        if (!h.empty() && h.back().scope == at) h.pop_back(); // the innermost scope's is last
    }
    stack_.pop_back();
}

Value* Scopes::lookup(uint32_t name) {
    if (unbound(name)) return nullptr;
    const Binding& b = held_[name].back();
    if (!b.is_ref) return b.value.get();
    Binding* to = in_scope(b.ref.name, b.ref.scope);
    return to && !to->is_ref ? to->value.get() : nullptr;
}

bool Scopes::find_variable(uint32_t name, size_t top, Ref& where) const {
    if (unbound(name)) return false;
    const std::vector<Binding>& h = held_[name];
    for (size_t i = h.size(); i-- > 0;) {
        const Binding& b = h[i];
        if (b.scope > top) continue;
        if (!b.is_ref) {
            where = {b.scope, name};
            return true;
        }
        where = b.ref; // resolved when bound
        const Binding* to = in_scope(where.name, where.scope);
        return to && !to->is_ref;
    }
    return false;
}

void Scopes::set(size_t scope, uint32_t name, Value v) {
    Binding* b = in_scope(name, scope);
    if (b && b->is_ref) {
        const Ref to = b->ref;
        b = in_scope(to.name, to.scope);
        if (!b) b = &bind(to.name, to.scope);
    } else if (!b) {
        b = &bind(name, scope);
    }
    if (b->value)
        *b->value = std::move(v);
    else
        b->value = std::make_unique<Value>(std::move(v));
}

bool Scopes::erase_innermost(uint32_t name) {
    if (unbound(name)) return false;
    std::vector<Binding>& h = held_[name];
    for (size_t i = h.size(); i-- > 0;)
        if (!h[i].is_ref) {
            std::vector<uint32_t>& names = stack_[h[i].scope].names;
            for (size_t k = names.size(); k-- > 0;)
                if (names[k] == name) {
                    names.erase(names.begin() + ptrdiff_t(k));
                    break;
                }
            h.erase(h.begin() + ptrdiff_t(i));
            return true;
        }
    return false;
}

void Scopes::erase_everywhere(uint32_t name) {
    while (erase_innermost(name)) {
    }
}

} // namespace sheaf::io::pov

// PovFunction -> FnProgram (see fn_compile.h).
#include "io/pov/fn_compile.h"

#include "io/pov/materials.h"

#include <map>

namespace sheaf::io::pov {

void FnCompiler::push(FnOp op, uint16_t arg, double value, uint8_t count) {
    if (code_.size() >= kMaxFnCode)
        throw FnCompileError("a function of more than " + std::to_string(kMaxFnCode) +
                             " operations (its calls written out)");
    FnInstr in;
    in.op = op, in.arg = arg, in.value = value, in.count = count;
    code_.push_back(in);
    const int pops = fn_pops(in);
    depth_ += 1 - pops;
    deepest_ = std::max(deepest_, depth_);
    if (deepest_ > kFnStack)
        throw FnCompileError("a function that needs more than " + std::to_string(kFnStack) +
                             " values at once (calls nested too deeply)");
}

uint16_t FnCompiler::add_pattern(const Pattern& p) {
    if (scene_.fn_patterns.size() >= 0xFFFF) throw FnCompileError("too many pattern functions");
    scene_.fn_patterns.push_back(p);
    return uint16_t(scene_.fn_patterns.size() - 1);
}

uint16_t FnCompiler::pattern(const PatternFunction& p) {
    if (auto it = patterns_.find(&p); it != patterns_.end()) return it->second;
    const uint16_t id = add_pattern(materials_.function_pattern(*p.source, p.local));
    patterns_.emplace(&p, id);
    return id;
}

uint16_t FnCompiler::pigment(const PigmentFunction& p) {
    if (auto it = pigments_.find(&p); it != pigments_.end()) return it->second;
    if (scene_.fn_pigments.size() >= 0xFFFF) throw FnCompileError("too many pigment functions");
    FnPigment pg = p.pigment;
    if (p.source) pg.scene_pigment = materials_.function_pigment(*p.source);
    if (pg.count > 0) {
        pg.pattern = add_pattern(p.pattern);
        pg.first = uint32_t(scene_.fn_pigment_entries.size());
        scene_.fn_pigment_entries.insert(scene_.fn_pigment_entries.end(), p.entries.begin(),
                                         p.entries.end());
    }
    scene_.fn_pigments.push_back(pg);
    const uint16_t id = uint16_t(scene_.fn_pigments.size() - 1);
    pigments_.emplace(&p, id);
    return id;
}

// The arguments are on the stack; calls f on them (a pigment function: its `component`).
void FnCompiler::call(const PovFunction& f, size_t nargs, int component) {
    if (!f.scene_unsupported.empty()) throw FnCompileError(f.scene_unsupported);
    if (f.pigment) {
        push(FnOp::Pigment, pigment(*f.pigment), 0, uint8_t(component));
        return;
    }
    if (f.internal >= 0) {
        push(FnOp::Internal, uint16_t(f.internal), 0, uint8_t(nargs));
        return;
    }
    if (f.pattern) {
        push(FnOp::Pattern, pattern(*f.pattern));
        return;
    }
    const uint32_t base = uint32_t(depth_ - int(nargs));
    emit(f.body, base);
    push(FnOp::Drop, uint16_t(nargs));
}

void FnCompiler::emit(const FnNode& n, uint32_t base) {
    switch (n.kind) {
    case FnNode::Const:
        push(FnOp::Const, 0, n.value);
        return;
    case FnNode::Param:
        push(FnOp::Load, uint16_t(base + uint32_t(n.param)));
        return;
    case FnNode::Operator: // the operands in order, then the operator
        for (const FnNode& a : n.args) emit(a, base);
        push(n.op);
        return;
    case FnNode::Call: {
        if (!n.fn) throw FnCompileError("a call without its function");
        const size_t want = n.fn->params.size();
        if (n.args.size() != want)
            throw FnCompileError("a call with " + std::to_string(n.args.size()) +
                                 " arguments of a function that takes " + std::to_string(want));
        for (const FnNode& a : n.args) emit(a, base);
        call(*n.fn, n.args.size(), n.component);
        return;
    }
    case FnNode::Builtin: {
        const std::string& name = n.name;
        const size_t k = n.args.size();
        if (auto it = math_builtins().find(name); it != math_builtins().end() && k == 1) {
            emit(n.args[0], base);
            push(FnOp::Math, uint16_t(it->second));
            return;
        }
        for (const FnNode& a : n.args) emit(a, base);
        if ((name == "min" || name == "max") && k >= 1) {
            for (size_t i = 1; i < k; ++i) push(name == "min" ? FnOp::Min : FnOp::Max);
        } else if (name == "select" && (k == 3 || k == 4)) {
            push(k == 3 ? FnOp::Select3 : FnOp::Select4);
        } else if (k == 2 && (name == "atan" || name == "atan2")) {
            push(FnOp::Atan2);
        } else if (k == 2 && name == "pow") {
            push(FnOp::Pow);
        } else if (k == 2 && name == "mod") {
            push(FnOp::Mod);
        } else if (k == 2 && name == "div") {
            push(FnOp::IntDiv);
        } else {
            throw FnCompileError("'" + name + "' with " + std::to_string(k) + " arguments");
        }
        return;
    }
    }
}

int32_t FnCompiler::program(const PovFunction& f) {
    if (auto it = programs_.find(&f); it != programs_.end()) return it->second;
    // Lowering a function's pigment or pattern may compile the functions they use: the
    // program being compiled waits.
    struct Outer {
        FnCompiler& c;
        std::vector<FnInstr> code;
        int depth, deepest;
        ~Outer() { c.code_ = std::move(code), c.depth_ = depth, c.deepest_ = deepest; }
    } outer{*this, std::move(code_), depth_, deepest_};
    code_.clear();
    const size_t params = f.params.size();
    if (params > size_t(kFnStack)) throw FnCompileError("a function of too many parameters");
    depth_ = deepest_ = int(params);
    if (f.internal >= 0 || f.pattern || f.pigment) { // its parameters, passed on
        for (size_t i = 0; i < params; ++i) push(FnOp::Load, uint16_t(i));
        call(f, params, int(FnComponent::Gray));
    } else {
        if (!f.scene_unsupported.empty()) throw FnCompileError(f.scene_unsupported);
        emit(f.body, 0);
    }
    // Leave exactly the result: drop the parameters below it.
    if (params > 0) push(FnOp::Drop, uint16_t(params));
    FnProgram pg;
    pg.first = uint32_t(scene_.fn_code.size());
    pg.count = uint32_t(code_.size());
    pg.params = uint32_t(params);
    scene_.fn_code.insert(scene_.fn_code.end(), code_.begin(), code_.end());
    scene_.fn_programs.push_back(pg);
    const int32_t id = int32_t(scene_.fn_programs.size() - 1);
    programs_.emplace(&f, id);
    return id;
}

} // namespace sheaf::io::pov

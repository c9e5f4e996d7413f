// Checking a compiled function before either backend runs it (see function.h).
#include "core/scene/function.h"

namespace sheaf {

int fn_pops(const FnInstr& in) {
    switch (in.op) {
    case FnOp::Const:
    case FnOp::Load:
        return 0;
    case FnOp::Drop:
        return int(in.arg) + 1;
    case FnOp::Neg:
    case FnOp::Not:
    case FnOp::Math:
        return 1;
    case FnOp::Add:
    case FnOp::Sub:
    case FnOp::Mul:
    case FnOp::Div:
    case FnOp::Lt:
    case FnOp::Le:
    case FnOp::Gt:
    case FnOp::Ge:
    case FnOp::Eq:
    case FnOp::Ne:
    case FnOp::And:
    case FnOp::Or:
    case FnOp::Min:
    case FnOp::Max:
    case FnOp::Pow:
    case FnOp::Atan2:
    case FnOp::Mod:
    case FnOp::IntDiv:
        return 2;
    case FnOp::Cond:
    case FnOp::Select3:
    case FnOp::Pattern:
    case FnOp::Pigment:
        return 3;
    case FnOp::Select4:
        return 4;
    case FnOp::Internal:
        return in.count;
    }
    return -1;
}

std::string check_fn_program(const FnProgram& p, const FnInstr* code, size_t code_size,
                             size_t patterns, size_t pigments, int* depth_out) {
    if (size_t(p.first) + p.count > code_size) return "its code lies outside the function code";
    if (p.count == 0) return "it has no code";
    if (p.params > uint32_t(kFnStack)) return "it has more parameters than its stack holds";
    int depth = int(p.params), deepest = depth;
    for (uint32_t i = 0; i < p.count; ++i) {
        const FnInstr& in = code[p.first + i];
        const int pops = fn_pops(in), pushes = 1;
        if (pops < 0) return "it has an unknown operation";
        if (in.op == FnOp::Load && int(in.arg) >= depth) return "it reads a slot above its stack";
        if (in.op == FnOp::Math && in.arg > uint16_t(FnMath::Radians))
            return "it calls an unknown math function";
        if (in.op == FnOp::Internal &&
            (fn_internal_extra(in.arg) < 0 || in.count != 3 + fn_internal_extra(in.arg)))
            return "it calls an unknown internal function";
        if (in.op == FnOp::Pattern && in.arg >= patterns)
            return "it names a pattern that does not exist";
        if (in.op == FnOp::Pigment && in.arg >= pigments)
            return "it names a pigment that does not exist";
        if (in.op == FnOp::Pigment && in.count > uint8_t(FnComponent::Gray))
            return "it reads an unknown component";
        if (depth < pops) return "its stack runs out";
        depth += pushes - pops;
        if (depth > deepest) deepest = depth;
        if (deepest > kFnStack) return "it needs a stack deeper than " + std::to_string(kFnStack);
    }
    if (depth != 1) return "it does not leave exactly one value";
    if (depth_out) *depth_out = deepest;
    return {};
}

} // namespace sheaf

// Writing function programs by hand in tests (test code only).
#pragma once

#include "core/scene/function.h"

namespace sheaf::test {

/// One instruction.
inline FnInstr op(FnOp o, uint16_t arg = 0, double value = 0, uint8_t count = 0) {
    FnInstr in;
    in.op = o, in.arg = arg, in.value = value, in.count = count;
    return in;
}

} // namespace sheaf::test

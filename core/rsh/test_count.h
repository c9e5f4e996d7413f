// Tests and hits of one kind of test: what the traversal counts at each level, on either side.
#pragma once

#include <cstdint>

namespace sheaf {

/// Tests and hits of one kind of test (objects, a level, the final tests).
struct TestCount {
    uint64_t tests = 0, hits = 0;
};

} // namespace sheaf

// What the elements of a compacting launch give (Exec::launch_compact): counts to add up and
// outputs to place. Each element says how many outputs it writes; the exec gives it that many
// consecutive slots of the launch's counter, in no particular order between elements, so it
// serves output whose use does not depend on the order of its slots (the traversal's
// candidate pairs: hits are minima, flags and sums).
#pragma once

#include <cstdint>

namespace sheaf::wavefront {

struct Compacted {
    uint32_t tests = 0, hits = 0; // added into the launch's TestCount
    uint32_t outputs = 0;         // slots this element fills: emit(i, what, first slot)
    uint64_t what = 0;            // what the element hands its emit (a bit mask, say)
};

} // namespace sheaf::wavefront

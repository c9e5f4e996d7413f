#include "core/rays/ray_gen.h"

#include "core/base/error.h"

#include <string>

namespace sheaf {

void check_batch_bound(uint64_t most, RayType type) {
    if (most <= 0xFFFFFFFFull) return;
    throw OutOfMemory(std::string("a wave of up to ") + std::to_string(most) + " " +
                      ray_type_name(type) +
                      " rays: Sheaf traces at most 4294967295 rays in one batch; a smaller "
                      "frame, fewer aa.samples, ao.samples or radiosity.samples need fewer");
}

} // namespace sheaf

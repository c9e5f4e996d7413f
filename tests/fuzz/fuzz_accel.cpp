// libFuzzer's entry point for the object-space hierarchies: scenes of many lattice triangles,
// rendered under every accel, which must agree (capi_input.h, CapiMode::Accels).
#include "tests/fuzz/capi_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return sheaf::fuzz::run_capi_input(data, size, nullptr, sheaf::fuzz::CapiMode::Accels);
}

// libFuzzer's entry point for a host's sequence of C ABI calls (capi_input.h).
#include "tests/fuzz/capi_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return sheaf::fuzz::run_capi_input(data, size);
}

// libFuzzer's entry point for a farm job's folder: job.txt and the state records
// (farm_input.h).
#include "tests/fuzz/farm_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return sheaf::fuzz::run_farm_input(data, size);
}

// libFuzzer's entry point for one scene format, chosen when compiled (SHEAF_FUZZ_EXT).
#include "tests/fuzz/scene_input.h"

#ifndef SHEAF_FUZZ_EXT
#error "SHEAF_FUZZ_EXT names the format: \".pov\", \".xml\", \".obj\" or \".ply\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return sheaf::fuzz::run_scene_input(data, size, SHEAF_FUZZ_EXT);
}

// One fuzz input as a user's scene file: written to a file with the format's extension, read
// through the C ABI (sheafSceneLoadFile), and when it loads, committed and rendered small on the
// CPU. What the C ABI promises is checked, and a broken promise aborts (a finding):
// - a failed call returns an error code with a message, and a load error names the file, or
//   FILE:LINE:COL in a file it includes;
// - a frame that renders has the size asked for and finite pixels.
// Crashes, sanitizer reports, hangs and runaway memory are the fuzzer's own findings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace sheaf::fuzz {

/// Runs one input as a scene file of extension `ext` (".pov", ".xml", ".obj", ".ply").
/// Returns 0; aborts with a message when the library breaks a promise. With `log`, writes
/// the outcome there in one line (the error, or the frame's size).
int run_scene_input(const uint8_t* data, size_t size, const char* ext, std::FILE* log = nullptr);

} // namespace sheaf::fuzz

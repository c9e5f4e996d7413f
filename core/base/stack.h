// Work that recurses as deep as its input: run on a thread of our own whose stack is known,
// so that no input crashes the process whatever stack the calling thread happens to have (1
// MiB on Windows, 512 KiB for macOS's secondary threads, less in some thread pools). The
// scene readers bound their nesting (io/pov/parser.h) by what this stack holds.
#pragma once

#include <cstddef>
#include <functional>

namespace sheaf {

/// The stack the scene readers run on: room for their nesting limits many times over, even
/// with a sanitizer's larger frames (only the pages used are ever touched).
constexpr size_t kReaderStackBytes = size_t(64) << 20;

/// Runs fn() on a new thread with `bytes` of stack and waits for it; what fn throws is thrown
/// here. On a thread run_on_stack started with at least `bytes`, or where the system refuses
/// the thread, fn runs on the calling thread.
void run_on_stack(size_t bytes, const std::function<void()>& fn);

} // namespace sheaf

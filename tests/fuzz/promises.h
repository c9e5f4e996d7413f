// What the C ABI promises a host, checked by the fuzzers and the replay: a broken promise
// aborts with a message (a finding).
#pragma once

#include "sheaf/sheaf.h"

#include <cstdio>
#include <string>

namespace sheaf::fuzz {

/// Reports a broken promise on stderr and aborts.
[[noreturn]] void broken(const std::string& what);

/// The last error's message after `call` returned `code`; a broken promise when
/// sheafGetLastError disagrees with `code` or the failed call left no message.
std::string failure(const char* call, SheafError code);

/// Renders `scene` small (24×16) on the CPU with one thread, after applying `renderer`'s own
/// settings when one is given (otherwise with the defaults). A frame that renders must have
/// that size and finite pixels. With `log`, writes the outcome there in one line.
void render_small(SheafScene scene, std::FILE* log, SheafRenderer renderer = nullptr);

} // namespace sheaf::fuzz

// What the C ABI promises a host, checked by the fuzzers and the replay: a broken promise
// aborts with a message (a finding).
#pragma once

#include "sheaf/sheaf.h"

#include <cstdio>
#include <string>
#include <vector>

namespace sheaf::fuzz {

/// Reports a broken promise on stderr and aborts.
[[noreturn]] void broken(const std::string& what);

/// The last error's message after `call` returned `code`; a broken promise when
/// sheafGetLastError disagrees with `code` or the failed call left no message.
std::string failure(const char* call, SheafError code);

/// Renders `scene` small (24×16) on the CPU with one thread, with `renderer`'s own settings
/// when one is given (otherwise the defaults), its region.* included. A frame that renders must
/// have finite pixels and the size asked for: the whole frame's, or its region's, which lies
/// inside the whole frame. A region is then rendered whole (region.* set to 0, and left so),
/// and its pixels must equal the whole frame's bit for bit (docs/settings.md, region.x). With
/// `log`, writes the outcome there. Returns the whole frame's combined pass (RGBA), or nothing
/// when the render failed.
std::vector<float> render_small(SheafScene scene, std::FILE* log, SheafRenderer renderer = nullptr);

} // namespace sheaf::fuzz

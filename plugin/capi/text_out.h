// Copies a string out of the C ABI with the snprintf protocol shared by every text getter.
#pragma once

#include "capi_internal.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace sheaf::capi {

/// Writes at most `size` bytes of `text` including the NUL to `buf` (NULL allowed when size is
/// 0) and sets *needed (when not NULL) to text.size() + 1.
inline void copy_text(const std::string& text, char* buf, size_t size, size_t* needed) {
    if (size > 0) require(buf, "buf");
    if (needed) *needed = text.size() + 1;
    if (size == 0) return;
    const size_t n = std::min(size - 1, text.size());
    std::memcpy(buf, text.data(), n);
    buf[n] = '\0';
}

} // namespace sheaf::capi

// The engine's exceptions. They never cross the C ABI: plugin/capi turns each into a code.
#pragma once

#include <stdexcept>
#include <string>

namespace sheaf {

/// A setting with an unknown key or a value out of range.
struct SettingsError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A scene that cannot be rendered (bad mesh, bad reference, unreadable file).
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A failure while rendering (out of memory, cancelled, backend unavailable).
struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A frame that needs more memory than the machine has available: found before the memory is
/// taken, so the process is not stopped by the system instead.
struct OutOfMemory : RenderError {
    using RenderError::RenderError;
};

} // namespace sheaf

// The C ABI's error reporting: the per-thread last error, the global error callback, and the
// mapping of the engine's exceptions to SheafError codes.
#include "capi_internal.h"

#include "core/base/error.h"

#include <new>

namespace sheaf::capi {

namespace {

struct LastError {
    SheafError code = SHEAF_OK;
    std::string message;
};

LastError& last_error() {
    thread_local LastError last;
    return last;
}

std::mutex g_callback_mutex;
SheafErrorCallback g_callback = nullptr;
void* g_callback_user = nullptr;

SheafError report(SheafError code, const char* message) noexcept {
    LastError& last = last_error();
    last.code = code;
    try {
        last.message = message;
    } catch (...) {
        last.message.clear(); // out of memory for the message itself
    }
    SheafErrorCallback callback = nullptr;
    void* user = nullptr;
    {
        std::lock_guard<std::mutex> lock(g_callback_mutex);
        callback = g_callback;
        user = g_callback_user;
    }
    if (callback) {
        try {
            callback(user, code, last.message.c_str());
        } catch (...) {
            // A C++ host's callback that throws must not unwind through the ABI.
        }
    }
    return code;
}

} // namespace

SheafError succeed() noexcept {
    LastError& last = last_error();
    last.code = SHEAF_OK;
    last.message.clear();
    return SHEAF_OK;
}

SheafError fail_current() noexcept {
    try {
        throw;
    } catch (const InvalidArgument& e) {
        return report(SHEAF_ERROR_INVALID_ARGUMENT, e.what());
    } catch (const IoError& e) {
        return report(SHEAF_ERROR_IO, e.what());
    } catch (const SettingsError& e) {
        return report(SHEAF_ERROR_INVALID_SETTING, e.what());
    } catch (const SceneError& e) {
        return report(SHEAF_ERROR_SCENE, e.what());
    } catch (const OutOfMemory& e) {
        return report(SHEAF_ERROR_OUT_OF_MEMORY, e.what());
    } catch (const RenderError& e) {
        const bool cancelled = std::string_view(e.what()) == "cancelled";
        return report(cancelled ? SHEAF_ERROR_CANCELLED : SHEAF_ERROR_RENDER, e.what());
    } catch (const std::bad_alloc&) {
        return report(SHEAF_ERROR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception& e) {
        return report(SHEAF_ERROR_UNKNOWN, e.what());
    } catch (...) {
        return report(SHEAF_ERROR_UNKNOWN, "unknown error");
    }
}

} // namespace sheaf::capi

extern "C" {

SHEAF_API SheafError sheafGetLastError(const char** message) {
    const sheaf::capi::LastError& last = sheaf::capi::last_error();
    if (message) *message = last.message.c_str();
    return last.code;
}

SHEAF_API void sheafSetErrorCallback(SheafErrorCallback callback, void* user) {
    try {
        std::lock_guard<std::mutex> lock(sheaf::capi::g_callback_mutex);
        sheaf::capi::g_callback = callback;
        sheaf::capi::g_callback_user = user;
    } catch (...) {
        // std::mutex::lock only throws when the system is out of resources; nothing to report to.
    }
}

} // extern "C"

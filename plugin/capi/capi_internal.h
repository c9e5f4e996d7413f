// Internals of the C ABI: the objects behind the opaque handles, the exception barrier that
// turns every C++ exception into a SheafError, and argument checks.
#pragma once

#include "sheaf/sheaf.h"

#include "core/frame/frame.h"
#include "core/scene/prepared_scene.h"
#include "core/scene/scene.h"
#include "core/settings/settings.h"
#include "io/image/raster.h"
#include "io/image/texture_sampler.h"
#include "io/scene/scene_file.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace sheaf::capi {

/// A NULL pointer, an index out of range, an unknown pass: SHEAF_ERROR_INVALID_ARGUMENT.
struct InvalidArgument : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// A file that cannot be written: SHEAF_ERROR_IO.
struct IoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Records success as the thread's last error and returns SHEAF_OK.
SheafError succeed() noexcept;
/// Maps the exception being handled to a code, records it and calls the error callback.
SheafError fail_current() noexcept;

/// The barrier every exported function body runs in: no exception crosses the ABI.
template <class Body> SheafError barrier(Body&& body) noexcept {
    try {
        body();
        return succeed();
    } catch (...) {
        return fail_current();
    }
}

/// Throws InvalidArgument naming `name` when `p` is NULL.
template <class T> T* require(T* p, const char* name) {
    if (!p) throw InvalidArgument(std::string("argument '") + name + "' is NULL");
    return p;
}

} // namespace sheaf::capi

struct SheafRefCounted {
    std::atomic<int> refs{1};
};

/// Reference counting shared by the three handle types.
template <class T> void sheaf_retain(T* handle) {
    sheaf::capi::require(handle, "handle")->refs.fetch_add(1, std::memory_order_relaxed);
}
template <class T> void sheaf_release(T* handle) {
    if (sheaf::capi::require(handle, "handle")->refs.fetch_sub(1, std::memory_order_acq_rel) == 1)
        delete handle;
}

struct SheafSceneT : SheafRefCounted {
    std::mutex mutex;
    sheaf::Scene scene;
    /// How sheafSceneLoadFile reads files (sheafSceneSetLoadOption), and what the last load
    /// warned about.
    sheaf::io::SceneFileOptions load_options = [] {
        sheaf::io::SceneFileOptions o;
        o.read_raster = &sheaf::io::read_raster; // height fields from images (OpenImageIO)
        o.attach_sampler = &sheaf::io::attach_texture_sampler; // and pigment functions' images
        return o;
    }();
    bool subdivision_limit = false;
    int subdivision_boundary = 0; // sheaf::io::SubdivBoundary
    std::vector<std::string> warnings;
    std::vector<sheaf::io::pov::LimitUse> limits; // what the last load used of the reader's limits
    /// The committed scene; null when never committed or changed since.
    std::shared_ptr<const sheaf::PreparedScene> prepared;

    /// The prepared scene, committing first when needed. Throws SceneError.
    std::shared_ptr<const sheaf::PreparedScene> commit() {
        std::lock_guard<std::mutex> lock(mutex);
        if (!prepared) {
            auto p = std::make_shared<sheaf::PreparedScene>(sheaf::prepare_scene(scene));
            sheaf::io::attach_texture_sampler(*p); // opens the image textures (OpenImageIO)
            prepared = std::move(p);
        }
        return prepared;
    }
};

struct SheafRendererT : SheafRefCounted {
    sheaf::Settings settings;
    SheafProgressCallback progress = nullptr;
    void* progress_user = nullptr;
};

struct SheafFrameT : SheafRefCounted {
    sheaf::Frame frame;
};

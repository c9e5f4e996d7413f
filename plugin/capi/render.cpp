// The C ABI's render call: resolves the settings, commits the scene when needed and runs the
// frame pipeline.
#include "capi_internal.h"

#include "core/backend/backend.h"

using namespace sheaf::capi;

extern "C" {

SHEAF_API SheafError sheafRender(SheafRenderer renderer, SheafScene scene, SheafFrame* out) {
    return barrier([&] {
        require(out, "out");
        *out = nullptr;
        const SheafRendererT& r = *require(renderer, "renderer");
        SheafSceneT& s = *require(scene, "scene");
        const std::shared_ptr<const sheaf::PreparedScene> prepared = s.commit();

        const sheaf::RenderSettings settings =
            sheaf::RenderSettings::resolve(r.settings, prepared->settings);
        sheaf::ProgressFn progress;
        if (r.progress) {
            const SheafProgressCallback callback = r.progress;
            void* user = r.progress_user;
            progress = [callback, user](float done) { return callback(user, done) != 0; };
        }
        auto frame = std::make_unique<SheafFrameT>();
        frame->frame = sheaf::render_frame(*prepared, settings, progress);
        frame->frame.settings = sheaf::RenderSettings::effective(r.settings, prepared->settings);
        *out = frame.release();
    });
}

} // extern "C"

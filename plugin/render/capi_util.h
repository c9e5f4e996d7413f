// The render tool's thin layer over the C ABI: owning handles, the last error, frame texts and
// passes, and the settings and scene steps every mode shares.
#pragma once

#include <sheaf/sheaf.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace render {

// Exit codes.
constexpr int kOk = 0, kUsage = 1, kScene = 2, kRender = 3;

/// Prints "render: error: MESSAGE" on stderr and returns `code`.
int error(int code, const std::string& message);

/// The message the last error() printed (empty when none).
const std::string& last_printed_error();

/// The message of the C ABI's last error on this thread.
std::string last_error();

/// The exit code for a failed sheafRender.
int render_error_code(SheafError e);

struct SceneDeleter {
    void operator()(SheafScene s) const { sheafSceneRelease(s); }
};
struct RendererDeleter {
    void operator()(SheafRenderer r) const { sheafRendererRelease(r); }
};
struct FrameDeleter {
    void operator()(SheafFrame f) const { sheafFrameRelease(f); }
};
using Scene = std::unique_ptr<std::remove_pointer_t<SheafScene>, SceneDeleter>;
using Renderer = std::unique_ptr<std::remove_pointer_t<SheafRenderer>, RendererDeleter>;
using Frame = std::unique_ptr<std::remove_pointer_t<SheafFrame>, FrameDeleter>;

/// A text of the frame ("stats.json", "stats.table", "settings") through the size protocol.
std::optional<std::string> frame_text(SheafFrame frame, const char* what);

/// Where the frame was computed, in one line: the library's own line with its reason
/// ("backend: cpu (no CUDA device: ...)") where the C ABI gives it, else from backend.cuda.
std::string frame_backend(SheafFrame frame);

/// A pass of the frame ("combined", "tests", ...) with `channels` floats per pixel.
std::optional<std::vector<float>> frame_pass(SheafFrame frame, const char* pass, int channels);

/// Every statistic of the frame, in the frame's order.
std::vector<std::pair<std::string, double>> frame_stats(SheafFrame frame);

/// The settings the command line applies to every renderer after its preset.
struct CommonSettings {
    std::optional<int> width, height, threads;
    /// KEY=VALUE in order (--set, and the +A/-A switches).
    std::vector<std::string> sets;
};

/// Applies `preset` (when not empty), then width/height/threads, then each set in order; prints
/// the error and returns its exit code on failure.
int apply_settings(SheafRenderer renderer, const std::string& preset, const CommonSettings& s);

/// Where the scene comes from and how its file is read.
struct SceneSource {
    std::string path;                       ///< empty: the default built-in scene
    std::vector<std::string> include_paths; ///< --include-path, +L
    bool strict = false;                    ///< --strict: unsupported features are errors
    std::optional<int> width, height;       ///< -W/-H: the size the scene is told
    /// POV-Ray's animation (load options initial_frame ... clock) and Declare= floats.
    std::optional<int> initial_frame, final_frame, frame;
    std::optional<double> initial_clock, final_clock, clock;
    std::optional<bool> cyclic;
    std::vector<std::string> declares; ///< NAME=VALUE
    std::vector<std::string> limits;   ///< NAME=N: the reader's limits (load options limit.*)
};

/// Loads and commits the scene, printing the reader's warnings on stderr. Returns an exit code.
int load_scene(SheafScene scene, const SceneSource& source);

/// What the scene's last load used of the reader's limits, "NAME USED of LIMIT (P%), ...";
/// empty when the reader has none.
std::string limits_used(SheafScene scene);

/// The scene argument as shown: the default built-in scene when empty.
std::string scene_label(const std::string& path);

/// Whether `key` is a setting the library knows.
bool is_setting_key(const std::string& key);

/// The keys the library knows, comma separated.
std::string setting_keys();

} // namespace render

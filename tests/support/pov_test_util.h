// Helpers for the POV-Ray reader's tests: scene text in a temporary folder, loading it, the
// error message of a failing load, and values declared by a scene.
#pragma once

#include "core/base/error.h"
#include "core/scene/analytic.h"
#include "core/scene/prepared_scene.h"
#include "io/pov/builder.h"
#include "io/pov/parser.h"
#include "io/pov/pov_reader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace sheaf::io::pov::test {

/// A temporary folder that is removed with the object.
class TempDir {
  public:
    TempDir() {
        static std::atomic<int> counter{0};
        dir_ = std::filesystem::temp_directory_path() /
               ("sheaf_pov_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(dir_);
    }
    ~TempDir() { std::filesystem::remove_all(dir_); }
    /// Writes `text` to NAME inside the folder and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const auto p = dir_ / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p.string();
    }
    std::string path() const { return dir_.string(); }

  private:
    std::filesystem::path dir_;
};

inline PovResult load_text(const std::string& text, const PovOptions& options = {}) {
    TempDir d;
    return load_pov_scene(d.write("scene.pov", text), options);
}

/// The message of the SceneError that loading `text` throws, with the folder replaced by
/// nothing (so "scene.pov:3:1: error: ..."); "" when it loads.
inline std::string error_of(const std::string& text, const PovOptions& options = {}) {
    TempDir d;
    const std::string path = d.write("scene.pov", text);
    try {
        load_pov_scene(path, options);
    } catch (const SceneError& e) {
        std::string m = e.what();
        for (size_t at; (at = m.find(d.path() + "/")) != std::string::npos;)
            m.erase(at, d.path().size() + 1);
        return m;
    }
    return "";
}

/// Parses `text` and returns the value it declares as `name` (at the top level).
inline Value declared(const std::string& text, const std::string& name) {
    TempDir d;
    Parser p(PovOptions{});
    p.parse_scene(d.write("scene.pov", text));
    const Value* v = p.lookup(name);
    if (!v) throw SceneError("'" + name + "' was not declared");
    return *v;
}

/// The first hit of a ray from `from` along `dir` (POV-Ray coordinates) on the scene's first
/// analytic object; -1 when it misses.
inline float first_hit(const PovResult& r, Vec3 from, Vec3 dir) {
    const PreparedScene p = prepare_scene(r.scene);
    Ray ray;
    ray.origin = pov_to_sheaf().point(from), ray.dir = pov_to_sheaf().vector(dir);
    ray.tmin = 0, ray.tmax = 100;
    AnalyticHit h;
    return analytic_first_hit(p, 0, ray, h) ? h.t : -1.0f;
}

inline double num(const std::string& expr) {
    return declared("#declare V = " + expr + ";", "V").v[0];
}

} // namespace sheaf::io::pov::test

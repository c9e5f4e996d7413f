// load_pov_scene: parses the scene file and builds the core scene (see pov_reader.h).
#include "io/pov/pov_reader.h"

#include "core/base/error.h"
#include "core/base/stack.h"
#include "io/pov/builder.h"
#include "io/pov/parser.h"

#include <filesystem>

namespace sheaf::io::pov {

void Parser::parse_scene(const std::string& path) {
    scene_dir_ = std::filesystem::path(path).parent_path().string();
    if (scene_dir_.empty()) scene_dir_ = ".";
    for (const auto& [name, value] : options_.declares) declare(name, Value::number(value), false);
    Token none;
    push_file(path, none);
    while (parse_statement()) {
    }
}

PovResult load_pov_scene(const std::string& path, const PovOptions& options) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw SceneError(path + ": error: no such scene file");
    PovResult r;
    // The parser recurses as deep as the scene nests (up to kMaxNesting): on a stack of known
    // size, whoever calls (core/base/stack.h; load_scene_file is on one already).
    run_on_stack(kReaderStackBytes, [&] {
        Parser p(options);
        try {
            p.parse_scene(path);
        } catch (const std::filesystem::filesystem_error& e) {
            // A system call the reader did not expect to fail: still the scene's error.
            throw SceneError(path + ": error: " + e.what());
        }
        r.assumed_gamma = build_scene(p, r.scene);
        r.version = p.model.version;
        r.warnings = std::move(p.warnings);
        r.usage = p.usage();
    });
    return r;
}

} // namespace sheaf::io::pov

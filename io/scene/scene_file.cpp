// load_scene_file: the dispatch on "builtin:" and the file's extension (see scene_file.h).
#include "io/scene/scene_file.h"

#include "core/base/error.h"
#include "core/base/stack.h"
#include "core/scenes/builtin.h"
#include "io/mesh/mesh_scene.h"
#include "io/pov/pov_reader.h"
#include "io/xml/xml_scene.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace sheaf::io {
namespace {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

SceneFile read_pov(const std::string& path, const SceneFileOptions& options) {
    pov::PovOptions po;
    po.include_paths = options.include_paths;
    po.strict = options.strict;
    po.image_width = options.image_width;
    po.image_height = options.image_height;
    po.read_raster = options.read_raster;
    po.attach_sampler = options.attach_sampler;
    if (const std::string problem = pov::animation_problem(options.animation); !problem.empty())
        throw SceneError(path + ": error: " + problem);
    po.clock = pov::clock_for(options.animation);
    po.declares = options.declares;
    po.limits = options.limits;
    pov::PovResult r = pov::load_pov_scene(path, po);
    return {std::move(r.scene), std::move(r.warnings), pov::limit_uses(r.usage, po.limits)};
}

struct Reader {
    std::string_view extension;
    SceneFile (*read)(const std::string&, const SceneFileOptions&);
};

constexpr Reader kReaders[] = {
    {".pov", read_pov},
    {".inc", read_pov},
    {".xml", read_xml_scene},
    {".obj", read_mesh_scene},
    {".ply", read_mesh_scene},
    {".gltf", read_mesh_scene},
    {".glb", read_mesh_scene},
};

} // namespace

std::string scene_file_extensions() {
    std::string s;
    for (const Reader& r : kReaders) s += (s.empty() ? "" : " ") + std::string(r.extension);
    return s;
}

SceneFile load_scene_file(const std::string& path, const SceneFileOptions& options) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (path.compare(0, kBuiltin.size(), kBuiltin) == 0)
        return {make_builtin_scene(std::string_view(path).substr(kBuiltin.size())), {}, {}};
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw SceneError(path + ": is a directory, not a scene file");
    if (!std::filesystem::exists(path, ec)) throw SceneError(path + ": no such file");
    if (!std::ifstream(path)) throw SceneError(path + ": cannot open file");
    const std::string ext = lower_extension(path);
    for (const Reader& r : kReaders)
        if (ext == r.extension) {
            // On a stack of known size, whatever the calling thread has (core/base/stack.h).
            SceneFile file;
            run_on_stack(kReaderStackBytes, [&] { file = r.read(path, options); });
            return file;
        }
    throw SceneError(path + ": no reader for '" + ext + "' files; scene files are " +
                     scene_file_extensions() + ", or builtin:NAME");
}

} // namespace sheaf::io

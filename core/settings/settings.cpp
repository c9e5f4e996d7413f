#include "core/settings/settings.h"

#include "core/base/error.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace sheaf {

const std::vector<std::string>& pass_names() {
    static const std::vector<std::string> names = {"combined", "depth",     "normal",
                                                   "albedo",   "object_id", "tests"};
    return names;
}

const std::vector<SettingSpec>& setting_specs() {
    using K = SettingKind;
    static const std::vector<SettingSpec> specs = {
        {"accel",
         K::Choice,
         "bvh",
         0,
         0,
         {"brute", "rah", "crsh", "bvh", "crsh-bvh", "rah-bvh", "strips"},
         "how secondary rays find geometry: every ray against every primitive (brute), the ray "
         "hierarchy over "
         "rays in generation order (rah, Roger et al.) or over rays hashed and sorted by hash.mode "
         "and sort.mode "
         "(crsh, paper 000), each ray through a bounding volume hierarchy of the primitives "
         "(bvh, SAH-built, eight-wide), or the ray hierarchy of crsh or rah with its top nodes "
         "through that BVH instead of the object spheres (crsh-bvh, rah-bvh), or each ray "
         "through triangle strips under an SAH BVH (strips, paper 004)"},
        {"hierarchy.depth",
         K::Int,
         "2",
         1,
         kMaxHierarchyDepth,
         {},
         "levels of ray-hierarchy nodes above the rays"},
        {"hierarchy.arity", K::Int, "8", 2, 64, {}, "children per hierarchy node"},
        {"hash.mode",
         K::Choice,
         "crsh",
         0,
         0,
         {"none", "crsh", "hash32", "hash192", "static1d", "static3d"},
         "ray hash: per ray type (crsh, paper 000), the 32/192-bit keys of paper 003, or "
         "paper 003's fixed orders: static1d (generation order: a pixel's rays together), "
         "static3d (8x16-pixel tiles, one sample or light at a time)"},
        {"sort.mode",
         K::Choice,
         "csd",
         0,
         0,
         {"none", "full", "csd"},
         "ray order before the hierarchy is built: unsorted, every ray sorted by key, or "
         "compress-sort-decompress"},
        {"sort.algorithm",
         K::Choice,
         "radix",
         0,
         0,
         {"radix", "bitonic"},
         "how keys are sorted: LSD radix sort, or a bitonic network (paper 003's comparison); "
         "both give the same order"},
        {"cull.objects",
         K::Bool,
         "true",
         0,
         0,
         {},
         "test top hierarchy nodes against object bounding spheres first"},
        {"cull.cluster",
         K::Int,
         "64",
         0,
         1 << 24,
         {},
         "with cull.objects: an object of more primitives than this is also culled in runs of "
         "this many consecutive primitives, each under its own sphere, tested where the "
         "object's sphere is hit, so a top node that reaches a large mesh meets only the "
         "primitives of the runs it reaches; 0 culls whole objects only, as the papers do"},
        {"cull.distance",
         K::Bool,
         "true",
         0,
         0,
         {},
         "hierarchy nodes also bound how far their rays reach (shadow rays end at the surface, "
         "AO rays at ao.distance): primitives beyond every ray's end are not candidates; false "
         "keeps the papers' unbounded cones"},
        {"trace.depth",
         K::Int,
         "5",
         0,
         64,
         {},
         "reflection/refraction bounces after the primary hit"},
        {"trace.bailout",
         K::Float,
         "0.001",
         0,
         1,
         {},
         "reflection and refraction rays that would carry less than this share of a "
         "pixel's light are not traced (POV-Ray's adc_bailout; POV scenes take theirs, 1/255 "
         "by default)"},
        {"backend",
         K::Choice,
         "auto",
         0,
         0,
         {"auto", "cpu", "cuda"},
         "where the frame is computed"},
        {"width", K::Int, "512", 1, 16384, {}, "image width in pixels"},
        {"height", K::Int, "512", 1, 16384, {}, "image height in pixels"},
        {"region.x",
         K::Int,
         "0",
         0,
         16383,
         {},
         "first column of the part of the frame rendered (0: the left edge); the pixels are "
         "those of the whole frame, so tiles put together equal it byte for byte"},
        {"region.y",
         K::Int,
         "0",
         0,
         16383,
         {},
         "first row of the part of the frame rendered (0: the top row)"},
        {"region.width",
         K::Int,
         "0",
         0,
         16384,
         {},
         "columns of the part of the frame rendered, 0 for all from region.x to the right edge"},
        {"region.height",
         K::Int,
         "0",
         0,
         16384,
         {},
         "rows of the part of the frame rendered, 0 for all from region.y to the bottom edge"},
        {"aa.samples",
         K::Int,
         "1",
         1,
         8,
         {},
         "anti-aliasing: n x n samples per pixel, box filtered"},
        {"threads", K::Int, "0", 0, 1024, {}, "worker threads, 0 for every core"},
        {"ao.samples",
         K::Int,
         "0",
         0,
         1024,
         {},
         "ambient-occlusion rays per pixel at the primary hit, 0 for none"},
        {"ao.distance",
         K::Float,
         "1",
         1e-6,
         1e30,
         {},
         "ambient-occlusion ray length in scene units"},
        {"radiosity.samples",
         K::Int,
         "0",
         0,
         1024,
         {},
         "diffuse interreflection (POV-Ray's radiosity): rays gathered at each point seen from "
         "the camera or in a mirror, 0 for none; POV-Ray scenes with radiosity set their count"},
        {"radiosity.depth",
         K::Int,
         "2",
         1,
         8,
         {},
         "diffuse bounces a gathered path takes (POV-Ray's recursion_limit); past the first, one "
         "ray per point"},
        {"radiosity.brightness",
         K::Float,
         "1",
         0,
         100,
         {},
         "scale of the gathered light (POV-Ray's radiosity brightness)"},
        {"output.display",
         K::String,
         "",
         0,
         0,
         {},
         "OpenColorIO display for 8-bit images (empty: the config's default, sRGB in Sheaf's "
         "config)"},
        {"output.view",
         K::String,
         "",
         0,
         0,
         {},
         "OpenColorIO view of the display (empty: its default)"},
        {"output.look",
         K::String,
         "",
         0,
         0,
         {},
         "OpenColorIO looks applied before the view, comma-separated"},
        {"output.ocio_config",
         K::String,
         "",
         0,
         0,
         {},
         "OpenColorIO config file (empty: $OCIO, else the config Sheaf ships)"},
        {"output.passes", K::Subset, "all", 0, 0, pass_names(),
         "the passes the frame keeps and hands back; the others are not read back from the "
         "device nor kept in memory, and asking a frame for one is an error naming this "
         "setting"},
        {"output.exr",
         K::Choice,
         "half",
         0,
         0,
         {"half", "float"},
         "OpenEXR colour channels as half or full float (depth, ids and test counts are always "
         "float)"},
        {"band.samples",
         K::Int,
         "0",
         0,
         1 << 30,
         {},
         "camera samples shaded at once: the frame is shaded in bands of whole pixel rows of "
         "about this many samples, which bounds its memory (the same picture whatever the "
         "size); 0 sizes it to the backend: on the CPU under bvh, strips and brute 65536 "
         "rays' worth at 2 + lights + ao.samples + radiosity.samples a sample (16384 samples "
         "with two lights), the whole frame on a GPU and under a ray hierarchy (rah, crsh, "
         "...), whose figures count a frame's rays at once"},
        {"traversal.batch",
         K::Int,
         "0",
         0,
         1 << 30,
         {},
         "candidate (node, primitive) pairs held at once per level; bounds traversal memory; 0 "
         "sizes it to the backend: 4194304 on the CPU, on a GPU 1/1024 of its memory as a power "
         "of two, 4194304..67108864"},
    };
    return specs;
}

const SettingSpec* find_setting(std::string_view key) {
    for (const SettingSpec& s : setting_specs())
        if (s.key == key) return &s;
    return nullptr;
}

std::string format_number(double v) {
    std::ostringstream os;
    os.precision(9);
    os << v;
    return os.str();
}

namespace {

std::string known_keys() {
    std::string out;
    for (const SettingSpec& s : setting_specs()) out += (out.empty() ? "" : ", ") + s.key;
    return out;
}

const SettingSpec& spec_or_throw(std::string_view key) {
    const SettingSpec* s = find_setting(key);
    if (!s)
        throw SettingsError("unknown setting '" + std::string(key) +
                            "'; known settings: " + known_keys());
    return *s;
}

[[noreturn]] void bad_value(const SettingSpec& s, std::string_view value) {
    throw SettingsError("setting '" + s.key + "': '" + std::string(value) +
                        "' is not allowed; expected " + describe_allowed(s));
}

/// A Subset's value in canonical text: its items in the order of the choices, each once,
/// separated by commas; "all" when every choice is there.
std::string canonical_subset(const SettingSpec& s, std::string_view value) {
    const uint32_t bits = subset_bits(s, value);
    if (bits == (1u << s.choices.size()) - 1) return "all";
    std::string out;
    for (size_t i = 0; i < s.choices.size(); ++i)
        if (bits & (1u << i)) out += (out.empty() ? "" : ",") + s.choices[i];
    return out;
}

} // namespace

std::string describe_allowed(const SettingSpec& s) {
    switch (s.kind) {
    case SettingKind::Int: // exact: format_number's 9 digits would print 2^30 as 1.07374182e+09
        return "an integer in " + std::to_string((long long)s.min) + ".." +
               std::to_string((long long)s.max);
    case SettingKind::Float:
        return "a number in " + format_number(s.min) + ".." + format_number(s.max);
    case SettingKind::Bool:
        return "true or false (also on/off, yes/no, 1/0)";
    case SettingKind::String:
        return "any text";
    case SettingKind::Choice: {
        std::string out = "one of ";
        for (size_t i = 0; i < s.choices.size(); ++i) out += (i ? ", " : "") + s.choices[i];
        return out;
    }
    case SettingKind::Subset: {
        std::string out = "a comma-separated list of ";
        for (size_t i = 0; i < s.choices.size(); ++i) out += (i ? ", " : "") + s.choices[i];
        return out + "; or all";
    }
    }
    return {};
}

std::string canonical_setting(std::string_view key, std::string_view value) {
    const SettingSpec& s = spec_or_throw(key);
    switch (s.kind) {
    case SettingKind::Int: {
        long long v = 0;
        auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (ec != std::errc() || end != value.data() + value.size() || v < s.min || v > s.max)
            bad_value(s, value);
        return std::to_string(v);
    }
    case SettingKind::Float: {
        double v = 0;
        auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v) ||
            v < s.min || v > s.max)
            bad_value(s, value);
        return format_number(v);
    }
    case SettingKind::Bool:
        if (value == "true" || value == "on" || value == "yes" || value == "1") return "true";
        if (value == "false" || value == "off" || value == "no" || value == "0") return "false";
        bad_value(s, value);
    case SettingKind::String:
        if (value.find('\n') != std::string_view::npos) bad_value(s, value);
        return std::string(value);
    case SettingKind::Choice:
        for (const std::string& c : s.choices)
            if (c == value) return c;
        bad_value(s, value);
    case SettingKind::Subset:
        return canonical_subset(s, value);
    }
    bad_value(s, value);
}

uint32_t subset_bits(const SettingSpec& s, std::string_view value) {
    if (value == "all") return (1u << s.choices.size()) - 1;
    uint32_t bits = 0;
    size_t start = 0;
    while (start <= value.size()) {
        size_t end = value.find(',', start);
        if (end == std::string_view::npos) end = value.size();
        std::string_view item = value.substr(start, end - start);
        while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
        size_t i = 0;
        while (i < s.choices.size() && s.choices[i] != item) ++i;
        if (i == s.choices.size()) bad_value(s, value);
        bits |= 1u << i;
        start = end + 1;
    }
    return bits;
}

void Settings::set(std::string_view key, std::string_view value) {
    std::string v = canonical_setting(key, value);
    values_.insert_or_assign(std::string(key), std::move(v));
}

void Settings::unset(std::string_view key) {
    spec_or_throw(key);
    if (auto it = values_.find(key); it != values_.end()) values_.erase(it);
}

bool Settings::has(std::string_view key) const {
    return values_.find(key) != values_.end();
}

std::string Settings::get(std::string_view key) const {
    if (auto it = values_.find(key); it != values_.end()) return it->second;
    return spec_or_throw(key).default_value;
}

std::vector<std::pair<std::string, std::string>>
RenderSettings::effective(const Settings& explicit_settings,
                          const std::map<std::string, std::string>& scene) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const SettingSpec& s : setting_specs()) {
        std::string v;
        if (explicit_settings.has(s.key))
            v = explicit_settings.get(s.key);
        else if (auto it = scene.find(s.key); it != scene.end()) {
            try {
                v = canonical_setting(s.key, it->second);
            } catch (const SettingsError& e) {
                throw SceneError(std::string("the scene's own ") + e.what());
            }
        } else
            v = s.default_value;
        out.emplace_back(s.key, std::move(v));
    }
    for (const auto& [k, v] : scene)
        if (!find_setting(k)) throw SceneError("the scene sets unknown setting '" + k + "'");
    return out;
}

RenderSettings RenderSettings::resolve(const Settings& explicit_settings,
                                       const std::map<std::string, std::string>& scene) {
    std::map<std::string, std::string> v;
    for (auto& [k, val] : effective(explicit_settings, scene)) v[k] = val;
    auto i = [&](const char* k) { return std::stoi(v.at(k)); };
    // Not std::stof: it throws on a subnormal, which the settings' ranges may allow.
    auto f = [&](const char* k) {
        const std::string& text = v.at(k);
        double d = 0;
        std::from_chars(text.data(), text.data() + text.size(), d);
        return float(d);
    };
    auto choice = [&](const char* k) { return v.at(k); };
    RenderSettings r;
    const std::string accel = choice("accel");
    r.accel = accel == "brute"      ? Accel::Brute
              : accel == "rah"      ? Accel::Rah
              : accel == "bvh"      ? Accel::Bvh
              : accel == "crsh-bvh" ? Accel::CrshBvh
              : accel == "rah-bvh"  ? Accel::RahBvh
              : accel == "strips"   ? Accel::Strips
                                    : Accel::Crsh;
    r.hierarchy_depth = i("hierarchy.depth");
    r.hierarchy_arity = i("hierarchy.arity");
    const std::string hash = choice("hash.mode");
    r.hash = hash == "none"       ? HashMode::None
             : hash == "hash32"   ? HashMode::Hash32
             : hash == "hash192"  ? HashMode::Hash192
             : hash == "static1d" ? HashMode::Static1d
             : hash == "static3d" ? HashMode::Static3d
                                  : HashMode::Crsh;
    const std::string sort = choice("sort.mode");
    r.sort = sort == "none" ? SortMode::None : sort == "full" ? SortMode::Full : SortMode::Csd;
    r.sort_algorithm =
        choice("sort.algorithm") == "bitonic" ? SortAlgorithm::Bitonic : SortAlgorithm::Radix;
    r.cull_objects = v.at("cull.objects") == "true";
    r.cull_distance = v.at("cull.distance") == "true";
    r.cull_cluster = i("cull.cluster");
    r.trace_depth = i("trace.depth");
    const std::string backend = choice("backend");
    r.backend = backend == "cpu" ? Backend::Cpu : backend == "cuda" ? Backend::Cuda : Backend::Auto;
    r.width = i("width");
    r.height = i("height");
    r.region_x = i("region.x");
    r.region_y = i("region.y");
    r.region_width = i("region.width");
    r.region_height = i("region.height");
    const Rect g = r.region();
    if (g.width <= 0 || g.x + g.width > r.width)
        throw SettingsError("region.x=" + v.at("region.x") +
                            ", region.width=" + v.at("region.width") +
                            ": the region's columns must lie within width=" + v.at("width") +
                            " (columns 0.." + std::to_string(r.width - 1) + ")");
    if (g.height <= 0 || g.y + g.height > r.height)
        throw SettingsError("region.y=" + v.at("region.y") +
                            ", region.height=" + v.at("region.height") +
                            ": the region's rows must lie within height=" + v.at("height") +
                            " (rows 0.." + std::to_string(r.height - 1) + ")");
    r.aa_samples = i("aa.samples");
    r.threads = i("threads");
    r.ao_samples = i("ao.samples");
    r.ao_distance = f("ao.distance");
    r.trace_bailout = f("trace.bailout");
    r.radiosity_samples = i("radiosity.samples");
    r.radiosity_depth = i("radiosity.depth");
    r.radiosity_brightness = f("radiosity.brightness");
    r.batch_pairs = std::stoll(v.at("traversal.batch"));
    r.band_samples = std::stoll(v.at("band.samples"));
    r.passes = subset_bits(spec_or_throw("output.passes"), v.at("output.passes"));
    return r;
}

size_t RenderSettings::band_or(bool host_memory, size_t frame_samples,
                               size_t rays_per_sample) const {
    if (band_samples > 0) return size_t(band_samples);
    if (!host_memory || uses_ray_hierarchy(accel)) return frame_samples;
    return std::max<size_t>(1, kCpuBandRays / std::max<size_t>(1, rays_per_sample));
}

size_t device_batch_pairs(uint64_t device_bytes) {
    const uint64_t want = device_bytes / 1024;
    size_t pairs = kCpuBatchPairs;
    while (pairs < (size_t(1) << 26) && uint64_t(pairs) * 2 <= want) pairs *= 2;
    return pairs;
}

const char* to_string(Accel a) {
    switch (a) {
    case Accel::Brute:
        return "brute";
    case Accel::Rah:
        return "rah";
    case Accel::Bvh:
        return "bvh";
    case Accel::CrshBvh:
        return "crsh-bvh";
    case Accel::RahBvh:
        return "rah-bvh";
    case Accel::Strips:
        return "strips";
    case Accel::Crsh:
        break;
    }
    return "crsh";
}
const char* to_string(HashMode h) {
    switch (h) {
    case HashMode::None:
        return "none";
    case HashMode::Crsh:
        return "crsh";
    case HashMode::Hash32:
        return "hash32";
    case HashMode::Hash192:
        return "hash192";
    case HashMode::Static1d:
        return "static1d";
    case HashMode::Static3d:
        return "static3d";
    }
    return "?";
}
const char* to_string(SortAlgorithm a) {
    return a == SortAlgorithm::Radix ? "radix" : "bitonic";
}
const char* to_string(SortMode s) {
    return s == SortMode::None ? "none" : s == SortMode::Full ? "full" : "csd";
}
const char* to_string(Backend b) {
    return b == Backend::Auto ? "auto" : b == Backend::Cpu ? "cpu" : "cuda";
}

} // namespace sheaf

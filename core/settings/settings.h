// Render settings: one dictionary of named keys, the same in presets, the CLI, the C ABI and
// the Blender panel. Every key has a kind, a default and a range; a bad value is an error
// that names the key and what is allowed.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sheaf {

/// Subset: a comma-separated list of some of `choices`, each once, or "all".
enum class SettingKind { Int, Float, Bool, Choice, String, Subset };

struct SettingSpec {
    std::string key;
    SettingKind kind;
    std::string default_value;
    double min = 0, max = 0;          // Int and Float
    std::vector<std::string> choices; // Choice and Subset
    std::string help;
};

/// Every known setting, in a stable order.
const std::vector<SettingSpec>& setting_specs();
/// nullptr when the key is unknown.
const SettingSpec* find_setting(std::string_view key);
/// What a key accepts, in words ("an integer in 2..64", "one of none, crsh").
std::string describe_allowed(const SettingSpec& spec);
/// A number as settings print it (9 significant digits, no trailing zeros).
std::string format_number(double v);
/// Checks `value` against the key and returns its canonical text ("on" -> "true", "08" -> "8").
/// Throws SettingsError naming the key and the allowed values.
std::string canonical_setting(std::string_view key, std::string_view value);
/// A Subset setting's value as bits, one per choice in order (bit i: choices[i]). Throws
/// SettingsError when an item is not one of the choices.
uint32_t subset_bits(const SettingSpec& spec, std::string_view value);

/// The values a host set explicitly. Unset keys fall back to the scene's own settings, then
/// to the defaults.
class Settings {
  public:
    void set(std::string_view key, std::string_view value);
    void unset(std::string_view key);
    bool has(std::string_view key) const;
    /// Explicit value, else the default.
    std::string get(std::string_view key) const;
    const std::map<std::string, std::string, std::less<>>& values() const { return values_; }

  private:
    std::map<std::string, std::string, std::less<>> values_;
};

enum class Accel { Brute, Rah, Crsh, Bvh, CrshBvh, RahBvh, Strips };

/// Whether `a` traces through a hierarchy of rays (rah, crsh and their forms over the BVH).
inline bool uses_ray_hierarchy(Accel a) {
    return a == Accel::Rah || a == Accel::Crsh || a == Accel::CrshBvh || a == Accel::RahBvh;
}
/// Whether `a` hashes and orders its rays before building the hierarchy (crsh, crsh-bvh).
inline bool orders_rays(Accel a) {
    return a == Accel::Crsh || a == Accel::CrshBvh;
}
/// Whether `a` tests the scene's BVH (bvh per ray; crsh-bvh and rah-bvh per top node).
inline bool uses_bvh(Accel a) {
    return a == Accel::Bvh || a == Accel::CrshBvh || a == Accel::RahBvh;
}
/// Whether `a` traces each ray through an object-space structure of its own (bvh, strips):
/// it counts box tests (tests.<type>.nodes) and no ray hierarchy.
inline bool per_ray_structure(Accel a) {
    return a == Accel::Bvh || a == Accel::Strips;
}
enum class HashMode { None, Crsh, Hash32, Hash192, Static1d, Static3d };
enum class SortMode { None, Full, Csd };
enum class SortAlgorithm { Radix, Bitonic };
enum class Backend { Auto, Cpu, Cuda };

/// A frame's passes by name, in PassBit order: combined, depth, normal, albedo, object_id,
/// tests (the choices of output.passes).
const std::vector<std::string>& pass_names();

/// The passes a frame keeps (output.passes), as bits in the order of pass_names().
enum PassBit : uint32_t {
    kPassCombined = 1u << 0,
    kPassDepth = 1u << 1,
    kPassNormal = 1u << 2,
    kPassAlbedo = 1u << 3,
    kPassObjectId = 1u << 4,
    kPassTests = 1u << 5,
    kAllPasses = (1u << 6) - 1,
};

/// The typed, resolved settings the pipeline runs with.
struct RenderSettings {
    Accel accel = Accel::Bvh;
    int hierarchy_depth = 2;
    int hierarchy_arity = 8;
    HashMode hash = HashMode::Crsh;
    SortMode sort = SortMode::Csd;
    SortAlgorithm sort_algorithm = SortAlgorithm::Radix;
    bool cull_objects = true;
    bool cull_distance = true;
    int cull_cluster = 64; // primitives per culling sphere within a split object; 0: objects
    int trace_depth = 5;
    float trace_bailout = 0.001f; // rays carrying less are not traced (RayGenParams::min_weight)
    Backend backend = Backend::Auto;
    int width = 512, height = 512;
    /// The part of the frame rendered (region.*), in the frame's pixels; a size of 0 reaches
    /// the frame's edge. The frame's image is the region; each of its pixels is computed as in
    /// the whole frame, so regions put together equal it exactly.
    int region_x = 0, region_y = 0, region_width = 0, region_height = 0;
    struct Rect {
        int x, y, width, height;
    };
    /// The region, sizes resolved (the whole frame by default).
    Rect region() const {
        return {region_x, region_y, region_width > 0 ? region_width : width - region_x,
                region_height > 0 ? region_height : height - region_y};
    }
    int aa_samples = 1; // per axis: aa x aa samples per pixel
    int threads = 0;    // 0: all cores
    int ao_samples = 0;
    float ao_distance = 1.0f;
    int radiosity_samples = 0; // gather rays per camera-path point; 0: no radiosity
    int radiosity_depth = 2;   // diffuse bounces of a gathered path
    float radiosity_brightness = 1.0f;
    long long batch_pairs = 0;    // candidate pairs held at once per level; 0: the backend's
    long long band_samples = 0;   // camera samples shaded at once; 0: band_or()
    uint32_t passes = kAllPasses; // PassBit: the passes the frame keeps
    bool keeps(PassBit pass) const { return (passes & pass) != 0; }
    /// traversal.batch, or `auto_pairs` when it is 0 (the backend's choice).
    size_t batch_or(size_t auto_pairs) const {
        return batch_pairs > 0 ? size_t(batch_pairs) : auto_pairs;
    }
    /// band.samples, or the choice for band.samples = 0: where the exec holds host memory and
    /// every ray is traced on its own (a band's rays then meet the same tests as the frame's),
    /// samples for about kCpuBandRays rays at `rays_per_sample` each (at least one); else the
    /// whole frame (`frame_samples`).
    size_t band_or(bool host_memory, size_t frame_samples, size_t rays_per_sample) const;

    /// Explicit values win over the scene's, which win over the defaults.
    static RenderSettings resolve(const Settings& explicit_settings,
                                  const std::map<std::string, std::string>& scene_settings = {});
    /// Every key with its effective value, canonical text, in the order of setting_specs().
    static std::vector<std::pair<std::string, std::string>>
    effective(const Settings& explicit_settings,
              const std::map<std::string, std::string>& scene_settings = {});
};

/// The deepest ray hierarchy (hierarchy.depth).
constexpr int kMaxHierarchyDepth = 8;

/// band.samples = 0 on the CPU under a per-ray accel: the rays a band makes, about. A sample
/// of a scene with two lights and mirrors makes about 4 (16384 samples a band, some 8 MiB of
/// buffers); one that gathers 400 radiosity rays takes a band of 160 samples.
constexpr size_t kCpuBandRays = size_t(1) << 16;
/// traversal.batch = 0 on the CPU: 4M candidate pairs a level holds at once.
constexpr size_t kCpuBatchPairs = size_t(1) << 22;
/// traversal.batch = 0 on a device of `device_bytes` memory: 1/1024 of it, rounded down to a
/// power of two, within 4M..64M pairs. On an H200 (141 GB) 64M, where paper 003's AO frames
/// took a quarter less time than with 4M (fewer chunks, so fewer host waits; docs/
/// performance.md). The wavefront traversal's buffers take at most about 35 bytes a pair at
/// hierarchy.depth 2 (10 more a level deeper): at most some 3% of a device of 4 GiB or more.
size_t device_batch_pairs(uint64_t device_bytes);

const char* to_string(Accel a);
const char* to_string(HashMode h);
const char* to_string(SortMode s);
const char* to_string(SortAlgorithm a);
const char* to_string(Backend b);

} // namespace sheaf

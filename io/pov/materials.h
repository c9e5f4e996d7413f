// PovTexture -> core materials: pigments, colour and pigment maps, normals, texture maps and
// layers become the core's procedural textures (core/scene/pattern.h), the finish and the
// interior the Material's terms. Colours are decoded with the scene's gamma; patterns get the
// transform from Sheaf's world to their own space (through POV-Ray's mirrored z).
#pragma once

#include "io/pov/fn_compile.h"
#include "io/pov/parser.h"

#include <map>
#include <set>
#include <string>
#include <utility>

namespace sheaf::io::pov {

/// A colour's red, green and blue, as written: Sheaf computes in the scene's working space
/// (Scene::working_gamma), as POV-Ray does.
inline Vec3 rgb(const Color5& c) {
    return Vec3(float(c[0]), float(c[1]), float(c[2]));
}

/// The core pattern of `pt` in the space `eff` maps to its own (no mirror: a function's
/// pattern reads POV-Ray coordinates). Its warps are appended to `warps` (null: a pattern
/// without warps is asked for).
Pattern lower_pattern(const PovPattern& pt, const Affine& eff, std::vector<Warp>* warps,
                      const PatternDefaults& scene);

/// Sets `slot` to `value` for a scope and puts its old value back after (also when the scope
/// ends by an error).
template <class T> class ScopedValue {
  public:
    ScopedValue(T& slot, T value) : slot_(slot), old_(std::move(slot)) { slot_ = std::move(value); }
    ~ScopedValue() { slot_ = std::move(old_); }
    ScopedValue(const ScopedValue&) = delete;
    ScopedValue& operator=(const ScopedValue&) = delete;

  private:
    T& slot_;
    T old_;
};

class MaterialBuilder {
  public:
    MaterialBuilder(Parser& p, Scene& scene) : p_(p), scene_(scene), functions_(scene, *this) {}
    // Its function compiler refers back to it.
    MaterialBuilder(const MaterialBuilder&) = delete;
    MaterialBuilder& operator=(const MaterialBuilder&) = delete;

    /// The material of texture `t` (its own transforms included) with interior `in` (may be
    /// null), showing texture `inside` (may be null; POV-Ray's interior_texture) from inside.
    uint32_t material(const PovTexture& t, const PovInterior* in,
                      const PovTexture* inside = nullptr);
    /// The material that holds the atmosphere's media (Scene::atmosphere), placed in the world.
    uint32_t atmosphere(const std::vector<PovMedia>& media);
    /// The sky_sphere's pigments as one (layered) pigment; -1 when there are none.
    int32_t sky(const std::vector<std::shared_ptr<const PovPigment>>& layers, const Affine& local);
    /// The program of user function `f` (function patterns, isosurfaces); a function that
    /// cannot be compiled is an error at its place.
    int32_t function(const PovFunction& f);
    /// Pigment `pg` in a function's space (the point as the function receives it, no mirror):
    /// its index in Scene::pigments.
    int32_t function_pigment(const PovPigment& pg);
    /// Pattern `pt` placed by `local` in a function's space, its warps and pigment added to the
    /// scene.
    Pattern function_pattern(const PovPattern& pt, const Affine& local);
    /// Normal `n` placed by `eff`, its map's entries first: its index in Scene::normal_patterns.
    int32_t normal(const PovNormal& n, const Affine& eff);
    /// Whether `material` (one material() made) has patterns evaluated at uv coordinates.
    bool uses_uv(uint32_t material) const { return uv_materials_.count(material) > 0; }

  private:
    uint32_t material_in(const PovTexture& t, const PovInterior* in, const Affine& outer,
                         int depth);
    int32_t pigment(const PovPigment& pg, const Affine& eff);
    PigmentEntry entry(const PovMapEntry& e, const Affine& eff);
    /// Adds `media` to the scene, their densities placed by `space` and each medium's own
    /// transforms, as m's media.
    void add_media(Material& m, const std::vector<PovMedia>& media, const Affine& space);
    /// A pigment composing `layers` (bottom first) by their filter and transmit.
    int32_t layer_pigment(const std::vector<PigmentEntry>& layers);
    Pattern pattern(const PovPattern& pt, const Affine& eff);
    /// The scene's grid for a density_file (its voxels copied once per file).
    int32_t density_grid(const PovDensity& d);
    int32_t image(const PovImage& img, const Affine& to_pattern,
                  const std::string& colorspace = "");

    Parser& p_;
    Scene& scene_;
    std::map<std::string, uint32_t> plain_; // materials without patterns, by their values
    std::map<std::pair<uint32_t, int32_t>, uint32_t> insides_; // (front, inside) -> material
    std::map<std::string, int32_t> images_;  // image textures by file and transform
    std::map<const void*, uint32_t> voxels_; // density_file voxels by file: their first
    FnCompiler functions_;
    // While set, the patterns made are uv-mapped (Pattern::uv): inside a uv_mapping texture or
    // pigment. uv_patterns_ counts them, so material() can tell which materials have them.
    bool uv_ = false;
    // While set, the patterns made are placed in another pattern's space (a pigment_pattern's
    // pigment): their transforms map from there, with no mirror from Sheaf's world.
    bool pattern_space_ = false;
    size_t uv_patterns_ = 0;
    std::set<uint32_t> uv_materials_;
    // While a warped pigment's map entries are made: its chain (POV-Ray evaluates the entries
    // at the point its pattern warped, so they inherit its warps).
    struct WarpChain {
        Affine to_pattern;       // its Pattern::to_pattern
        std::vector<Warp> warps; // its warps, the last declared first
        Affine eff;              // its placement in POV-Ray's space
        bool uv = false;
    };
    WarpChain chain_;
};

} // namespace sheaf::io::pov

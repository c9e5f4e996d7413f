// Image textures at surface points: where a point falls in its texture (s, t) and the colour
// there. The core asks a TextureSampler for colours; the IO layer implements it with
// OpenImageIO's TextureSystem (cached, filtered, mip-mapped).
#pragma once

#include "core/math/vec3.h"

#include <cstdint>

namespace sheaf {

struct Texture;

class TextureSampler {
  public:
    virtual ~TextureSampler() = default;
    /// Scene-linear RGB of texture `index` at (s, t), repeating outside [0, 1).
    virtual Vec3 sample(uint32_t index, float s, float t) const = 0;
    /// Texture `index`'s size in pixels (0 x 0 when not known): what a bump map steps by.
    virtual void size(uint32_t index, int& width, int& height) const {
        (void)index;
        width = height = 0;
    }
};

/// (s, t) of a world-space point for a projection mapping (planar, spherical, cylindrical);
/// `uv` is what the surface itself provides, used by TextureMapping::Uv.
void texture_coordinates(const Texture& tex, Vec3 world_point, float uv_s, float uv_t, float& s,
                         float& t);

} // namespace sheaf

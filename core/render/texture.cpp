#include "core/render/texture.h"

#include "core/scene/scene.h"

#include <cmath>

namespace sheaf {

void texture_coordinates(const Texture& tex, Vec3 world_point, float uv_s, float uv_t, float& s,
                         float& t) {
    const Vec3 p = tex.transform.point(world_point);
    switch (tex.mapping) {
    case TextureMapping::Uv:
        s = uv_s, t = uv_t;
        return;
    case TextureMapping::Planar:
        s = p.x, t = p.y;
        return;
    case TextureMapping::Spherical: {
        const float r = length(p);
        s = 0.5f + std::atan2(p.x, p.z) / (2 * kPi);
        t = r > 0 ? 0.5f + std::asin(std::fmax(-1.0f, std::fmin(1.0f, p.y / r))) / kPi : 0.5f;
        return;
    }
    case TextureMapping::Cylindrical:
        s = 0.5f + std::atan2(p.x, p.z) / (2 * kPi);
        t = p.y;
        return;
    }
}

} // namespace sheaf

#include "core/texture/texture.h"

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
    case TextureMapping::Torus: {
        // POV-Ray's map_type 5: s around y as the cylindrical mapping's; t the angle around
        // the unit circle of the xz plane (major radius 1, whatever the torus's), starting
        // inside the ring and turning down through its outside.
        s = 0.5f + std::atan2(p.x, p.z) / (2 * kPi);
        const float d = std::sqrt(p.x * p.x + p.z * p.z) - 1.0f, r = std::sqrt(d * d + p.y * p.y);
        const float phi = r > 0 ? std::acos(std::fmax(-1.0f, std::fmin(1.0f, -d / r))) : 0.0f;
        t = (p.y > 0 ? 2 * kPi - phi : phi) / (2 * kPi);
        return;
    }
    }
}

} // namespace sheaf

// A shaded surface point: a primary hit from the G-buffer, or what a reflection, refraction or
// radiosity gather ray found.
#pragma once

#include "core/math/vec3.h"

#include <cstdint>

namespace sheaf {

struct SurfaceHit {
    uint32_t pixel = 0;
    uint32_t prim = 0;
    uint32_t material = 0;
    Vec3 position;
    Vec3 normal;       // shading normal, turned to face the incoming ray
    Vec3 geo_normal;   // geometric normal, turned to face the incoming ray
    Vec3 incoming;     // unit direction of the ray that found the point
    Vec3 throughput; // share of this point's radiance that reaches the pixel
    Vec3 albedo;     // the material's colour here (its pigment, or colour times texture)
    float filter = 0;   // share of light passing through, tinted by albedo
    float transmit = 0; // share of light passing through untinted
    float t = 0;       // distance along the incoming ray
    bool front = true; // the ray arrived on the side the winding calls outside
    uint16_t light_group = 0; // the material's (Material::light_group): which lights reach it
    /// Radiosity: 0 on camera, reflection and refraction paths; on a gathered path, the
    /// diffuse bounces so far (low 8 bits) and the gather sample the path began with (above).
    uint32_t gather = 0;
};

} // namespace sheaf

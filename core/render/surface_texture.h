// Procedural textures at surface points: the material a texture map picks, the pigment's
// colour, filter and transmit, the tilted shading normal, and the sky seen along a direction.
#pragma once

#include "core/scene/prepared_scene.h"

namespace sheaf {

/// A POV-Ray colour: linear RGB, filter (light passes tinted by rgb), transmit (passes as is).
struct SurfaceColor {
    Vec3 rgb;
    float filter = 0, transmit = 0;
};

/// Follows material switches (texture maps) from `material` at world point p.
uint32_t resolve_material(const PreparedScene& scene, uint32_t material, Vec3 p);

/// Pigment `pigment` at world point p; (uv_s, uv_t) are the surface's texture coordinates,
/// used by image pigments with uv mapping.
SurfaceColor evaluate_pigment(const PreparedScene& scene, uint32_t pigment, Vec3 p, float uv_s,
                              float uv_t);

/// The unit shading normal n tilted by normal pattern `normal` at world point p.
Vec3 perturb_normal(const PreparedScene& scene, uint32_t normal, Vec3 p, Vec3 n);

/// What a ray leaving the scene along unit `dir` sees: the sky pigment or the background.
Vec3 sky_color(const PreparedScene& scene, Vec3 dir);

} // namespace sheaf

// Secondary ray generation from a wave of surface hits: shadow rays (one per light per lit
// point, origin moved to the light as in paper 000 section 3.3.2), ambient-occlusion rays
// (cosine-weighted, Halton, paper 003) and reflection/refraction rays (Fresnel, Snell).
// Every generator counts, scans and fills, so the ray order is the same on every run.
#pragma once

#include "core/rays/ray_batch.h"
#include "core/render/surface.h"
#include "core/scene/prepared_scene.h"

#include <vector>

namespace sheaf {

struct RayGenParams {
    float epsilon = 1e-4f;   // offset from surfaces, in scene units
    float far = 1e4f;        // beyond the scene: where parallel lights' shadow rays start
    int ao_samples = 0;
    float ao_distance = 1.0f;
    float min_weight = 1e-3f; // reflection/refraction rays carrying less are not traced
};

/// Radical inverse in base b of index i (the Halton sequence's coordinate).
float radical_inverse(uint32_t i, uint32_t base);

/// True when light l lights hit h at all (the surface faces it, a spot reaches it).
bool lights_point(const Light& l, const SurfaceHit& h, const RayGenParams& p);

/// Shadow rays for every lit (hit, light) pair of the lights that cast shadows.
void generate_shadow_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& out);
/// `ao_samples` rays per hit; each hit's Halton points start at its pixel index times the count.
void generate_ao_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                      const RayGenParams& p, RayBatch& out);
/// Reflection rays go to `refl`, refraction rays to `refr`.
void generate_bounce_rays(const PreparedScene& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& refl, RayBatch& refr);

} // namespace sheaf

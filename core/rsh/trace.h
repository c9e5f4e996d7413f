// What tracing a batch of rays gives (the tracers: core/frame/wavefront_tracer.h and its host
// traversal, core/rsh/cpu_traversal.h): packed closest hits, occlusion, the light a shadow
// ray keeps through transparent surfaces, each ray's exact tests, and the statistics rows of
// the counts (tests.<type>.objects, level<k>, final, total).
#pragma once

#include "core/base/memory.h"
#include "core/rays/ray_batch.h"
#include "core/rsh/cull_units.h"
#include "core/rsh/test_count.h"
#include "core/scene/prepared_scene.h"
#include "core/settings/settings.h"
#include "core/stats/stats.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace sheaf {

constexpr uint64_t kNoHit = ~uint64_t(0);

/// Closest hits packed as (float bits of t) << 32 | primitive: the minimum is the nearest
/// hit, and equal distances go to the lower primitive id, whatever the order of the tests.
SHEAF_HD_INLINE uint64_t pack_hit(float t, uint32_t prim) {
    uint32_t u;
    memcpy(&u, &t, sizeof u);
    return (uint64_t(u) << 32) | prim;
}
SHEAF_HD_INLINE float hit_t(uint64_t h) {
    const uint32_t u = uint32_t(h >> 32);
    float t;
    memcpy(&t, &u, sizeof t);
    return t;
}
SHEAF_HD_INLINE uint32_t hit_prim(uint64_t h) {
    return uint32_t(h & 0xFFFFFFFFu);
}

struct TraceResult {
    std::vector<uint64_t> closest; // reflection and refraction rays: packed hit or kNoHit
    std::vector<uint8_t> occluded; // shadow and AO rays: 1 when something opaque is in the way
    /// Shadow rays: per ray and channel, the light kept through transparent surfaces as
    /// -log2 in fixed point (core/shading/shadow_pass.h); empty when none was crossed.
    std::vector<uint64_t> pass_log;
    /// The light shadow ray i keeps, per channel (1 when nothing transparent was crossed).
    Vec3 pass(size_t i) const;
    std::vector<uint32_t> tests;   // exact ray-primitive tests each ray took part in
};

/// The statistics rows of one traced batch from its counts: `prefix` ("tests.shadow.")
/// objects.* (when culling objects; not in the total, as in the paper), level<k>.* for k from
/// the top (levels[k]) down to 1, nodes.* (accel=bvh: ray-box tests, when `nodes` is given),
/// final.*, and total.
void add_test_counts(Stats& stats, const std::string& prefix, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final, const TestCount* nodes = nullptr);

/// Adds a batch's counts to the rows add_test_counts wrote (objects.* when culling objects,
/// level<k>.* for each levels[k], k >= 1, final.* and total): for counts read after the batch,
/// the rows written first with the counts zero, so the keys keep their order.
void add_late_counts(Stats& stats, const std::string& prefix, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final, const TestCount* nodes = nullptr);

/// Whether some primitive of `scene` may let a shadow ray through (its pass log is kept).
bool shadows_pass_surfaces(const PreparedScene& scene);

} // namespace sheaf

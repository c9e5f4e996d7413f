#include "core/rays/ray_gen.h"

#include "core/base/error.h"
#include "core/base/parallel.h"
#include "core/sort/radix_sort.h"

#include <algorithm>
#include <string>

namespace sheaf {

namespace {

// Calls count(i) for every hit, scans the counts, then fill(i, first_slot): the output order
// is hit order, then the order each hit emits in, whatever the thread schedule.
template <class Count, class Fill>
void emit(size_t hits, RayBatch& out, const Count& count, const Fill& fill) {
    std::vector<uint32_t> offset(hits);
    parallel_for(
        "raygen.count", hits, [&](size_t i) { offset[i] = count(i); }, 1024);
    const uint32_t total = exclusive_scan_inplace(offset);
    out.resize(total);
    parallel_for(
        "raygen.fill", hits, [&](size_t i) { fill(i, offset[i]); }, 1024);
}

// As emit, for elements that give at most one ray each (shadow rays: one per (hit, light)),
// which can be many times the hits: a byte per element says whether it gives its ray, blocks
// of elements are counted, scanned and filled in element order, so the rays come out in the
// order emit gives them, and `fill` runs only where `gives` said yes.
template <class Gives, class Fill>
void emit_at_most_one(size_t elements, RayBatch& out, const Gives& gives, const Fill& fill) {
    constexpr size_t kBlock = 4096;
    const size_t blocks = (elements + kBlock - 1) / kBlock;
    std::vector<uint8_t> on(elements);
    std::vector<uint32_t> first(blocks);
    parallel_for(
        "raygen.count", blocks,
        [&](size_t b) {
            const size_t end = std::min(elements, (b + 1) * kBlock);
            uint32_t n = 0;
            for (size_t e = b * kBlock; e < end; ++e) n += on[e] = gives(e) ? 1 : 0;
            first[b] = n;
        },
        1);
    const uint32_t total = exclusive_scan_inplace(first);
    out.resize(total);
    parallel_for(
        "raygen.fill", blocks,
        [&](size_t b) {
            const size_t end = std::min(elements, (b + 1) * kBlock);
            uint32_t slot = first[b];
            for (size_t e = b * kBlock; e < end; ++e)
                if (on[e]) fill(e, slot++);
        },
        1);
}

RaySlots slots(RayBatch& b) {
    return {b.rays.data(), b.pixel.data(), b.weight.data(), b.light.data()};
}

} // namespace

void check_batch_bound(uint64_t most, RayType type) {
    if (most <= 0xFFFFFFFFull) return;
    throw OutOfMemory(std::string("a wave of up to ") + std::to_string(most) + " " +
                      ray_type_name(type) +
                      " rays: Sheaf traces at most 4294967295 rays in one batch; a smaller "
                      "frame, fewer aa.samples, ao.samples or radiosity.samples need fewer");
}

ShadowLayout shadow_layout(const SceneView& scene, const std::vector<SurfaceHit>& hits) {
    ShadowLayout l;
    l.hits = hits.size();
    while (l.camera < l.hits && hits[l.camera].gather == 0) ++l.camera;
    l.lights = scene.light_count;
    return l;
}

void generate_shadow_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& out) {
    const ShadowLayout layout = shadow_layout(scene, hits);
    check_batch_bound(layout.elements(), RayType::Shadow);
    emit_at_most_one(
        layout.elements(), out,
        [&](size_t e) { return shadow_ray_count(scene, hits.data(), layout, e, p) != 0; },
        [&](size_t e, uint32_t slot) {
            shadow_ray_write(scene, hits.data(), layout, e, slot, p, slots(out));
        });
}

void generate_ao_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                      const RayGenParams& p, RayBatch& out) {
    const uint32_t n = uint32_t(p.ao_samples);
    if (n == 0) {
        out.resize(0);
        return;
    }
    check_batch_bound(uint64_t(hits.size()) * n, RayType::Ao);
    emit(
        hits.size(), out, [&](size_t) { return n; },
        [&](size_t i, uint32_t slot) { ao_ray_fill(scene, hits[i], slot, p, slots(out)); });
}

void generate_bounce_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                          const RayGenParams& p, RayBatch& refl, RayBatch& refr) {
    std::vector<BounceSplit> splits(hits.size());
    parallel_for(
        "raygen.split", hits.size(), [&](size_t i) { splits[i] = bounce_split(scene, hits[i]); },
        1024);
    emit(
        hits.size(), refl, [&](size_t i) { return reflect_ray_count(splits[i], p); },
        [&](size_t i, uint32_t slot) { reflect_ray_fill(hits[i], splits[i], slot, p, slots(refl)); });
    emit(
        hits.size(), refr, [&](size_t i) { return refract_ray_count(splits[i], p); },
        [&](size_t i, uint32_t slot) { refract_ray_fill(hits[i], splits[i], slot, p, slots(refr)); });
}

void generate_diffuse_rays(const SceneView& scene, const std::vector<SurfaceHit>& hits,
                           const RayGenParams& p, RayBatch& out) {
    check_batch_bound(uint64_t(hits.size()) * uint64_t(std::max(p.radiosity_samples, 1)),
                      RayType::Diffuse);
    std::vector<uint32_t> count(hits.size());
    parallel_for(
        "raygen.diffuse_count", hits.size(),
        [&](size_t i) { count[i] = diffuse_ray_count(scene, hits[i], p); }, 1024);
    emit(
        hits.size(), out, [&](size_t i) { return count[i]; },
        [&](size_t i, uint32_t slot) {
            diffuse_ray_fill(scene, hits[i], count[i], slot, p, slots(out));
        });
}

} // namespace sheaf

// accel=bvh's per-ray traversal compiled for AVX2 (core/accel/bvh_trace.h): the same body as
// bvh_trace_from, its eight slab tests of a node one vector operation instead of two. Only
// this function carries the target; what it does not inline (the analytic shapes' exact
// tests) stays the portable build's, so the library runs on any x86-64 processor and takes
// this path where cpuid reports AVX2. No fused multiply-add: the hits are bit for bit the
// portable path's (Trace.Avx2WalkFindsWhatTheSseWalkFinds).
#include "core/accel/bvh_trace.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace sheaf {

#if SHEAF_BVH_AVX2
namespace {

bool avx2_wanted() {
    const char* simd = std::getenv("SHEAF_SIMD");
    if (simd && std::strcmp(simd, "sse") == 0) return false;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
}

std::atomic<bool>& avx2_flag() {
    static std::atomic<bool> on{avx2_wanted()};
    return on;
}

} // namespace

bool bvh_avx2() {
    return avx2_flag().load(std::memory_order_relaxed);
}

void bvh_set_avx2(bool on) {
    avx2_flag().store(on && avx2_wanted());
}

__attribute__((target("avx2,popcnt"))) BvhCounts
bvh_trace_from_avx2(bool any, const BvhView& bvh, const SceneView& scene, const Ray& r, uint32_t i,
                    uint32_t start, bool unbounded, bool shared, bool shadow, uint8_t skip,
                    const HitSinks& out) {
    return any ? bvh_trace_body<true, true>(bvh, scene, r, i, start, unbounded, shared, shadow,
                                            skip, out)
               : bvh_trace_body<false, true>(bvh, scene, r, i, start, unbounded, shared, shadow,
                                             skip, out);
}
#endif

} // namespace sheaf

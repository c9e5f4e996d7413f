// The per-thread stack the device code needs for a scene. csg_spans recurses once per level
// of CSG nesting (ptxas -v: 7,048 bytes a level on sm_80 and sm_90, 7,080 on sm_90 since
// shapes carry a poly index; plus 1,952 (sm_90) or 1,960 (sm_80) under a clipped_by: about
// 9,000 of the 10 KiB allowed), and the shading, pigment and pattern code needs a base of its
// own (the largest tracing kernel's frame is 2,704 bytes on both, 2,736 on sm_90 with the
// ground fog, 2,752 with glyphs, 2,768 with solids of revolution; nested pigments 328 to 344
// bytes a level; the out-of-line poly_spans (1,752 bytes on sm_90), superellipsoid_spans (584),
// glyph_spans with glyph_pieces (296 + 1,448) and revolution_spans with revolution_pieces
// (296 + 2,328) are on the stack once, at the leaf; csg_spans stays at 7,064 to 7,080 a level).
// A lone lathe: 2,768 + 7,064 + 2,624 = 12,456 bytes, so the base is 13 KiB. The device
// reserves the
// stack for every resident thread (about 270,000 on an H100), so it is capped; a scene nested
// more deeply renders on the CPU (backend=auto) or is an error (backend=cuda).
#pragma once

#include "core/scene/prepared_scene.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sheaf {

constexpr size_t kDeviceStackBase = size_t(13) << 10;
constexpr size_t kDeviceStackPerCsgLevel = size_t(10) << 10;
constexpr size_t kDeviceStackCap = size_t(96) << 10;
// Media (core/render/media.h) walk their containers' spans while a hit is shaded: three span
// lists (772 bytes each), the step loop and a density pigment on top of the shading frame,
// their csg_spans levels counted as above. Estimated from those sizes, not yet by ptxas.
constexpr size_t kDeviceStackMedia = size_t(4) << 10;
// A julia fractal's march (core/geometry/julia.h) keeps one point's iterates at the leaf: an
// orbit of 65 x 4 doubles (2,080 bytes) and the span arrays, beside csg_spans' level.
// Estimated from those sizes, not yet by ptxas.
constexpr size_t kDeviceStackJulia = size_t(3) << 10;

/// The deepest nesting of CSG operations below any analytic root (a lone shape: 0). Each
/// node's height is computed once (roots may share subtrees).
inline int csg_nesting(const PreparedScene& s) {
    std::vector<int> height(s.csg.size(), -1);
    std::vector<uint32_t> pending;
    int deepest = 0;
    for (uint32_t root : s.analytic_root) {
        pending.push_back(root);
        while (!pending.empty()) {
            const uint32_t node = pending.back();
            const PreparedCsgNode& n = s.csg[node];
            if (height[node] >= 0) {
                pending.pop_back();
                continue;
            }
            int h = 0;
            bool ready = true;
            if (n.op != CsgOp::Leaf)
                for (uint32_t c = 0; c < n.count; ++c) {
                    const uint32_t child = s.csg_children[n.first + c];
                    if (height[child] < 0) {
                        ready = false;
                        pending.push_back(child);
                    } else {
                        h = std::max(h, height[child] + 1);
                    }
                }
            if (!ready) {
                if (pending.size() > s.csg_children.size() + 1) return 1 << 20; // only a cycle
                continue;
            }
            height[node] = n.op == CsgOp::Leaf ? 0 : std::max(h, 1);
            pending.pop_back();
        }
        deepest = std::max(deepest, height[root]);
    }
    return deepest;
}

/// The stack the device code needs for `s`, in bytes (may exceed kDeviceStackCap).
inline size_t device_stack_bytes(const PreparedScene& s) {
    return kDeviceStackBase + size_t(csg_nesting(s)) * kDeviceStackPerCsgLevel +
           (s.media_containers.empty() ? 0 : kDeviceStackMedia) +
           (s.julias.empty() ? 0 : kDeviceStackJulia);
}

} // namespace sheaf

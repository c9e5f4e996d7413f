// The per-thread stack the device code needs for a scene, from ptxas -v on sm_80 and sm_90
// (CUDA 13) and the module's call graph (gpu/ptx_report.py prints both). csg_spans recurses
// once per level of CSG nesting: 7,176 bytes a level, plus 1,960 under a clipped_by, so 10 KiB
// a level. Everything else is on the stack once: the deepest chain is the G-buffer kernel's
// frame (4,704 bytes; the media's span lists are in the shading kernels' frames) + one
// csg_spans level + the largest out-of-line leaf (a julia fractal's march, 280 + 2,416; a
// lathe's 296 + 2,328): 14,576 bytes (14,896 since the G-buffer kernel's frame grew to 5,024
// with the media segment it writes), so the base is 16 KiB. The pattern, pigment and normal
// code is called, not inlined (pigments nest at 128 bytes a level), far below that.
// A scene whose media (a container's or the atmosphere's) scatter the light of a light that
// casts shadows also runs the media light kernel (core/shading/media_light.h: a media walk
// whose steps walk the media again towards each light): its frame is 7,192 bytes on sm_90
// with the atmosphere and rainbows (6,944 before), so its chain is 17,312 bytes, and such
// scenes (PreparedScene::media_scatter_light) got 2 KiB more (3 KiB since; below). The G-buffer
// kernel's frame is 5,000 bytes with them (the atmosphere's part of the media walk shares the
// containers' loop and span list: a second list took it to 6,608). A function pattern whose program
// reads a scene pigment (core/shading/surface_texture.h's FnSceneContext) evaluates that pigment,
// which may hold another such pattern: each nested level is the program's frame (728 bytes), the
// context's (160), the pigment's and an entry's (112 + 16) and pattern_value's (96), 1,112 bytes,
// so a level gets 2 KiB (fn_pigment_nesting counts the levels). The media's walk over their solid
// objects (leave_solids, core/shading/media.h: a BVH walk's stack of kBvhStack entries, 620 bytes,
// and the container spans' owners, 128) adds about 850 bytes to each media walk of a chain,
// estimated from the arrays (not yet measured with ptxas): the G-buffer kernel's chain to about
// 15,750 bytes, within the base, and the media light kernel's, which walks twice, to about 19,000,
// so such scenes get 3 KiB more. The device reserves the stack for every resident thread (about
// 270,000 on an H100), so it is capped; a scene nested more deeply renders on the CPU
// (backend=auto) or is an error (backend=cuda).
#pragma once

#include "core/scene/prepared_scene.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace sheaf {

constexpr size_t kDeviceStackBase = size_t(16) << 10;
constexpr size_t kDeviceStackPerCsgLevel = size_t(10) << 10;
constexpr size_t kDeviceStackCap = size_t(96) << 10;
constexpr size_t kDeviceStackMediaLight = size_t(3) << 10;
constexpr size_t kDeviceStackPerFnLevel = size_t(2) << 10;

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

/// How many times, nested, a pigment's evaluation may pass through a function program that
/// reads a scene pigment (a pigment function, core/shading/surface_texture.h's FnSceneContext)
/// or a pigment pattern: 0 when no program does. At most kFnNestingLimit (the evaluator's
/// depth limit stops deeper chains, and tables that name each other).
constexpr int kFnNestingLimit = 16;
inline int fn_pigment_nesting(const PreparedScene& s) {
    // below[p]: the crossings under pigment p (-1: not yet known, -2: being computed).
    std::vector<int> below(s.pigments.size(), -1);
    std::vector<int> program_below(s.fn_programs.size(), -1);
    std::function<int(int32_t, int)> pigment;
    std::function<int(const Pattern&, int)> pattern;
    auto program = [&](int32_t pg, int depth) {
        if (pg < 0 || size_t(pg) >= s.fn_programs.size()) return 0;
        if (program_below[size_t(pg)] >= 0) return program_below[size_t(pg)];
        const FnProgram& f = s.fn_programs[size_t(pg)];
        int most = 0;
        for (uint32_t i = f.first; i < f.first + f.count && i < s.fn_code.size(); ++i) {
            const FnInstr& in = s.fn_code[i];
            if (in.op == FnOp::Pigment && in.arg < s.fn_pigments.size() &&
                s.fn_pigments[in.arg].scene_pigment >= 0)
                most = std::max(most, 1 + pigment(s.fn_pigments[in.arg].scene_pigment, depth + 1));
            if (in.op == FnOp::Pattern && in.arg < s.fn_patterns.size())
                most = std::max(most, 1 + pattern(s.fn_patterns[in.arg], depth + 1));
        }
        return program_below[size_t(pg)] = std::min(most, kFnNestingLimit);
    };
    pattern = [&](const Pattern& pt, int depth) {
        if (pt.kind == PatternKind::PigmentPattern) return pigment(pt.pigment, depth);
        if (pt.kind == PatternKind::Function) return program(pt.program, depth);
        return 0;
    };
    pigment = [&](int32_t pg, int depth) {
        if (pg < 0 || size_t(pg) >= s.pigments.size() || depth > kFnNestingLimit) return 0;
        int& b = below[size_t(pg)];
        if (b >= 0) return b;
        if (b == -2) return kFnNestingLimit; // a cycle: as deep as the evaluator goes
        b = -2;
        const Pigment& p = s.pigments[size_t(pg)];
        int most = p.solid ? 0 : pattern(p.pattern, depth);
        for (uint32_t i = p.first; i < p.first + p.count && i < s.pigment_entries.size(); ++i)
            most = std::max(most, pigment(s.pigment_entries[i].pigment, depth));
        return b = std::min(most, kFnNestingLimit);
    };
    int most = 0;
    for (size_t pg = 0; pg < s.fn_programs.size(); ++pg)
        most = std::max(most, program(int32_t(pg), 0));
    return most;
}

/// The stack the device code needs for `s`, in bytes (may exceed kDeviceStackCap).
inline size_t device_stack_bytes(const PreparedScene& s) {
    return kDeviceStackBase + size_t(csg_nesting(s)) * kDeviceStackPerCsgLevel +
           size_t(fn_pigment_nesting(s)) * kDeviceStackPerFnLevel +
           (s.media_scatter_light() ? kDeviceStackMediaLight : 0);
}

} // namespace sheaf

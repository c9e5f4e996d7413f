// Checking a shape's spans along a ray against a reference inside test (test code only).
#pragma once

#include "core/geometry/shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sheaf::test {

/// A ray from `o` along `d`, the whole line ahead of it.
inline Ray ray_from(Vec3 o, Vec3 d) {
    Ray r;
    r.origin = o, r.dir = d, r.tmin = 0, r.tmax = 1e30f;
    return r;
}

/// Checks spans sp[0..n) of ray `l`: in order, and, sampled every 0.02 over [0, t_end]
/// away from their ends (2e-3), exactly where `inside(point)` holds. Returns the samples
/// checked; 0 when n is kMaxShapeSpans (more pieces may have been left out); -1 at the first
/// disagreement, reported with `what`.
template <class Inside>
int check_spans(const Span* sp, int n, const Ray& l, Inside&& inside, float t_end,
                const std::string& what) {
    std::vector<float> ends;
    for (int s = 0; s < n; ++s) {
        EXPECT_LE(sp[s].t0, sp[s].t1) << what;
        if (s > 0) EXPECT_LE(sp[s - 1].t1, sp[s].t0) << what;
        ends.push_back(sp[s].t0), ends.push_back(sp[s].t1);
    }
    if (n == kMaxShapeSpans) return 0;
    int checked = 0;
    for (float t = 0; t <= t_end; t += 0.02f) {
        bool near_end = false;
        for (float e : ends) near_end = near_end || std::fabs(e - t) < 2e-3f;
        if (near_end) continue;
        bool in_span = false;
        for (int s = 0; s < n; ++s) in_span = in_span || (sp[s].t0 < t && t < sp[s].t1);
        const bool want = inside(ray_at(l, t));
        EXPECT_EQ(in_span, want) << what << " at t " << t << " (" << n << " spans)";
        if (in_span != want) return -1;
        ++checked;
    }
    return checked;
}

} // namespace sheaf::test

// Constructive solid geometry on ray spans (Roth): each leaf gives the spans of the ray inside
// its shape; operations combine sorted span lists. An object's hit is the first span end inside
// the ray's (tmin, tmax). POV-Ray's `union` is evaluated like `merge` here (the outer surface);
// the two differ only in the inner surfaces seen through transparent objects.
#pragma once

#include "core/geometry/shape.h"

#include <cfloat>
#include <cstdint>

namespace sheaf {

struct CsgEnd {
    float t;
    uint32_t leaf; // index of the placed shape whose surface this is
    Vec3 n_local;  // outward normal of that shape, in its local space
    bool flip;     // the surface faces the other way in this solid (inverse, difference)
};

struct CsgSpan {
    CsgEnd a, b;
};

constexpr int kMaxCsgSpans = 16;

struct SpanList {
    int n = 0;
    CsgSpan s[kMaxCsgSpans];
    SHEAF_HD SpanList() {}
    // Copies the n spans held, not the whole array: CSG trees copy lists at every node.
    SHEAF_HD SpanList(const SpanList& o) : n(o.n) {
        for (int i = 0; i < n; ++i) s[i] = o.s[i];
    }
    SHEAF_HD SpanList& operator=(const SpanList& o) {
        n = o.n;
        for (int i = 0; i < n; ++i) s[i] = o.s[i];
        return *this;
    }
    SHEAF_HD void push(const CsgSpan& span) {
        if (n < kMaxCsgSpans) s[n++] = span;
    }
};

SHEAF_HD_INLINE SpanList span_complement(const SpanList& a) {
    SpanList out;
    CsgEnd lo{-FLT_MAX, 0xFFFFFFFFu, Vec3(0, 0, 1), false};
    for (int i = 0; i < a.n; ++i) {
        CsgEnd start = a.s[i].a, end = a.s[i].b;
        start.flip = !start.flip, end.flip = !end.flip;
        if (start.t > lo.t || (start.t == lo.t && lo.t > -FLT_MAX)) out.push({lo, start});
        lo = end;
    }
    if (lo.t < FLT_MAX) out.push({lo, CsgEnd{FLT_MAX, 0xFFFFFFFFu, Vec3(0, 0, 1), false}});
    return out;
}

SHEAF_HD_INLINE SpanList span_union(const SpanList& a, const SpanList& b) {
    SpanList out;
    int i = 0, j = 0;
    while (i < a.n || j < b.n) {
        const CsgSpan next =
            (j >= b.n || (i < a.n && a.s[i].a.t <= b.s[j].a.t)) ? a.s[i++] : b.s[j++];
        if (out.n > 0 && next.a.t <= out.s[out.n - 1].b.t) {
            // Overlapping or touching: extend the last span; zero-length surfaces inside vanish.
            if (next.b.t > out.s[out.n - 1].b.t) out.s[out.n - 1].b = next.b;
        } else {
            out.push(next);
        }
    }
    return out;
}

SHEAF_HD_INLINE SpanList span_intersection(const SpanList& a, const SpanList& b) {
    SpanList out;
    int i = 0, j = 0;
    while (i < a.n && j < b.n) {
        const CsgSpan& x = a.s[i];
        const CsgSpan& y = b.s[j];
        const CsgEnd lo = x.a.t >= y.a.t ? x.a : y.a;
        const CsgEnd hi = x.b.t <= y.b.t ? x.b : y.b;
        if (lo.t <= hi.t) out.push({lo, hi});
        if (x.b.t < y.b.t)
            ++i;
        else
            ++j;
    }
    return out;
}

SHEAF_HD_INLINE SpanList span_difference(const SpanList& a, const SpanList& b) {
    return span_intersection(a, span_complement(b));
}

} // namespace sheaf

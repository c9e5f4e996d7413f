// Constructive solid geometry on ray spans (Roth): each leaf gives the spans of the ray inside
// its shape; operations combine sorted span lists. An object's hit is the first span end inside
// the ray's (tmin, tmax). POV-Ray's `union` is evaluated like `merge` here (the outer surface);
// the two differ only in the inner surfaces seen through transparent objects.
#pragma once

#include "core/geometry/shape.h"

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
    void push(const CsgSpan& span) {
        if (n < kMaxCsgSpans) s[n++] = span;
    }
};

SpanList span_complement(const SpanList& a);
SpanList span_union(const SpanList& a, const SpanList& b);
SpanList span_intersection(const SpanList& a, const SpanList& b);
SpanList span_difference(const SpanList& a, const SpanList& b);

} // namespace sheaf

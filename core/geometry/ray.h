// A ray with its valid parameter interval.
#pragma once

#include "core/math/vec3.h"

namespace sheaf {

struct Ray {
    Vec3 origin;
    float tmin = 0;
    Vec3 dir; // unit length
    float tmax = 0;
};

SHEAF_HD_INLINE Vec3 ray_at(const Ray& r, float t) {
    return r.origin + r.dir * t;
}

} // namespace sheaf

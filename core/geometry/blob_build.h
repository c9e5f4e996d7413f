// Building a blob (core/geometry/blob.h) from its components as POV-Ray defines them: shared
// by the POV-Ray and XML readers. Host only.
#pragma once

#include "core/geometry/blob.h"
#include "core/math/affine.h"
#include "core/math/vec3.h"

#include <stdexcept>

namespace sheaf {

/// A component the numbers cannot make (a radius that is not positive, a value that is not
/// finite, a placement that flattens it).
struct BlobError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Adds a sphere component: its field `strength` at `centre`, falling to zero at `radius`,
/// then moved by `placement` (the component's own transforms).
void add_blob_sphere(BlobModel& b, Vec3 centre, float radius, float strength,
                     const Affine& placement);

/// Adds a cylinder component: the segment from `base` to `end` with hemispherical ends, of
/// `radius` and `strength`, then moved by `placement`. A segment of no length is a sphere.
void add_blob_cylinder(BlobModel& b, Vec3 base, Vec3 end, float radius, float strength,
                       const Affine& placement);

/// The BlobRef bound: a sphere holding every component of positive strength (nothing else can
/// be inside); radius 0 when there is none.
void blob_bound(const BlobModel& b, float bound[4]);

/// The box POV-Ray gives a blob (min_extent, max_extent): around the bounding spheres of its
/// components of positive strength; false when there is none.
bool blob_box(const BlobModel& b, Vec3& lo, Vec3& hi);

} // namespace sheaf

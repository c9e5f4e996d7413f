// Building a solid of revolution's profile (core/geometry/revolution.h) from points, as
// POV-Ray defines its lathe and sor: shared by the POV-Ray and XML readers. Host only.
#pragma once

#include "core/geometry/revolution.h"
#include "core/math/vec3.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace sheaf {

/// A lathe's spline: linear through the points; quadratic from the second point, the first
/// only steering; cubic (Catmull-Rom) from the second point to the last but one; bezier four
/// points a segment.
enum class LatheSpline { Linear, Quadratic, Cubic, Bezier };

/// A profile the points cannot make: `point` is the index of the point at fault, or -1 when
/// it is their number.
struct ProfileError : std::runtime_error {
    ProfileError(int at, const std::string& what) : std::runtime_error(what), point(at) {}
    int point;
};

/// The fewest points a lathe with `spline` takes (2, 3, 4, 4).
int lathe_min_points(LatheSpline spline);

/// A lathe's profile through `p` (x: the radius, y: the height). `solid`: whether it encloses
/// a solid (its curve closes, or runs from the axis to the axis); otherwise it is a surface.
/// Throws ProfileError: too few points, a bezier count not a multiple of 4, a negative radius
/// on the curve, a point that is not finite.
RevolutionProfile lathe_profile(const std::vector<Vec3>& p, LatheSpline spline, bool& solid);

/// A sor's profile through `p` (x: the radius, y: the height): the radius squared a cubic in
/// the height from the second point to the last but one, its slopes there set by the
/// neighbours; closed by flat caps unless `open`. Throws ProfileError: fewer than 4 points, a
/// negative radius, heights that do not rise, end points level with their neighbours' ones.
RevolutionProfile sor_profile(const std::vector<Vec3>& p, bool open);

} // namespace sheaf

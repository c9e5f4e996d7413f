// Bounds of a quadric solid cut by a box, as POV-Ray bounds a quadric inside an intersection:
// shapes.inc's Hyperboloid_Y, Cylinder_X, Cone_Z ... are unbounded, and the planes cut from
// them bound only one axis each, so without this the box of `intersection { Hyperboloid_Y
// plane { y, 5 } plane { -y, -2 } }` is infinite across and every ray tests the object.
// Host only (scene preparation).
#pragma once

#include "core/geometry/poly.h"
#include "core/geometry/world_box.h"
#include "core/math/affine.h"

namespace sheaf {

/// A quadric in world coordinates: the solid where p^T q p + b . p + c < 0.
struct WorldQuadric {
    double q[3][3]; // symmetric
    double b[3];
    double c;
};

/// The world quadric of polynomial p (the solid P < 0, in the local space `to_local` maps the
/// world into); false when p has a term of degree above 2.
bool world_quadric(const PolyCoeffs& p, const Affine& to_local, WorldQuadric& out);

/// Narrows box b (whose solid is known to lie in it) to where the quadric's solid can meet it:
/// along each axis whose square has a positive coefficient, the range of x where
/// q_ii x^2 + L x + R <= 0 for some L and R the other axes' ranges allow. Conservative:
/// never drops a point of the solid inside b. Infinite sides stay where nothing bounds them.
void narrow_by_quadric(const WorldQuadric& w, WorldBox& b);

} // namespace sheaf

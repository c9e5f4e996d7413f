// Exact ray tests of analytic primitives (a shape or a CSG tree) of a prepared scene.
#pragma once

#include "core/geometry/csg.h"
#include "core/geometry/sphere.h"
#include "core/scene/prepared_scene.h"

namespace sheaf {

struct AnalyticHit {
    float t = 0;
    uint32_t leaf = 0; // placed shape of the surface hit
    Vec3 normal;       // world-space, pointing out of the solid
};

/// The first surface of analytic primitive `index` (0-based among the analytic ones) along the
/// ray inside (tmin, tmax). Deterministic: the same ray gives the same t on every accel mode.
bool analytic_first_hit(const PreparedScene& scene, uint32_t index, const Ray& ray,
                        AnalyticHit& hit);

/// The spans of the ray inside CSG node `node`.
SpanList csg_spans(const PreparedScene& scene, uint32_t node, const Ray& ray);

/// A world-space sphere holding the node's solid; radius +inf when unbounded (planes,
/// `inverse`), so the node is a candidate for every ray.
Sphere csg_bound(const PreparedScene& scene, uint32_t node);

/// Placed shape of a leaf: world <-> local transforms from the leaf's world transform.
PlacedShape place_shape(const Shape& shape, const Affine& local_to_world);

} // namespace sheaf

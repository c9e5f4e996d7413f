// The coarse test of the ray-space hierarchy: can any ray of a node (origins inside a sphere,
// directions inside a cone) reach a primitive's bounding sphere? Paper 000 eq. (9).
#pragma once

#include "core/geometry/cone.h"
#include "core/geometry/sphere.h"
#include "core/math/hd_math.h"

namespace sheaf {

/// A hierarchy node prepared for the test: the sphere, the cone, and the cone's tangent and
/// inverse cosine computed once at build time.
struct RayNode {
    Vec3 center;
    float radius = 0;
    Vec3 axis;
    float angle = 0;
    float tan_angle = 0;
    float inv_cos_angle = 1;
    /// How far from `center` any point of the node's rays lies (origins plus lengths); +inf
    /// for rays without an end, or when the hierarchy does not bound distances.
    float reach = INFINITY;
};

SHEAF_HD_INLINE RayNode make_ray_node(const Sphere& s, const Cone& c) {
    RayNode n;
    n.center = s.center;
    n.radius = s.radius;
    n.axis = c.axis;
    n.angle = c.angle;
    if (c.angle < 1.5f) { // below ~86 degrees eq. (9) is used, above it the angular test
        n.tan_angle = hdm::tanf(c.angle);
        n.inv_cos_angle = 1.0f / hdm::cosf(c.angle);
    }
    return n;
}

/// Conservative: returns true whenever some ray with origin in the node sphere and direction
/// in the node cone intersects the sphere `prim`. The node sphere is folded into the primitive
/// sphere (the ray from the node centre with the same direction passes within node.radius of
/// the original ray), then the cone from the node centre is tested against the enlarged sphere
/// with eq. (9): |C-H| tan(a) + (d + r) / cos(a) >= |P-H|, H the projection of P on the axis.
SHEAF_HD_INLINE bool node_hits_sphere(const RayNode& node, const Sphere& prim) {
    const float R = prim.radius + node.radius;
    const Vec3 v = prim.center - node.center;
    const float dist2 = dot(v, v);
    if (dist2 <= R * R) return true; // the apex region touches the sphere
    // Beyond every ray's end (padded for rounding; an infinite reach never culls).
    const float far = (node.reach + prim.radius) * (1.0f + 1e-5f);
    if (dist2 > far * far) return false;
    const float h = dot(v, node.axis); // |C - H|, signed along the axis
    if (node.angle < 1.5f) {
        if (h < -R) return false; // wholly behind the apex: a cone under 90 degrees looks forward
        const float q = sqrtf(hdm::fmaxf(dist2 - h * h, 0.0f)); // |P - H|
        return h * node.tan_angle + R * node.inv_cos_angle >= q * (1.0f - 1e-6f);
    }
    // Wide cones: the directions that reach the sphere form a cap of half-angle asin(R/dist)
    // around v; they meet the node's cone when the angular distance is within the sum.
    const float dist = sqrtf(dist2);
    const float theta = hdm::atan2f(length(cross(v, node.axis)), h);
    return theta <= node.angle + hdm::asinf(hdm::fminf(1.0f, R / dist)) + 1e-6f;
}

} // namespace sheaf

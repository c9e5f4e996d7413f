// Mesh builders for the built-in scenes: boxes, quads, cylinders, cones, surfaces of
// revolution, spheres, tori and arches. Every builder returns a Mesh with one normal per vertex
// and counter-clockwise winding seen from outside (cross(b - a, c - a) points outward).
// Flat faces get their own vertices, so their normals are exact.
#pragma once

#include "core/scene/scene.h"

#include <vector>

namespace sheaf {

/// An axis-aligned box: 12 triangles, 24 vertices (4 per face).
Mesh make_box(Vec3 min, Vec3 max);
/// A parallelogram from `corner` spanned by `edge_u` and `edge_v`, cut into nu x nv cells.
/// Its normal is normalize(cross(edge_u, edge_v)).
Mesh make_quad(Vec3 corner, Vec3 edge_u, Vec3 edge_v, int nu = 1, int nv = 1);
/// A round cylinder from `base` to `top`; `caps` closes both ends with flat disks.
Mesh make_cylinder(Vec3 base, Vec3 top, float radius, int segments, bool caps);
/// A cone or frustum from `base` (radius base_radius) to `top` (radius top_radius, may be 0);
/// `caps` closes each end whose radius is not zero.
Mesh make_cone(Vec3 base, Vec3 top, float base_radius, float top_radius, int segments, bool caps);

/// One point of a lathe profile: a radius at a height along the axis.
struct ProfilePoint {
    float radius;
    float height;
};
/// A surface of revolution about the axis from `base` towards `axis_dir`, through the profile
/// points (in order of increasing height for an outward-facing surface); smooth normals.
Mesh make_lathe(Vec3 base, Vec3 axis_dir, const std::vector<ProfilePoint>& profile, int segments);

/// A sphere with `stacks` bands from pole to pole (poles on +-y) and `slices` around:
/// 2 * slices * (stacks - 1) triangles.
Mesh make_uv_sphere(Vec3 center, float radius, int stacks, int slices);
/// A torus around `axis`: 2 * major_segments * minor_segments triangles.
Mesh make_torus(Vec3 center, Vec3 axis, float major_radius, float minor_radius, int major_segments,
                int minor_segments);
/// An arch block for arcades in the x-y plane, extruded along z over `depth` centred on
/// `spring_center` (the middle of the spring line): a rectangle from x = -half_width to
/// +half_width and y = 0 to `height`, less a half-disc opening of `inner_radius` (which must be
/// below half_width and height). 6 * segments + 10 triangles.
Mesh make_arch(Vec3 spring_center, float inner_radius, float half_width, float height, float depth,
               int segments);

/// Appends `src`, transformed by `t`, to `dst` (positions by t.point, normals by t.normal, the
/// winding flipped when t mirrors). The result keeps normals only if both meshes have them.
void append_mesh(Mesh& dst, const Mesh& src, const Affine& t = {});

} // namespace sheaf

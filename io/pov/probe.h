// Queries of one object while the scene is read: POV-Ray's trace() and inside(). The object
// is built alone (its geometry only) and prepared once; each query then runs the renderer's
// own exact tests (core/scene/analytic.h, core/geometry/ray_triangle.h) over its primitives.
#pragma once

#include "core/accel/bvh.h"
#include "core/scene/prepared_scene.h"
#include "core/scene/scene.h"
#include "io/pov/parser.h"

#include <memory>

namespace sheaf::io::pov {

struct ObjectProbe {
    Scene scene;
    PreparedScene prepared;
    Bvh bvh; // over prepared: trace() walks it (a height field is many thousand triangles)
};

/// The probe of object `o` (its geometry in Sheaf's world space).
/// What Scene::validate refuses in the object is an error at `at`, the call that asked (found
/// by the POV fuzzer: a blob of infinite threshold was reported with no place).
std::shared_ptr<const ObjectProbe> make_probe(Parser& p, const PovObject& o, const Token& at);

/// Whether the point (POV-Ray coordinates) lies inside the object's solids. Meshes and
/// triangles enclose nothing (as in POV-Ray without inside_vector).
bool probe_inside(const ObjectProbe& q, Vec3 point);

/// The ray from `from` along `dir` (POV-Ray coordinates, dir not zero) in Sheaf's world, unit
/// direction, the whole half-line.
Ray probe_ray(Vec3 from, Vec3 dir);

/// The first surface of the object along the ray from `from` in direction `dir` (POV-Ray
/// coordinates): its point and its unit normal, out of the solid (a triangle's: facing
/// `from`); false when it meets none. Of hits at the same distance the lowest primitive's
/// wins, as in a walk over them all in order.
bool probe_trace(const ObjectProbe& q, Vec3 from, Vec3 dir, Vec3& hit, Vec3& normal);

} // namespace sheaf::io::pov

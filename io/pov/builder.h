// Turns the parsed PovModel into a sheaf::Scene: materials from textures, analytic objects
// and CSG trees, meshes, lights (area lights as jittered samples), the camera and settings.
// POV-Ray's left-handed coordinates are mirrored in z so that the picture is not mirrored.
#pragma once

#include "io/pov/parser.h"

namespace sheaf::io::pov {

/// The mirror from POV-Ray's left-handed world to Sheaf's right-handed one: z -> -z.
Affine pov_to_sheaf();

/// Builds `scene` from `p.model`; warnings (mesh inside CSG ...) go through p.unsupported.
/// Returns the assumed gamma the colours were decoded with.
double build_scene(Parser& p, Scene& scene);

/// Builds object `o` alone into `scene`, its geometry only (every surface material 0, which
/// this adds), its warnings dropped: for the queries trace() and inside() make while the
/// scene is read (io/pov/probe.h).
void build_object_geometry(Parser& p, const PovObject& o, Scene& scene);

} // namespace sheaf::io::pov

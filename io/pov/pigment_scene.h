// A pigment function's pigment lowered into a scene of its own when the function is parsed,
// so that the scene language can evaluate any pigment at a point (height fields of pigment
// functions, functions.inc's eval_pigment, F(x, y, z).red in a function the language
// calls): the same MaterialBuilder and the same evaluator (core/render/surface_texture.h) as
// the render, over only the tables a pigment reads.
#pragma once

#include "core/scene/prepared_scene.h"
#include "core/scene/scene.h"

#include <array>
#include <cstdint>

namespace sheaf::io::pov {

struct PigmentScene {
    Scene scene;          // the pigment, its patterns, warps, images and functions
    PreparedScene tables; // their copy the evaluator reads (copy_texture_tables)
    int32_t pigment = -1;

    /// The pigment's red, green, blue, filter and transmit at (x, y, z), the function's space.
    std::array<float, 5> at(double x, double y, double z) const;
};

} // namespace sheaf::io::pov

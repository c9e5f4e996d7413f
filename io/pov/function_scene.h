// A pigment function's pigment, or a pattern function's pattern, lowered into a scene of its
// own when the function is parsed, so that the scene language evaluates it as the render
// does (height fields of functions, functions.inc's eval_pigment, calls in expressions):
// the same MaterialBuilder and the same evaluator (core/shading/surface_texture.h), over only
// the tables pigments and patterns read.
#pragma once

#include "core/scene/prepared_scene.h"
#include "core/scene/scene.h"

#include <array>
#include <cstdint>

namespace sheaf::io::pov {

struct FunctionScene {
    Scene scene;          // the pigment or pattern, its warps, images and functions
    PreparedScene tables; // their copy the evaluator reads (copy_texture_tables)
    int32_t pigment = -1; // in scene.pigments, or
    int32_t pattern = -1; // in scene.fn_patterns

    /// The pigment's red, green, blue, filter and transmit at (x, y, z), the function's space.
    std::array<float, 5> color_at(double x, double y, double z) const;
    /// The pattern's value at (x, y, z), as a function pattern gives it (list patterns: 0 or
    /// 1).
    double value_at(double x, double y, double z) const;
};

} // namespace sheaf::io::pov

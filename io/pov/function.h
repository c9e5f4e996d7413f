// User functions (`function { ... }`, `function(a, b) { ... }`): the body is compiled to a small
// expression tree over the parameters (x, y, z by default) and evaluated with doubles. The
// float built-ins (sin, pow, min, select ...) are shared with the scene-language expressions.
#pragma once

#include "core/scene/function.h"
#include "core/scene/pattern.h"
#include "io/pov/lexer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sheaf::io::pov {

struct FnNode {
    enum Kind : uint8_t {
        Const,
        Param,
        Operator, // `op` over the arguments: the programs' own operators (FnOp)
        Builtin,  // name(args)
        Call,     // a user function (args)
    };
    Kind kind = Const;
    FnOp op = FnOp::Const; // Operator: Neg, Not, Add ... Or, Cond (a ? b : c)
    double value = 0;      // Const
    int param = 0;         // Param
    std::string name;      // Builtin
    std::shared_ptr<const struct PovFunction> fn;
    int component = 5; // Call of a pigment function: the FnComponent taken (.red ...; gray)
    std::vector<FnNode> args;
    int height = 1; // levels of the tree below and including this node
};

struct FunctionScene;
struct PovSpline;
struct PovPattern;
struct PovPigment;

/// A pigment function's pigment: as parsed (the render lowers it into its scene, where
/// programs read any pigment), in a scene of its own for the scene language
/// (io/pov/function_scene.h), and in the small form programs read without a scene
/// (isosurfaces, core/scene/function.h), when it is a solid colour or a colour map or list
/// over a pattern without warps: its pattern (in the function's space), the pigment with
/// pattern 0 and first entry 0, its colours.
struct PigmentFunction {
    std::shared_ptr<const PovPigment> source;
    std::shared_ptr<const FunctionScene> scene;
    Pattern pattern;
    FnPigment pigment;
    std::vector<PigmentEntry> entries;
    /// Component `comp` (FnComponent) at (x, y, z), as the scene language evaluates it.
    double at(int comp, double x, double y, double z) const;
};

/// A pattern function's pattern (`function { pattern { ... } }`): as parsed with its
/// transforms (the render lowers it into its scene), and in a scene of its own for the scene
/// language.
struct PatternFunction {
    std::shared_ptr<const PovPattern> source;
    Affine local;
    std::shared_ptr<const FunctionScene> scene;
    /// The value at (x, y, z), as the scene language evaluates it.
    double at(double x, double y, double z) const;
};

/// Thrown by PovFunction::eval when the steps allowed run out.
struct FnStepsExceeded {};

struct PovFunction {
    std::vector<std::string> params; // x, y, z when none were given
    FnNode body;
    // Non-empty: what it uses that programs without a scene cannot run (isosurfaces), and
    // what cannot be evaluated on a scene either (function patterns, the scene language's
    // height fields and calls); the second implies the first.
    std::string unsupported, scene_unsupported;
    Token where; // its `function` keyword
    // Instead of a body: internal(N) (core/scene/function.h's fn_internal) over x, y, z and
    // its parameters, or a pattern's value at x, y, z (in the function's own space).
    int internal = -1;
    std::shared_ptr<const PatternFunction> pattern;
    std::shared_ptr<const PigmentFunction> pigment; // a pigment function (gray when a number)
    // A transform function (`function { transform { ... } }`): called in the scene language
    // it gives the point transformed, a vector (transforms.inc's vtransform); a function body
    // cannot use it (`unsupported` says so).
    std::shared_ptr<const Affine> transform;
    // A spline function (`function { spline { ... } }`): called in the scene language it
    // gives the spline's point, a vector; a function body cannot use it.
    std::shared_ptr<const PovSpline> spline;
    /// Evaluates the body; each node evaluated takes one of `steps` (FnStepsExceeded when
    /// none is left).
    double eval(const double* args, int n, uint64_t& steps) const;
};

/// Evaluates the float built-in `name` (sin, cos, pow, min, max, select, mod ...). Returns
/// false when `name` is not one, or takes another number of arguments (then `out` is unset).
bool eval_builtin(const std::string& name, const std::vector<double>& args, double& out);
/// Whether `name` is a float built-in with `n` arguments (min/max/select: variadic).
bool is_float_builtin(const std::string& name);
/// The float built-ins of one argument and the operations programs run them with (sin,
/// sqrt, log ...): one table for the language's evaluation and the function compiler.
const std::map<std::string, FnMath>& math_builtins();

} // namespace sheaf::io::pov

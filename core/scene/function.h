// User functions on both backends (POV-Ray's `function { ... }`): a body compiled to a short
// program for a stack machine, run in double precision with Sheaf's own host-and-device math
// (core/math/hd_math.h), so the CPU and the CUDA backend compute the same values. Function
// patterns and isosurfaces run them.
//
// A program's parameters are the first slots of its stack; calls to other user functions are
// compiled inline (their arguments pushed, their body reading them where they lie, then Drop),
// so a program has no jumps and its stack depth at every instruction is known when it is
// compiled (kFnStack bounds it). Conditionals evaluate both branches and pick one.
#pragma once

#include "core/math/hd_math.h"
#include "core/scene/fn_internal.h"
#include "core/scene/pattern.h"
#include "core/texture/pattern_eval.h"
#include "core/texture/pov_noise.h"

#include <cstdint>
#include <string>

namespace sheaf {

enum class FnOp : uint8_t {
    Const, // push value
    Load,  // push slot `arg`
    Drop,  // keep the top, remove the `arg` slots below it
    Neg,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Cond,    // a ? b : c (pops 3)
    Select3, // select(a, b, c): a < 0 ? b : c
    Select4, // select(a, b, c, d): a < 0 ? b : a == 0 ? c : d
    Min,
    Max,
    Pow,
    Atan2,
    Mod,      // fmod
    IntDiv,   // div: the quotient truncated
    Math,     // a one-argument function: FnMath `arg`
    Internal, // a built-in shape or noise function (FnInternal `arg`) of `count` arguments
    Pattern,  // pattern `arg` of the program table at the point (pops 3)
    Pigment,  // component `count` (FnComponent) of function pigment `arg` at the point (pops 3)
};

/// What a Pigment instruction takes of the colour.
enum class FnComponent : uint8_t { Red, Green, Blue, Filter, Transmit, Gray };

/// One-argument functions of Math.
enum class FnMath : uint8_t {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Sqrt,
    Exp,
    Log10, // POV-Ray's log
    Ln,
    Abs,
    Int, // truncated toward zero
    Floor,
    Ceil,
    Degrees,
    Radians,
};

struct FnInstr {
    FnOp op = FnOp::Const;
    uint8_t count = 0; // Internal: its arguments
    uint16_t arg = 0;  // Load and Drop: slots; Math, Internal: which; Pattern: its index
    double value = 0;  // Const
};

/// A pigment a function reads (POV-Ray's `function { pigment { ... } }`): a solid colour
/// (count 0), or function pattern `pattern` choosing among the function pigment entries
/// [first, first + count): blended by value, or by index when `list`.
/// `scene_pigment`: the same pigment in Scene::pigments (-1: none), which a program run on a
/// scene reads instead (FnSceneContext, core/shading/surface_texture.h), so that any pigment
/// works there; a pigment this small form cannot hold is black in it (the POV reader warns
/// isosurfaces of such functions, the only programs run without a scene).
struct FnPigment {
    uint32_t pattern = 0, first = 0, count = 0;
    uint32_t list = 0;
    float color[5] = {0, 0, 0, 0, 0};
    int32_t scene_pigment = -1;
};

/// A compiled function: instructions [first, first + count) of the scene's function code,
/// reading its `params` arguments from its first slots.
struct FnProgram {
    uint32_t first = 0, count = 0;
    uint32_t params = 0;
};

/// The largest stack a program may use, in slots.
constexpr int kFnStack = 48;

/// The values instruction `in` takes from the stack (it leaves one); -1 for an unknown
/// operation. Host only.
int fn_pops(const FnInstr& in);

/// Why program `p` over code[0, code_size) cannot run safely: its code outside the table, a
/// stack deeper than kFnStack or read below its bottom, an unknown operation, a Pattern
/// instruction naming one of more than `patterns`. Empty when it can; `depth` gets its deepest
/// stack. Host only.
std::string check_fn_program(const FnProgram& p, const FnInstr* code, size_t code_size,
                             size_t patterns, size_t pigments, int* depth = nullptr);

/// A scene's compiled functions as the executing side sees them.
struct FnView {
    const FnProgram* programs = nullptr;
    const FnInstr* code = nullptr;
    const Pattern* patterns = nullptr;             // the patterns Pattern instructions read
    const FnPigment* pigments = nullptr;           // the pigments Pigment instructions read
    const PigmentEntry* pigment_entries = nullptr; // their entries (colours only)
    const Warp* warps = nullptr;                   // the scene's warps, which patterns name
};

namespace fn_detail {

SHEAF_HD_INLINE double sq(double v) {
    return v * v;
}

SHEAF_HD_INLINE double math(FnMath m, double a) {
    switch (m) {
    case FnMath::Sin:
        return hdm::sin(a);
    case FnMath::Cos:
        return hdm::cos(a);
    case FnMath::Tan:
        return hdm::tan(a);
    case FnMath::Asin:
        return hdm::asin(a);
    case FnMath::Acos:
        return hdm::acos(a);
    case FnMath::Atan:
        return hdm::atan(a);
    case FnMath::Sinh:
        return 0.5 * (hdm::exp(a) - hdm::exp(-a));
    case FnMath::Cosh:
        return 0.5 * (hdm::exp(a) + hdm::exp(-a));
    case FnMath::Tanh: {
        if (a > 20) return 1;
        if (a < -20) return -1;
        const double e = hdm::exp(2 * a);
        return (e - 1) / (e + 1);
    }
    case FnMath::Asinh:
        return a < 0 ? -hdm::log(-a + sqrt(a * a + 1)) : hdm::log(a + sqrt(a * a + 1));
    case FnMath::Acosh:
        return hdm::log(a + sqrt(a * a - 1));
    case FnMath::Atanh:
        return 0.5 * hdm::log((1 + a) / (1 - a));
    case FnMath::Sqrt:
        return sqrt(a);
    case FnMath::Exp:
        return hdm::exp(a);
    case FnMath::Log10:
        return hdm::log(a) * 0.43429448190325182765;
    case FnMath::Ln:
        return hdm::log(a);
    case FnMath::Abs:
        return fabs(a);
    case FnMath::Int:
        return trunc(a);
    case FnMath::Floor:
        return floor(a);
    case FnMath::Ceil:
        return ceil(a);
    case FnMath::Degrees:
        return a * (180.0 / 3.14159265358979323846);
    case FnMath::Radians:
        return a * (3.14159265358979323846 / 180.0);
    }
    return 0;
}

} // namespace fn_detail

/// Pattern `pt` (a function's: no warps, Scene::validate checks) as a function at (x, y, z): a
/// continuous pattern's value in [0, 1], a list pattern's entry spread over [0, 1] (checker: 0 or
/// 1).
SHEAF_HD_INLINE double fn_pattern(const FnView& fv, const Pattern& pt, double x, double y,
                                  double z) {
    const Vec3 q = pattern_point(pt, Vec3(float(x), float(y), float(z)), fv.warps);
    if (pattern_is_list(pt.kind)) return pattern_index_at(pt, q) != 0 ? 1.0 : 0.0;
    return pattern_value_at(pt, q);
}

/// Component `comp` (FnComponent) of colour c (red, green, blue, filter, transmit); gray is
/// POV-Ray's 0.297 red + 0.589 green + 0.114 blue.
SHEAF_HD_INLINE double fn_component(const float* c, int comp) {
    if (comp >= 0 && comp < 5) return c[comp];
    return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
}

/// Component `comp` (FnComponent) of function pigment `pg` at (x, y, z).
SHEAF_HD_INLINE double fn_pigment(const FnView& fv, const FnPigment& pg, int comp, double x,
                                  double y, double z) {
    float c[5];
    for (int i = 0; i < 5; ++i) c[i] = pg.color[i];
    if (pg.count > 0) {
        const Pattern& pt = fv.patterns[pg.pattern];
        const PigmentEntry* e = fv.pigment_entries + pg.first;
        const Vec3 q = pattern_point(pt, Vec3(float(x), float(y), float(z)), fv.warps);
        if (pg.list) {
            const uint32_t i = uint32_t(pattern_index_at(pt, q));
            for (int k = 0; k < 5; ++k) c[k] = e[i < pg.count ? i : pg.count - 1].color[k];
        } else {
            const MapSpan m = map_span(e, pg.count, pattern_value_at(pt, q));
            for (int k = 0; k < 5; ++k)
                c[k] = e[m.lo].color[k] * (1.0f - m.t) + e[m.hi].color[k] * m.t;
        }
    }
    return fn_component(c, comp);
}

/// What a program reads of its function tables alone: patterns without warps or pigments,
/// pigments in their small form (isosurfaces run programs so).
struct FnTablesContext {
    const FnView& fv;
    SHEAF_HD double pattern(uint32_t i, double x, double y, double z) const {
        return fn_pattern(fv, fv.patterns[i], x, y, z);
    }
    SHEAF_HD double pigment(uint32_t i, int comp, double x, double y, double z) const {
        return fn_pigment(fv, fv.pigments[i], comp, x, y, z);
    }
};

/// Runs program `program` on its arguments (params of them), its Pattern and Pigment
/// instructions read through `ctx` (FnTablesContext, or a scene's). NaN stays NaN.
template <class Context>
SHEAF_HD_NOINLINE double fn_eval(const FnView& fv, uint32_t program, const double* args,
                                 const Context& ctx) {
    using fn_detail::math;
    const FnProgram& pg = fv.programs[program];
    double s[kFnStack];
    uint32_t sp = 0;
    for (; sp < pg.params && sp < uint32_t(kFnStack); ++sp) s[sp] = args[sp];
    const FnInstr* code = fv.code + pg.first;
    for (uint32_t i = 0; i < pg.count; ++i) {
        const FnInstr& in = code[i];
        // The compiler proved the depth; the checks keep a corrupt program inside the stack.
        switch (in.op) {
        case FnOp::Const:
            if (sp < uint32_t(kFnStack)) s[sp++] = in.value;
            continue;
        case FnOp::Load:
            if (sp < uint32_t(kFnStack)) {
                const double v = in.arg < sp ? s[in.arg] : 0.0;
                s[sp++] = v;
            }
            continue;
        default:
            break;
        }
        if (sp == 0) return 0;
        double& a = s[sp - 1]; // one operand: the top
        switch (in.op) {
        case FnOp::Drop:
            if (in.arg < sp) {
                s[sp - 1 - in.arg] = a;
                sp -= in.arg;
            }
            continue;
        case FnOp::Neg:
            a = -a;
            continue;
        case FnOp::Not:
            a = a == 0 ? 1 : 0;
            continue;
        case FnOp::Math:
            a = math(FnMath(in.arg), a);
            continue;
        default:
            break;
        }
        if (sp < 2) return 0;
        if (in.op == FnOp::Cond || in.op == FnOp::Select3) {
            if (sp < 3) return 0;
            const double c = s[sp - 3];
            const bool first = in.op == FnOp::Cond ? c != 0 : c < 0;
            s[sp - 3] = first ? s[sp - 2] : s[sp - 1];
            sp -= 2;
            continue;
        }
        if (in.op == FnOp::Select4) {
            if (sp < 4) return 0;
            const double c = s[sp - 4];
            s[sp - 4] = c < 0 ? s[sp - 3] : c == 0 ? s[sp - 2] : s[sp - 1];
            sp -= 3;
            continue;
        }
        if (in.op == FnOp::Internal) {
            const uint32_t n = in.count;
            if (n < 3 || sp < n) return 0;
            double* p = &s[sp - n];
            p[0] = fn_internal(in.arg, p[0], p[1], p[2], p + 3);
            sp -= n - 1;
            continue;
        }
        if (in.op == FnOp::Pattern || in.op == FnOp::Pigment) {
            if (sp < 3) return 0;
            double* p = &s[sp - 3];
            p[0] = in.op == FnOp::Pattern ? ctx.pattern(in.arg, p[0], p[1], p[2])
                                          : ctx.pigment(in.arg, in.count, p[0], p[1], p[2]);
            sp -= 2;
            continue;
        }
        const double l = s[sp - 2], r = a;
        double v = 0;
        switch (in.op) {
        case FnOp::Add:
            v = l + r;
            break;
        case FnOp::Sub:
            v = l - r;
            break;
        case FnOp::Mul:
            v = l * r;
            break;
        case FnOp::Div:
            v = l / r;
            break;
        case FnOp::Lt:
            v = l < r;
            break;
        case FnOp::Le:
            v = l <= r;
            break;
        case FnOp::Gt:
            v = l > r;
            break;
        case FnOp::Ge:
            v = l >= r;
            break;
        case FnOp::Eq:
            v = l == r;
            break;
        case FnOp::Ne:
            v = l != r;
            break;
        case FnOp::And:
            v = (l != 0) && (r != 0);
            break;
        case FnOp::Or:
            v = (l != 0) || (r != 0);
            break;
        case FnOp::Min:
            v = r < l ? r : l;
            break;
        case FnOp::Max:
            v = r > l ? r : l;
            break;
        case FnOp::Pow:
            v = hdm::pow(l, r);
            break;
        case FnOp::Atan2:
            v = hdm::atan2(l, r);
            break;
        case FnOp::Mod:
            v = fmod(l, r);
            break;
        case FnOp::IntDiv:
            v = trunc(l / r);
            break;
        default:
            break;
        }
        s[sp - 2] = v;
        --sp;
    }
    return sp > 0 ? s[sp - 1] : 0;
}

SHEAF_HD_INLINE double fn_eval(const FnView& fv, uint32_t program, const double* args) {
    return fn_eval(fv, program, args, FnTablesContext{fv});
}

/// Program `program` at a point.
SHEAF_HD_INLINE double fn_eval3(const FnView& fv, uint32_t program, double x, double y, double z) {
    const double args[3] = {x, y, z};
    return fn_eval(fv, program, args);
}

} // namespace sheaf

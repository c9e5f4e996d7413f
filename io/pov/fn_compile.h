// PovFunction -> the core's function programs (core/scene/function.h): the body's tree in
// postfix order, with the calls to other user functions inline, internal functions and
// pattern functions as single instructions.
#pragma once

#include "io/pov/function.h"

#include "core/scene/scene.h"

#include <map>
#include <stdexcept>

namespace sheaf::io::pov {

/// Why a function cannot be compiled: it uses an unsupported part, or is too deep or too long.
struct FnCompileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The most instructions one program may have (inline calls included).
constexpr size_t kMaxFnCode = size_t(1) << 16;

class MaterialBuilder;

class FnCompiler {
  public:
    /// Compiles into `scene`; `materials` lowers the pigments and patterns functions read.
    FnCompiler(Scene& scene, MaterialBuilder& materials) : scene_(scene), materials_(materials) {}
    /// The index of `f`'s program in the scene's fn_programs, compiled on its first use.
    /// Throws FnCompileError.
    int32_t program(const PovFunction& f);

  private:
    void emit(const FnNode& n, uint32_t base);
    void call(const PovFunction& f, size_t nargs, int component);
    void push(FnOp op, uint16_t arg = 0, double value = 0, uint8_t count = 0);
    uint16_t add_pattern(const Pattern& p);
    uint16_t pattern(const PatternFunction& p);
    uint16_t pigment(const PigmentFunction& p);

    Scene& scene_;
    MaterialBuilder& materials_;
    std::map<const PovFunction*, int32_t> programs_;
    std::map<const PatternFunction*, uint16_t> patterns_;
    std::map<const PigmentFunction*, uint16_t> pigments_;
    std::vector<FnInstr> code_; // the program being compiled
    int depth_ = 0, deepest_ = 0;
};

} // namespace sheaf::io::pov

// POV-Ray's own command line switches (+W640 +H480 +Ofile.png +A -A +L<dir> -D +I<file>, the
// animation switches +K...), its .ini files and Key=Value options, and
// the bare KEY=VALUES words after --sweep, translated into the tool's options before CLI11
// parses the command line.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace render {

/// A malformed or unknown POV-Ray switch; the message names it.
struct SwitchError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The samples per pixel side `+A` turns on (aa.samples): POV-Ray's default antialias depth.
constexpr int kPovAntialiasSamples = 3;

/// Appends the translation of one POV-Ray switch (a word starting with + or one of -A, -D, -KC)
/// to `out`; returns false when `word` is not one. Throws SwitchError for an unknown "+X" switch
/// or a bad value.
bool translate_switch(const std::string& word, std::vector<std::string>& out);

/// Translates `args` (without the program name):
///   +W<n> -> -W n        +H<n> -> -H n          +O<file> -> -o file     +I<file> -> --input file
///   +A, +A<threshold> -> --set aa.samples=3      -A, -A<threshold> -> --set aa.samples=1
///   +L<dir> -> --include-path dir                +D, -D -> --no-display
///   +K<v> -> --clock v    +KFI<n> -> --initial-frame n    +KFF<n> -> --final-frame n
///   +KI<v> -> --initial-clock v    +KF<v> -> --final-clock v
///   +KC, -KC -> --cyclic-animation, --no-cyclic-animation
///   +SF<n> -> --subset-start-frame n    +EF<n> -> --subset-end-frame n
/// A FILE.ini (or FILE.ini[Section]) in place of the scene is replaced by its translation
/// (pov_ini.h), and POV-Ray's Key=Value options (Width=640, Declare=N=2) are translated too.
/// and every KEY=VALUES word following --sweep into its own "--sweep KEY=VALUES". Arguments after
/// "--" are left alone. Throws SwitchError for an unknown "+X" switch or a missing value.
std::vector<std::string> translate_args(const std::vector<std::string>& args);

} // namespace render

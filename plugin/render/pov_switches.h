// POV-Ray's own command line switches (+W640 +H480 +Ofile.png +A -A +L<dir> -D +I<file>) and
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

/// Translates `args` (without the program name):
///   +W<n> -> -W n        +H<n> -> -H n          +O<file> -> -o file     +I<file> -> --input file
///   +A, +A<threshold> -> --set aa.samples=3      -A, -A<threshold> -> --set aa.samples=1
///   +L<dir> -> --include-path dir                +D, -D -> --no-display
/// and every KEY=VALUES word following --sweep into its own "--sweep KEY=VALUES". Arguments after
/// "--" are left alone. Throws SwitchError for an unknown "+X" switch or a missing value.
std::vector<std::string> translate_args(const std::vector<std::string>& args);

} // namespace render

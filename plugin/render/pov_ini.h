// POV-Ray's .ini files and Key=Value options (Width=640, Initial_Frame=1, Declare=N=2 ...),
// translated into the tool's long options before CLI11 parses the command line, as POV-Ray's
// switches are (pov_switches.h).
#pragma once

#include <string>
#include <vector>

namespace render {

/// Whether `word` names an .ini file: FILE.ini, or FILE.ini[Section] (any case).
bool is_ini_file(const std::string& word);

/// Appends the translation of one Key=Value option (Width=640, +W640 style lines are switches)
/// to `out` and returns true; false when `word` is not KEY=VALUE with a key POV-Ray knows.
/// `where` ("FILE:LINE" or "command line") prefixes errors and warnings. Keys that change
/// nothing in Sheaf's picture (consoles, display, pause, commands) are accepted silently;
/// keys for what Sheaf does not do (jitter, radiosity files, partial renders ...) print a
/// warning on stderr. Throws SwitchError for a value that is not allowed.
bool translate_ini_option(const std::string& word, const std::string& where,
                          std::vector<std::string>& out);

/// Reads FILE.ini (every line before the first [Section]) or FILE.ini[Section] (that section's
/// lines) and returns its translation: each Key=Value line through translate_ini_option, each
/// +X/-X switch as on the command line; ';' starts a comment. An Input_File_Name without an
/// Output_File_Name names the image after the scene, as POV-Ray does (SCENE.png). A relative
/// Input_File_Name is found next to the .ini when it is not in the current folder. The .ini's
/// image name comes out as --default-output, which -o overrides wherever it stands. Throws
/// SwitchError for an unreadable file, an unknown section or a bad line ("FILE:LINE: ...").
std::vector<std::string> read_ini_file(const std::string& spec);

} // namespace render

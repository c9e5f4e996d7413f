// Finding and opening Sheaf's run-time modules: shared libraries that libsheaf dlopen()s at
// first use instead of linking, so that a process pays for their dependencies only when it
// needs them (the CUDA module: the CUDA runtime; the image module: OpenImageIO and the
// hundreds of libraries it brings).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sheaf {

/// Where a module file is looked for, in order: $`env` (a file; when set, only it), beside
/// the image that holds this code (libsheaf.so, or a program linking the core statically),
/// `build_path` (the build tree's copy, set at configure time; may be empty), then `file`
/// alone, for the dynamic loader's own search path (LD_LIBRARY_PATH, ld.so.cache).
std::vector<std::string> module_candidates(const char* env, const char* file,
                                           const std::string& build_path);

/// Asked of each module that opens: its table, from the address of its entry symbol (null
/// when the symbol is missing), or null with the reason in `why`.
using ModuleAccept = std::function<const void*(void* entry, std::string& why)>;

/// A module opened for the life of the process (never dlclose'd).
struct OpenedModule {
    const void* table = nullptr; // what `accept` returned; null when no candidate was taken
    std::string path;            // the file it came from
    std::string tried;           // each candidate refused and why, "; "-separated
};

/// Opens the candidates in order and returns the first that `accept` takes.
OpenedModule open_module(const std::vector<std::string>& candidates, const char* entry,
                         const ModuleAccept& accept);

} // namespace sheaf

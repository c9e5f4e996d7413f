// Checks of a subdivision cage before OpenSubdiv sees it: OpenSubdiv asserts (or reads out of
// bounds) on some malformed topology, so everything it relies on is checked here first.
#pragma once

#include "io/subdiv/subdivide.h"

#include <string>

namespace sheaf::io {

/// Throws SceneError "WHAT: ..." naming the first bad vertex, face, crease or option.
void check_cage(const SubdivCage& cage, const SubdivOptions& options, const std::string& what);

} // namespace sheaf::io

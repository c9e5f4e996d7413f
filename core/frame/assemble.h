// A whole frame put together from parts rendered with region.* (render --tile, a farm's
// tasks): each part's pixels at its place. Parts compute each pixel as the whole frame does
// (core/raster/sample_window.h), so the result equals the frame rendered in one piece.
#pragma once

#include "core/frame/frame.h"

#include <vector>

namespace sheaf {

/// The whole frame from `parts`, in any order. Every pass the parts keep is assembled; the
/// settings are the parts' without region.*; the statistics are summed over the parts (rays,
/// tests, times), except frame.* and scene.* (the whole frame's) and memory.* (the largest).
/// Throws RenderError when a part is of another frame (whole size, passes or settings other
/// than region.*), when parts overlap, or when pixels are left uncovered, naming the first.
Frame assemble_frame(const std::vector<const Frame*>& parts);

} // namespace sheaf

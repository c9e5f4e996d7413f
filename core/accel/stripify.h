// Triangle strips for ray tracing (accel=strips): one vertex sequence in which triangle j is
// (v[j], v[j + 1], v[j + 2]), for a set of triangles given by vertex numbers. Unlike strips
// for rasterisers, winding does not matter (the ray's edge tests take either orientation), so
// a strip continues across any shared edge and pieces join with two triangles of the sequence
// that are none of the set, never four degenerate ones.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace sheaf {

struct Stripified {
    std::vector<uint32_t> verts; // the sequence
    std::vector<int32_t> tri;    // per position j < verts.size() - 2: the triangle, or -1
};

/// Greedy strips over `tris` (no two corners of a triangle the same vertex): each piece
/// starts at a triangle with the fewest free neighbours and grows both ways from the best of
/// its three orientations; the next piece starts near the last one's end. Every triangle
/// once.
Stripified stripify(const std::vector<std::array<uint32_t, 3>>& tris);

} // namespace sheaf

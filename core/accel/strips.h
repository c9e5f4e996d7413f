// The object-space structure of accel=strips (paper 004, Lauterbach et al., "Ray-Strips"): the
// triangles of each leaf of a top-level SAH BVH made into a triangle strip (core/accel/
// stripify.h; pieces joined end to start), each strip under a balanced hierarchy of two
// planes a node (a spatial kd-tree on the strip order, no child pointers), its vertices its
// own and indexed by 16 bits, and the edges of consecutive triangles shared by the ray's edge
// tests (core/accel/strips_trace.h). Analytic shapes and triangles that fit
// no strip stay single items of the top level; primitives without finite bounds are kept aside
// as in accel=bvh. Built once per scene on the host (strips_for) and traversed by the same
// per-ray function on both backends.
#pragma once

#include "core/accel/bvh.h"
#include "core/math/vec3.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sheaf {

struct PreparedScene;

/// Triangles a top-level leaf holds at most: those of its strips (ranges with analytic shapes
/// are split as accel=bvh splits them).
constexpr uint32_t kStripChunk = 128;
/// Triangles a leaf of a strip's hierarchy holds at most (10 vertices, 17 edges: their edge
/// tests four at a time).
constexpr uint32_t kStripLeaf = 8;
/// A top-level item naming a strip (else it names a primitive).
constexpr uint32_t kStripItem = 0x80000000u;
/// The id of a joining (degenerate) triangle of a strip.
constexpr uint16_t kStripJoin = 0xFFFFu;
/// Levels of a strip's hierarchy at most: 2^9 leaves of kStripLeaf triangles.
constexpr int kStripDepth = 9;

/// One strip: its bounds, its triangles (joins included) and where its arrays begin. Triangle
/// j (0-based) has the vertices index[first + j .. first + j + 2] (numbers of verts from
/// base_vertex) and the primitive base_prim + ids[first + j], unless that is kStripJoin. Its
/// hierarchy's nodes are [first_node, first_node + leaves - 1), leaves = ceil(tris /
/// kStripLeaf), in the order strip_split describes.
struct StripHeader {
    float lo[3], hi[3]; // padded like a BVH box
    float edge;         // the longest edge of its triangles, summed over the axes (L1)
    uint32_t tris, first, first_node, base_vertex, base_prim;
};
static_assert(sizeof(StripHeader) == 48, "a strip header is 48 bytes");

/// A strip node's planes: along `axis` (meta & 3), the lower child lies below `below` and the
/// upper one above `above`; meta bit 2 set when the strip's first part is the upper child.
struct StripPlanes {
    float below, above;
};

/// The structure as the per-ray traversal reads it (host or device pointers).
struct StripsView {
    BvhView top; // its leaves' entries are items: kStripItem | strip, or a primitive
    const StripHeader* strips = nullptr;
    const StripPlanes* planes = nullptr;
    const uint8_t* meta = nullptr;
    const uint16_t* index = nullptr;
    const uint16_t* ids = nullptr;
    const Vec3* verts = nullptr;
    uint32_t strip_count = 0;
};

/// How a node over `m` triangles (m > kStripLeaf) splits them: its first part, the first
/// `first` triangles, is a perfect tree of `span` leaves (node k + 1); the rest is node k + span.
SHEAF_HD_INLINE void strip_split(uint32_t m, uint32_t& first, uint32_t& span) {
    const uint32_t leaves = (m + kStripLeaf - 1) / kStripLeaf;
    span = 1;
    while (2 * span < leaves) span *= 2;
    first = span * kStripLeaf;
}

struct Strips {
    Bvh top;
    std::vector<StripHeader> strips;
    std::vector<StripPlanes> planes;
    std::vector<uint8_t> meta;
    std::vector<uint16_t> index, ids;
    std::vector<Vec3> verts;
    size_t triangles = 0; // the scene's bounded triangles
    size_t loose = 0;     // of which in no strip (single items)
    size_t joins = 0;     // joining triangles in the strips

    StripsView view() const {
        return {top.view(),   strips.data(), planes.data(), meta.data(),
                index.data(), ids.data(),    verts.data(),  uint32_t(strips.size())};
    }
    /// Bytes of hierarchy: the top level's nodes and items, the strips' headers and nodes.
    size_t hierarchy_bytes() const {
        return top.bytes() + strips.size() * sizeof(StripHeader) +
               planes.size() * sizeof(StripPlanes) + meta.size();
    }
    /// Bytes of geometry: the strips' vertices, indices and primitive ids.
    size_t geometry_bytes() const {
        return verts.size() * sizeof(Vec3) + (index.size() + ids.size()) * sizeof(uint16_t);
    }
};

/// The strips of every bounded triangle of `scene` and the top level over them and the other
/// primitives: each primitive once, in a strip or as an item. Multithreaded; the same
/// structure for the same scene. `chunk`: primitives a top-level leaf holds at most.
Strips build_strips(const PreparedScene& scene, uint32_t chunk = kStripChunk);

/// The scene's strips, built on first use and kept with the scene (PreparedScene's cache).
std::shared_ptr<const Strips> strips_for(const PreparedScene& scene);

} // namespace sheaf

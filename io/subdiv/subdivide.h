// Subdivision surfaces through OpenSubdiv's Far API: a polygon cage refined uniformly with
// Catmull-Clark (any polygons) or Loop (triangles only), with creased edges, a boundary rule and
// per-vertex texture coordinates, into a triangle mesh with smooth normals. Optionally every
// refined vertex is moved onto the limit surface (Far::PrimvarRefiner::Limit).
#pragma once

#include "core/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sheaf::io {

enum class SubdivScheme { CatmullClark, Loop };

/// How boundary vertices are treated (OpenSubdiv's VtxBoundaryInterpolation).
enum class SubdivBoundary {
    EdgeOnly,      // boundary edges are smooth B-spline curves; corners are rounded
    EdgeAndCorner, // the same, and vertices of only one face stay sharp corners
    None,          // boundary faces are dropped from the limit surface (OpenSubdiv's "none")
};

struct SubdivCage {
    std::vector<Vec3> positions;
    std::vector<uint32_t> face_sizes;    // vertices per face (3 or more)
    std::vector<uint32_t> face_indices;  // the faces' vertices, concatenated
    std::vector<uint32_t> crease_edges;  // two vertex indices per creased edge (a cage edge)
    std::vector<float> crease_sharpness; // one per crease: 0 smooth .. 10 (and above) sharp
    std::vector<float> uvs;              // empty, or two per vertex, refined like positions
};

struct SubdivOptions {
    SubdivScheme scheme = SubdivScheme::CatmullClark;
    int level = 2; // 0 (the cage, triangulated) .. kMaxSubdivLevel
    SubdivBoundary boundary = SubdivBoundary::EdgeOnly;
    /// Move every vertex of the last level onto the limit surface (needs level >= 1); its
    /// normals then come from the limit tangents.
    bool limit = false;
};

constexpr int kMaxSubdivLevel = 8;
/// The most faces the last level may have (before triangulation): bounds time and memory.
constexpr uint64_t kMaxSubdivFaces = uint64_t(1) << 22;

/// Faces of the last level before triangulation: Catmull-Clark makes n quads of an n-gon at
/// level 1 and four of each face after; Loop four triangles of each triangle per level.
/// Saturates at UINT64_MAX.
uint64_t subdivided_face_count(const std::vector<uint32_t>& face_sizes, SubdivScheme scheme,
                               int level);

/// Refines the cage. Throws SceneError "WHAT: ..." for a bad cage (non-finite positions, a face
/// of fewer than 3 vertices or naming a vertex twice, indices out of range, a Loop cage with a
/// non-triangle, a crease that is not an edge of the cage or has a bad sharpness), a level
/// outside 0..kMaxSubdivLevel or more than kMaxSubdivFaces refined faces.
Mesh subdivide(const SubdivCage& cage, const SubdivOptions& options,
               const std::string& what = "subdivision cage");

} // namespace sheaf::io

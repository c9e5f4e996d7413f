// check_cage: see cage_check.h.
#include "io/subdiv/cage_check.h"

#include "core/base/error.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace sheaf::io {
namespace {

// OpenSubdiv counts a vertex's faces and edges and a face's vertices in 16 bits
// (Vtr::VALENCE_LIMIT); a vertex has at most twice as many edges as faces.
constexpr uint32_t kMaxFaceSize = 65535;
constexpr uint32_t kMaxValence = 32767;

uint64_t edge_key(uint32_t a, uint32_t b) {
    return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
}

} // namespace

void check_cage(const SubdivCage& cage, const SubdivOptions& options, const std::string& what) {
    if (options.level < 0 || options.level > kMaxSubdivLevel)
        throw SceneError(what + ": subdivision level " + std::to_string(options.level) +
                         " is out of range; expected 0.." + std::to_string(kMaxSubdivLevel));
    if (options.limit && options.level < 1)
        throw SceneError(what + ": projecting to the limit surface needs level 1 or more");
    const size_t n = cage.positions.size();
    if (n == 0) throw SceneError(what + ": the cage has no vertices");
    if (n > size_t(INT32_MAX)) throw SceneError(what + ": the cage has too many vertices");
    for (size_t i = 0; i < n; ++i)
        if (!is_finite(cage.positions[i]))
            throw SceneError(what + ": vertex " + std::to_string(i) +
                             " is not finite (NaN or infinity)");
    if (cage.face_sizes.empty()) throw SceneError(what + ": the cage has no faces");
    if (cage.face_sizes.size() > size_t(INT32_MAX))
        throw SceneError(what + ": the cage has too many faces");
    size_t corners = 0;
    for (size_t f = 0; f < cage.face_sizes.size(); ++f) {
        const uint32_t size = cage.face_sizes[f];
        if (size > kMaxFaceSize)
            throw SceneError(what + ": face " + std::to_string(f) + " has " + std::to_string(size) +
                             " vertices; at most " + std::to_string(kMaxFaceSize) + " are allowed");
        if (size < 3)
            throw SceneError(what + ": face " + std::to_string(f) + " has " + std::to_string(size) +
                             " vertices; a face needs 3 or more");
        if (options.scheme == SubdivScheme::Loop && size != 3)
            throw SceneError(what + ": Loop subdivision needs a cage of triangles; face " +
                             std::to_string(f) + " has " + std::to_string(size) + " vertices");
        corners += size;
        if (corners > cage.face_indices.size()) break;
    }
    if (corners != cage.face_indices.size())
        throw SceneError(
            what + ": the face sizes add up to " +
            (corners > cage.face_indices.size() ? std::string("more than ") : std::string("")) +
            std::to_string(corners) + " vertex indices, but " +
            std::to_string(cage.face_indices.size()) + " are given");
    const uint64_t refined = subdivided_face_count(cage.face_sizes, options.scheme, options.level);
    if (refined > kMaxSubdivFaces)
        throw SceneError(
            what + ": level " + std::to_string(options.level) + " would make " +
            (refined == UINT64_MAX ? std::string("too many") : std::to_string(refined)) +
            " faces; at most " + std::to_string(kMaxSubdivFaces) +
            " are allowed (use a lower level)");

    std::unordered_set<uint64_t> edges;
    std::vector<uint32_t> valence(n, 0), sorted;
    size_t first = 0;
    for (size_t f = 0; f < cage.face_sizes.size(); ++f) {
        const uint32_t size = cage.face_sizes[f];
        for (uint32_t k = 0; k < size; ++k) {
            const uint32_t v = cage.face_indices[first + k];
            if (v >= n)
                throw SceneError(what + ": face " + std::to_string(f) + " names vertex " +
                                 std::to_string(v) + ", out of range (" + std::to_string(n) +
                                 " vertices)");
            if (++valence[v] > kMaxValence)
                throw SceneError(what + ": vertex " + std::to_string(v) + " is in more than " +
                                 std::to_string(kMaxValence) + " faces");
            if (!cage.crease_edges.empty())
                edges.insert(edge_key(v, cage.face_indices[first + (k + 1) % size]));
        }
        // A vertex named twice (sorted: a face can have thousands of vertices).
        sorted.assign(cage.face_indices.begin() + first, cage.face_indices.begin() + first + size);
        std::sort(sorted.begin(), sorted.end());
        const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
        if (twice != sorted.end())
            throw SceneError(what + ": face " + std::to_string(f) + " names vertex " +
                             std::to_string(*twice) + " twice");
        first += size;
    }

    if (cage.crease_edges.size() != 2 * cage.crease_sharpness.size())
        throw SceneError(what + ": " + std::to_string(cage.crease_edges.size()) +
                         " crease vertex indices for " +
                         std::to_string(cage.crease_sharpness.size()) +
                         " sharpness values; expected two per crease");
    for (size_t c = 0; c < cage.crease_sharpness.size(); ++c) {
        const uint32_t a = cage.crease_edges[2 * c], b = cage.crease_edges[2 * c + 1];
        const float s = cage.crease_sharpness[c];
        if (!std::isfinite(s) || s < 0)
            throw SceneError(what + ": crease " + std::to_string(c) + " has sharpness " +
                             std::to_string(s) + "; expected a finite value >= 0");
        if (a >= n || b >= n)
            throw SceneError(what + ": crease " + std::to_string(c) + " names vertex " +
                             std::to_string(a >= n ? a : b) + ", out of range (" +
                             std::to_string(n) + " vertices)");
        if (!edges.count(edge_key(a, b)))
            throw SceneError(what + ": crease " + std::to_string(c) + " (" + std::to_string(a) +
                             ", " + std::to_string(b) + ") is not an edge of the cage");
    }

    if (!cage.uvs.empty() && cage.uvs.size() != 2 * n)
        throw SceneError(what + ": " + std::to_string(cage.uvs.size()) +
                         " texture coordinate values for " + std::to_string(n) +
                         " vertices; expected two per vertex");
    for (size_t i = 0; i < cage.uvs.size(); ++i)
        if (!std::isfinite(cage.uvs[i]))
            throw SceneError(what + ": the texture coordinate of vertex " + std::to_string(i / 2) +
                             " is not finite");
}

} // namespace sheaf::io

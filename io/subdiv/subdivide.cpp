// subdivide: the cage through Far::TopologyRefinerFactory, uniform refinement, primvar
// interpolation level by level, optional limit projection, then triangles and normals.
#include "io/subdiv/subdivide.h"

#include "core/base/error.h"
#include "core/scene/scene.h"
#include "io/subdiv/cage_check.h"

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

namespace sheaf::io {
namespace {

using namespace OpenSubdiv;
using Descriptor = Far::TopologyDescriptor;
using Factory = Far::TopologyRefinerFactory<Descriptor>;

/// A primvar of N floats, as Far's interpolation wants it (Clear, AddWithWeight).
template <int N> struct Primvar {
    float v[N];
    void Clear() {
        for (int i = 0; i < N; ++i) v[i] = 0;
    }
    void AddWithWeight(const Primvar& src, float weight) {
        for (int i = 0; i < N; ++i) v[i] += weight * src.v[i];
    }
};
using Point = Primvar<3>;
using Coord = Primvar<2>;

// Far reports errors and warnings through global callbacks that print by default. Sheaf
// installs its own once: errors are kept per thread for the SceneError, warnings are dropped
// (the cage checks catch what matters before Far sees it).
thread_local std::string t_far_error;

void on_far_error(Far::ErrorType, const char* message) {
    if (t_far_error.empty()) t_far_error = message ? message : "unknown OpenSubdiv error";
}
void on_far_warning(const char*) {}

void install_far_callbacks() {
    static std::once_flag once;
    std::call_once(once, [] {
        Far::SetErrorCallback(on_far_error);
        Far::SetWarningCallback(on_far_warning);
    });
}

Sdc::Options::VtxBoundaryInterpolation boundary_rule(SubdivBoundary b) {
    switch (b) {
    case SubdivBoundary::EdgeAndCorner:
        return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
    case SubdivBoundary::None:
        return Sdc::Options::VTX_BOUNDARY_NONE;
    case SubdivBoundary::EdgeOnly:
        break;
    }
    return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
}

std::unique_ptr<Far::TopologyRefiner>
make_refiner(const SubdivCage& cage, const SubdivOptions& options, const std::string& what) {
    std::vector<int> sizes(cage.face_sizes.begin(), cage.face_sizes.end());
    std::vector<Far::Index> indices(cage.face_indices.begin(), cage.face_indices.end());
    std::vector<Far::Index> creases(cage.crease_edges.begin(), cage.crease_edges.end());
    std::vector<float> sharpness(cage.crease_sharpness.size());
    for (size_t i = 0; i < sharpness.size(); ++i)
        sharpness[i] = std::min(cage.crease_sharpness[i], float(Sdc::Crease::SHARPNESS_INFINITE));

    Descriptor desc;
    desc.numVertices = int(cage.positions.size());
    desc.numFaces = int(sizes.size());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = indices.data();
    desc.numCreases = int(sharpness.size());
    desc.creaseVertexIndexPairs = creases.empty() ? nullptr : creases.data();
    desc.creaseWeights = sharpness.empty() ? nullptr : sharpness.data();

    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(boundary_rule(options.boundary));
    const Sdc::SchemeType type =
        options.scheme == SubdivScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;

    install_far_callbacks();
    t_far_error.clear();
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(type, sdc)));
    if (!refiner)
        throw SceneError(what + ": OpenSubdiv rejects the cage: " +
                         (t_far_error.empty() ? std::string("invalid topology") : t_far_error));
    if (options.level > 0) {
        Far::TopologyRefiner::UniformOptions uniform(options.level);
        uniform.fullTopologyInLastLevel = options.limit; // Limit() needs the last level's edges
        refiner->RefineUniform(uniform);
    }
    if (!t_far_error.empty()) throw SceneError(what + ": OpenSubdiv: " + t_far_error);
    return refiner;
}

/// Interpolates a per-vertex primvar from the cage to the last level.
template <class T>
std::vector<T> refine_primvar(const Far::TopologyRefiner& refiner, std::vector<T> values) {
    const Far::PrimvarRefiner primvars(refiner);
    std::vector<T> next;
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        next.resize(size_t(refiner.GetLevel(level).GetNumVertices()));
        primvars.Interpolate(level, values, next);
        values.swap(next);
    }
    return values;
}

Vec3 vec(const Point& p) {
    return {p.v[0], p.v[1], p.v[2]};
}

/// Area-weighted normals of the triangles around each vertex.
std::vector<Vec3> face_normals(const Mesh& mesh) {
    std::vector<Vec3> n(mesh.positions.size());
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const Vec3 fn =
            cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        n[a] += fn, n[b] += fn, n[c] += fn;
    }
    return n;
}

} // namespace

uint64_t subdivided_face_count(const std::vector<uint32_t>& face_sizes, SubdivScheme scheme,
                               int level) {
    uint64_t faces = 0;
    for (uint32_t s : face_sizes) {
        faces += (scheme == SubdivScheme::CatmullClark && level > 0) ? s : 1;
        if (faces > (uint64_t(1) << 40)) return UINT64_MAX;
    }
    const int doublings = scheme == SubdivScheme::CatmullClark ? level - 1 : level;
    for (int i = 0; i < doublings; ++i) {
        if (faces > (UINT64_MAX >> 2)) return UINT64_MAX;
        faces *= 4;
    }
    return faces;
}

Mesh subdivide(const SubdivCage& cage, const SubdivOptions& options, const std::string& what) {
    check_cage(cage, options, what);
    const std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(cage, options, what);
    const Far::TopologyRefiner& r = *refiner;

    std::vector<Point> points(cage.positions.size());
    for (size_t i = 0; i < points.size(); ++i)
        points[i] = {{cage.positions[i].x, cage.positions[i].y, cage.positions[i].z}};
    points = refine_primvar(r, std::move(points));
    std::vector<Coord> coords;
    if (!cage.uvs.empty()) {
        coords.resize(cage.positions.size());
        for (size_t i = 0; i < coords.size(); ++i)
            coords[i] = {{cage.uvs[2 * i], cage.uvs[2 * i + 1]}};
        coords = refine_primvar(r, std::move(coords));
    }

    std::vector<Point> du, dv;
    if (options.limit) {
        const Far::PrimvarRefiner primvars(r);
        std::vector<Point> at_limit(points.size());
        du.resize(points.size()), dv.resize(points.size());
        primvars.Limit(points, at_limit, du, dv);
        points.swap(at_limit);
        if (!coords.empty()) {
            std::vector<Coord> coords_at_limit(coords.size());
            primvars.Limit(coords, coords_at_limit);
            coords.swap(coords_at_limit);
        }
    }

    Mesh mesh;
    mesh.positions.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) mesh.positions[i] = vec(points[i]);
    for (const Coord& c : coords) mesh.uvs.insert(mesh.uvs.end(), {c.v[0], c.v[1]});

    const Far::TopologyLevel& last = r.GetLevel(r.GetMaxLevel());
    for (int f = 0; f < last.GetNumFaces(); ++f) {
        const Far::ConstIndexArray fv = last.GetFaceVertices(f);
        for (int k = 1; k + 1 < fv.size(); ++k) // a fan: quads and n-gons of level 0
            mesh.indices.insert(mesh.indices.end(),
                                {uint32_t(fv[0]), uint32_t(fv[k]), uint32_t(fv[k + 1])});
    }

    // Smooth normals: the limit surface's (du x dv) where known, else the area-weighted normals
    // of the refined triangles; both point the way the cage's faces wind.
    std::vector<Vec3> normals = face_normals(mesh);
    for (size_t i = 0; i < normals.size(); ++i) {
        Vec3 n = normals[i];
        if (options.limit) {
            const Vec3 ln = cross(vec(du[i]), vec(dv[i]));
            if (is_finite(ln) && length(ln) > 0 && length(n) > 0) n = dot(ln, n) < 0 ? -ln : ln;
        }
        n = normalize(n);
        normals[i] = is_finite(n) && length(n) > 0 ? n : Vec3(0, 0, 1);
    }
    mesh.normals = std::move(normals);
    validate_mesh(mesh, what);
    return mesh;
}

} // namespace sheaf::io

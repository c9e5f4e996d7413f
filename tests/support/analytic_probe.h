// Test support: a scene's analytic objects probed ray by ray on an executing side (the CUDA
// exec, or the CPU exec, whose scene is the same packed copy) against the host's own scene,
// bit for bit. analytic_first_hit (the transform to local space, the shape's spans, CSG, the
// normal back to world space) is shot with rays aimed at each object's bounding sphere;
// isosurfaces are also taken apart: their user function at points inside the container, and
// iso_pieces (the march, the bisection, the gradient) along local rays. Where the sides part,
// the first such ray is printed whole, values as hexadecimal floats, so that one run says at
// which step and on what input they part.
//
// Isosurfaces' normals are the one known exception between the CPU and the GPU
// (gpu/cuda_backend_test.cpp): there, and only there, they may part by kIsoTolerance.
#pragma once

#include "core/frame/buffer.h"
#include "core/frame/scene_copy.h"
#include "core/rsh/cull_units.h"
#include "core/scene/analytic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

// A named namespace: nvcc's extended lambdas may not live in functions of an unnamed one.
namespace sheaf::probe {

constexpr int kRaysPerObject = 512;
constexpr int kPointsPerIso = 4096;
constexpr int kMaxPieces = 4;
constexpr float kIsoTolerance = 1e-3f; // the frame test's bound on isosurface normals

struct Hit {
    uint32_t hit = 0;
    float t = 0;
    uint32_t leaf = 0;
    Vec3 normal;
};

struct Pieces {
    int n = 0;
    double t0[kMaxPieces], t1[kMaxPieces];
    Vec3 n0[kMaxPieces], n1[kMaxPieces];
};

struct Point3d {
    double x, y, z;
};

/// What probe_scene looked at.
struct Tally {
    size_t objects = 0, rays = 0, isosurfaces = 0;
};

SHEAF_HD_INLINE Hit first_hit(const SceneView& s, uint32_t index, const Ray& r) {
    Hit p;
    AnalyticHit h;
    if (!analytic_first_hit(s, index, r, h)) return p;
    p.hit = 1, p.t = h.t, p.leaf = h.leaf, p.normal = h.normal;
    return p;
}

SHEAF_HD_INLINE Pieces pieces(const SceneView& s, uint32_t iso, const Ray& r) {
    Pieces p;
    for (int i = 0; i < kMaxPieces; ++i) p.t0[i] = p.t1[i] = 0, p.n0[i] = p.n1[i] = Vec3(0.0f);
    p.n = iso_pieces(s.isosurfaces[iso], s.functions, r, p.t0, p.t1, p.n0, p.n1, kMaxPieces);
    return p;
}

inline uint32_t bits(float v) {
    uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}
inline uint64_t bits(double v) {
    uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}
inline bool same(Vec3 a, Vec3 b) {
    return bits(a.x) == bits(b.x) && bits(a.y) == bits(b.y) && bits(a.z) == bits(b.z);
}
inline bool same(const Hit& a, const Hit& b) {
    return a.hit == b.hit &&
           (!a.hit || (bits(a.t) == bits(b.t) && a.leaf == b.leaf && same(a.normal, b.normal)));
}
inline bool same(const Pieces& a, const Pieces& b) {
    if (a.n != b.n) return false;
    for (int i = 0; i < a.n; ++i)
        if (bits(a.t0[i]) != bits(b.t0[i]) || bits(a.t1[i]) != bits(b.t1[i]) ||
            !same(a.n0[i], b.n0[i]) || !same(a.n1[i], b.n1[i]))
            return false;
    return true;
}
inline float most_apart(Vec3 a, Vec3 b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
/// most_apart relative to the larger vector: iso_pieces' normals are raw gradients (central
/// differences, of the order of the accuracy), not unit vectors.
inline float relatively_apart(Vec3 a, Vec3 b) {
    const float scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x),
                                  std::fabs(b.y), std::fabs(b.z), 1e-30f});
    return most_apart(a, b) / scale;
}

inline std::string hex(Vec3 v) {
    char b[160];
    std::snprintf(b, sizeof b, "(%a, %a, %a)", double(v.x), double(v.y), double(v.z));
    return b;
}
inline std::string describe(const Ray& r) {
    char b[80];
    std::snprintf(b, sizeof b, " tmin %a tmax %a", double(r.tmin), double(r.tmax));
    return "origin " + hex(r.origin) + " dir " + hex(r.dir) + b;
}
inline std::string describe(const Hit& p) {
    if (!p.hit) return "no hit";
    char b[80];
    std::snprintf(b, sizeof b, "t %a leaf %u normal ", double(p.t), p.leaf);
    return b + hex(p.normal);
}
inline std::string describe(const Pieces& p) {
    std::string s = std::to_string(p.n) + " pieces";
    for (int i = 0; i < p.n; ++i) {
        char b[120];
        std::snprintf(b, sizeof b, "; [%a, %a] ", p.t0[i], p.t1[i]);
        s += b + hex(p.n0[i]) + " " + hex(p.n1[i]);
    }
    return s;
}

/// n rays from a sphere three times around `bound` at points inside it.
inline std::vector<Ray> rays_at(const Sphere& bound, int n, std::mt19937& g) {
    std::normal_distribution<float> normal;
    std::uniform_real_distribution<float> u01(0, 1);
    auto unit = [&] {
        for (;;) {
            const Vec3 v(normal(g), normal(g), normal(g));
            if (length(v) > 1e-3f) return normalize(v);
        }
    };
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        Ray r;
        r.origin = bound.center + unit() * (3 * bound.radius);
        const Vec3 target = bound.center + unit() * (bound.radius * std::cbrt(u01(g)));
        r.dir = normalize(target - r.origin);
        r.tmin = 0, r.tmax = FLT_MAX;
        rays.push_back(r);
    }
    return rays;
}

/// fn(in[i]) for every input on `ex`'s side: the inputs uploaded, one launch, the outputs
/// read back.
template <class Out, class In, class Exec, class Fn>
std::vector<Out> on_side(Exec& ex, const char* name, const std::vector<In>& in, Fn fn) {
    const size_t n = in.size();
    wavefront::DeviceBuffer<In, Exec> inputs(ex, n);
    wavefront::DeviceBuffer<Out, Exec> outputs(ex, n);
    inputs.upload(in.data(), n);
    const In* ip = inputs.data();
    Out* op = outputs.data();
    ex.launch(name, n, [=] SHEAF_HD_LAMBDA(size_t i) { op[i] = fn(ip[i]); });
    return outputs.download();
}

/// A ray aimed at analytic object `index`.
struct AimedRay {
    uint32_t index;
    Ray ray;
};

template <class Exec>
std::vector<Hit> side_hits(Exec& ex, const SceneView& side, const std::vector<AimedRay>& rays) {
    return on_side<Hit>(ex, "probe.analytic", rays, [=] SHEAF_HD_LAMBDA(const AimedRay& r) {
        return first_hit(side, r.index, r.ray);
    });
}

template <class Exec>
std::vector<Pieces> side_pieces(Exec& ex, const SceneView& side, uint32_t iso,
                                const std::vector<Ray>& rays) {
    return on_side<Pieces>(ex, "probe.iso", rays,
                           [=] SHEAF_HD_LAMBDA(const Ray& r) { return pieces(side, iso, r); });
}

template <class Exec>
std::vector<double> side_values(Exec& ex, const SceneView& side, uint32_t program,
                                const std::vector<Point3d>& points) {
    const FnView fv = side.functions;
    return on_side<double>(ex, "probe.function", points, [=] SHEAF_HD_LAMBDA(const Point3d& p) {
        return fn_eval3(fv, program, p.x, p.y, p.z);
    });
}

/// The six values of the function that the gradient of host pieces `p` took at its first
/// end, on both sides: where normals part while the ends agree, these say whether the
/// function does there.
template <class Exec>
void print_gradient_samples(Exec& ex, const SceneView& host, const SceneView& side, uint32_t iso,
                            const Ray& r, const Pieces& p) {
    if (p.n == 0) return;
    const IsoRef& s = host.isosurfaces[iso];
    const double t = p.t0[0] > -FLT_MAX ? p.t0[0] : p.t1[0];
    const Vec3 q(float(r.origin.x + r.dir.x * t), float(r.origin.y + r.dir.y * t),
                 float(r.origin.z + r.dir.z * t));
    const double h = s.accuracy > 1e-5f ? s.accuracy : 1e-5;
    std::vector<Point3d> pts;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            double c[3] = {q.x, q.y, q.z};
            c[axis] += sign * h;
            pts.push_back({c[0], c[1], c[2]});
        }
    const std::vector<double> sv = side_values(ex, side, s.program, pts);
    for (size_t i = 0; i < pts.size(); ++i) {
        const double hv = fn_eval3(host.functions, s.program, pts[i].x, pts[i].y, pts[i].z);
        std::printf("    f(%a, %a, %a): host %a %s %a%s\n", pts[i].x, pts[i].y, pts[i].z, hv,
                    Exec::kName, sv[i], bits(hv) == bits(sv[i]) ? "" : "  <- differs");
    }
}

/// Isosurface `iso` taken apart: its function at points in its container (exactly equal),
/// then its pieces along local rays (ends exactly equal, gradients within kIsoTolerance of
/// their size).
template <class Exec>
void probe_isosurface(Exec& ex, const std::string& name, const SceneView& host,
                      const SceneView& side, uint32_t iso, std::mt19937& g) {
    const IsoRef& s = host.isosurfaces[iso];
    const Sphere bound{Vec3(s.bound[0], s.bound[1], s.bound[2]), s.bound[3]};
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point3d> pts;
    while (pts.size() < size_t(kPointsPerIso)) {
        const double x = u(g), y = u(g), z = u(g);
        if (x * x + y * y + z * z > 1) continue;
        pts.push_back({bound.center.x + bound.radius * x, bound.center.y + bound.radius * y,
                       bound.center.z + bound.radius * z});
    }
    const std::vector<double> sv = side_values(ex, side, s.program, pts);
    size_t values_apart = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        const double hv = fn_eval3(host.functions, s.program, pts[i].x, pts[i].y, pts[i].z);
        if (bits(hv) == bits(sv[i])) continue;
        if (values_apart++ == 0)
            std::printf("%s isosurface %u: f(%a, %a, %a) host %a %s %a\n", name.c_str(), iso,
                        pts[i].x, pts[i].y, pts[i].z, hv, Exec::kName, sv[i]);
    }
    EXPECT_EQ(values_apart, 0u) << name << " isosurface " << iso << ": its function differs on "
                                << Exec::kName;

    const std::vector<Ray> rays = rays_at(bound, kRaysPerObject, g);
    const std::vector<Pieces> sp = side_pieces(ex, side, iso, rays);
    size_t apart = 0, found = 0;
    float worst = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Pieces hp = pieces(host, iso, rays[i]);
        found += hp.n > 0;
        if (same(hp, sp[i])) continue;
        bool ends_agree = hp.n == sp[i].n;
        for (int k = 0; ends_agree && k < hp.n; ++k) {
            ends_agree = bits(hp.t0[k]) == bits(sp[i].t0[k]) && bits(hp.t1[k]) == bits(sp[i].t1[k]);
            worst = std::max({worst, relatively_apart(hp.n0[k], sp[i].n0[k]),
                              relatively_apart(hp.n1[k], sp[i].n1[k])});
        }
        if (!ends_agree) worst = INFINITY;
        if (apart++ == 0) {
            std::printf("%s isosurface %u, local ray %s\n  host: %s\n  %s: %s\n", name.c_str(), iso,
                        describe(rays[i]).c_str(), describe(hp).c_str(), Exec::kName,
                        describe(sp[i]).c_str());
            print_gradient_samples(ex, host, side, iso, rays[i], hp);
        }
    }
    if (apart)
        std::printf("%s isosurface %u: %zu of %zu rays differ (%s), gradients at most %g apart "
                    "relative to their size\n",
                    name.c_str(), iso, apart, rays.size(),
                    worst == INFINITY ? "ends too" : "normals only", double(worst));
    EXPECT_GT(found, rays.size() / 20) << name << " isosurface " << iso << ": rays miss it";
    EXPECT_LE(worst, kIsoTolerance) << name << " isosurface " << iso << " on " << Exec::kName;
}

/// Every analytic object of `scene` (bounded ones: planes are not aimed at) and every
/// isosurface, on `ex`'s side against the host. Failures are test failures.
template <class Exec>
void probe_scene(Exec& ex, const std::string& name, const PreparedScene& scene, Tally& tally) {
    if (scene.analytic_root.empty()) return;
    const std::shared_ptr<const CullUnits> units = cull_units_for(scene, RenderSettings{});
    wavefront::DeviceScene<Exec> uploaded(ex, scene, *units);
    const SceneView host(scene), &side = uploaded.view;
    std::mt19937 g(2024);
    auto is_iso = [&](uint32_t leaf) {
        return leaf < scene.shapes.size() && scene.shapes[leaf].shape.kind == ShapeKind::Isosurface;
    };
    std::vector<AimedRay> rays;
    for (uint32_t a = 0; a < host.analytic_count; ++a) {
        const Sphere& b = scene.prim_sphere[host.tri_count + a];
        if (!(b.radius > 0) || !(b.radius < 1e6f)) continue; // unbounded (planes)
        ++tally.objects;
        for (const Ray& r : rays_at(b, kRaysPerObject, g)) rays.push_back({a, r});
    }
    tally.rays += rays.size();
    const std::vector<Hit> sh = side_hits(ex, side, rays);
    size_t apart = 0, iso_apart = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Hit hh = first_hit(host, rays[i].index, rays[i].ray);
        if (same(hh, sh[i])) continue;
        const bool iso_normal_only = hh.hit && sh[i].hit && bits(hh.t) == bits(sh[i].t) &&
                                     hh.leaf == sh[i].leaf && is_iso(hh.leaf) &&
                                     most_apart(hh.normal, sh[i].normal) <= kIsoTolerance;
        if ((iso_normal_only ? iso_apart : apart)++ == 0)
            std::printf("%s object %u (%s), ray %s\n  host: %s\n  %s: %s\n", name.c_str(),
                        rays[i].index, iso_normal_only ? "an isosurface's normal" : "differs",
                        describe(rays[i].ray).c_str(), describe(hh).c_str(), Exec::kName,
                        describe(sh[i]).c_str());
    }
    if (apart || iso_apart)
        std::printf("%s: %zu of %zu rays differ, %zu more in isosurface normals alone\n",
                    name.c_str(), apart, rays.size(), iso_apart);
    EXPECT_EQ(apart, 0u) << name << ": analytic hits differ on " << Exec::kName;
    for (uint32_t k = 0; k < uint32_t(scene.isosurfaces.size()); ++k, ++tally.isosurfaces)
        probe_isosurface(ex, name, host, side, k, g);
}

} // namespace sheaf::probe

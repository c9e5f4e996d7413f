#include "core/frame/photon_pass.h"

#include "core/base/error.h"
#include "core/base/parallel.h"
#include "core/base/timer.h"
#include "core/frame/frame_stats.h"
#include "core/frame/host_tracer.h"
#include "core/rays/ray_gen.h"
#include "core/scene/scene_view.h"
#include "core/shading/shade.h"
#include "core/shading/surface_hit.h"
#include "core/texture/lattice_hash.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <string>

namespace sheaf {
namespace {

/// One light shooting at one target: rings of photons around the way to the target's
/// bounding sphere (a point or spot light: rings of directions `dtheta` apart; a parallel
/// light: rings of points `spread` apart on a disc across the light's direction).
struct Emitter {
    uint32_t light = 0, object = 0;
    bool parallel = false;
    Vec3 center, axis, u, v; // the target's centre; the shooting axis and two across it
    float spread = 0; // POV-Ray's photon spread: spacing at unit distance (parallel: spacing)
    float step = 0;   // between rings: an angle, or a length for a parallel light
};

/// A ring of an emitter: `count` photons from shot number `first`.
struct Ring {
    uint64_t first = 0;
    uint32_t emitter = 0, index = 0, count = 0;
};

/// A photon path's state beside its ray.
struct PathState {
    uint32_t emitter = 0;
    uint32_t level = 0; // surfaces met so far
    float depth = 0;    // length travelled so far
};

/// What a photon ray brings about where it lands: a kept photon, and up to two rays on.
struct Landing {
    bool keep = false;
    Photon photon;
    uint32_t children = 0;
    Ray ray[2];
    Vec3 weight[2];
};

/// Every emitter of the scene and its rings; `total` receives the photons they shoot.
void plan_emitters(const PreparedScene& scene, float spacing, std::vector<Emitter>& emitters,
                   std::vector<Ring>& rings, uint64_t& total) {
    total = 0;
    emitters.clear(), rings.clear();
    for (uint32_t li = 0; li < scene.lights.size(); ++li) {
        const Light& l = scene.lights[li];
        if (l.shadowless || max_component(l.color) <= 0) continue;
        if (l.photon_reflection == PhotonSwitch::Off && l.photon_refraction == PhotonSwitch::Off)
            continue;
        for (uint32_t o = 0; o < scene.object_photons.size(); ++o) {
            const PhotonObject& po = scene.object_photons[o];
            const Sphere& s = scene.object_sphere[o];
            if (!(po.target > 0) || !(std::fabs(s.radius) <= 1e30f)) continue; // unbounded: no aim
            Emitter e;
            e.light = li, e.object = o, e.center = s.center;
            e.parallel = l.type == LightType::Parallel;
            float max_step; // how far the rings go: an angle, or the disc's radius
            if (e.parallel) {
                e.axis = normalize(l.direction);
                e.spread = po.target * spacing;
                e.step = e.spread;
                max_step = s.radius;
            } else {
                const Vec3 to = s.center - l.position;
                const float dist = length(to);
                e.axis = dist > 0 ? to / dist : Vec3(0, 0, 1);
                if (!(std::max(dist, s.radius) > 0)) continue; // a point target at the light
                e.spread = po.target * spacing / std::max(dist, s.radius);
                e.step = std::atan(e.spread);
                max_step = dist > s.radius ? std::asin(s.radius / dist) : float(kPi);
            }
            raygen_detail::basis(e.axis, e.u, e.v);
            if (!(e.step > 0)) continue;
            const uint32_t ei = uint32_t(emitters.size());
            emitters.push_back(e);
            const double k_max = std::floor(double(max_step) / e.step);
            if (k_max > 1e7) throw RenderError("photons: the spacing is too fine for the scene");
            for (uint32_t k = 0; k <= uint32_t(k_max); ++k) {
                // Photons around ring k: its circumference over the step (one at the axis).
                const double around =
                    e.parallel ? 2 * kPi * k : 2 * kPi * std::sin(double(k) * e.step) / e.step;
                const uint32_t n = k == 0 ? 1u : uint32_t(std::max(1.0, std::floor(around + 0.5)));
                rings.push_back({total, ei, k, n});
                total += n;
                if (total > kMaxPhotonsShot)
                    throw RenderError("photons: spacing " + std::to_string(spacing) +
                                      " would shoot more than " +
                                      std::to_string(kMaxPhotonsShot / 1000000) +
                                      " million photons; raise the spacing (or the targets' "
                                      "multipliers)");
            }
        }
    }
}

/// Shot number i: its ray and the light it carries (zero outside a spotlight's cone).
void photon_ray(const PreparedScene& scene, const std::vector<Emitter>& emitters,
                const std::vector<Ring>& rings, uint64_t i, float jitter, float far, Ray& ray,
                Vec3& weight, uint32_t& emitter) {
    const auto it = std::upper_bound(rings.begin(), rings.end(), i,
                                     [](uint64_t x, const Ring& r) { return x < r.first; }) -
                    1;
    const Ring& ring = *it;
    const Emitter& e = emitters[ring.emitter];
    const Light& l = scene.lights[e.light];
    const uint32_t j = uint32_t(i - ring.first);
    const uint32_t salt = lattice_hash(int(ring.emitter), int(ring.index), int(j), 0x70686f74u);
    const float ja = (hash_unit(salt) - 0.5f) * jitter,
                jb = (hash_unit(salt ^ 0x9e3779b9u) - 0.5f) * jitter;
    const float radial =
        std::max(0.0f, (float(ring.index) + (ring.index ? ja : 0.5f * std::fabs(ja))) * e.step);
    const float phi = 2.0f * float(kPi) * (float(j) + 0.5f + jb) / float(ring.count);
    const Vec3 across = e.u * std::cos(phi) + e.v * std::sin(phi);
    emitter = ring.emitter;
    ray.tmin = 0.0f;
    ray.tmax = FLT_MAX;
    if (e.parallel) {
        const Vec3 p = e.center + across * radial;
        ray.dir = e.axis;
        ray.origin = p - e.axis * far;
        weight = l.color * l.photon_weight;
        return;
    }
    ray.dir = normalize(e.axis * std::cos(radial) + across * std::sin(radial));
    ray.origin = l.position;
    weight = l.color * l.photon_weight;
    if (l.type == LightType::Spot) weight = weight * spot_factor(l, ray.dir);
}

/// Where photon ray `ray` (state `ps`, carrying `w`) lands on hit `closest`.
Landing land(const PreparedScene& scene, const SceneView& view,
             const std::vector<Emitter>& emitters, const Ray& ray, uint64_t closest, Vec3 w,
             const PathState& ps, uint32_t max_level, const RayGenParams& params) {
    Landing out;
    const Emitter& e = emitters[ps.emitter];
    const uint32_t prim = hit_prim(closest);
    const uint32_t object = view.prim_object[prim];
    if (ps.level == 0 && object != e.object) return out; // the light's way to its target is blocked
    SurfaceHit h = make_surface_hit(view, ray, prim, hit_t(closest));
    const Material& m = view.materials[h.material];
    if (!h.front) w = w * interior_fade(m, h.t); // it crossed the object's inside
    const float depth = ps.depth + h.t;
    const Light& l = scene.lights[e.light];
    if (ps.level >= 1 && !view.prim_flag(prim, kNoPhotonCollect)) {
        float k = e.spread * e.spread;
        if (!e.parallel) k *= depth * depth;
        // Parallel lights do not fade (their paths start far outside the scene).
        if (!e.parallel && l.fade_distance > 0 && l.fade_power > 0)
            k *= 2.0f / (1.0f + std::pow(depth / l.fade_distance, l.fade_power));
        const Vec3 power = w * k;
        out.keep = is_finite(h.position) && std::isfinite(power.x + power.y + power.z);
        out.photon.position = h.position;
        out.photon.power = power;
        out.photon.from = -ray.dir;
    }
    if (ps.level + 1 >= max_level) return out;
    const PhotonObject& po = scene.object_photons[object];
    const bool reflect_on = photon_switch_on(po.reflection, l.photon_reflection);
    const bool refract_on = photon_switch_on(po.refraction, l.photon_refraction);
    const float bailout = scene.photons.adc_bailout;
    h.throughput = w;
    const Vec3 mirror = mirror_weight(m, h);
    bool total_internal = false;
    if (refract_on) {
        // What passes: tinted by the colour (filter) or not (transmit); no Fresnel share, as
        // POV-Ray's photons.
        Vec3 pass = h.albedo * h.filter + Vec3(h.transmit);
        if (m.conserve_energy) pass = pass * std::max(0.0f, 1.0f - max_component(mirror));
        if (max_component(w * pass) > bailout) {
            const float eta = h.front ? 1.0f / m.ior : m.ior;
            Vec3 dir;
            if (m.ior == 1.0f) {
                dir = ray.dir;
            } else if (!refract(h.incoming, h.normal, eta, dir)) {
                total_internal = true; // the light turns back whole, unfiltered
                dir = mirror_direction(h);
                pass = Vec3(1.0f);
            }
            out.ray[out.children] = bounce_ray(h, dir, total_internal ? 1.0f : -1.0f, params);
            out.weight[out.children++] = w * pass;
        }
    }
    if (reflect_on && !total_internal && max_component(w * mirror) > bailout) {
        out.ray[out.children] = bounce_ray(h, mirror_direction(h), 1.0f, params);
        out.weight[out.children++] = w * mirror;
    }
    return out;
}

void build_tree(std::vector<Photon>& p, size_t lo, size_t hi) { // [lo, hi]
    if (hi <= lo) {
        if (hi == lo) p[lo].axis = 0;
        return;
    }
    Vec3 mn(INFINITY), mx(-INFINITY);
    for (size_t i = lo; i <= hi; ++i) mn = vmin(mn, p[i].position), mx = vmax(mx, p[i].position);
    const Vec3 ext = mx - mn;
    const uint32_t a = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    const size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        p.begin() + lo, p.begin() + mid, p.begin() + hi + 1, [a](const Photon& x, const Photon& y) {
            return photon_detail::axis_of(x.position, a) < photon_detail::axis_of(y.position, a);
        });
    p[mid].axis = a;
    if (mid > lo) build_tree(p, lo, mid - 1);
    build_tree(p, mid + 1, hi);
}

/// The squared distance of the k-th nearest photon to p (all of them when fewer), plain
/// distances, and how many that is.
float kth_nearest2(const std::vector<Photon>& tree, Vec3 p, uint32_t k, float limit2,
                   uint32_t& found) {
    found = 0;
    if (k == 0 || tree.empty()) return limit2;
    std::priority_queue<float> best; // the k smallest so far, largest on top
    float r2 = limit2;
    std::vector<std::pair<size_t, size_t>> stack{{0, tree.size() - 1}};
    while (!stack.empty()) {
        const auto [lo, hi] = stack.back();
        stack.pop_back();
        const size_t mid = lo + (hi - lo) / 2;
        const Photon& ph = tree[mid];
        const Vec3 v = ph.position - p;
        const float d2 = dot(v, v);
        if (d2 < r2) {
            best.push(d2);
            if (best.size() > k) best.pop();
            if (best.size() == k) r2 = best.top();
        }
        const float delta = photon_detail::axis_of(v, ph.axis), r = std::sqrt(r2);
        if (mid > lo && delta > -r) stack.push_back({lo, mid - 1});
        if (mid < hi && delta < r) stack.push_back({mid + 1, hi});
    }
    found = uint32_t(best.size());
    if (best.size() == k) return best.top();
    // Fewer than k: within the limit, or, searching without one, within the farthest found.
    if (std::isfinite(limit2) || best.empty()) return limit2;
    float farthest = 0;
    for (; !best.empty(); best.pop()) farthest = std::max(farthest, best.top());
    return farthest;
}

} // namespace

void build_photon_tree(std::vector<Photon>& photons) {
    if (!photons.empty()) build_tree(photons, 0, photons.size() - 1);
}

float estimate_photon_radius(const std::vector<Photon>& tree, uint32_t gather_max) {
    if (tree.empty()) return 0.0f;
    // A sample spread evenly over the tree: 5% of the photons, from 100 to 1000.
    const size_t n = tree.size();
    const size_t samples = std::min(n, std::clamp<size_t>(n / 20, 100, 1000));
    auto sample = [&](size_t i) { return tree[i * n / samples].position; };
    double sum = 0;
    for (size_t i = 0; i < samples; ++i) {
        uint32_t found = 0;
        const float r2 = kth_nearest2(tree, sample(i), gather_max, INFINITY, found);
        const double density = r2 > 0 && std::isfinite(r2) ? found / (kPi * double(r2))
                               : i > 0                     ? sum / double(i)
                                                           : 0.0;
        sum += density;
    }
    const double mean = sum / double(samples);
    if (!(mean > 0)) return 0.0f;
    double radius = std::sqrt(gather_max / (mean * kPi));
    // Widened by the share of samples much sparser than the mean (POV-Ray's factor 20); not
    // when the whole map holds no more than gather_max photons (every sample would then count
    // as sparse against a radius sized for gather_max).
    if (n <= gather_max) return float(radius);
    size_t sparse = 0;
    for (size_t i = 0; i < samples; ++i) {
        uint32_t found = 0;
        float r2 = kth_nearest2(tree, sample(i), gather_max, float(radius * radius), found);
        if (!(r2 > 0)) continue;
        const double density = found / (kPi * double(r2));
        if (density < 0.7 * mean && density > 0.05 * mean) ++sparse;
    }
    radius *= 1.0 + 20.0 * double(sparse) / double(samples);
    return float(radius);
}

PhotonMap shoot_photons(const PreparedScene& scene, const CullUnits& units, const RenderSettings& s,
                        Stats& st, MemoryTracker& memory) {
    PhotonMap map;
    if (!scene.has_photons()) return map;
    PhaseTimer timer(st, "time_ms.photons");
    const RayGenParams params = frame_ray_params(scene, s);
    const SceneView view(scene);
    std::vector<Emitter> emitters;
    std::vector<Ring> rings;
    uint64_t total = 0;
    const PhotonSettings& ps = scene.photons;
    float spacing = ps.spacing;
    if (ps.count > 0) { // the spacing that shoots about `count`: photons go as 1 / spacing^2
        // A first guess of a tenth of the largest target, so the first plans stay small.
        float largest = 0;
        for (size_t o = 0; o < scene.object_photons.size(); ++o)
            if (scene.object_photons[o].target > 0 && std::isfinite(scene.object_sphere[o].radius))
                largest = std::max(largest, scene.object_sphere[o].radius);
        spacing = largest > 0 ? 0.1f * largest : 1.0f;
        for (int i = 0; i < 4; ++i) {
            plan_emitters(scene, spacing, emitters, rings, total);
            if (total == 0) break;
            spacing *= float(std::sqrt(double(total) / double(ps.count)));
        }
    }
    plan_emitters(scene, spacing, emitters, rings, total);
    const uint32_t max_level =
        std::max(2u, ps.max_trace_level > 0 ? ps.max_trace_level : uint32_t(s.trace_depth + 1));
    // Photons are traced in pieces of at most kChunk rays, each piece's rays on to the next
    // surface, then the pieces of what they send on, depth first: a path that splits at
    // every surface never holds more than a few pieces per level at once (each ray with its
    // state and landing about 200 bytes: 50 MiB a piece).
    constexpr uint64_t kChunk = uint64_t(1) << 18;
    constexpr size_t kLandSlice = size_t(1) << 14;
    uint64_t shot = 0, traced = 0;
    size_t counted = 0; // photons the memory tracker counts
    std::function<void(RayBatch&, std::vector<PathState>&)> trace_piece =
        [&](RayBatch& batch, std::vector<PathState>& state) {
            traced += batch.size();
            if (traced > kMaxPhotonRays)
                throw RenderError("photons: the photons' paths split into more than " +
                                  std::to_string(kMaxPhotonRays / 1000000) +
                                  " million rays; raise the spacing or lower max_trace_level");
            TraceResult r;
            trace_batch(scene, units, batch, s, st, memory, r);
            RayBatch next(RayType::Photon, memory);
            std::vector<PathState> next_state;
            // The landings a slice of kLandSlice rays at a time (a landing is 136 bytes: a
            // whole piece's at once would be 34 MiB), taken in ray order: the same map every
            // run.
            {
                std::vector<Landing> landing(std::min<size_t>(batch.size(), kLandSlice));
                for (size_t first = 0; first < batch.size(); first += kLandSlice) {
                    const size_t n = std::min<size_t>(kLandSlice, batch.size() - first);
                    parallel_for("photons.land", n, [&](size_t j) {
                        const size_t i = first + j;
                        landing[j] = r.closest[i] == kNoHit
                                         ? Landing{}
                                         : land(scene, view, emitters, batch.rays[i], r.closest[i],
                                                batch.weight[i], state[i], max_level, params);
                    });
                    for (size_t j = 0; j < n; ++j) {
                        const size_t i = first + j;
                        const Landing& g = landing[j];
                        if (g.keep) map.photons.push_back(g.photon);
                        for (uint32_t c = 0; c < g.children; ++c) {
                            next.rays.push_back(g.ray[c]);
                            next.pixel.push_back(0);
                            next.weight.push_back(g.weight[c]);
                            next_state.push_back({state[i].emitter, state[i].level + 1,
                                                  state[i].depth + hit_t(r.closest[i])});
                        }
                    }
                }
            }
            if (map.photons.size() > kMaxPhotonsShot)
                throw RenderError("photons: more than " +
                                  std::to_string(kMaxPhotonsShot / 1000000) +
                                  " million photons kept; raise the spacing or lower "
                                  "max_trace_level");
            // Kept for the whole frame: counted as they come, refused when they would not fit.
            memory.add(int64_t((map.photons.size() - counted) * sizeof(Photon)));
            counted = map.photons.size();
            batch = RayBatch(RayType::Photon, memory); // this piece is done with
            state = {};
            for (size_t first = 0; first < next.size(); first += kChunk) {
                const size_t n = std::min<size_t>(kChunk, next.size() - first);
                RayBatch piece(RayType::Photon, memory);
                piece.rays.assign(next.rays.begin() + first, next.rays.begin() + first + n);
                piece.pixel.assign(n, 0);
                piece.weight.assign(next.weight.begin() + first, next.weight.begin() + first + n);
                std::vector<PathState> piece_state(next_state.begin() + first,
                                                   next_state.begin() + first + n);
                trace_piece(piece, piece_state);
            }
        };
    for (uint64_t first = 0; first < total; first += kChunk) {
        const uint64_t n = std::min(kChunk, total - first);
        RayBatch batch(RayType::Photon, memory);
        std::vector<PathState> state;
        {
            std::vector<Ray> rays(n);
            std::vector<Vec3> weight(n);
            std::vector<uint32_t> emitter(n);
            parallel_for("photons.emit", n, [&](size_t i) {
                photon_ray(scene, emitters, rings, first + i, ps.jitter, params.far, rays[i],
                           weight[i], emitter[i]);
            });
            for (size_t i = 0; i < n; ++i) {
                if (!(max_component(weight[i]) > 0)) continue;
                batch.rays.push_back(rays[i]);
                batch.pixel.push_back(0);
                batch.weight.push_back(weight[i]);
                state.push_back({emitter[i], 0, 0.0f});
            }
            shot += batch.size();
        }
        if (batch.size() > 0) trace_piece(batch, state);
    }
    build_photon_tree(map.photons);
    PhotonMapView& v = map.settings;
    v.radius = (ps.radius > 0 ? ps.radius : estimate_photon_radius(map.photons, ps.gather_max)) *
               ps.radius_scale;
    v.step = 2.0f * v.radius;
    v.steps = ps.steps;
    v.gather_min = ps.gather_min, v.gather_max = ps.gather_max;
    v.expand_min = ps.expand_min, v.expand_tolerance = ps.expand_tolerance;
    st.set("photons.shot", double(shot));
    st.set("photons.stored", double(map.photons.size()));
    st.set("photons.radius", double(v.radius));
    st.set("photons.spacing", double(spacing));
    return map;
}

} // namespace sheaf

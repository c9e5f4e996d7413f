#include "core/rsh/trace.h"

#include "core/base/parallel.h"
#include "core/base/timer.h"
#include "core/geometry/ray_triangle.h"
#include "core/hash/ray_hash.h"
#include "core/rsh/hierarchy.h"
#include "core/rsh/trace_kernels.h"
#include "core/sort/ray_order.h"

#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <cfloat>
#include <chrono>
#include <string>

namespace sheaf {
namespace {

struct Pair {
    uint32_t node, prim;
};

struct Counter {
    std::atomic<uint64_t> tests{0}, hits{0};
    void add(uint64_t t, uint64_t h) {
        tests.fetch_add(t, std::memory_order_relaxed);
        hits.fetch_add(h, std::memory_order_relaxed);
    }
    TestCount count() const { return {tests.load(), hits.load()}; }
};

HitSinks sinks(const HitSpan& out) {
    return {out.closest, out.occluded, out.pass_log};
}

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------------
// brute: every ray against every primitive. Any-hit queries stop at the first hit.
void trace_brute(const SceneView& scene, const RaySpan& batch, bool any, bool shadow,
                 uint8_t skip, Counter& final, const HitSpan& out) {
    const HitSinks sink = sinks(out);
    parallel_for_range(
        "brute.trace", batch.n,
        [&](size_t b, size_t e) {
            uint64_t tests = 0, hits = 0;
            for (size_t i = b; i < e; ++i) {
                const TestCount c =
                    brute_trace_ray(scene, batch.rays[i], uint32_t(i), any, shadow, skip, sink);
                tests += c.tests, hits += c.hits;
                out.tests[i] = uint32_t(std::min<uint64_t>(c.tests, 0xFFFFFFFFu));
            }
            final.add(tests, hits);
        },
        16);
}

// ---------------------------------------------------------------------------------------------
// The hierarchy traversal with bounded candidate lists.
class Traversal {
  public:
    Traversal(const PreparedScene& scene, const CullUnits& units, const RayHierarchy& h,
              const TrackedVector<Ray>& rays, const std::vector<uint32_t>& perm, bool any,
              bool shadow, uint8_t skip, size_t batch, MemoryTracker& memory, const HitSpan& out)
        : levels_(size_t(h.depth) + 1), scene_(scene), units_(units), view_(scene),
          sinks_(sinks(out)), h_(h), rays_(rays), perm_(perm), any_(any), shadow_(shadow),
          skip_(skip), batch_(batch),
          local_(TrackedVector<Pair>(TrackedAllocator<Pair>(&memory))) {
        for (int k = 0; k <= h.depth; ++k) buffers_.push_back(tracked_vector<Pair>(memory));
        leaf_pairs_.assign(h.node_count(1), 0);
    }

    void run(bool cull) {
        const int top = h_.depth;
        const size_t top_nodes = h_.node_count(top);
        const size_t prims = scene_.prim_count();
        // At most batch_ candidate pairs come out of one group of top nodes.
        const size_t group = std::max<size_t>(1, batch_ / std::max<size_t>(1, prims));
        const RayNode* nodes = h_.levels[size_t(top) - 1].data();
        for (size_t g0 = 0; g0 < top_nodes; g0 += group) {
            const size_t g1 = std::min(top_nodes, g0 + group);
            for (auto& l : local_) l.clear();
            parallel_for_range(
                "rsh.top", g1 - g0,
                [&](size_t b, size_t e) {
                    auto& outp = local_.local();
                    uint64_t ot = 0, oh = 0, lt = 0, lh = 0;
                    for (size_t i = g0 + b; i < g0 + e; ++i) {
                        const RayNode& n = nodes[i];
                        auto test_range = [&](uint32_t p0, uint32_t p1) {
                            for (uint32_t p = p0; p < p1; ++p) {
                                if (skip_ && scene_.prim_flag(p, skip_)) continue;
                                ++lt;
                                if (node_hits_sphere(n, scene_.prim_sphere[p])) {
                                    ++lh;
                                    outp.push_back({uint32_t(i), p});
                                }
                            }
                        };
                        if (cull) {
                            // Each object's sphere, then, where it is hit and the object
                            // is split (cull.cluster), the spheres of its runs.
                            for (uint32_t o = 0; o < uint32_t(scene_.object_count()); ++o) {
                                ++ot;
                                if (!node_hits_sphere(n, scene_.object_sphere[o])) continue;
                                ++oh;
                                const uint32_t u0 = units_.object_units[o];
                                if (!units_.split(o)) {
                                    test_range(units_.begin[u0], units_.begin[u0 + 1]);
                                    continue;
                                }
                                for (uint32_t u = u0; u < units_.object_units[o + 1]; ++u) {
                                    ++ot;
                                    if (!node_hits_sphere(n, units_.sphere[u])) continue;
                                    ++oh;
                                    test_range(units_.begin[u], units_.begin[u + 1]);
                                }
                            }
                        } else {
                            test_range(0, uint32_t(prims));
                        }
                    }
                    objects_.add(ot, oh);
                    levels_[size_t(top)].add(lt, lh);
                },
                1);
            gather(buffers_[size_t(top)]);
            descend(top);
        }
    }

    Counter objects_, final_;
    std::vector<Counter> levels_; // index k: level k
    double final_ms_ = 0;
    // Candidate primitives of each level-1 node: every ray of the node is tested against each.
    std::vector<uint32_t> leaf_pairs_;

  private:
    void gather(TrackedVector<Pair>& dst) {
        size_t n = 0;
        for (auto& l : local_) n += l.size();
        dst.clear();
        dst.reserve(n);
        for (auto& l : local_) dst.insert(dst.end(), l.begin(), l.end());
    }

    // buffers_[level] holds candidate pairs of nodes at `level`; expands them to level - 1.
    void descend(int level) {
        const TrackedVector<Pair>& pairs = buffers_[size_t(level)];
        if (level == 1) {
            finals(pairs);
            return;
        }
        const RayNode* children = h_.levels[size_t(level) - 2].data();
        const size_t chunk = std::max<size_t>(1, batch_ / size_t(h_.arity));
        for (size_t c0 = 0; c0 < pairs.size(); c0 += chunk) {
            const size_t c1 = std::min(pairs.size(), c0 + chunk);
            for (auto& l : local_) l.clear();
            parallel_for_range(
                "rsh.level", c1 - c0,
                [&](size_t b, size_t e) {
                    auto& outp = local_.local();
                    uint64_t t = 0, hcount = 0;
                    for (size_t i = c0 + b; i < c0 + e; ++i) {
                        const Pair pr = pairs[i];
                        const Sphere& s = scene_.prim_sphere[pr.prim];
                        for (size_t c = h_.first_child(pr.node),
                                    last = h_.last_child(level, pr.node);
                             c < last; ++c) {
                            ++t;
                            if (node_hits_sphere(children[c], s)) {
                                ++hcount;
                                outp.push_back({uint32_t(c), pr.prim});
                            }
                        }
                    }
                    levels_[size_t(level) - 1].add(t, hcount);
                },
                256);
            gather(buffers_[size_t(level) - 1]);
            descend(level - 1);
        }
    }

    void finals(const TrackedVector<Pair>& pairs) {
        const auto t0 = std::chrono::steady_clock::now();
        parallel_for_range(
            "rsh.final", pairs.size(),
            [&](size_t b, size_t e) {
                uint64_t t = 0, hcount = 0;
                for (size_t i = b; i < e; ++i) {
                    const Pair pr = pairs[i];
                    std::atomic_ref<uint32_t>(leaf_pairs_[pr.node])
                        .fetch_add(1, std::memory_order_relaxed);
                    const size_t first = h_.first_child(pr.node), last = h_.last_child(1, pr.node);
                    t += last - first;
                    hcount += final_tests(view_, rays_.data(), perm_.data(), first, last,
                                          pr.prim, any_, shadow_, sinks_);
                }
                final_.add(t, hcount);
            },
            256);
        final_ms_ += ms_since(t0);
    }

    const PreparedScene& scene_;
    const CullUnits& units_;
    SceneView view_;
    HitSinks sinks_;
    const RayHierarchy& h_;
    const TrackedVector<Ray>& rays_;
    const std::vector<uint32_t>& perm_;
    bool any_;
    bool shadow_; // shadow rays pass transparent primitives (record_pass)
    uint8_t skip_; // primitives whose objects have these flags are not candidates
    size_t batch_;
    tbb::enumerable_thread_specific<TrackedVector<Pair>> local_;
    std::vector<TrackedVector<Pair>> buffers_;
};

// Keys of the batch under hash.mode (rah: none). Returns the number of 32-bit words per key.
// Paper 003's static 3D order: 8 x 16-pixel tiles of the sample grid, one sample index (AO) or
// light (shadow rays) at a time; a 64-bit key as two words.
int static3d_keys(const RaySpan& batch, const RenderSettings& s, std::vector<uint32_t>& keys) {
    const size_t n = batch.n;
    const uint64_t grid_w = uint64_t(s.width) * uint64_t(s.aa_samples);
    const uint64_t grid_h = uint64_t(s.height) * uint64_t(s.aa_samples);
    const uint64_t tiles_x = (grid_w + 7) / 8, tiles = tiles_x * ((grid_h + 15) / 16);
    const uint64_t per_pixel = batch.type == RayType::Ao ? uint64_t(std::max(1, s.ao_samples))
                               : batch.type == RayType::Diffuse
                                   ? uint64_t(std::max(1, s.radiosity_samples))
                                   : 1;
    keys.resize(n * 2);
    parallel_for(
        "hash.static3d", n,
        [&](size_t i) {
            const uint64_t sample = batch.type == RayType::Shadow ? batch.light[i]
                                                                  : uint64_t(i) % per_pixel;
            const uint64_t key = static3d_key(batch.pixel[i], sample, grid_w, tiles_x, tiles);
            keys[2 * i] = uint32_t(key), keys[2 * i + 1] = uint32_t(key >> 32);
        },
        4096);
    return 2;
}

int hash_rays(const PreparedScene& scene, const RaySpan& batch, const RenderSettings& s,
              HashMode mode, std::vector<uint32_t>& keys) {
    const size_t n = batch.n;
    // static1d is the generation order: a pixel's rays together (paper 003's 1D work groups).
    if (mode == HashMode::None || mode == HashMode::Static1d) return 0;
    if (mode == HashMode::Static3d) return static3d_keys(batch, s, keys);
    Aabb box{Vec3(FLT_MAX), Vec3(-FLT_MAX)};
    for (size_t i = 0; i < n; ++i)
        box.lo = vmin(box.lo, batch.rays[i].origin), box.hi = vmax(box.hi, batch.rays[i].origin);
    if (mode == HashMode::Hash192) {
        keys.resize(n * 6);
        parallel_for(
            "hash.192", n,
            [&](size_t i) {
                hash192_key(box, batch.rays[i].origin, batch.rays[i].dir, &keys[i * 6]);
            },
            1024);
        return 6;
    }
    keys.resize(n);
    if (mode == HashMode::Hash32) {
        parallel_for(
            "hash.32", n,
            [&](size_t i) { keys[i] = hash32_key(box, batch.rays[i].origin, batch.rays[i].dir); },
            1024);
    } else if (batch.type == RayType::Shadow) {
        const int lb = light_bits(uint32_t(scene.lights.size()));
        parallel_for(
            "hash.crsh_shadow", n,
            [&](size_t i) { keys[i] = crsh_shadow_key(batch.light[i], lb, batch.rays[i].dir); },
            1024);
    } else {
        parallel_for(
            "hash.crsh", n,
            [&](size_t i) {
                keys[i] = crsh_secondary_key(box, batch.rays[i].origin, batch.rays[i].dir);
            },
            1024);
    }
    return 1;
}

} // namespace

Vec3 TraceResult::pass(size_t i) const {
    if (pass_log.empty()) return Vec3(1.0f);
    return pass_from_logs(&pass_log[3 * i]);
}

void trace_batch(const PreparedScene& scene, const RayBatch& batch, const RenderSettings& s,
                 Stats& stats, MemoryTracker& memory, TraceResult& out) {
    trace_batch(scene, *cull_units_for(scene, s), batch, s, stats, memory, out);
}

bool shadows_pass_surfaces(const PreparedScene& scene) {
    for (uint8_t f : scene.prim_flags)
        if (f & kPrimMayPass) return true;
    return false;
}

void trace_batch(const PreparedScene& scene, const CullUnits& units, const RayBatch& batch,
                 const RenderSettings& s, Stats& stats, MemoryTracker& memory, TraceResult& out) {
    const size_t n = batch.size();
    const bool any = any_hit_query(batch.type);
    out.closest.assign(any ? 0 : n, kNoHit);
    out.occluded.assign(any ? n : 0, 0);
    out.pass_log.assign(batch.type == RayType::Shadow && shadows_pass_surfaces(scene) ? 3 * n : 0,
                        0);
    out.tests.assign(n, 0);
    const RaySpan rays{batch.type, n, batch.rays.data(), batch.pixel.data(),
                       batch.light.empty() ? nullptr : batch.light.data()};
    trace_rays(scene, units, rays, s, stats, memory,
               {out.closest.data(), out.occluded.data(),
                out.pass_log.empty() ? nullptr : out.pass_log.data(), out.tests.data()});
}

void trace_rays(const PreparedScene& scene, const CullUnits& units, const RaySpan& batch,
                const RenderSettings& s, Stats& stats, MemoryTracker& memory, const HitSpan& out) {
    const size_t n = batch.n;
    const bool any = any_hit_query(batch.type);
    // Objects without shadows let shadow and AO rays pass; objects without reflections are
    // not seen by reflection rays.
    const uint8_t skip = skip_flags(batch.type);
    const std::string p = std::string("tests.") + ray_type_name(batch.type) + ".";
    stats.add(std::string("rays.") + ray_type_name(batch.type), double(n));
    stats.add(p + "brute_force", double(n) * double(scene.prim_count()));
    if (any)
        std::fill_n(out.occluded, n, uint8_t(0));
    else
        std::fill_n(out.closest, n, kNoHit);
    if (out.pass_log) std::fill_n(out.pass_log, 3 * n, uint64_t(0));
    std::fill_n(out.tests, n, 0u);
    if (n == 0 || scene.prim_count() == 0) return;

    if (s.accel == Accel::Brute) {
        Counter final;
        {
            PhaseTimer t(stats, "time_ms.final_tests");
            trace_brute(SceneView(scene), batch, any, batch.type == RayType::Shadow, skip, final,
                        out);
        }
        add_test_counts(stats, p, false, {}, {}, final.count()); // brute: final tests only
        return;
    }

    // Hash and order (crsh); rah keeps the generation order.
    const HashMode hash = s.accel == Accel::Crsh ? s.hash : HashMode::None;
    std::vector<uint32_t> keys;
    int words = 0;
    {
        PhaseTimer t(stats, "time_ms.hashing");
        words = hash_rays(scene, batch, s, hash, keys);
    }
    const SortMode sort = words == 0 ? SortMode::None : s.sort;
    // The static 3D order is a fixed permutation, whatever sort.mode says: every key sorted.
    const SortMode mode = hash == HashMode::Static3d ? SortMode::Full : sort;
    OrderResult order = order_rays(keys, words, n, mode, stats, s.sort_algorithm);
    memory.add(int64_t(keys.capacity() + order.perm.capacity()) * 4);
    if (sort == SortMode::Csd)
        stats.add(std::string("sort.") + ray_type_name(batch.type) + ".chunks",
                  double(order.chunks));

    // Rays gathered into sorted order, then the hierarchy over them.
    TrackedVector<Ray> sorted = tracked_vector<Ray>(memory, n);
    RayHierarchy h;
    {
        PhaseTimer t(stats, "time_ms.hierarchy");
        parallel_for(
            "rsh.gather", n, [&](size_t j) { sorted[j] = batch.rays[order.perm[j]]; }, 4096);
        h = build_hierarchy(sorted, s.hierarchy_depth, s.hierarchy_arity, memory,
                            s.cull_distance);
    }
    stats.add(std::string("hierarchy.") + ray_type_name(batch.type) + ".top_nodes",
              double(h.node_count(s.hierarchy_depth)));

    const auto t0 = std::chrono::steady_clock::now();
    Traversal trav(scene, units, h, sorted, order.perm, any, batch.type == RayType::Shadow, skip,
                   s.batch_or(kCpuBatchPairs), memory, out);
    trav.run(s.cull_objects);
    const double total_ms = ms_since(t0);
    parallel_for(
        "rsh.ray_tests", n,
        [&](size_t j) {
            out.tests[order.perm[j]] = trav.leaf_pairs_[j / size_t(s.hierarchy_arity)];
        },
        4096);
    stats.add("time_ms.traversal", total_ms - trav.final_ms_);
    stats.add("time_ms.final_tests", trav.final_ms_);
    memory.sub(int64_t(keys.capacity() + order.perm.capacity()) * 4);

    std::vector<TestCount> levels(trav.levels_.size());
    for (size_t k = 0; k < levels.size(); ++k) levels[k] = trav.levels_[k].count();
    add_test_counts(stats, p, s.cull_objects, trav.objects_.count(), levels, trav.final_.count());
}

namespace {

void add_row(Stats& stats, const std::string& row, const TestCount& c) {
    stats.add(row + "tests", double(c.tests));
    stats.add(row + "hits", double(c.hits));
    stats.add(row + "misses", double(c.tests - c.hits));
}

} // namespace

void add_test_counts(Stats& stats, const std::string& p, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final) {
    if (cull_objects) add_row(stats, p + "objects.", TestCount{});
    for (size_t k = levels.size(); k-- > 1;)
        add_row(stats, p + "level" + std::to_string(k) + ".", TestCount{});
    add_row(stats, p + "final.", TestCount{});
    stats.add(p + "total", 0.0);
    add_late_counts(stats, p, cull_objects, objects, levels, final);
}

void add_late_counts(Stats& stats, const std::string& p, bool cull_objects,
                     const TestCount& objects, const std::vector<TestCount>& levels,
                     const TestCount& final) {
    if (cull_objects) add_row(stats, p + "objects.", objects);
    uint64_t total = final.tests;
    for (size_t k = levels.size(); k-- > 1;) {
        add_row(stats, p + "level" + std::to_string(k) + ".", levels[k]);
        total += levels[k].tests;
    }
    add_row(stats, p + "final.", final);
    stats.add(p + "total", double(total));
}

} // namespace sheaf

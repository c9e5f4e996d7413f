#include "core/rsh/cpu_traversal.h"

#include "core/base/parallel.h"
#include "core/rsh/bvh_top.h"

#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <chrono>

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

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The hierarchy traversal with bounded candidate lists.
class Traversal {
  public:
    Traversal(const PreparedScene& scene, const CullUnits& units, const LevelsView& h,
              const Ray* rays, const uint32_t* perm, bool any, bool shadow, uint8_t skip,
              size_t batch, MemoryTracker& memory, const HitSinks& sinks, uint32_t* leaf_pairs,
              uint32_t* ray_tests)
        : levels_(size_t(h.depth) + 1), leaf_pairs_(leaf_pairs), ray_tests_(ray_tests),
          scene_(scene), units_(units), bvh_(units.bvh ? units.bvh->view() : BvhView{}),
          over_bvh_(units.bvh != nullptr), view_(scene), sinks_(sinks), h_(h), rays_(rays),
          perm_(perm), any_(any), shadow_(shadow), skip_(skip), batch_(batch),
          local_(TrackedVector<Pair>(TrackedAllocator<Pair>(&memory))) {
        for (int k = 0; k <= h.depth; ++k) buffers_.push_back(tracked_vector<Pair>(memory));
    }

    void run(bool cull) {
        if (over_bvh_) {
            run_over_bvh();
            return;
        }
        const int top = h_.depth;
        const size_t top_nodes = h_.node_count(top);
        const size_t prims = scene_.prim_count();
        // At most batch_ candidate pairs come out of one group of top nodes.
        const size_t group = std::max<size_t>(1, batch_ / std::max<size_t>(1, prims));
        const RayNode* nodes = h_.nodes[size_t(top) - 1];
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

    // crsh-bvh, rah-bvh: each top node through the BVH (core/rsh/bvh_top.h), in groups small
    // enough that their pairs stay in cache (kGroupPairs, or traversal.batch when smaller):
    // the first group of 16 nodes, each later one sized at the rate the nodes before it found.
    void run_over_bvh() {
        constexpr size_t kGroupPairs = size_t(1) << 16;
        const size_t want = std::min(batch_, kGroupPairs);
        const int top = h_.depth;
        const size_t top_nodes = h_.node_count(top);
        const RayNode* nodes = h_.nodes[size_t(top) - 1];
        size_t group = 16;
        for (size_t g0 = 0; g0 < top_nodes;) {
            const size_t g1 = std::min(top_nodes, g0 + group);
            for (auto& l : local_) l.clear();
            parallel_for_range(
                "rsh.top_bvh", g1 - g0,
                [&](size_t b, size_t e) {
                    auto& outp = local_.local();
                    TestCount c;
                    for (size_t i = g0 + b; i < g0 + e; ++i)
                        bvh_top_node(bvh_, view_, nodes[i], skip_, c, [&](uint32_t ref) {
                            outp.push_back({uint32_t(i), ref});
                        });
                    levels_[size_t(top)].add(c.tests, c.hits);
                },
                1);
            gather(buffers_[size_t(top)]);
            const double rate = double(buffers_[size_t(top)].size()) / double(g1 - g0);
            descend(top);
            g0 = g1;
            group = std::max<size_t>(1, size_t(double(want) / std::max(rate, 1.0)));
        }
    }

    Counter objects_, final_, nodes_;
    std::vector<Counter> levels_; // index k: level k
    double final_ms_ = 0;
    // Candidate primitives of each level-1 node: every ray of the node is tested against each.
    uint32_t* leaf_pairs_;

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
        const RayNode* children = h_.nodes[size_t(level) - 2];
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
                        // Over the BVH a pair names a BVH slot or primitive (bvh_top.h).
                        const Sphere s = over_bvh_ ? bvh_ref_sphere(bvh_, view_, pr.prim)
                                                   : scene_.prim_sphere[pr.prim];
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
        if (over_bvh_) {
            // Each ray of a level-1 node through what its node kept, on its own.
            parallel_for_range(
                "rsh.final_bvh", pairs.size(),
                [&](size_t b, size_t e) {
                    BvhCounts sum;
                    for (size_t i = b; i < e; ++i) {
                        const Pair pr = pairs[i];
                        const BvhCounts c =
                            bvh_ref_rays(bvh_, view_, rays_, perm_, h_.first_child(pr.node),
                                         h_.last_child(1, pr.node), pr.prim, any_, shadow_, skip_,
                                         sinks_, ray_tests_);
                        sum.nodes.tests += c.nodes.tests, sum.nodes.hits += c.nodes.hits;
                        sum.prims.tests += c.prims.tests, sum.prims.hits += c.prims.hits;
                    }
                    nodes_.add(sum.nodes.tests, sum.nodes.hits);
                    final_.add(sum.prims.tests, sum.prims.hits);
                },
                64);
            final_ms_ += ms_since(t0);
            return;
        }
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
                    hcount += final_tests(view_, rays_, perm_, first, last, pr.prim, any_,
                                          shadow_, sinks_);
                }
                final_.add(t, hcount);
            },
            256);
        final_ms_ += ms_since(t0);
    }

    uint32_t* ray_tests_; // over the BVH: each ray's exact tests, by batch index
    const PreparedScene& scene_;
    const CullUnits& units_;
    BvhView bvh_;
    bool over_bvh_; // crsh-bvh, rah-bvh: the units carry the BVH the top nodes descend
    SceneView view_;
    HitSinks sinks_;
    const LevelsView& h_;
    const Ray* rays_;
    const uint32_t* perm_;
    bool any_;
    bool shadow_; // shadow rays pass transparent primitives (record_pass)
    uint8_t skip_; // primitives whose objects have these flags are not candidates
    size_t batch_;
    tbb::enumerable_thread_specific<TrackedVector<Pair>> local_;
    std::vector<TrackedVector<Pair>> buffers_;
};

} // namespace

void traverse_on_cpu(const PreparedScene& scene, const CullUnits& units, const LevelsView& h,
                     const Ray* sorted, const uint32_t* perm, bool any, bool shadow, uint8_t skip,
                     size_t batch, bool cull, MemoryTracker& memory, const HitSinks& sinks,
                     uint32_t* leaf_pairs, uint32_t* ray_tests, TraversalCounts& counts) {
    Traversal trav(scene, units, h, sorted, perm, any, shadow, skip, batch, memory, sinks,
                   leaf_pairs, ray_tests);
    trav.run(cull);
    counts.objects = trav.objects_.count();
    counts.final = trav.final_.count();
    counts.nodes = trav.nodes_.count();
    counts.levels.resize(trav.levels_.size());
    for (size_t k = 0; k < counts.levels.size(); ++k) counts.levels[k] = trav.levels_[k].count();
    counts.final_ms = trav.final_ms_;
}

} // namespace sheaf

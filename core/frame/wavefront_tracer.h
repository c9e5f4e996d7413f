// Tracing one batch of secondary rays on the executing side, as core/rsh/trace.cpp does on the
// CPU: brute (every ray against every primitive), or hash, order, the ray hierarchy built level
// by level, and the top-down traversal with compaction of candidate (node, primitive) pairs
// (counters on the executing side: the next level launched for the count found there), then
// the final tests. The same per-element functions, the same counts in the same statistics
// keys, the same hits.
#pragma once

#include "core/accel/bvh_trace.h"
#include "core/accel/strips_trace.h"
#include "core/frame/batch.h"
#include "core/frame/compact.h"
#include "core/frame/order.h"
#include "core/frame/scene_copy.h"
#include "core/hash/ray_hash.h"
#include "core/rays/ray_gen.h"
#include "core/rsh/bvh_top.h"
#include "core/rsh/cpu_traversal.h"
#include "core/rsh/hierarchy.h"
#include "core/rsh/trace_kernels.h"

#include <cfloat>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sheaf::wavefront {

struct NodePrim {
    uint32_t node, prim;
};

struct NodeUnit {
    uint32_t node, unit; // a top node and a culling unit (core/rsh/cull_units.h)
};

/// The top level's candidate pairs of a group of top nodes from g0, in order of node, then
/// primitive: every primitive of every node (no culling, or every unit hit), or, when
/// `sparse`, the primitives of each hit (node, unit) pair j, whose first candidate is
/// start[j]. Candidates are taken a chunk at a time from c0; candidate c belongs to pair
/// *j0 + owner[c - c0].
struct TopCandidates {
    bool sparse;
    uint32_t g0, prims;
    const NodeUnit* hit;
    const uint32_t* start;
    const uint32_t* owner;
    const uint32_t* j0;
    const uint32_t* unit_begin;
    uint32_t c0;

    SHEAF_HD NodePrim operator()(size_t c) const {
        if (!sparse) return {g0 + uint32_t(c / prims), uint32_t(c % prims)};
        const uint32_t j = *j0 + owner[c - c0];
        return {hit[j].node, unit_begin[hit[j].unit] + (uint32_t(c) - start[j])};
    }
};

/// A traced batch's counts kept on the executing side until the frame reads them (at
/// namespace scope: nvcc's extended lambdas may not capture a class's private types).
struct BatchCounts {
    TestCount objects, final, nodes; // nodes: accel=bvh's ray-box tests
    TestCount levels[kMaxHierarchyDepth + 1]; // index k: level k
};

/// The fewest top candidates a chunk takes (WavefrontTracer::top_chunk_size): below this, a
/// deep hierarchy's chunk reads its count once rather than being cut smaller.
constexpr size_t kMinTopChunk = size_t(1) << 16;

/// How many elements a counted launch (Exec::launch_compact, launch_tally) runs: *p, a counter
/// that earlier launches filled on the executing side, or a number the host knows (p null).
struct LaunchCount {
    const uint32_t* p;
    size_t known;
    SHEAF_HD size_t operator()() const { return p ? size_t(*p) : known; }
};

struct SumCounts {
    SHEAF_HD TestCount operator()(const TestCount& a, const TestCount& b) const {
        return {a.tests + b.tests, a.hits + b.hits};
    }
};

struct BoxUnion {
    SHEAF_HD Aabb operator()(const Aabb& a, const Aabb& b) const {
        return {vmin(a.lo, b.lo), vmax(a.hi, b.hi)};
    }
};

/// How a tracer walks the ray hierarchy down to the exact tests: as launches with a count,
/// compaction and next launch per level (a device's way), or on host memory through
/// per-thread candidate lists (core/rsh/cpu_traversal.h: faster on CPU cores).
enum class Traversal { Wavefront, Host };

/// The intersection seam's implementation (seam.h): brute, or hash, order, the ray hierarchy
/// and its traversal (rah, crsh). Every stage but the traversal is written once, as launches;
/// the traversal is the wavefront's on a device (the CUDA module's tracer) or the CPU's
/// (HostTracer, core/frame/host_tracer.h, the CPU backend's). The tests hold the two against
/// each other under the CPU policy.
template <class Exec, Traversal kTraversal = Traversal::Wavefront> class WavefrontTracer {
    static_assert(kTraversal == Traversal::Wavefront || Exec::kHostMemory,
                  "the host traversal reads host memory");

  public:
    /// Whether its launches are what a device would run: the frame then reports device.*
    /// counters.
    static constexpr bool kDeviceWork = kTraversal == Traversal::Wavefront;

    /// `units`: the culling units on the host, `cull` the same on the executing side.
    WavefrontTracer(Exec& ex, const PreparedScene& host, const SceneView& scene,
                 const CullUnits& units, const CullView& cull, const RenderSettings& s,
                 Stats& stats, PhaseClock<Exec>& clock)
        : ex_(ex), host_(host), units_(units), scene_(scene), cull_(cull), s_(s), st_(stats),
          clock_(clock),
          light_count_(uint32_t(host.lights.size())), batch_(s.batch_or(ex.auto_batch_pairs())) {
        for (uint8_t f : host.prim_flags) flags_ = uint8_t(flags_ | f);
        transparent_ = (flags_ & kPrimMayPass) != 0;
        for (size_t u = 0; u < units.count(); ++u)
            units_with_prims_ += units.begin[u + 1] > units.begin[u] ? 1 : 0;
    }

    /// Candidate pairs a level holds at once: traversal.batch, or the exec's choice.
    size_t batch_pairs() const { return batch_; }

    void trace(const DeviceBatch<Exec>& batch, DeviceTraceResult<Exec>& out) {
        const size_t n = batch.n;
        const uint32_t prims = scene_.prim_count();
        any_ = any_hit_query(batch.type);
        shadow_ = batch.type == RayType::Shadow;
        // Flags no primitive has skip nothing: no candidate then reads its primitive's flags.
        skip_ = uint8_t(skip_flags(batch.type) & flags_);
        const std::string p = std::string("tests.") + ray_type_name(batch.type) + ".";
        st_.add(std::string("rays.") + ray_type_name(batch.type), double(n));
        st_.add(p + "brute_force", double(n) * double(prims));
        out = DeviceTraceResult<Exec>();
        if (any_) {
            out.occluded = DeviceBuffer<uint8_t, Exec>(ex_, n);
            fill(ex_, out.occluded.data(), n, uint8_t(0));
        } else {
            out.closest = DeviceBuffer<uint64_t, Exec>(ex_, n);
            fill(ex_, out.closest.data(), n, kNoHit);
        }
        if (shadow_ && transparent_) {
            out.pass_log = DeviceBuffer<uint64_t, Exec>(ex_, 3 * n);
            fill(ex_, out.pass_log.data(), 3 * n, uint64_t(0));
        }
        out.tests = DeviceBuffer<uint32_t, Exec>(ex_, n);
        fill(ex_, out.tests.data(), n, 0u);
        if (n == 0 || prims == 0) return;

        // Object and final tests count into this batch's slot, read with the others' by
        // flush().
        const bool per_ray = !uses_ray_hierarchy(s_.accel);
        // crsh-bvh and rah-bvh: the top nodes through the BVH, not the object spheres.
        over_bvh_ = !per_ray && uses_bvh(s_.accel);
        if (over_bvh_ && (cull_.bvh.node_count >= kBvhTopMaxNodes || prims >= kBvhTopMaxPrims))
            throw std::runtime_error("accel=" + std::string(to_string(s_.accel)) +
                                     " takes at most 2^28 BVH nodes and 2^30 primitives; use "
                                     "accel=bvh for this scene");
        const bool cull = !per_ray && !over_bvh_ && s_.cull_objects;
        const int depth = per_ray ? 0 : s_.hierarchy_depth;
        const bool bvh = uses_bvh(s_.accel) || s_.accel == Accel::Strips; // counts box tests
        BatchCounts* slot = take_slot(p, cull, depth, bvh);
        objects_count_ = &slot->objects;
        final_count_ = &slot->final;
        node_count_ = &slot->nodes;
        level_counts_ = slot->levels;
        if (per_ray) {
            const TestCount none;
            if (bvh)
                per_ray_trace(batch, out);
            else
                brute(batch, out);
            add_test_counts(st_, p, false, {}, {}, {}, bvh ? &none : nullptr); // no levels
            return;
        }

        // Hash and order (crsh); rah keeps the generation order.
        const HashMode hash = orders_rays(s_.accel) ? s_.hash : HashMode::None;
        DeviceBuffer<uint32_t, Exec> keys;
        int words = 0;
        clock_.start("hashing");
        words = hash_rays(batch, hash, keys);
        clock_.stop("hashing");
        const SortMode sort = words == 0 ? SortMode::None : s_.sort;
        // The static 3D order is a fixed permutation, whatever sort.mode says: every key sorted.
        const SortMode mode = hash == HashMode::Static3d ? SortMode::Full : sort;
        DeviceOrder<Exec> order =
            order_rays(ex_, keys.data(), words, n, mode, clock_, s_.sort_algorithm);
        if (sort == SortMode::Csd)
            st_.add(std::string("sort.") + ray_type_name(batch.type) + ".chunks",
                    double(order.chunks));

        // Rays gathered into sorted order, then the hierarchy over them.
        clock_.start("hierarchy");
        sorted_ = DeviceBuffer<Ray, Exec>(ex_, n);
        gather_rays(batch.rays.data(), order.perm.data(), sorted_.data(), n);
        build_levels(n);
        clock_.stop("hierarchy");
        perm_ = order.perm.data();
        st_.add(std::string("hierarchy.") + ray_type_name(batch.type) + ".top_nodes",
                double(node_count(s_.hierarchy_depth)));

        sinks_ = out.sinks();
        ray_tests_ = out.tests.data();
        leaf_pairs_ = DeviceBuffer<uint32_t, Exec>(ex_, node_count(1));
        fill(ex_, leaf_pairs_.data(), node_count(1), 0u);
        if constexpr (kTraversal == Traversal::Host) {
            host_traverse(cull, depth);
            clock_.start("traversal");
        } else {
            clock_.start("traversal");
            counters_ = DeviceBuffer<uint32_t, Exec>(ex_, size_t(depth) + 1);
            pair_bufs_.resize(size_t(depth) + 1);
            if (over_bvh_)
                traverse_bvh();
            else
                traverse();
            pair_bufs_.clear();
            counters_ = DeviceBuffer<uint32_t, Exec>();
        }
        if (!over_bvh_) spread_ray_tests(out.tests.data(), n); // over the BVH: counted per ray
        clock_.stop("traversal");

        const TestCount none;
        add_test_counts(st_, p, cull, {}, std::vector<TestCount>(size_t(depth) + 1), {},
                        over_bvh_ ? &none : nullptr);
        levels_.clear();
        sorted_ = DeviceBuffer<Ray, Exec>();
        leaf_pairs_ = DeviceBuffer<uint32_t, Exec>();
    }

    /// Adds the counts of every batch traced since the last flush to the statistics: one read
    /// for them all, at the end of the frame, so tracing a batch costs the host no wait for
    /// its counts.
    void flush() {
        if (pending_.empty()) return;
        const std::vector<BatchCounts> counts = slots_.download(pending_.size());
        for (size_t i = 0; i < pending_.size(); ++i) {
            const BatchCounts& c = counts[i];
            const std::vector<TestCount> levels(c.levels, c.levels + pending_[i].depth + 1);
            add_late_counts(st_, pending_[i].prefix, pending_[i].cull, c.objects, levels, c.final,
                            pending_[i].bvh ? &c.nodes : nullptr);
        }
        pending_.clear();
        // A batch traced after this takes a new buffer, zeroed when allocated: no launch to
        // clear slots that the frame, which flushes once at its end, would never use again.
        slots_ = DeviceBuffer<BatchCounts, Exec>();
    }

    // The stages below are public only because nvcc's extended lambdas may not live in private
    // member functions.

    void brute(const DeviceBatch<Exec>& batch, DeviceTraceResult<Exec>& out) {
        clock_.start("final_tests");
        const size_t n = batch.n;
        DeviceBuffer<uint32_t, Exec> hits_buf(ex_, n);
        const SceneView scene = scene_;
        const Ray* rays = batch.rays.data();
        uint32_t* tests = out.tests.data();
        uint32_t* hits = hits_buf.data();
        const bool any = any_, shadow = shadow_;
        const uint8_t skip = skip_;
        const HitSinks sinks = out.sinks();
        ex_.launch("brute.trace", n, [=] SHEAF_HD_LAMBDA(size_t i) {
            const TestCount c =
                brute_trace_ray(scene, rays[i], uint32_t(i), any, shadow, skip, sinks);
            tests[i] = uint32_t(c.tests < 0xFFFFFFFFu ? c.tests : 0xFFFFFFFFu);
            hits[i] = uint32_t(c.hits);
        });
        ex_.reduce_into(
            "brute.counts", n, final_count_, TestCount{},
            [=] SHEAF_HD_LAMBDA(size_t i) -> TestCount {
                return {tests[i], hits[i]};
            },
            SumCounts{});
        clock_.stop("final_tests");
    }

    // accel=bvh and accel=strips: each ray through the scene's structure (core/accel/
    // bvh_trace.h, strips_trace.h), written once for both backends.
    void per_ray_trace(const DeviceBatch<Exec>& batch, DeviceTraceResult<Exec>& out) {
        clock_.start("traversal");
        const size_t n = batch.n;
        DeviceBuffer<BvhCounts, Exec> counts(ex_, n);
        const SceneView scene = scene_;
        const bool strips = s_.accel == Accel::Strips;
        const BvhView bvh = cull_.bvh;
        const StripsView sv = cull_.strips;
        const Ray* rays = batch.rays.data();
        uint32_t* tests = out.tests.data();
        BvhCounts* per = counts.data();
        const bool any = any_, shadow = shadow_;
        const uint8_t skip = skip_;
        const HitSinks sinks = out.sinks();
        ex_.launch(strips ? "strips.trace" : "bvh.trace", n, [=] SHEAF_HD_LAMBDA(size_t i) {
            const BvhCounts c =
                strips ? strips_trace_ray(sv, scene, rays[i], uint32_t(i), any, shadow, skip, sinks)
                       : bvh_trace_ray(bvh, scene, rays[i], uint32_t(i), any, shadow, skip, sinks);
            tests[i] = uint32_t(c.prims.tests < 0xFFFFFFFFu ? c.prims.tests : 0xFFFFFFFFu);
            per[i] = c;
        });
        ex_.reduce_into(
            "per_ray.prim_counts", n, final_count_, TestCount{},
            [=] SHEAF_HD_LAMBDA(size_t i) -> TestCount { return per[i].prims; }, SumCounts{});
        ex_.reduce_into(
            "per_ray.node_counts", n, node_count_, TestCount{},
            [=] SHEAF_HD_LAMBDA(size_t i) -> TestCount { return per[i].nodes; }, SumCounts{});
        clock_.stop("traversal");
    }

    // Keys of the batch under hash.mode. Returns the number of 32-bit words per key.
    int hash_rays(const DeviceBatch<Exec>& batch, HashMode mode,
                  DeviceBuffer<uint32_t, Exec>& keys) {
        const size_t n = batch.n;
        // static1d is the generation order: a pixel's rays together (paper 003's 1D work groups).
        if (mode == HashMode::None || mode == HashMode::Static1d) return 0;
        const Ray* rays = batch.rays.data();
        if (mode == HashMode::Static3d) {
            const uint64_t grid_w = uint64_t(s_.width) * uint64_t(s_.aa_samples);
            const uint64_t grid_h = uint64_t(s_.height) * uint64_t(s_.aa_samples);
            const uint64_t tiles_x = (grid_w + 7) / 8, tiles = tiles_x * ((grid_h + 15) / 16);
            const int per = batch.type == RayType::Ao        ? s_.ao_samples
                            : batch.type == RayType::Diffuse ? s_.radiosity_samples
                                                             : 1;
            const uint64_t per_pixel = uint64_t(per > 1 ? per : 1);
            const bool shadow = batch.type == RayType::Shadow;
            keys = DeviceBuffer<uint32_t, Exec>(ex_, 2 * n);
            uint32_t* k = keys.data();
            const uint32_t* pixel = batch.pixel.data();
            const uint32_t* light = batch.light.data();
            ex_.launch("hash.static3d", n, [=] SHEAF_HD_LAMBDA(size_t i) {
                const uint64_t sample = shadow ? light[i] : uint64_t(i) % per_pixel;
                const uint64_t key = static3d_key(pixel[i], sample, grid_w, tiles_x, tiles);
                k[2 * i] = uint32_t(key), k[2 * i + 1] = uint32_t(key >> 32);
            });
            return 2;
        }
        if (mode == HashMode::Crsh && batch.type == RayType::Shadow) {
            keys = DeviceBuffer<uint32_t, Exec>(ex_, n);
            uint32_t* k = keys.data();
            const int lb = light_bits(light_count_);
            const uint32_t* light = batch.light.data();
            ex_.launch("hash.crsh_shadow", n, [=] SHEAF_HD_LAMBDA(size_t i) {
                k[i] = crsh_shadow_key(light[i], lb, rays[i].dir);
            });
            return 1;
        }
        // The origins' bounding box, kept on the executing side for the hash kernels.
        if (box_.empty()) box_ = DeviceBuffer<Aabb, Exec>(ex_, 1);
        const Aabb none{Vec3(FLT_MAX), Vec3(-FLT_MAX)};
        fill(ex_, box_.data(), 1, none);
        ex_.reduce_into(
            "hash.box", n, box_.data(), none,
            [=] SHEAF_HD_LAMBDA(size_t i) -> Aabb {
                return {rays[i].origin, rays[i].origin};
            },
            BoxUnion{});
        const Aabb* box = box_.data();
        if (mode == HashMode::Hash192) {
            keys = DeviceBuffer<uint32_t, Exec>(ex_, 6 * n);
            uint32_t* k = keys.data();
            ex_.launch("hash.192", n, [=] SHEAF_HD_LAMBDA(size_t i) {
                hash192_key(*box, rays[i].origin, rays[i].dir, &k[i * 6]);
            });
            return 6;
        }
        keys = DeviceBuffer<uint32_t, Exec>(ex_, n);
        uint32_t* k = keys.data();
        if (mode == HashMode::Hash32) {
            ex_.launch("hash.32", n, [=] SHEAF_HD_LAMBDA(size_t i) {
                k[i] = hash32_key(*box, rays[i].origin, rays[i].dir);
            });
        } else {
            ex_.launch("hash.crsh", n, [=] SHEAF_HD_LAMBDA(size_t i) {
                k[i] = crsh_secondary_key(*box, rays[i].origin, rays[i].dir);
            });
        }
        return 1;
    }

    void gather_rays(const Ray* rays, const uint32_t* perm, Ray* sorted, size_t n) {
        ex_.launch("rsh.gather", n, [=] SHEAF_HD_LAMBDA(size_t j) { sorted[j] = rays[perm[j]]; });
    }

    size_t node_count(int level) const {
        return level == 0 ? sorted_.size() : levels_[size_t(level) - 1].size();
    }

    // The hierarchy level by level: node i of level k unites children [i arity, (i+1) arity).
    void build_levels(size_t n) {
        levels_.clear();
        const int arity = s_.hierarchy_arity;
        const bool reach = s_.cull_distance;
        for (int level = 1; level <= s_.hierarchy_depth; ++level) {
            const size_t below = level == 1 ? n : levels_.back().size();
            const size_t count = (below + size_t(arity) - 1) / size_t(arity);
            DeviceBuffer<RayNode, Exec> nodes(ex_, count);
            RayNode* out = nodes.data();
            const Ray* rays = sorted_.data();
            const RayNode* children = level == 1 ? nullptr : levels_.back().data();
            ex_.launch("rsh.build", count, [=] SHEAF_HD_LAMBDA(size_t i) {
                out[i] = build_ray_node(rays, children, i * size_t(arity),
                                        node_last_child(i, arity, below), reach);
            });
            levels_.push_back(std::move(nodes));
        }
    }

    // The CPU's traversal (core/rsh/cpu_traversal.h) over the levels built here, its counts
    // into the batch's slot as the wavefront's go there; its time as the phases traversal and
    // final_tests.
    void host_traverse(bool cull, int depth) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<const RayNode*> nodes(levels_.size());
        std::vector<size_t> count(levels_.size() + 1);
        count[0] = sorted_.size();
        for (size_t k = 0; k < levels_.size(); ++k)
            nodes[k] = levels_[k].data(), count[k + 1] = levels_[k].size();
        const LevelsView h{depth, s_.hierarchy_arity, nodes.data(), count.data()};
        TraversalCounts counts;
        traverse_on_cpu(host_, units_, h, sorted_.data(), perm_, any_, shadow_, skip_, batch_, cull,
                        ex_.memory(), sinks_, leaf_pairs_.data(), ray_tests_, counts);
        *objects_count_ = counts.objects;
        *final_count_ = counts.final;
        *node_count_ = counts.nodes;
        for (size_t k = 1; k < counts.levels.size(); ++k) level_counts_[k] = counts.levels[k];
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        st_.add("time_ms.traversal", ms - counts.final_ms);
        st_.add("time_ms.final_tests", counts.final_ms);
    }

    // Top nodes against the object spheres and, within split objects, the unit spheres
    // (cull.objects, cull.cluster: core/rsh/cull_units.h), then against the primitive spheres
    // of the units they reach, then down the levels to the final tests. Top nodes go in groups
    // of at most traversal.batch (node, unit) pairs with culling, (node, primitive) pairs
    // without. With culling only the primitives of hit units are candidates (unit u's
    // primitives are cull_.begin[u] .. cull_.begin[u + 1]), so the work is the tests the
    // statistics count; where every node hit every unit, the candidates are all the
    // primitives, with no expansion. A group's candidates go down in chunks small enough that
    // each level's pairs fit traversal.batch (top_chunk_size): every level's hits are then
    // compacted by counters on the executing side (Exec::launch_compact; the order of the pairs
    // changes no result: hits are minima, flags and sums), and the next level is launched for
    // the count it finds there, so the host waits once per group, for the number of
    // candidates. Every count stays on the executing side until flush().
    void traverse() {
        const int top = s_.hierarchy_depth;
        const size_t top_nodes = node_count(top);
        const uint32_t prims = scene_.prim_count();
        const uint32_t units = cull_.count;
        const bool cull = s_.cull_objects;
        const size_t batch = batch_;
        // A group's candidate indices fit 32 bits.
        const size_t group =
            std::max<size_t>(1, std::min(batch / std::max<size_t>(1, cull ? units : prims),
                                         size_t(UINT32_MAX) / std::max<size_t>(1, prims)));
        const size_t most = std::min(group, top_nodes);
        const size_t chunk = top_chunk_size();
        const size_t most_chunk = std::min(chunk, most * size_t(prims));
        DeviceBuffer<uint8_t, Exec> objhit_buf(ex_, cull ? most * units : 0);
        DeviceBuffer<uint64_t, Exec> objoff_buf(ex_, cull ? most * units : 0);
        DeviceBuffer<uint32_t, Exec> owner_buf(ex_, cull ? most_chunk : 0);
        DeviceBuffer<uint32_t, Exec> j0_buf(ex_, cull ? 1 : 0);
        const RayNode* nodes = levels_[size_t(top) - 1].data();
        const CullView cv = cull_;
        uint8_t* objhit = objhit_buf.data();
        uint64_t* objoff = objoff_buf.data();
        const Sphere* object_sphere = scene_.object_sphere;
        uint32_t* own = owner_buf.data();
        uint32_t* j0 = j0_buf.data();
        for (size_t g0 = 0; g0 < top_nodes; g0 += group) {
            const size_t gn = std::min(top_nodes, g0 + group) - g0;
            // Candidate c of the group is the (node, primitive) pair candidate(c).
            size_t candidates = gn * size_t(prims);
            DeviceBuffer<NodeUnit, Exec> hit_buf;
            DeviceBuffer<uint32_t, Exec> start_buf;
            TopCandidates candidate{false,   uint32_t(g0),       prims, nullptr, nullptr, nullptr,
                                    nullptr, cv.begin,          0};
            uint32_t hits = 0;
            if (cull) {
                // Every (node, unit) pair: the unit's object's sphere, then, where that is hit
                // and the object split, the unit's; counted as the CPU counts them (the
                // object's test with its first unit). The pairs that pass and have primitives
                // are compacted, in order: one scan gives each its place (low 32 bits) and its
                // first candidate (high 32 bits). objhit: bit 0 passes, bits 1-2 tests, bits
                // 3-4 hits.
                ex_.launch("rsh.objects", gn * units, [=] SHEAF_HD_LAMBDA(size_t x) {
                    const uint32_t u = uint32_t(x % units);
                    const RayNode& node = nodes[g0 + x / units];
                    const uint32_t o = cv.object[u], u0 = cv.object_units[o];
                    const bool split = cv.object_units[o + 1] - u0 > 1;
                    const bool ho = node_hits_sphere(node, object_sphere[o]);
                    const bool hu = ho && split && node_hits_sphere(node, cv.sphere[u]);
                    const uint32_t t = (u == u0 ? 1u : 0u) + (ho && split ? 1u : 0u);
                    const uint32_t h = (u == u0 && ho ? 1u : 0u) + (hu ? 1u : 0u);
                    const uint32_t size = cv.begin[u + 1] - cv.begin[u];
                    const bool pass = ho && (!split || hu) && size > 0;
                    objhit[x] = uint8_t((pass ? 1u : 0u) | t << 1 | h << 3);
                    objoff[x] = pass ? uint64_t(size) << 32 | 1u : 0u;
                });
                ex_.reduce_into(
                    "rsh.object_counts", gn * units, objects_count_, TestCount{},
                    [=] SHEAF_HD_LAMBDA(size_t x) -> TestCount {
                        return {uint32_t(objhit[x] >> 1 & 3u), uint32_t(objhit[x] >> 3 & 3u)};
                    },
                    SumCounts{});
                // Totals below 2^32 each: at most gn * units pairs, gn * prims candidates.
                const uint64_t total = ex_.exclusive_scan(objoff, gn * units);
                hits = uint32_t(total);
                // Unless every node hit every unit with primitives (one small object, say),
                // when the candidates are all the primitives in the plain order: the hit
                // pairs' primitive ranges.
                if (hits < gn * units_with_prims_) {
                    hit_buf = DeviceBuffer<NodeUnit, Exec>(ex_, hits);
                    start_buf = DeviceBuffer<uint32_t, Exec>(ex_, hits);
                    NodeUnit* h = hit_buf.data();
                    uint32_t* sp = start_buf.data();
                    ex_.launch("rsh.object_fill", gn * units, [=] SHEAF_HD_LAMBDA(size_t x) {
                        if (!(objhit[x] & 1u)) return;
                        const uint32_t j = uint32_t(objoff[x]);
                        h[j] = {uint32_t(g0 + x / units), uint32_t(x % units)};
                        sp[j] = uint32_t(objoff[x] >> 32);
                    });
                    candidates = size_t(total >> 32);
                    candidate.sparse = true;
                    candidate.hit = h;
                    candidate.start = sp;
                    candidate.owner = own;
                    candidate.j0 = j0;
                }
            }
            for (size_t c0 = 0; c0 < candidates; c0 += chunk) {
                const size_t cn = std::min(candidates, c0 + chunk) - c0;
                if (candidate.sparse) {
                    // The chunk's first pair, *j0: the last whose first candidate is at most
                    // c0 (start increases strictly, every span being at least one); then a 1
                    // at start[j] - c0 - 1 for each pair starting in (c0, c0 + cn], scanned:
                    // own[x] counts the pairs after j0 that candidate c0 + x has passed.
                    const uint32_t lo = uint32_t(c0), hi = uint32_t(c0 + cn);
                    const uint32_t* st = candidate.start;
                    uint32_t* first = j0;
                    candidate.c0 = lo;
                    fill(ex_, own, cn, 0u);
                    ex_.launch("rsh.owner", hits, [=] SHEAF_HD_LAMBDA(size_t j) {
                        if (st[j] <= lo && (j + 1 == hits || st[j + 1] > lo)) *first = uint32_t(j);
                        if (j > 0 && st[j] > lo && st[j] <= hi) own[st[j] - lo - 1] = 1;
                    });
                    ex_.exclusive_scan_async(own, cn);
                }
                top_chunk(candidate, c0, cn, nodes);
            }
        }
    }

    // crsh-bvh, rah-bvh: each top node through the BVH (core/rsh/bvh_top.h), in groups of
    // nodes: one launch counts each node's references (and its tests), a scan places them,
    // the host reads the total (its one wait a group), a second launch writes the (node,
    // reference) pairs, which go down the levels as the flat top level's pairs do. The first
    // group is sized for 64 references a node, each later one for traversal.batch at the rate
    // the nodes before it found.
    void traverse_bvh() {
        const int top = s_.hierarchy_depth;
        const size_t top_nodes = node_count(top);
        const RayNode* nodes = levels_[size_t(top) - 1].data();
        const BvhView bvh = cull_.bvh;
        const SceneView scene = scene_;
        const uint8_t skip = skip_;
        size_t group = std::max<size_t>(1, batch_ / 64);
        for (size_t g0 = 0; g0 < top_nodes;) {
            const size_t gn = std::min(top_nodes - g0, group);
            DeviceBuffer<uint64_t, Exec> off_buf(ex_, gn);
            DeviceBuffer<TestCount, Exec> tests_buf(ex_, gn);
            uint64_t* off = off_buf.data();
            TestCount* tests = tests_buf.data();
            ex_.launch("rsh.bvh_count", gn, [=] SHEAF_HD_LAMBDA(size_t x) {
                TestCount c;
                uint64_t refs = 0;
                bvh_top_node(bvh, scene, nodes[g0 + x], skip, c, [&](uint32_t) { ++refs; });
                off[x] = refs;
                tests[x] = c;
            });
            ex_.reduce_into(
                "rsh.bvh_top_counts", gn, level_counts_ + top, TestCount{},
                [=] SHEAF_HD_LAMBDA(size_t x) -> TestCount { return tests[x]; }, SumCounts{});
            const uint64_t total = ex_.exclusive_scan(off, gn);
            if (total > 0) {
                NodePrim* pairs = level_pairs(top, size_t(total));
                ex_.launch("rsh.bvh_fill", gn, [=] SHEAF_HD_LAMBDA(size_t x) {
                    TestCount c;
                    uint64_t j = off[x];
                    const uint32_t node = uint32_t(g0 + x);
                    bvh_top_node(bvh, scene, nodes[g0 + x], skip, c, [&](uint32_t ref) {
                        pairs[j++] = {node, ref};
                    });
                });
                fill(ex_, counters_.data(), counters_.size(), 0u);
                descend(top, pairs, size_t(total), LaunchCount{nullptr, size_t(total)});
            }
            g0 += gn;
            const double rate = double(total) / double(gn);
            group = std::max<size_t>(1, size_t(double(batch_) / std::max(rate, 1.0)));
        }
    }

    // Top candidates a chunk: as many as keep every level's pairs within traversal.batch while
    // the host waits for no count (each level expands a pair into at most arity), so at depth
    // 2 a chunk costs the host no wait; deeper, the chunk's count is read where a level would
    // pass the batch (descend).
    size_t top_chunk_size() const {
        const size_t arity = size_t(s_.hierarchy_arity);
        size_t chunk = batch_;
        for (int level = s_.hierarchy_depth; level > 1 && chunk / arity >= kMinTopChunk; --level)
            chunk /= arity;
        return std::max<size_t>(1, chunk);
    }

    // Room for n pairs of nodes at `level`, kept for the batch's later chunks: a chunk's pairs
    // are used up, in the executing side's order, before the next chunk's overwrite them.
    NodePrim* level_pairs(int level, size_t n) {
        DeviceBuffer<NodePrim, Exec>& b = pair_bufs_[size_t(level)];
        if (b.size() < n) b = DeviceBuffer<NodePrim, Exec>(ex_, n);
        return b.data();
    }

    // Candidates [c0, c0 + n) of a group, each tested against its primitive's sphere: the hit
    // (node, primitive) pairs are compacted and go down.
    void top_chunk(const TopCandidates candidate, size_t c0, size_t n, const RayNode* nodes) {
        const int top = s_.hierarchy_depth;
        const SceneView scene = scene_;
        const uint8_t skip = skip_;
        // The chunk's counters of pairs, one a level, zeroed at once.
        fill(ex_, counters_.data(), counters_.size(), 0u);
        NodePrim* pairs = level_pairs(top, n);
        uint32_t* found = counters_.data() + top;
        ex_.launch_compact(
            "rsh.top", n, LaunchCount{nullptr, n}, found, level_counts_ + top,
            [=] SHEAF_HD_LAMBDA(size_t x) -> Compacted {
                const NodePrim np = candidate(c0 + x);
                const bool tested = !(skip && scene.prim_flag(np.prim, skip));
                const bool hit =
                    tested && node_hits_sphere(nodes[np.node], scene.prim_sphere[np.prim]);
                return {tested ? 1u : 0u, hit ? 1u : 0u, hit ? 1u : 0u, 0};
            },
            [=] SHEAF_HD_LAMBDA(size_t x, uint64_t, uint32_t slot) {
                pairs[slot] = candidate(c0 + x);
            });
        descend(top, pairs, n, LaunchCount{found, 0});
    }

    // At most `most` pairs of nodes at `level`, count() of them: expanded to level - 1 at once
    // when that fits traversal.batch, else the host reads the count and expands them in chunks
    // of traversal.batch / arity; at level 1, the final tests. The counters of the levels
    // below are zero.
    void descend(int level, const NodePrim* pairs, size_t most, LaunchCount count) {
        if (level == 1) {
            finals(pairs, most, count);
            return;
        }
        const size_t arity = size_t(s_.hierarchy_arity);
        if (most * arity <= batch_) {
            expand(level, pairs, most, count);
            return;
        }
        uint32_t counted = 0;
        if (count.p) ex_.copy_to_host(&counted, count.p, sizeof counted); // the one wait
        const size_t n = count.p ? size_t(counted) : count.known;
        const size_t chunk = std::max<size_t>(1, batch_ / arity);
        for (size_t c0 = 0; c0 < n; c0 += chunk) {
            const size_t cn = std::min(n, c0 + chunk) - c0;
            fill(ex_, counters_.data(), size_t(level), 0u); // the levels below, again
            expand(level, pairs + c0, cn, LaunchCount{nullptr, cn});
        }
    }

    // The count() pairs (at most `most`) of nodes at `level` against the primitive spheres of
    // their nodes' children: the hit (child, primitive) pairs compacted, counted at
    // counters_[level - 1], then down.
    void expand(int level, const NodePrim* in, size_t most, LaunchCount count) {
        const int arity = s_.hierarchy_arity;
        const size_t below = node_count(level - 1);
        const RayNode* children = levels_[size_t(level) - 2].data();
        const Sphere* spheres = scene_.prim_sphere;
        const bool over_bvh = over_bvh_; // pairs name BVH slots or primitives (bvh_top.h)
        const BvhView bvh = cull_.bvh;
        const SceneView scene = scene_;
        NodePrim* next = level_pairs(level - 1, most * size_t(arity));
        uint32_t* found = counters_.data() + (level - 1);
        ex_.launch_compact(
            "rsh.level", most, count, found, level_counts_ + (level - 1),
            [=] SHEAF_HD_LAMBDA(size_t j) -> Compacted {
                const NodePrim pr = in[j];
                const Sphere s = over_bvh ? bvh_ref_sphere(bvh, scene, pr.prim) : spheres[pr.prim];
                const size_t first = size_t(pr.node) * size_t(arity);
                const size_t last = node_last_child(pr.node, arity, below);
                uint64_t m = 0;
                uint32_t c = 0;
                for (size_t ch = first; ch < last; ++ch)
                    if (node_hits_sphere(children[ch], s)) m |= uint64_t(1) << (ch - first), ++c;
                return {uint32_t(last - first), c, c, m};
            },
            [=] SHEAF_HD_LAMBDA(size_t j, uint64_t m, uint32_t slot) {
                const uint32_t first = in[j].node * uint32_t(arity);
                for (; m; m &= m - 1) {
                    int bit = 0;
                    while (!((m >> bit) & 1u)) ++bit;
                    next[slot++] = {first + uint32_t(bit), in[j].prim};
                }
            });
        descend(level - 1, next, most * size_t(arity), LaunchCount{found, 0});
    }

    // Each level-1 pair (count() of them, at most `most`): every ray of the node against the
    // primitive, exactly: the phase final_tests within traversal. The counts go to the batch's
    // slot on the executing side, so the host does not wait here.
    void finals(const NodePrim* pairs, size_t most, LaunchCount count) {
        if (most == 0) return;
        clock_.stop("traversal");
        clock_.start("final_tests");
        const int arity = s_.hierarchy_arity;
        const size_t rays_n = sorted_.size();
        const SceneView scene = scene_;
        const Ray* rays = sorted_.data();
        const uint32_t* perm = perm_;
        uint32_t* leaf_pairs = leaf_pairs_.data();
        const bool any = any_, shadow = shadow_;
        const HitSinks sinks = sinks_;
        TestCount* counts = final_count_;
        if (over_bvh_) {
            // Each ray of a level-1 node through what its node kept, on its own: exact tests
            // into the slot's final counts, box tests added to its node counts.
            const BvhView bvh = cull_.bvh;
            const uint8_t skip = skip_;
            uint32_t* ray_tests = ray_tests_;
            TestCount* node_counts = node_count_;
            ex_.launch_tally(
                "rsh.final_bvh", most, count, counts, [=] SHEAF_HD_LAMBDA(size_t j) -> TestCount {
                    const NodePrim pr = pairs[j];
                    const size_t first = size_t(pr.node) * size_t(arity);
                    const size_t last = node_last_child(pr.node, arity, rays_n);
                    const BvhCounts c = bvh_ref_rays(bvh, scene, rays, perm, first, last, pr.prim,
                                                     any, shadow, skip, sinks, ray_tests);
                    atomic_add_u64(&node_counts->tests, c.nodes.tests);
                    atomic_add_u64(&node_counts->hits, c.nodes.hits);
                    return c.prims;
                });
            clock_.stop("final_tests");
            clock_.start("traversal");
            return;
        }
        // Plain triangle pairs in one launch, the rest (analytic shapes, surfaces a shadow
        // passes) in another where the scene has any: the first kernel then needs few registers.
        ex_.launch_tally(
            "rsh.final", most, count, counts, [=] SHEAF_HD_LAMBDA(size_t j) -> TestCount {
                const NodePrim pr = pairs[j];
                atomic_add_u32(&leaf_pairs[pr.node], 1);
                if (!plain_final(scene, pr.prim, any, shadow)) return {};
                const size_t first = size_t(pr.node) * size_t(arity);
                const size_t last = node_last_child(pr.node, arity, rays_n);
                return {last - first,
                        final_triangle_tests(scene, rays, perm, first, last, pr.prim, any, sinks)};
            });
        if (scene.analytic_count > 0 || (shadow && transparent_))
            ex_.launch_tally("rsh.final_shapes", most, count, counts,
                             [=] SHEAF_HD_LAMBDA(size_t j) -> TestCount {
                                 const NodePrim pr = pairs[j];
                                 if (plain_final(scene, pr.prim, any, shadow)) return {};
                                 const size_t first = size_t(pr.node) * size_t(arity);
                                 const size_t last = node_last_child(pr.node, arity, rays_n);
                                 return {last - first, final_tests(scene, rays, perm, first, last,
                                                                   pr.prim, any, shadow, sinks)};
                             });
        clock_.stop("final_tests");
        clock_.start("traversal");
    }

    // Every ray's exact tests: the candidates of its level-1 node.
    void spread_ray_tests(uint32_t* tests, size_t n) {
        const uint32_t* perm = perm_;
        const uint32_t* leaf_pairs = leaf_pairs_.data();
        const size_t arity = size_t(s_.hierarchy_arity);
        ex_.launch("rsh.ray_tests", n,
                   [=] SHEAF_HD_LAMBDA(size_t j) { tests[perm[j]] = leaf_pairs[j / arity]; });
    }

  private:
    struct Pending {
        std::string prefix; // of the batch's statistics keys
        bool cull;          // whether it has objects.* rows
        int depth;          // its level<k>.* rows: k in 1..depth
        bool bvh;           // whether it has nodes.* rows
    };

    // A zeroed slot for the next batch; the slots grow by doubling.
    BatchCounts* take_slot(const std::string& prefix, bool cull, int depth, bool bvh) {
        if (pending_.size() == slots_.size()) {
            DeviceBuffer<BatchCounts, Exec> grown(ex_, std::max<size_t>(16, 2 * slots_.size()));
            fill(ex_, grown.data(), grown.size(), BatchCounts{});
            if (!slots_.empty())
                ex_.copy_on_device(grown.data(), slots_.data(), slots_.size() * sizeof(BatchCounts));
            slots_ = std::move(grown);
        }
        pending_.push_back({prefix, cull, depth, bvh});
        return slots_.data() + (pending_.size() - 1);
    }

    Exec& ex_;
    const PreparedScene& host_; // the scene and units in host memory (the host traversal)
    const CullUnits& units_;
    SceneView scene_;
    CullView cull_;
    const RenderSettings& s_;
    Stats& st_;
    PhaseClock<Exec>& clock_;
    uint32_t light_count_;
    size_t batch_; // traversal.batch, or the exec's choice when it is 0
    uint32_t units_with_prims_ = 0;
    bool transparent_ = false; // some primitive may let light through (shadow pass logs)
    uint8_t flags_ = 0;        // every flag some primitive has
    // The batch being traced.
    bool any_ = false, shadow_ = false;
    bool over_bvh_ = false; // crsh-bvh, rah-bvh: the top nodes through the BVH
    uint8_t skip_ = 0;
    DeviceBuffer<Ray, Exec> sorted_;
    const uint32_t* perm_ = nullptr;
    std::vector<DeviceBuffer<RayNode, Exec>> levels_;
    DeviceBuffer<uint32_t, Exec> leaf_pairs_;
    uint32_t* ray_tests_ = nullptr; // the batch's per-ray exact tests (out.tests)
    // The traversal's pairs of nodes and primitives (index k: level k) and their counters.
    std::vector<DeviceBuffer<NodePrim, Exec>> pair_bufs_;
    DeviceBuffer<uint32_t, Exec> counters_;
    HitSinks sinks_;
    // The batch's counts on the executing side, in its slot of slots_.
    TestCount* objects_count_ = nullptr;
    TestCount* final_count_ = nullptr;
    TestCount* node_count_ = nullptr;
    TestCount* level_counts_ = nullptr; // index k: level k
    // Object and final-test counts of the batches traced since the last flush.
    DeviceBuffer<BatchCounts, Exec> slots_;
    std::vector<Pending> pending_;
    DeviceBuffer<Aabb, Exec> box_; // the batch's ray origins' bounding box (hashes)
};

} // namespace sheaf::wavefront

// Building the BVH (core/accel/bvh.h): primitive bounds, then top-down binned SAH. Each node
// takes its range's best split, then splits the child of largest surface area again (below
// kBvhSahDepth, the one with the most primitives) until it has eight children or none can be
// split; a child that the heuristic keeps whole becomes a
// leaf. Large ranges bin in parallel and large children build in parallel; nodes are taken
// from one pool with an atomic counter and renumbered depth-first at the end, so the tree and
// its layout are the same on every run.
#include "core/accel/bvh.h"

#include "core/geometry/sphere.h"
#include "core/scene/prepared_scene.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace sheaf {
namespace {

constexpr int kBins = 32;
constexpr uint32_t kMaxLeaf = 8;              // primitives a leaf holds at most
constexpr float kNodeCost = 1.0f;             // a box test against a primitive test
constexpr uint32_t kParallelBin = 1u << 16;   // ranges binned in parallel from this size
constexpr uint32_t kParallelBuild = 1u << 12; // children built in parallel from this size

struct Box {
    Vec3 lo{FLT_MAX}, hi{-FLT_MAX};
    void grow(const Box& b) { lo = vmin(lo, b.lo), hi = vmax(hi, b.hi); }
    void grow(const Vec3& p) { lo = vmin(lo, p), hi = vmax(hi, p); }
    bool empty() const { return !(lo.x <= hi.x); }
    float half_area() const {
        if (empty()) return 0;
        const Vec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

/// A run of the primitive order [begin, end) with its bounds and its centroids' bounds.
struct Range {
    uint32_t begin = 0, end = 0;
    Box box, centroids;
    uint32_t size() const { return end - begin; }
};

struct Bin {
    Box box, centroids;
    uint32_t count = 0;
    void add(const Bin& b) { box.grow(b.box), centroids.grow(b.centroids), count += b.count; }
};
using Bins = std::array<Bin, kBins>;

/// A range's fate: a leaf, or a split into two.
struct Split {
    bool leaf = true;
    Range left, right;
};

/// Bounds that stay conservative after rounding: grown by kBoundPad of their magnitude.
Box padded(Box b) {
    const Vec3 m = vmax(vmax(vabs(b.lo), vabs(b.hi)), b.hi - b.lo);
    const float pad = kBoundPad * max_component(m) + FLT_MIN;
    b.lo = b.lo - Vec3(pad), b.hi = b.hi + Vec3(pad);
    return b;
}

int widest_axis(const Box& b) {
    const Vec3 e = b.hi - b.lo;
    return e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
}

bool finite_box(const Box& b) {
    const auto fin = [](const Vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    return fin(b.lo) && fin(b.hi) && max_component(vabs(b.lo)) < 1e30f &&
           max_component(vabs(b.hi)) < 1e30f;
}

class Builder {
  public:
    /// `chunk` > 0: every range of at most `chunk` triangles a leaf, every larger one split.
    /// `subset`: the primitives to hold (all of them when null).
    /// `in_order`: each range split at its middle in the primitives' order, no heuristic.
    Builder(const PreparedScene& scene, Bvh& out, uint32_t chunk,
            const std::vector<uint32_t>* subset = nullptr, bool in_order = false)
        : scene_(scene), out_(out), chunk_(chunk), subset_(subset), in_order_(in_order) {}

    void run() {
        // While building, a primitive is its key k: its place in the subset (boxes_ and
        // centers_ hold the subset's only), or its id without one; id(k) names it.
        const uint32_t count = subset_ ? uint32_t(subset_->size()) : uint32_t(scene_.prim_count());
        boxes_.resize(count);
        centers_.resize(count);
        std::vector<uint8_t> bounded(count);
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 4096),
                          [&](const tbb::blocked_range<uint32_t>& r) {
                              for (uint32_t k = r.begin(); k != r.end(); ++k) {
                                  Box b = prim_box(id(k));
                                  bounded[k] = finite_box(b) ? 1 : 0;
                                  if (!bounded[k]) continue;
                                  b = padded(b);
                                  boxes_[k] = b;
                                  centers_[k] = (b.lo + b.hi) * 0.5f;
                              }
                          });
        std::vector<uint32_t>& order = out_.prims;
        for (uint32_t k = 0; k < count; ++k) {
            if (bounded[k])
                order.push_back(k);
            else
                out_.unbounded.push_back(id(k));
        }
        if (order.empty()) return;
        Range all{0, uint32_t(order.size()), {}, {}};
        const Bin b = bin_whole(all);
        all.box = b.box, all.centroids = b.centroids;
        // Inner nodes number at most the leaves less one, and leaves the primitives: a pool
        // of that size, of which only the pages the nodes use are ever touched.
        pool_size_ = std::max<size_t>(1, order.size());
        pool_.reset(new BvhNode[pool_size_]);
        const Split split = split_range(all, 0);
        const uint32_t root = take_node();
        if (split.leaf)
            fill_node(root, {all}, {split}, 1);
        else
            build(root, split, 1);
        renumber(root);
        if (subset_)
            for (uint32_t& k : order) k = id(k);
    }

  private:
    uint32_t id(uint32_t k) const { return subset_ ? (*subset_)[k] : k; }

    Box prim_box(uint32_t p) const {
        Box b;
        if (p < scene_.tris.size()) {
            const TriangleVerts& t = scene_.tris[p];
            b.grow(t.a), b.grow(t.b), b.grow(t.c);
        } else {
            // The cube around its sphere (infinite for an unbounded one), and within it the
            // object's own box where the scene has one (csg_box: an intersection of planes
            // along the axes is bounded though its sphere is not).
            const Sphere& s = scene_.prim_sphere[p];
            if (std::fabs(s.radius) <= 1e30f)
                b.lo = s.center - Vec3(std::fabs(s.radius)),
                b.hi = s.center + Vec3(std::fabs(s.radius));
            else
                b.lo = Vec3(-INFINITY), b.hi = Vec3(INFINITY);
            const size_t a = p - scene_.tris.size();
            if (a < scene_.analytic_box.size()) {
                const WorldBox& w = scene_.analytic_box[a];
                b.lo = vmax(b.lo, w.lo), b.hi = vmin(b.hi, w.hi);
            }
        }
        return b;
    }

    uint32_t take_node() {
        const size_t i = next_.fetch_add(1, std::memory_order_relaxed);
        return uint32_t(i); // pool_size_ bounds it (see run)
    }

    // Each primitive of r in its centroid bin along `axis` (r.centroids spans the bins).
    Bins bin(const Range& r, int axis) const {
        const float lo = r.centroids.lo[axis], ext = r.centroids.hi[axis] - lo;
        const float scale = float(kBins) * (1.0f - 1e-6f) / ext;
        const std::vector<uint32_t>& order = out_.prims;
        auto fill = [&](uint32_t b, uint32_t e, Bins& bins) {
            for (uint32_t i = b; i < e; ++i) {
                const uint32_t p = order[i];
                const int k = std::clamp(int((centers_[p][axis] - lo) * scale), 0, kBins - 1);
                bins[size_t(k)].box.grow(boxes_[p]);
                bins[size_t(k)].centroids.grow(centers_[p]);
                ++bins[size_t(k)].count;
            }
        };
        if (r.size() < kParallelBin) {
            Bins bins;
            fill(r.begin, r.end, bins);
            return bins;
        }
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(r.begin, r.end, 8192), Bins{},
            [&](const tbb::blocked_range<uint32_t>& br, Bins bins) {
                fill(br.begin(), br.end(), bins);
                return bins;
            },
            [](Bins a, const Bins& b) {
                for (int k = 0; k < kBins; ++k) a[size_t(k)].add(b[size_t(k)]);
                return a;
            });
    }

    // The bounds of a whole range (the root's).
    Bin bin_whole(const Range& r) const {
        const std::vector<uint32_t>& order = out_.prims;
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(r.begin, r.end, 8192), Bin{},
            [&](const tbb::blocked_range<uint32_t>& br, Bin b) {
                for (uint32_t i = br.begin(); i != br.end(); ++i) {
                    b.box.grow(boxes_[order[i]]);
                    b.centroids.grow(centers_[order[i]]);
                }
                return b;
            },
            [](Bin a, const Bin& b) {
                a.add(b);
                return a;
            });
    }

    // The bounds of [begin, end), computed (the median split's halves).
    Range measured(uint32_t begin, uint32_t end) const {
        Range r{begin, end, {}, {}};
        for (uint32_t i = begin; i < end; ++i) {
            r.box.grow(boxes_[out_.prims[i]]);
            r.centroids.grow(centers_[out_.prims[i]]);
        }
        return r;
    }

    // Whether r is one leaf of `chunk_` (only triangles: analytic shapes stay in leaves of
    // kMaxLeaf, where the heuristic puts them).
    bool chunk_leaf(const Range& r) const {
        if (r.size() > chunk_) return false;
        for (uint32_t i = r.begin; i < r.end; ++i)
            if (!scene_.is_triangle(id(out_.prims[i]))) return false;
        return true;
    }

    // Half the range by count along the centroids' widest axis (nth_element): the split of
    // ranges whose centroids coincide, where a split must be made, and below kBvhSahDepth.
    Split median(const Range& r) {
        const int axis = widest_axis(r.centroids);
        std::vector<uint32_t>& order = out_.prims;
        const uint32_t mid = r.begin + r.size() / 2;
        std::nth_element(order.begin() + r.begin, order.begin() + mid, order.begin() + r.end,
                         [&](uint32_t a, uint32_t b) {
                             return centers_[a][axis] < centers_[b][axis] ||
                                    (centers_[a][axis] == centers_[b][axis] && a < b);
                         });
        Split s;
        s.leaf = false;
        s.left = measured(r.begin, mid);
        s.right = measured(mid, r.end);
        return s;
    }

    // The heuristic's choice for r at `depth`: a leaf when testing its primitives costs no
    // more than any split (and it fits a leaf), else the cheapest split of binned centroids.
    Split split_range(const Range& r, int depth) {
        Split s;
        if (r.size() <= 1 || chunk_leaf(r)) return s;
        if (in_order_) {
            if (r.size() <= kMaxLeaf) return s;
            const uint32_t mid = r.begin + r.size() / 2;
            s.leaf = false;
            s.left = measured(r.begin, mid);
            s.right = measured(mid, r.end);
            return s;
        }
        if (depth >= kBvhSahDepth) {
            if (r.size() <= kMaxLeaf) return s;
            return median(r);
        }
        const Vec3 e = r.centroids.hi - r.centroids.lo;
        const int axis = widest_axis(r.centroids);
        if (!(e[axis] > 0)) {
            if (r.size() <= kMaxLeaf) return s;
            return median(r);
        }
        const Bins bins = bin(r, axis);
        // Sweep: the cost of every split between bins k and k + 1.
        std::array<float, kBins> right_cost{};
        Bin acc;
        for (int k = kBins - 1; k > 0; --k) {
            acc.add(bins[size_t(k)]);
            right_cost[size_t(k)] = acc.box.half_area() * float(acc.count);
        }
        acc = Bin{};
        float best = FLT_MAX;
        int best_k = -1;
        for (int k = 0; k < kBins - 1; ++k) {
            acc.add(bins[size_t(k)]);
            if (acc.count == 0 || acc.count == r.size()) continue;
            const float c = acc.box.half_area() * float(acc.count) + right_cost[size_t(k) + 1];
            if (c < best) best = c, best_k = k;
        }
        const float area = r.box.half_area();
        const float split_cost = kNodeCost + (area > 0 ? best / area : 0.0f);
        if (best_k < 0) {
            if (r.size() <= kMaxLeaf) return s;
            return median(r);
        }
        if (r.size() <= kMaxLeaf && float(r.size()) <= split_cost) return s;
        // Partition the order by bin (stable within each side: the same tree every run).
        std::vector<uint32_t>& order = out_.prims;
        const float lo = r.centroids.lo[axis];
        const float scale = float(kBins) * (1.0f - 1e-6f) / e[axis];
        const auto left_of = [&](uint32_t p) {
            return std::clamp(int((centers_[p][axis] - lo) * scale), 0, kBins - 1) <= best_k;
        };
        // Stable, through a scratch buffer of this thread's (std::stable_partition allocates
        // one every call: fresh pages, faulted in, at every node).
        thread_local std::vector<uint32_t> right;
        right.clear();
        auto out = order.begin() + r.begin;
        for (auto it = order.begin() + r.begin; it != order.begin() + r.end; ++it)
            if (left_of(*it))
                *out++ = *it;
            else
                right.push_back(*it);
        const auto mid = out;
        std::copy(right.begin(), right.end(), out);
        s.leaf = false;
        Bin l, rt;
        for (int k = 0; k < kBins; ++k) (k <= best_k ? l : rt).add(bins[size_t(k)]);
        s.left = {r.begin, uint32_t(mid - order.begin()), l.box, l.centroids};
        s.right = {s.left.end, r.end, rt.box, rt.centroids};
        return s;
    }

    // Node `at` over the split range `split`: up to eight children, each a leaf or a node.
    // The child split next is the widest (by surface area), or below kBvhSahDepth the one
    // with the most primitives, so that there every level divides them by eight (kBvhStack).
    void build(uint32_t at, const Split& split, int depth) {
        std::vector<Range> kids{split.left, split.right};
        std::vector<Split> fate{split_range(split.left, depth), split_range(split.right, depth)};
        const bool by_count = depth >= kBvhSahDepth;
        const auto weight = [&](size_t i) {
            return by_count ? float(kids[i].size()) : kids[i].box.half_area();
        };
        while (kids.size() < size_t(kBvhWidth)) {
            int pick = -1;
            for (size_t i = 0; i < kids.size(); ++i)
                if (!fate[i].leaf && (pick < 0 || weight(i) > weight(size_t(pick)))) pick = int(i);
            if (pick < 0) break;
            const Split s = fate[size_t(pick)];
            kids[size_t(pick)] = s.left, fate[size_t(pick)] = split_range(s.left, depth);
            kids.push_back(s.right), fate.push_back(split_range(s.right, depth));
        }
        fill_node(at, kids, fate, depth);
    }

    // Writes node `at` and builds its inner children (in parallel where they are large).
    void fill_node(uint32_t at, const std::vector<Range>& kids, const std::vector<Split>& fate,
                   int depth) {
        BvhNode& node = pool_[at];
        std::array<uint32_t, kBvhWidth> child{};
        for (int i = 0; i < kBvhWidth; ++i) {
            node.child[i] = kBvhNoChild, node.count[i] = 0;
            for (int a = 0; a < 3; ++a) node.lo[a][i] = FLT_MAX, node.hi[a][i] = -FLT_MAX;
        }
        for (size_t i = 0; i < kids.size(); ++i) {
            for (int a = 0; a < 3; ++a)
                node.lo[a][i] = kids[i].box.lo[a], node.hi[a][i] = kids[i].box.hi[a];
            if (fate[i].leaf) {
                node.child[i] = kids[i].begin, node.count[i] = kids[i].size();
            } else {
                node.child[i] = child[i] = take_node();
            }
        }
        record_depth(depth);
        auto build_kid = [&](size_t i) {
            if (!fate[i].leaf) build(child[i], fate[i], depth + 1);
        };
        uint32_t inner = 0;
        for (size_t i = 0; i < kids.size(); ++i) inner += fate[i].leaf ? 0 : kids[i].size();
        if (inner < kParallelBuild) {
            for (size_t i = 0; i < kids.size(); ++i) build_kid(i);
            return;
        }
        tbb::parallel_for(size_t(0), kids.size(), build_kid);
    }

    void record_depth(int depth) {
        int d = max_depth_.load(std::memory_order_relaxed);
        while (d < depth && !max_depth_.compare_exchange_weak(d, depth)) {
        }
    }

    // The pool's nodes depth-first from the root into out_.nodes: the layout of a subtree
    // together, and the same on every run.
    void renumber(uint32_t root) {
        out_.nodes.reserve(next_.load());
        // Depth-first: pop a pool node, append it, push its inner children (last first).
        struct Item {
            uint32_t pool;
            uint32_t parent; // new index of the parent, or kBvhNoChild
            int slot;
        };
        std::vector<Item> work{{root, kBvhNoChild, 0}};
        while (!work.empty()) {
            const Item it = work.back();
            work.pop_back();
            const uint32_t at = uint32_t(out_.nodes.size());
            out_.nodes.push_back(pool_[it.pool]);
            if (it.parent != kBvhNoChild) out_.nodes[it.parent].child[it.slot] = at;
            const BvhNode& n = out_.nodes.back();
            for (int i = kBvhWidth; i-- > 0;)
                if (n.child[i] != kBvhNoChild && n.count[i] == 0)
                    work.push_back({n.child[i], at, i});
        }
        out_.depth = max_depth_.load();
        pool_.reset();
        // The traversal's stack holds seven waiting siblings a level (kBvhStack).
        if ((kBvhWidth - 1) * out_.depth + 1 > kBvhStack)
            throw std::length_error("BVH deeper than its stack");
    }

    const PreparedScene& scene_;
    Bvh& out_;
    uint32_t chunk_;
    const std::vector<uint32_t>* subset_ = nullptr;
    bool in_order_ = false;
    std::vector<Box> boxes_;
    std::vector<Vec3> centers_;
    std::unique_ptr<BvhNode[]> pool_;
    size_t pool_size_ = 0;
    std::atomic<size_t> next_{0};
    std::atomic<int> max_depth_{0};
};

} // namespace

struct BvhCache {
    std::mutex mutex;
    std::shared_ptr<const Bvh> bvh;
};

std::shared_ptr<BvhCache> new_bvh_cache() {
    return std::make_shared<BvhCache>();
}

Bvh build_bvh(const PreparedScene& scene, uint32_t chunk) {
    Bvh bvh;
    Builder(scene, bvh, chunk).run();
    return bvh;
}

Bvh build_bvh_over(const PreparedScene& scene, const std::vector<uint32_t>& prims) {
    Bvh bvh;
    Builder(scene, bvh, 0, &prims).run();
    return bvh;
}

Bvh build_bvh_in_order(const PreparedScene& scene) {
    Bvh bvh;
    Builder(scene, bvh, 0, nullptr, true).run();
    return bvh;
}

std::shared_ptr<const Bvh> bvh_for(const PreparedScene& scene) {
    BvhCache* cache = scene.bvh_cache.get();
    if (!cache) return std::make_shared<const Bvh>(build_bvh(scene));
    std::lock_guard<std::mutex> lock(cache->mutex);
    // Isolated: a thread waiting inside the build takes none of its caller's other tasks,
    // which might ask for this lock again.
    if (!cache->bvh)
        tbb::this_task_arena::isolate(
            [&] { cache->bvh = std::make_shared<const Bvh>(build_bvh(scene)); });
    return cache->bvh;
}

} // namespace sheaf

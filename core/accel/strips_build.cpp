// Building the strips (core/accel/strips.h): the top level is the SAH builder's, with leaves
// of up to kStripChunk primitives; each leaf's triangles are welded where their corners are
// the same floats and made into strips (core/accel/stripify.h), one strip for each run of
// primitive numbers that 16-bit ids reach. Leaves are made in parallel and joined in leaf order,
// so the structure is the same on every run.
#include "core/accel/strips.h"

#include "core/accel/stripify.h"

#include "core/geometry/sphere.h"
#include "core/scene/prepared_scene.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <mutex>
#include <stdexcept>

namespace sheaf {
namespace {

struct Bounds {
    Vec3 lo{FLT_MAX}, hi{-FLT_MAX};
    void grow(const Vec3& p) { lo = vmin(lo, p), hi = vmax(hi, p); }
};

/// One strip of a leaf, its arrays its own until the leaves are joined.
struct LeafStrip {
    StripHeader header{};
    std::vector<StripPlanes> planes;
    std::vector<uint8_t> meta;
    std::vector<uint16_t> index, ids;
    std::vector<Vec3> verts;
    size_t joins = 0;
};

/// What one top-level leaf becomes: its strips, and its other primitives as single items.
struct LeafStrips {
    std::vector<LeafStrip> strips;
    std::vector<uint32_t> loose;
};

float bound_pad(const Bounds& b) {
    const Vec3 m = vmax(vmax(vabs(b.lo), vabs(b.hi)), b.hi - b.lo);
    return kBoundPad * max_component(m) + FLT_MIN;
}

class StripMaker {
  public:
    StripMaker(const PreparedScene& scene, LeafStrips& leaf) : scene_(scene), leaf_(leaf) {}

    void make(const uint32_t* prims, uint32_t count) {
        std::vector<uint32_t> tris;
        for (uint32_t k = 0; k < count; ++k)
            (scene_.is_triangle(prims[k]) ? tris : leaf_.loose).push_back(prims[k]);
        std::sort(tris.begin(), tris.end());
        // A strip's ids are 16 bits from its least: runs of primitive numbers that fit.
        for (size_t b = 0; b < tris.size();) {
            size_t e = b + 1;
            while (e < tris.size() && tris[e] - tris[b] < kStripJoin) ++e;
            one(std::vector<uint32_t>(tris.begin() + long(b), tris.begin() + long(e)));
            b = e;
        }
    }

  private:
    // One strip of `tris` (sorted, within 16 bits of the first), if any fits one.
    void one(const std::vector<uint32_t>& tris) {
        weld(tris);
        std::vector<std::array<uint32_t, 3>> faces; // welded corners
        std::vector<uint32_t> prims;                // the primitive of each face
        for (size_t t = 0; t < tris.size(); ++t) {
            const uint32_t a = corner_[3 * t], b = corner_[3 * t + 1], c = corner_[3 * t + 2];
            if (a == b || b == c || a == c) {
                leaf_.loose.push_back(tris[t]); // two corners in one place: no strip edge
                continue;
            }
            faces.push_back({a, b, c});
            prims.push_back(tris[t]);
        }
        if (faces.empty()) return;
        LeafStrip made;
        out_ = &made;
        if (assign(stripify(faces), prims)) leaf_.strips.push_back(std::move(made));
        out_ = nullptr;
    }

    // Corner k of triangle t (of `tris`) becomes welded vertex corner_[3t + k]; corners in
    // the same place (the same floats) share one.
    void weld(const std::vector<uint32_t>& tris) {
        struct Key {
            uint32_t bits[3];
            uint32_t corner;
        };
        std::vector<Key> keys(3 * tris.size());
        for (size_t t = 0; t < tris.size(); ++t) {
            const TriangleVerts& tv = scene_.tris[tris[t]];
            const Vec3 c[3] = {tv.a, tv.b, tv.c};
            for (int k = 0; k < 3; ++k) {
                Key& key = keys[3 * t + size_t(k)];
                std::memcpy(key.bits, &c[k], sizeof key.bits);
                key.corner = uint32_t(3 * t + size_t(k));
            }
        }
        std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
            return std::memcmp(a.bits, b.bits, sizeof a.bits) < 0 ||
                   (std::memcmp(a.bits, b.bits, sizeof a.bits) == 0 && a.corner < b.corner);
        });
        corner_.assign(keys.size(), 0);
        positions_.clear();
        for (size_t i = 0; i < keys.size(); ++i) {
            if (i == 0 || std::memcmp(keys[i].bits, keys[i - 1].bits, sizeof keys[i].bits) != 0) {
                Vec3 p;
                std::memcpy(&p, keys[i].bits, sizeof keys[i].bits);
                positions_.push_back(p);
            }
            corner_[keys[i].corner] = uint32_t(positions_.size() - 1);
        }
        welded_ = positions_.size();
    }

    // The strip's arrays: its vertices in the order of first use, its triangles' ids (from
    // the least primitive), and its hierarchy; false when it holds no triangle of the scene.
    bool assign(const Stripified& strip, const std::vector<uint32_t>& prims) {
        const uint32_t base = *std::min_element(prims.begin(), prims.end());
        const size_t n = strip.tri.size();
        std::vector<uint16_t> ids(n, kStripJoin);
        std::vector<uint8_t> placed(prims.size(), 0);
        size_t real = 0;
        for (size_t j = 0; j < n; ++j) {
            if (strip.tri[j] < 0 || placed[size_t(strip.tri[j])]) continue;
            placed[size_t(strip.tri[j])] = 1;
            ids[j] = uint16_t(prims[size_t(strip.tri[j])] - base);
            ++real;
        }
        for (size_t f = 0; f < prims.size(); ++f)
            if (!placed[f]) leaf_.loose.push_back(prims[f]);
        if (real == 0) return false;
        out_->joins = n - real;
        // The strip's vertices in the order of first use, numbered from 0.
        std::vector<uint32_t> local(welded_, 0xFFFFFFFFu);
        out_->index.reserve(strip.verts.size());
        for (uint32_t w : strip.verts) {
            if (local[w] == 0xFFFFFFFFu) {
                local[w] = uint32_t(out_->verts.size());
                out_->verts.push_back(positions_[w]);
            }
            out_->index.push_back(uint16_t(local[w]));
        }
        out_->ids = std::move(ids);
        StripHeader& h = out_->header;
        Bounds all;
        for (const Vec3& p : out_->verts) all.grow(p);
        pad_ = bound_pad(all);
        for (int a = 0; a < 3; ++a) h.lo[a] = all.lo[a] - pad_, h.hi[a] = all.hi[a] + pad_;
        float edge = 0;
        for (size_t j = 0; j < n; ++j) {
            if (out_->ids[j] == kStripJoin) continue;
            for (size_t k = 0; k < 3; ++k) {
                const Vec3 e =
                    out_->verts[out_->index[j + k]] - out_->verts[out_->index[j + (k + 1) % 3]];
                edge = std::max(edge, std::fabs(e.x) + std::fabs(e.y) + std::fabs(e.z));
            }
        }
        h.edge = edge;
        h.tris = uint32_t(n);
        h.base_prim = base;
        const uint32_t leaves = (h.tris + kStripLeaf - 1) / kStripLeaf;
        if (leaves > (1u << kStripDepth))
            throw std::length_error("strip longer than its hierarchy");
        out_->planes.resize(leaves - 1);
        out_->meta.resize(leaves - 1);
        if (leaves > 1) node(0, 0, h.tris);
        return true;
    }

    // The bounds of the strip's triangles [l, l + m): their vertices.
    Bounds part(uint32_t l, uint32_t m) const {
        Bounds b;
        for (uint32_t k = l; k < l + m + 2; ++k) b.grow(out_->verts[out_->index[k]]);
        return b;
    }

    // Node k over triangles [l, l + m): the axis along which its two parts overlap least,
    // the lower part's upper plane and the upper part's lower plane.
    void node(uint32_t k, uint32_t l, uint32_t m) {
        uint32_t first, span;
        strip_split(m, first, span);
        const Bounds a = part(l, first), b = part(l + first, m - first);
        int axis = 0;
        float least = FLT_MAX;
        for (int x = 0; x < 3; ++x) {
            const float overlap = std::min(a.hi[x], b.hi[x]) - std::max(a.lo[x], b.lo[x]);
            if (overlap < least) least = overlap, axis = x;
        }
        const bool first_upper = a.lo[axis] + a.hi[axis] > b.lo[axis] + b.hi[axis];
        const Bounds& lower = first_upper ? b : a;
        const Bounds& upper = first_upper ? a : b;
        out_->planes[k] = {lower.hi[axis] + pad_, upper.lo[axis] - pad_};
        out_->meta[k] = uint8_t(axis | (first_upper ? 4 : 0));
        if (first > kStripLeaf) node(k + 1, l, first);
        if (m - first > kStripLeaf) node(k + span, l + first, m - first);
    }

    const PreparedScene& scene_;
    LeafStrips& leaf_;
    LeafStrip* out_ = nullptr; // the strip assign() fills
    std::vector<uint32_t> corner_;
    std::vector<Vec3> positions_;
    size_t welded_ = 0;
    float pad_ = 0;
};

} // namespace

struct StripsCache {
    std::mutex mutex;
    std::shared_ptr<const Strips> strips;
};

std::shared_ptr<StripsCache> new_strips_cache() {
    return std::make_shared<StripsCache>();
}

Strips build_strips(const PreparedScene& scene, uint32_t chunk) {
    Strips s;
    s.top = build_bvh(scene, chunk);
    struct Leaf {
        uint32_t node;
        int slot;
    };
    std::vector<Leaf> leaves;
    for (uint32_t i = 0; i < s.top.nodes.size(); ++i)
        for (int k = 0; k < kBvhWidth; ++k)
            if (s.top.nodes[i].child[k] != kBvhNoChild && s.top.nodes[i].count[k] > 0)
                leaves.push_back({i, k});
    std::vector<LeafStrips> made(leaves.size());
    tbb::parallel_for(size_t(0), leaves.size(), [&](size_t i) {
        const BvhNode& n = s.top.nodes[leaves[i].node];
        const int k = leaves[i].slot;
        StripMaker(scene, made[i]).make(s.top.prims.data() + n.child[k], n.count[k]);
    });
    for (uint32_t p : s.top.prims) s.triangles += scene.is_triangle(p) ? 1 : 0;
    // Joined in leaf order: each leaf's items (its strips first) and the strips' arrays.
    std::vector<uint32_t> items;
    items.reserve(s.top.prims.size() / 16 + 1);
    for (size_t i = 0; i < leaves.size(); ++i) {
        LeafStrips& leaf = made[i];
        BvhNode& n = s.top.nodes[leaves[i].node];
        const int k = leaves[i].slot;
        n.child[k] = uint32_t(items.size());
        for (LeafStrip& m : leaf.strips) {
            items.push_back(kStripItem | uint32_t(s.strips.size()));
            StripHeader h = m.header;
            h.first = uint32_t(s.index.size());
            h.first_node = uint32_t(s.planes.size());
            h.base_vertex = uint32_t(s.verts.size());
            s.strips.push_back(h);
            s.index.insert(s.index.end(), m.index.begin(), m.index.end());
            s.ids.insert(s.ids.end(), m.ids.begin(), m.ids.end());
            s.ids.resize(s.index.size(), kStripJoin); // ids parallel to the index
            s.planes.insert(s.planes.end(), m.planes.begin(), m.planes.end());
            s.meta.insert(s.meta.end(), m.meta.begin(), m.meta.end());
            s.verts.insert(s.verts.end(), m.verts.begin(), m.verts.end());
            s.joins += m.joins;
        }
        items.insert(items.end(), leaf.loose.begin(), leaf.loose.end());
        for (uint32_t p : leaf.loose) s.loose += scene.is_triangle(p) ? 1 : 0;
        n.count[k] = uint32_t(items.size()) - n.child[k];
        leaf = LeafStrips();
    }
    if (s.strips.size() >= kStripItem || s.verts.size() >= 0xFFFFFFFFu)
        throw std::length_error("too many strips");
    s.top.prims = std::move(items);
    s.top.prims.shrink_to_fit();
    return s;
}

std::shared_ptr<const Strips> strips_for(const PreparedScene& scene) {
    StripsCache* cache = scene.strips_cache.get();
    if (!cache) return std::make_shared<const Strips>(build_strips(scene));
    std::lock_guard<std::mutex> lock(cache->mutex);
    if (!cache->strips)
        tbb::this_task_arena::isolate(
            [&] { cache->strips = std::make_shared<const Strips>(build_strips(scene)); });
    return cache->strips;
}

} // namespace sheaf

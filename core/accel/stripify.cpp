// Greedy strips (core/accel/stripify.h), in the manner of the SGI stripifier: a piece starts
// where the fewest free triangles border it, so that pieces seldom strand single triangles,
// and of its start's three orientations keeps the one that grows the longest both ways.
#include "core/accel/stripify.h"

#include <algorithm>

namespace sheaf {
namespace {

class Stripper {
  public:
    explicit Stripper(const std::vector<std::array<uint32_t, 3>>& tris)
        : tris_(tris), used_(tris.size(), 0), mark_(tris.size(), 0) {
        edges_.reserve(3 * tris.size());
        for (uint32_t t = 0; t < tris.size(); ++t)
            for (int k = 0; k < 3; ++k)
                edges_.push_back({key(tris[t][size_t(k)], tris[t][size_t(k + 1) % 3]), t});
        std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) {
            return a.key < b.key || (a.key == b.key && a.tri < b.tri);
        });
    }

    Stripified run() {
        Stripified out;
        for (size_t left = tris_.size(); left > 0;) {
            const uint32_t s = start();
            Piece best;
            for (int o = 0; o < 3; ++o) {
                Piece p = piece(s, o);
                if (p.tri.size() > best.tri.size()) best = std::move(p);
            }
            for (uint32_t t : best.tri) used_[t] = 1;
            left -= best.tri.size();
            if (!out.verts.empty()) out.tri.insert(out.tri.end(), {-1, -1}); // the join
            out.verts.insert(out.verts.end(), best.verts.begin(), best.verts.end());
            for (uint32_t t : best.tri) out.tri.push_back(int32_t(t));
        }
        return out;
    }

  private:
    struct Edge {
        uint64_t key;
        uint32_t tri;
    };
    struct Piece {
        std::vector<uint32_t> verts, tri;
    };

    static uint64_t key(uint32_t a, uint32_t b) {
        return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a;
    }

    bool free(uint32_t t) const { return !used_[t] && mark_[t] != epoch_; }

    // A free triangle across edge (a, b), the lowest first; or none (-1).
    int64_t across(uint32_t a, uint32_t b) const {
        const uint64_t k = key(a, b);
        auto it = std::lower_bound(edges_.begin(), edges_.end(), k,
                                   [](const Edge& e, uint64_t x) { return e.key < x; });
        for (; it != edges_.end() && it->key == k; ++it)
            if (free(it->tri)) return it->tri;
        return -1;
    }

    uint32_t third(uint32_t t, uint32_t a, uint32_t b) const {
        for (uint32_t v : tris_[t])
            if (v != a && v != b) return v;
        return tris_[t][0];
    }

    // The unused triangle with the fewest unused neighbours (the lowest of equals).
    uint32_t start() {
        ++epoch_; // no trial marks
        uint32_t best = 0;
        int fewest = 4;
        for (uint32_t t = 0; t < tris_.size(); ++t) {
            if (used_[t]) continue;
            int n = 0;
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = tris_[t][size_t(k)], b = tris_[t][size_t(k + 1) % 3];
                mark_[t] = epoch_; // not its own neighbour
                n += across(a, b) >= 0 ? 1 : 0;
                mark_[t] = 0;
            }
            if (n < fewest) fewest = n, best = t;
            if (n == 0) break;
        }
        return best;
    }

    // Grows `seq` (its triangles `tri`) past its last two vertices while a free triangle
    // borders them, marking what it takes.
    void grow(std::vector<uint32_t>& seq, std::vector<uint32_t>& tri) {
        for (;;) {
            const uint32_t x = seq[seq.size() - 2], y = seq.back();
            const int64_t t = across(x, y);
            if (t < 0) return;
            mark_[size_t(t)] = epoch_;
            seq.push_back(third(uint32_t(t), x, y));
            tri.push_back(uint32_t(t));
        }
    }

    // The piece through triangle s entered with its corners rotated by o: grown forward from
    // its last edge, then backward from its first.
    Piece piece(uint32_t s, int o) {
        ++epoch_;
        mark_[s] = epoch_;
        const uint32_t a = tris_[s][size_t(o)], b = tris_[s][size_t(o + 1) % 3],
                       c = tris_[s][size_t(o + 2) % 3];
        Piece f;
        f.verts = {a, b, c};
        f.tri = {s};
        grow(f.verts, f.tri);
        std::vector<uint32_t> back = {c, b, a}, back_tri = {s};
        grow(back, back_tri);
        Piece p;
        p.verts.assign(back.rbegin(), back.rend());
        p.verts.insert(p.verts.end(), f.verts.begin() + 3, f.verts.end());
        p.tri.assign(back_tri.rbegin(), back_tri.rend() - 1);
        p.tri.insert(p.tri.end(), f.tri.begin(), f.tri.end());
        return p;
    }

    const std::vector<std::array<uint32_t, 3>>& tris_;
    std::vector<Edge> edges_;
    std::vector<uint8_t> used_;
    std::vector<uint32_t> mark_;
    uint32_t epoch_ = 0;
};

} // namespace

Stripified stripify(const std::vector<std::array<uint32_t, 3>>& tris) {
    if (tris.empty()) return {};
    return Stripper(tris).run();
}

} // namespace sheaf

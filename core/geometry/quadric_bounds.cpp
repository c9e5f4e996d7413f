#include "core/geometry/quadric_bounds.h"

#include <algorithm>
#include <cmath>

namespace sheaf {

namespace {

struct Range {
    double lo, hi;
};

Range scaled(double s, Range r) {
    if (s == 0) return {0, 0};
    return s > 0 ? Range{s * r.lo, s * r.hi} : Range{s * r.hi, s * r.lo};
}

Range squared(Range r) {
    const double a = r.lo * r.lo, b = r.hi * r.hi;
    if (r.lo >= 0) return {a, b};
    if (r.hi <= 0) return {b, a};
    return {0, std::max(a, b)};
}

// The product of two ranges; 0 x infinity (a side at 0 against an infinite one) is left out,
// the other corners covering it.
Range product(Range a, Range b) {
    if ((a.lo == 0 && a.hi == 0) || (b.lo == 0 && b.hi == 0)) return {0, 0};
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    Range r{INFINITY, -INFINITY};
    for (double v : p)
        if (!std::isnan(v)) r.lo = std::min(r.lo, v), r.hi = std::max(r.hi, v);
    return r;
}

Range sum(Range a, Range b) {
    return {a.lo + b.lo, a.hi + b.hi};
}

// The roots of a x^2 + l x + r (a > 0), false where it has none (positive everywhere).
bool roots(double a, double l, double r, double& r0, double& r1) {
    const double disc = l * l - 4 * a * r;
    if (!(disc >= 0)) return false;
    const double s = std::sqrt(disc);
    r0 = (-l - s) / (2 * a), r1 = (-l + s) / (2 * a);
    return true;
}

} // namespace

bool world_quadric(const PolyCoeffs& p, const Affine& to_local, WorldQuadric& out) {
    // The local quadric u^T A u + a . u + a0.
    double A[3][3] = {}, a[3] = {}, a0 = 0;
    bool quadric = true;
    poly_detail::for_each_term([&](int term, int i, int j, int k) {
        const double v = p.c[term];
        if (v == 0) return;
        const int e[3] = {i, j, k};
        if (i + j + k > 2) {
            quadric = false;
            return;
        }
        if (i + j + k == 0) {
            a0 += v;
            return;
        }
        int axes[2], n = 0;
        for (int x = 0; x < 3; ++x)
            for (int m = 0; m < e[x]; ++m) axes[n++] = x;
        if (n == 1) {
            a[axes[0]] += v;
        } else if (axes[0] == axes[1]) {
            A[axes[0]][axes[0]] += v;
        } else {
            A[axes[0]][axes[1]] += 0.5 * v, A[axes[1]][axes[0]] += 0.5 * v;
        }
    });
    if (!quadric) return false;
    // u = M p + t: q = M^T A M, b = 2 M^T A t + M^T a, c = t^T A t + a . t + a0.
    double M[3][3], t[3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) M[r][c] = to_local.m[r][c];
        t[r] = to_local.m[r][3];
    }
    double AM[3][3], At[3];
    for (int r = 0; r < 3; ++r) {
        At[r] = 0;
        for (int c = 0; c < 3; ++c) {
            AM[r][c] = 0;
            for (int k = 0; k < 3; ++k) AM[r][c] += A[r][k] * M[k][c];
            At[r] += A[r][c] * t[c];
        }
    }
    out.c = a0;
    for (int r = 0; r < 3; ++r) {
        out.b[r] = 0;
        for (int k = 0; k < 3; ++k) out.b[r] += 2 * M[k][r] * At[k] + M[k][r] * a[k];
        for (int c = 0; c < 3; ++c) {
            out.q[r][c] = 0;
            for (int k = 0; k < 3; ++k) out.q[r][c] += M[k][r] * AM[k][c];
        }
        out.c += t[r] * At[r] + a[r] * t[r];
    }
    return true;
}

void narrow_by_quadric(const WorldQuadric& w, WorldBox& b) {
    Range x[3];
    for (int k = 0; k < 3; ++k) x[k] = {b.lo[k], b.hi[k]};
    for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < 3; ++i) {
            const double a = w.q[i][i];
            if (!(a > 0)) continue;
            // q = a x_i^2 + L x_i + R, L and R ranging with the other axes.
            Range L{w.b[i], w.b[i]}, R{w.c, w.c};
            for (int j = 0; j < 3; ++j) {
                if (j == i) continue;
                L = sum(L, scaled(2 * w.q[i][j], x[j]));
                // q_jj x^2 + b_j x as q_jj (x + s)^2 - q_jj s^2: x counted once, so an axis
                // without bounds still gives its least value where q_jj > 0.
                const double qj = w.q[j][j];
                if (qj != 0) {
                    const double s = w.b[j] / (2 * qj);
                    const Range moved = squared({x[j].lo + s, x[j].hi + s});
                    R = sum(R, sum(scaled(qj, moved), Range{-qj * s * s, -qj * s * s}));
                } else {
                    R = sum(R, scaled(w.b[j], x[j]));
                }
                for (int k = j + 1; k < 3; ++k)
                    if (k != i && w.q[j][k] != 0)
                        R = sum(R, scaled(2 * w.q[j][k], product(x[j], x[k])));
            }
            if (!(std::isfinite(L.lo) && std::isfinite(L.hi) && std::isfinite(R.lo))) continue;
            // x_i >= 0 can satisfy it only where a x^2 + L.lo x + R.lo <= 0, x_i < 0 where
            // a x^2 + L.hi x + R.lo <= 0.
            Range got{INFINITY, -INFINITY};
            double r0, r1;
            if (roots(a, L.lo, R.lo, r0, r1) && r1 >= 0)
                got.lo = std::min(got.lo, std::max(r0, 0.0)), got.hi = std::max(got.hi, r1);
            if (roots(a, L.hi, R.lo, r0, r1) && r0 <= 0)
                got.lo = std::min(got.lo, r0), got.hi = std::max(got.hi, std::min(r1, 0.0));
            if (!(got.lo <= got.hi)) continue; // no point of it in the box: left as it was
            // Rounding: room of 1e-6 of the range's size and place.
            const double room =
                1e-6 * (got.hi - got.lo + std::fabs(got.lo) + std::fabs(got.hi)) + 1e-9;
            const double lo = std::max(x[i].lo, got.lo - room),
                         hi = std::min(x[i].hi, got.hi + room);
            if (lo <= hi) x[i] = {lo, hi};
        }
    for (int k = 0; k < 3; ++k) b.lo[k] = float(x[k].lo), b.hi[k] = float(x[k].hi);
}

} // namespace sheaf

// Polynomial surfaces of degree at most 4 (POV-Ray's quadric, cubic, quartic and poly): the
// solid where P(x, y, z) < 0, exactly along a ray. P's 35 coefficients are kept in POV-Ray's
// order for a quartic: the power of x falls from 4 to 0, within it the power of y, within that
// the power of z (x^4, x^3 y, x^3 z, x^3, x^2 y^2, ..., z, 1); lower degrees use the same
// layout with the higher terms zero.
//
// Along a ray p = o + t d, P is a polynomial q(t) of degree at most 4. Its real roots are
// isolated by the roots of its derivatives (q is monotone between consecutive roots of q') and
// each is found by a bracketed Newton iteration in double precision, so no root is missed
// however close two of them lie, and no sampling step has to be chosen.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/hd_math.h"

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace sheaf {

constexpr int kPolyTerms = 35;
constexpr int kPolyMaxDegree = 4;

struct PolyCoeffs {
    double c[kPolyTerms] = {};
};

namespace poly_detail {

/// Calls f(term, i, j, k) for the 35 terms x^i y^j z^k in POV-Ray's order.
template <class F> SHEAF_HD_INLINE void for_each_term(F&& f) {
    int term = 0;
    for (int i = kPolyMaxDegree; i >= 0; --i)
        for (int j = kPolyMaxDegree - i; j >= 0; --j)
            for (int k = kPolyMaxDegree - i - j; k >= 0; --k) f(term++, i, j, k);
}

/// Coefficients of (o + d t)^n for n = 0..4: pw[n][m] is the one of t^m.
SHEAF_HD_INLINE void binomial_powers(double o, double d, double pw[5][5]) {
    for (int n = 0; n < 5; ++n)
        for (int m = 0; m < 5; ++m) pw[n][m] = 0;
    pw[0][0] = 1;
    for (int n = 1; n < 5; ++n)
        for (int m = 0; m <= n; ++m)
            pw[n][m] = (m < n ? pw[n - 1][m] * o : 0) + (m > 0 ? pw[n - 1][m - 1] * d : 0);
}

SHEAF_HD_INLINE double eval(const double* q, int n, double t) {
    double v = q[n];
    for (int m = n - 1; m >= 0; --m) v = v * t + q[m];
    return v;
}

/// The root of q (degree n <= MaxDeg) in [lo, hi], where q(lo) and q(hi) differ in sign and q
/// is monotone: Newton steps that stay inside the bracket, bisection otherwise.
template <int MaxDeg = kPolyMaxDegree>
SHEAF_HD_INLINE double bracketed_root(const double* q, int n, double lo, double hi) {
    double dq[MaxDeg];
    for (int m = 1; m <= n; ++m) dq[m - 1] = m * q[m];
    const bool rising = eval(q, n, lo) < 0;
    double t = 0.5 * (lo + hi);
    for (int it = 0; it < 200; ++it) {
        const double v = eval(q, n, t);
        if (v == 0) return t;
        if ((v < 0) == rising)
            lo = t;
        else
            hi = t;
        const double slope = eval(dq, n - 1, t);
        double next = slope != 0 ? t - v / slope : lo;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == t || !(hi - lo > 1e-15 * (fabs(lo) + fabs(hi)))) return next;
        t = next;
    }
    return t;
}

} // namespace poly_detail

/// q(t) = P(o + t d) for the local ray `r`: q[0..4]. The degree returned drops a leading
/// coefficient that is only rounding left from cancelling terms (a ray along a cylinder's
/// axis); -1 when every coefficient is zero (the ray lies in the surface).
SHEAF_HD_INLINE int ray_polynomial(const PolyCoeffs& p, const Ray& r, double q[5]) {
    using namespace poly_detail;
    double px[5][5], py[5][5], pz[5][5], ax[5][5], ay[5][5], az[5][5];
    binomial_powers(r.origin.x, r.dir.x, px);
    binomial_powers(r.origin.y, r.dir.y, py);
    binomial_powers(r.origin.z, r.dir.z, pz);
    binomial_powers(fabs(double(r.origin.x)), fabs(double(r.dir.x)), ax);
    binomial_powers(fabs(double(r.origin.y)), fabs(double(r.dir.y)), ay);
    binomial_powers(fabs(double(r.origin.z)), fabs(double(r.dir.z)), az);
    double mag[5] = {0, 0, 0, 0, 0};
    for (int m = 0; m < 5; ++m) q[m] = 0;
    for_each_term([&](int term, int i, int j, int k) {
        const double c = p.c[term];
        if (c == 0) return;
        double xy[5] = {0, 0, 0, 0, 0}, axy[5] = {0, 0, 0, 0, 0};
        for (int a = 0; a <= i; ++a)
            for (int b = 0; b <= j; ++b) {
                xy[a + b] += px[i][a] * py[j][b];
                axy[a + b] += ax[i][a] * ay[j][b];
            }
        for (int a = 0; a <= i + j; ++a)
            for (int b = 0; b <= k; ++b) {
                q[a + b] += c * xy[a] * pz[k][b];
                mag[a + b] += fabs(c) * axy[a] * az[k][b];
            }
    });
    int n = kPolyMaxDegree;
    while (n >= 0 && !(fabs(q[n]) > 1e-12 * mag[n])) --n;
    return n;
}

/// The real roots of q (degree n <= MaxDeg, q[n] != 0) inside (lo_b, hi_b) where q changes
/// sign, ascending; returns their count (at most n). A root exactly at lo_b or hi_b is not
/// reported. The roots of q's derivatives, from the linear one up, split the interval into
/// pieces where the next one is monotone, so no root is missed however close two lie.
template <int MaxDeg = kPolyMaxDegree>
SHEAF_HD_INLINE int poly_roots_in(const double* q, int n, double lo_b, double hi_b, double* roots) {
    using namespace poly_detail;
    if (n <= 0) return 0;
    if (n == 1) {
        const double t = -q[0] / q[1];
        if (!(t > lo_b && t < hi_b)) return 0;
        roots[0] = t;
        return 1;
    }
    double d[MaxDeg + 1][MaxDeg + 1];
    for (int m = 0; m <= n; ++m) d[0][m] = q[m];
    for (int level = 1; level < n; ++level)
        for (int m = 0; m + level <= n; ++m) d[level][m] = (m + 1) * d[level - 1][m + 1];
    double crit[MaxDeg];
    int ncrit = 0;
    {
        const double* lin = d[n - 1]; // degree 1
        const double t = -lin[0] / lin[1];
        if (t > lo_b && t < hi_b) crit[ncrit++] = t;
    }
    int nroots = 0;
    for (int level = n - 2; level >= 0; --level) {
        const int deg = n - level;
        const double* p = d[level];
        nroots = 0;
        double lo = lo_b, flo = eval(p, deg, lo);
        for (int c = 0; c <= ncrit; ++c) {
            const double hi = c < ncrit ? crit[c] : hi_b, fhi = eval(p, deg, hi);
            if (fhi == 0 && c < ncrit) {
                // A root at a critical point: a sign change only if the sides differ.
                if ((flo < 0) != (eval(p, deg, c + 1 < ncrit ? crit[c + 1] : hi_b) < 0))
                    roots[nroots++] = hi;
            } else if (flo != 0 && (flo < 0) != (fhi < 0)) {
                roots[nroots++] = bracketed_root<MaxDeg>(p, deg, lo, hi);
            }
            lo = hi, flo = fhi;
        }
        for (int m = 0; m < nroots; ++m) crit[m] = roots[m];
        ncrit = nroots;
    }
    return nroots;
}

/// Makes the roots of a polynomial found inside (0, 1) agree with its signs at the ends, fa
/// and fb (values shared with the neighbouring pieces of a curve or a ray): where rounding near an
/// end found one root too many or too few, the end nearer to zero gets or loses it.
SHEAF_HD_INLINE int reconcile_roots(double* roots, int nr, double fa, double fb) {
    const bool odd = (fa >= 0) != (fb >= 0);
    if ((nr & 1) == int(odd)) return nr;
    if (fabs(fa) <= fabs(fb)) {
        if (nr > 0 && roots[0] < 1e-3) {
            for (int i = 1; i < nr; ++i) roots[i - 1] = roots[i];
            return nr - 1;
        }
        for (int i = nr; i > 0; --i) roots[i] = roots[i - 1];
        roots[0] = 0;
        return nr + 1;
    }
    if (nr > 0 && roots[nr - 1] > 1 - 1e-3) return nr - 1;
    roots[nr] = 1;
    return nr + 1;
}

/// The real roots of q (degree n <= 4, q[n] != 0) where q changes sign, ascending; returns
/// their count (at most n).
SHEAF_HD_INLINE int poly_roots(const double* q, int n, double* roots) {
    if (n <= 0) return 0;
    if (n == 1) {
        roots[0] = -q[0] / q[1];
        return 1;
    }
    // Every complex root lies within Fujiwara's bound, so every critical point does too.
    double bound = 0;
    for (int k = 1; k <= n; ++k) {
        double ratio = fabs(q[n - k] / q[n]);
        if (k == n) ratio *= 0.5;
        const double r = hdm::pow(ratio, 1.0 / k); // same bits on both backends
        if (r > bound) bound = r;
    }
    bound = 2 * bound + 1;
    return poly_roots_in(q, n, -bound, bound, roots);
}

/// The gradient of P at local point (x, y, z): the outward normal (P < 0 inside).
SHEAF_HD_INLINE Vec3 poly_gradient(const PolyCoeffs& p, double x, double y, double z) {
    double px[5] = {1, x, x * x, x * x * x, x * x * x * x}, py[5] = {1, y, y * y, y * y * y, 0},
           pz[5] = {1, z, z * z, z * z * z, 0};
    py[4] = py[2] * py[2], pz[4] = pz[2] * pz[2];
    double g[3] = {0, 0, 0};
    poly_detail::for_each_term([&](int term, int i, int j, int k) {
        const double c = p.c[term];
        if (c == 0) return;
        if (i > 0) g[0] += c * i * px[i - 1] * py[j] * pz[k];
        if (j > 0) g[1] += c * j * px[i] * py[j - 1] * pz[k];
        if (k > 0) g[2] += c * k * px[i] * py[j] * pz[k - 1];
    });
    return Vec3(float(g[0]), float(g[1]), float(g[2]));
}

/// P at a local point: negative inside.
SHEAF_HD_INLINE double poly_value(const PolyCoeffs& p, double x, double y, double z) {
    double v = 0;
    poly_detail::for_each_term([&](int term, int i, int j, int k) {
        const double c = p.c[term];
        if (c == 0) return;
        double m = c;
        for (int e = 0; e < i; ++e) m *= x;
        for (int e = 0; e < j; ++e) m *= y;
        for (int e = 0; e < k; ++e) m *= z;
        v += m;
    });
    return v;
}

/// Index of the term x^i y^j z^k (i + j + k <= 4) in the 35-term layout.
SHEAF_HD_INLINE int poly_term(int i, int j, int k) {
    int found = -1;
    poly_detail::for_each_term([&](int term, int a, int b, int c) {
        if (a == i && b == j && c == k) found = term;
    });
    return found;
}

/// How many coefficients a polynomial of degree `order` has in POV-Ray's layout (10, 20, 35).
inline size_t poly_coefficient_count(int order) {
    return size_t(order + 1) * size_t(order + 2) * size_t(order + 3) / 6;
}

/// Coefficients given in POV-Ray's order for degree `order` <= 4 (the power of x falls from
/// `order`, within it y's, within that z's; poly_coefficient_count(order) of them), placed in
/// the 35-term layout. Host only: the readers' one way in.
template <class T> PolyCoeffs poly_from_pov_order(int order, const T* c) {
    PolyCoeffs p;
    size_t at = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) p.c[poly_term(i, j, k)] = double(c[at++]);
    return p;
}

/// Whether every coefficient is zero (no surface at all).
inline bool poly_is_zero(const PolyCoeffs& p) {
    for (double c : p.c)
        if (c != 0) return false;
    return true;
}

} // namespace sheaf

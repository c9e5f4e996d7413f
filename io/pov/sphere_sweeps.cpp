// sphere_sweep { linear_spline | b_spline | cubic_spline N, <C>, R, ... [tolerance T]
// modifiers }: a sphere moved along a spline, its radius following the same spline. Built as a
// union of spheres and the cones tangent to each neighbouring pair, which is exactly a linear
// sweep; a b_spline (uniform cubic B-spline, not through its points) or cubic_spline
// (Catmull-Rom through all points but the first and last) is sampled kSweepSteps times a
// segment and swept linearly between the samples.
#include "io/pov/parser.h"

#include "core/base/error.h"

#include <cmath>

namespace sheaf::io::pov {

namespace {

/// Samples taken along each segment of a b_spline or cubic_spline.
constexpr int kSweepSteps = 16;

struct Ball {
    Vec3 c;
    double r;
};

/// The point at t in [0, 1] of the segment through p[0..3]: a uniform cubic B-spline, or
/// Catmull-Rom (from p[1] to p[2]).
Ball spline_point(const Ball* p, double t, bool b_spline) {
    double w[4];
    const double t2 = t * t, t3 = t2 * t;
    if (b_spline) {
        w[0] = (1 - t) * (1 - t) * (1 - t) / 6;
        w[1] = (3 * t3 - 6 * t2 + 4) / 6;
        w[2] = (-3 * t3 + 3 * t2 + 3 * t + 1) / 6;
        w[3] = t3 / 6;
    } else {
        w[0] = (-t3 + 2 * t2 - t) / 2;
        w[1] = (3 * t3 - 5 * t2 + 2) / 2;
        w[2] = (-3 * t3 + 4 * t2 + t) / 2;
        w[3] = (t3 - t2) / 2;
    }
    Ball b{Vec3(0, 0, 0), 0};
    for (int i = 0; i < 4; ++i) {
        b.c += p[i].c * float(w[i]);
        b.r += p[i].r * w[i];
    }
    return b;
}

PovObject sphere_piece(const Ball& b) {
    PovObject s;
    s.kind = PovKind::Shape;
    s.shape.kind = ShapeKind::Sphere;
    s.local = Affine::translate(b.c) * Affine::scale(Vec3(float(b.r)));
    return s;
}

/// The cone touching both balls along a circle each (the envelope of the sphere moving from a
/// to b); false when one ball holds the other, so that the spheres alone are the sweep.
bool cone_piece(const Ball& a, const Ball& b, PovObject& out) {
    const Vec3 axis = b.c - a.c;
    const double d = length(axis);
    if (!(d > 1e-9) || std::fabs(a.r - b.r) >= d * (1 - 1e-6)) return false;
    const Vec3 w = axis * float(1 / d);
    const double s = (a.r - b.r) / d, c = std::sqrt(1 - s * s);
    // The circles of contact: offset by r * s along the axis, of radius r * c.
    const Vec3 base = a.c + w * float(a.r * s), cap = b.c + w * float(b.r * s);
    Vec3 u, v;
    basis(w, u, v);
    out = PovObject();
    out.kind = PovKind::Shape;
    out.shape.kind = ShapeKind::Cone;
    out.shape.a = float(a.r * c), out.shape.b = float(b.r * c);
    out.local = frame(base, u, v, cap - base);
    return true;
}

} // namespace

bool Parser::parse_sphere_sweep(const Token& kw, PovObject& o) {
    expect_sym("{");
    const Token& type = peek();
    int minimum = 0;
    bool b_spline = false;
    if (accept_kw("linear_spline")) {
        minimum = 2;
    } else if (accept_kw("b_spline")) {
        minimum = 4, b_spline = true;
    } else if (accept_kw("cubic_spline")) {
        minimum = 4;
    } else {
        error_expected(type, "linear_spline, b_spline or cubic_spline");
    }
    const Token& count_at = peek();
    ++no_lt_; // "4 <0, 0, 0>, 1 ..." is the count and the first sphere
    const double count = parse_float();
    --no_lt_;
    if (!(count >= minimum && count <= 1e6) || count != std::floor(count))
        error_at(count_at, "a sphere_sweep with " + type.text +
                               " needs a whole number of at least " + std::to_string(minimum) +
                               " spheres");
    charge(size_t(count) * sizeof(Ball), count_at);
    std::vector<Ball> balls;
    ++no_lt_; // "<0, 0, 0>, 1 <1, 0, 0>, 1": a radius and the next centre
    for (int i = 0; i < int(count); ++i) {
        accept_sym(",");
        const Vec3 c = parse_vector();
        accept_sym(",");
        const Token& r_at = peek();
        const double r = parse_float();
        if (!(r > 0)) error_at(r_at, "a sphere_sweep's radius must be greater than 0");
        balls.push_back({c, r});
    }
    --no_lt_;
    if (accept_kw("tolerance")) parse_float(); // the depth tolerance of POV-Ray's root finder

    // The sweep's path as balls to join: the points themselves, or the spline's samples.
    std::vector<Ball> path;
    if (minimum == 2) {
        path = balls;
    } else {
        for (size_t s = 0; s + 3 < balls.size(); ++s)
            for (int k = s == 0 ? 0 : 1; k <= kSweepSteps; ++k)
                path.push_back(spline_point(&balls[s], double(k) / kSweepSteps, b_spline));
    }
    o.kind = PovKind::Csg;
    o.op = CsgOp::Union;
    charge(path.size() * 2 * sizeof(PovObject), kw);
    count_objects(kw, path.size() * 2);
    for (size_t i = 0; i < path.size(); ++i) {
        o.children.push_back(sphere_piece(path[i]));
        o.children.back().where = kw;
        PovObject cone;
        if (i + 1 < path.size() && cone_piece(path[i], path[i + 1], cone)) {
            cone.where = kw;
            o.children.push_back(std::move(cone));
        }
    }
    bool texture_here = false;
    parse_object_modifiers(o, texture_here);
    return true;
}

} // namespace sheaf::io::pov

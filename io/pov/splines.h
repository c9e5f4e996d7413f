// POV-Ray's splines in the scene language: `spline { [TYPE] TIME, POINT [,] … }`, declared,
// copied and extended (`spline { S [TYPE] … }`), and called as S(t [, TYPE]) or through a
// spline function (`function { spline { … } }`): the point at time t, interpolated as
// POV-Ray 3.7 interpolates each type (linear, quadratic, Catmull-Rom for cubic_spline, natural
// cubic), clamped to the ends outside the times.
#pragma once

#include <array>
#include <vector>

namespace sheaf::io::pov {

enum class SplineKind { Linear, Quadratic, Cubic, Natural };

struct PovSpline {
    struct Entry {
        double time;
        std::array<double, 5> point; // floats and shorter vectors padded with zeros
    };
    SplineKind kind = SplineKind::Linear;
    int dim = 1;                // the most components a point has: the dimension of a value
    std::vector<Entry> entries; // by increasing time
    /// The natural spline's second derivatives at the entries, once the spline is read
    /// (finish); empty until then.
    std::vector<std::array<double, 5>> moments;

    /// Adds a point at `time`, keeping the times in order; a time given again replaces its
    /// point, but for the last time, whose new point is dropped (as POV-Ray 3.7 does).
    void insert(double time, const std::array<double, 5>& point, int components);
    /// Computes what evaluation derives from the entries (the natural spline's moments).
    void finish();
    /// The point at time t, as `kind` interpolates it.
    std::array<double, 5> at(double t, SplineKind kind) const;
    std::array<double, 5> at(double t) const { return at(t, kind); }
};

} // namespace sheaf::io::pov

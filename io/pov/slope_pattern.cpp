// The slope pattern's arguments, as POV-Ray 3.7 reads them:
//   slope <S>
//   slope { <S> [,] [LO] [,] [HI] [altitude <A> [,] [LO] [,] [HI]] }
//   slope { point_at <P> [,] [LO] [,] [HI] }
// A missing LO or HI is 0; a range whose ends are equal (and not 0) is warned and ignored.
// The lengths of S and A weigh the slope against the altitude (core/scene/pattern.h).
#include "io/pov/parser.h"

namespace sheaf::io::pov {

void Parser::parse_slope(PovPattern& pt, const Token& keyword) {
    pt.kind = PatternKind::Slope;
    pt.slope_point_at = false;
    pt.slope_altitude = Vec3(0.0f);
    for (double& p : pt.param) p = 0;
    if (!accept_sym("{")) { // the old form: a direction alone
        pt.vector = parse_vector();
    } else {
        pt.slope_point_at = accept_kw("point_at");
        pt.vector = parse_vector();
        // [,] [LO] [,] [HI], each number optional; equal ends (not 0) are no range.
        auto range = [&](double* lo_hi, const char* what) {
            accept_sym(",");
            const Token& at = peek();
            if (starts_expression(peek())) lo_hi[0] = parse_float();
            accept_sym(",");
            if (starts_expression(peek())) lo_hi[1] = parse_float();
            if (lo_hi[1] != 0 && lo_hi[1] == lo_hi[0]) {
                warn(at, std::string("a zero ") + what + " range (low = high), ignored");
                lo_hi[0] = lo_hi[1] = 0;
            }
        };
        range(pt.param, "slope");
        while (is_kw("altitude")) {
            const Token at = next();
            if (pt.slope_point_at) error_at(at, "a slope with point_at takes no altitude");
            pt.slope_altitude = parse_vector();
            pt.param[2] = pt.param[3] = 0;
            range(pt.param + 2, "altitude");
        }
        expect_sym("}", "'}' closing the slope pattern (after its direction, range and altitude)");
    }
    if (!pt.slope_point_at && !(length(pt.vector) > 0) && !(length(pt.slope_altitude) > 0))
        error_at(keyword, "a slope pattern needs a slope or altitude direction other than zero");
}

} // namespace sheaf::io::pov

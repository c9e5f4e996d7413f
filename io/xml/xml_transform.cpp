// Transform elements: <translate value>, <rotate axis angle>, <scale value>, <matrix value>.
// Each applies after the ones before it in the document (the first one written acts first).
#include "io/xml/xml_reader.h"

#include <cmath>

namespace sheaf::io::xml {

bool SceneReader::apply_transform(const pugi::xml_node& n, Affine& t) const {
    const std::string_view name = n.name();
    if (name != "translate" && name != "rotate" && name != "scale" && name != "matrix")
        return false;
    const std::vector<pugi::xml_node> children = child_elements(ctx_, n);
    if (!children.empty()) unknown_element(ctx_, children[0], n, {});
    Attributes a(ctx_, n);
    Affine m;
    if (name == "translate") {
        Vec3 v;
        a.get("value", v);
        a.finish();
        a.require("value");
        m = Affine::translate(v);
    } else if (name == "rotate") {
        Vec3 axis;
        float degrees = 0;
        a.get("axis", axis);
        a.get("angle", degrees);
        a.finish();
        a.require("axis");
        a.require("angle");
        if (!(length(axis) > 0))
            ctx_.fail(n, n.attribute("axis"), "the rotation axis must not be zero");
        m = Affine::rotate(axis, degrees * float(M_PI) / 180.0f);
    } else if (name == "scale") {
        Vec3 s;
        a.get("value", s, true);
        a.finish();
        a.require("value");
        if (s.x == 0 || s.y == 0 || s.z == 0)
            ctx_.fail(n, n.attribute("value"), "a scale factor must not be 0");
        m = Affine::scale(s);
    } else {
        std::vector<float> v;
        a.get_numbers("value", v);
        a.finish();
        a.require("value");
        const bool affine_row =
            v.size() == 16 && v[12] == 0 && v[13] == 0 && v[14] == 0 && v[15] == 1;
        if (v.size() != 12 && !affine_row)
            ctx_.fail(n, n.attribute("value"),
                      "<matrix> needs 12 numbers (3 rows of 4, row-major) or 16 whose last row is "
                      "0 0 0 1; found " +
                          std::to_string(v.size()));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) m.m[r][c] = v[size_t(r * 4 + c)];
    }
    t = m * t;
    return true;
}

} // namespace sheaf::io::xml

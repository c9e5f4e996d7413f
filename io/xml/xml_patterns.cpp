// What <pigment>, <normal> and <switch> share: the pattern named by the 'pattern' attribute
// with its modifiers (core/scene/pattern.h, evaluated by core/texture/pattern_eval.h), the
// transform children that place it, and the values and count of its <entry> elements.
#include "io/xml/xml_reader.h"

#include <cmath>

namespace sheaf::io::xml {
namespace {

struct PatternName {
    const char* name;
    PatternKind kind;
};

// POV-Ray's spelling of every PatternKind; bumps and spotted are POV-Ray's names for bozo.
const PatternName kPatterns[] = {
    {"gradient", PatternKind::Gradient},
    {"marble", PatternKind::Marble},
    {"wood", PatternKind::Wood},
    {"onion", PatternKind::Onion},
    {"radial", PatternKind::Radial},
    {"spherical", PatternKind::Spherical},
    {"cylindrical", PatternKind::Cylindrical},
    {"planar", PatternKind::Planar},
    {"boxed", PatternKind::Boxed},
    {"leopard", PatternKind::Leopard},
    {"bozo", PatternKind::Bozo},
    {"bumps", PatternKind::Bozo},
    {"spotted", PatternKind::Bozo},
    {"granite", PatternKind::Granite},
    {"agate", PatternKind::Agate},
    {"wrinkles", PatternKind::Wrinkles},
    {"dents", PatternKind::Dents},
    {"crackle", PatternKind::Crackle},
    {"cells", PatternKind::Cells},
    {"ripples", PatternKind::Ripples},
    {"waves", PatternKind::Waves},
    {"spiral1", PatternKind::Spiral1},
    {"spiral2", PatternKind::Spiral2},
    {"quilted", PatternKind::Quilted},
    {"mandel", PatternKind::Mandel},
    {"julia", PatternKind::Julia},
    {"slope", PatternKind::Slope},
    {"checker", PatternKind::Checker},
    {"hexagon", PatternKind::Hexagon},
    {"brick", PatternKind::Brick},
    {"square", PatternKind::Square},
    {"triangular", PatternKind::Triangular},
    {"image", PatternKind::Image},
};

const char* name_of(PatternKind k) {
    for (const PatternName& p : kPatterns)
        if (p.kind == k) return p.name;
    return "?";
}

std::string quote(const std::string& s) {
    return "'" + s + "'";
}

} // namespace

PatternKind SceneReader::pattern_kind(Attributes& a, PatternUse use) const {
    const pugi::xml_node& node = a.node();
    std::string name;
    if (!a.get("pattern", name)) a.require("pattern");
    for (const PatternName& p : kPatterns) {
        if (name != p.name) continue;
        if (p.kind == PatternKind::Image && use != PatternUse::Pigment)
            ctx_.fail(node, node.attribute("pattern"),
                      "the image pattern gives colours, so only a <pigment> takes it");
        return p.kind;
    }
    std::vector<std::string> names;
    for (const PatternName& p : kPatterns)
        if (p.kind != PatternKind::Image || use == PatternUse::Pigment) names.push_back(p.name);
    ctx_.fail(node, node.attribute("pattern"),
              "unknown pattern " + quote(name) + " on " + tag(node) + "; expected one of " +
                  join(names));
}

Pattern SceneReader::read_pattern(Attributes& a, PatternKind kind) const {
    const pugi::xml_node& node = a.node();
    const std::string kind_name = name_of(kind);
    const bool list = pattern_is_list(kind);
    // Attributes that only some patterns take: an error naming what they belong to.
    auto only_for = [&](const char* attribute, bool applies, const std::string& owner) {
        if (!applies && node.attribute(attribute))
            ctx_.fail(node, node.attribute(attribute),
                      "attribute '" + std::string(attribute) + "' of " + tag(node) +
                          " belongs to " + owner + "; this pattern is " + quote(kind_name));
    };
    auto fail_value = [&](const char* attribute, const std::string& why) {
        ctx_.fail(node, node.attribute(attribute),
                  "attribute '" + std::string(attribute) + "' of " + tag(node) + ": " + why);
    };

    Pattern pt;
    pt.kind = kind;
    // Marble, wood and the spirals are triangle-waved unless the scene says otherwise, as in
    // POV-Ray.
    pt.wave = kind == PatternKind::Marble || kind == PatternKind::Wood ||
                      kind == PatternKind::Spiral1 || kind == PatternKind::Spiral2
                  ? Wave::Triangle
                  : Wave::Ramp;
    if (kind == PatternKind::Crackle) set_crackle_defaults(pt); // the nearest two's difference
    // mapping="uv": the pattern reads the surface's texture coordinates (u, v, 0).
    int mapping = 0;
    if (a.get("mapping", mapping, {"space", "uv"})) pt.uv = mapping == 1;

    std::vector<float> turbulence;
    if (a.get_numbers("turbulence", turbulence)) {
        if (turbulence.size() == 1)
            pt.turbulence = Vec3(turbulence[0]);
        else if (turbulence.size() == 3)
            pt.turbulence = Vec3(turbulence[0], turbulence[1], turbulence[2]);
        else
            fail_value("turbulence",
                       "expected one or three numbers, found " + std::to_string(turbulence.size()));
        pt.has_turbulence = pt.turbulence.x != 0 || pt.turbulence.y != 0 || pt.turbulence.z != 0;
    }
    for (const char* t : {"octaves", "omega", "lambda"})
        if (turbulence.empty() && node.attribute(t))
            ctx_.fail(node, node.attribute(t),
                      "attribute '" + std::string(t) + "' of " + tag(node) +
                          " shapes the turbulence; give 'turbulence' too");
    int octaves = pt.octaves;
    a.get("octaves", octaves, 1, 10);
    pt.octaves = int8_t(octaves);
    a.get("omega", pt.omega);
    a.get("lambda", pt.lambda);

    // Continuous patterns: frequency, phase and the wave shape the value.
    const std::string continuous = "continuous patterns (a list pattern picks its entries by tile)";
    for (const char* t : {"frequency", "phase", "wave"}) only_for(t, !list, continuous);
    a.get("frequency", pt.frequency);
    a.get("phase", pt.phase);
    int wave = -1;
    if (a.get("wave", wave, {"ramp", "triangle", "sine", "scallop", "cubic", "poly"}))
        pt.wave = Wave(wave);
    only_for("wave_exponent", pt.wave == Wave::Poly, "wave=\"poly\"");
    if (a.get("wave_exponent", pt.wave_exponent) && !(pt.wave_exponent > 0))
        fail_value("wave_exponent", "the exponent must be > 0");

    // The patterns' own parameters.
    only_for("vector", kind == PatternKind::Gradient, "the gradient pattern");
    if (a.get("vector", pt.vector) && !(length(pt.vector) > 0))
        fail_value("vector", "the gradient's direction must not be zero");
    const bool spiral = kind == PatternKind::Spiral1 || kind == PatternKind::Spiral2;
    only_for("arms", spiral, "the spiral1 and spiral2 patterns");
    if (spiral) {
        pt.param[0] = 1;
        if (a.get("arms", pt.param[0]) && pt.param[0] == 0)
            fail_value("arms", "a spiral needs a number of arms other than 0");
    }
    only_for("control0", kind == PatternKind::Quilted, "the quilted pattern");
    only_for("control1", kind == PatternKind::Quilted, "the quilted pattern");
    if (kind == PatternKind::Quilted) { // POV-Ray's control points, 1 and 1 when not given
        pt.param[0] = pt.param[1] = 1;
        a.get("control0", pt.param[0]);
        a.get("control1", pt.param[1]);
    }
    only_for("agate_turb", kind == PatternKind::Agate, "the agate pattern");
    if (kind == PatternKind::Agate) {
        pt.param[0] = 1;
        if (a.get("agate_turb", pt.param[0]) && !(pt.param[0] > 0))
            fail_value("agate_turb", "expected a number > 0");
    }
    only_for("brick_size", kind == PatternKind::Brick, "the brick pattern");
    only_for("mortar", kind == PatternKind::Brick, "the brick pattern");
    if (kind == PatternKind::Brick) {
        Vec3 size(8, 3, 4.5f);
        float mortar = 0.5f;
        if (a.get("brick_size", size, true) && !(size.x > 0 && size.y > 0 && size.z > 0))
            fail_value("brick_size", "a brick's size must be > 0 in x, y and z");
        if (a.get("mortar", mortar) && !(mortar > 0))
            fail_value("mortar", "the mortar's width must be > 0");
        pt.param[0] = size.x, pt.param[1] = size.y, pt.param[2] = size.z, pt.param[3] = mortar;
    }
    const bool fractal = kind == PatternKind::Mandel || kind == PatternKind::Julia;
    for (const char* t : {"iterations", "exponent", "magnet", "interior", "exterior"})
        only_for(t, fractal, "the mandel and julia patterns");
    only_for("c", kind == PatternKind::Julia, "the julia pattern");
    if (fractal) read_fractal(a, kind, pt.fractal);
    const bool slope = kind == PatternKind::Slope;
    for (const char* t : {"direction", "point_at", "range", "altitude", "altitude_range"})
        only_for(t, slope, "the slope pattern");
    if (slope) read_slope(a, pt);
    return pt;
}

// pattern="slope": direction="X Y Z" (world space) or point_at="X Y Z" (a world point the
// surface faces), range="LO HI", altitude="X Y Z" (pattern space), altitude_range="LO HI";
// the lengths of direction and altitude weigh the two (core/scene/pattern.h, SlopeParams).
void SceneReader::read_slope(Attributes& a, Pattern& pt) const {
    const pugi::xml_node& node = a.node();
    auto fail = [&](const char* attribute, const std::string& why) {
        ctx_.fail(node, node.attribute(attribute),
                  "attribute '" + std::string(attribute) + "' of " + tag(node) + ": " + why);
    };
    if (node.attribute("direction") && node.attribute("point_at"))
        fail("point_at", "a slope faces a direction or a point, not both");
    Vec3 direction(0.0f), altitude(0.0f);
    const bool point_at = a.get("point_at", direction);
    if (!point_at) a.get("direction", direction);
    a.get("altitude", altitude);
    float lo_hi[4] = {0, 0, 0, 0};
    for (const bool alt : {false, true}) {
        const char* name = alt ? "altitude_range" : "range";
        std::vector<float> v;
        if (!a.get_numbers(name, v)) continue;
        if (v.size() != 2)
            fail(name, "expected two numbers (low and high), found " + std::to_string(v.size()));
        if (v[0] == v[1]) fail(name, "the low and high ends must differ");
        if (alt && !(length(altitude) > 0)) fail(name, "there is no altitude to remap");
        lo_hi[alt ? 2 : 0] = v[0], lo_hi[alt ? 3 : 1] = v[1];
    }
    if (point_at && length(altitude) > 0)
        fail("altitude", "a slope towards a point (point_at) takes no altitude");
    if (!set_slope(pt, direction, lo_hi[0], lo_hi[1], altitude, lo_hi[2], lo_hi[3], point_at))
        ctx_.fail(node, node.attribute(point_at ? "point_at" : "direction"),
                  tag(node) + ": a slope pattern needs a direction or an altitude other than zero");
}

void SceneReader::read_fractal(Attributes& a, PatternKind kind, FractalParams& f) const {
    const pugi::xml_node& node = a.node();
    int iterations = 30, exponent = 2, magnet = 0;
    a.get("iterations", iterations, 1, kFractalMaxIterations);
    a.get("exponent", exponent, kFractalMinExponent, kFractalMaxExponent);
    a.get("magnet", magnet, 0, 2);
    f.iterations = uint16_t(iterations), f.exponent = uint8_t(exponent);
    f.magnet = uint8_t(magnet);
    if (magnet && node.attribute("exponent"))
        ctx_.fail(node, node.attribute("exponent"),
                  "attribute 'exponent' of " + tag(node) +
                      " does not apply to the magnet formulas (magnet=\"" + std::to_string(magnet) +
                      "\")");
    std::vector<float> v;
    if (kind == PatternKind::Julia) {
        if (!a.get_numbers("c", v)) a.require("c");
        if (v.size() != 2)
            ctx_.fail(node, node.attribute("c"),
                      "attribute 'c' of " + tag(node) +
                          ": expected two numbers (the complex "
                          "constant's real and imaginary parts), found " +
                          std::to_string(v.size()));
        f.c[0] = v[0], f.c[1] = v[1];
    }
    // interior="TYPE FACTOR", exterior="TYPE FACTOR" (core/scene/pattern.h lists the types).
    for (const bool inside : {true, false}) {
        const char* name = inside ? "interior" : "exterior";
        if (!a.get_numbers(name, v)) continue;
        auto fail = [&](const std::string& why) {
            ctx_.fail(node, node.attribute(name),
                      "attribute '" + std::string(name) + "' of " + tag(node) + ": " + why);
        };
        if (v.size() != 2)
            fail("expected a type and a factor, found " + std::to_string(v.size()) + " numbers");
        if (const char* why = fractal_type_error(inside, v[0])) fail(why);
        if (const char* why = fractal_factor_error(inside, v[0], v[1])) fail(why);
        (inside ? f.interior_type : f.exterior_type) = uint8_t(v[0]);
        (inside ? f.interior_factor : f.exterior_factor) = v[1];
    }
}

void SceneReader::place_pattern(const pugi::xml_node& node, const Affine& placement,
                                Pattern& pattern) const {
    if (std::fabs(placement.determinant()) < 1e-20f)
        ctx_.fail(node, "the transform of " + tag(node) + " is singular");
    pattern.to_pattern = placement.inverse();
}

float SceneReader::entry_value(Attributes& e, const char* ordered_by, float& previous) const {
    const pugi::xml_node& node = e.node();
    if (ordered_by) {
        if (node.attribute("value"))
            ctx_.fail(node, node.attribute("value"),
                      "an <entry> of " + std::string(ordered_by) +
                          " takes no 'value': the entries count in order");
        return 0;
    }
    float v = 0;
    if (!e.get("value", v))
        ctx_.fail(node, "an <entry> of a continuous pattern needs the attribute 'value' (where "
                        "in 0..1 of the pattern it stands)");
    if (!(v >= 0 && v <= 1))
        ctx_.fail(node, node.attribute("value"), "an entry's value must lie in 0..1");
    if (v < previous)
        ctx_.fail(node, node.attribute("value"),
                  "entry values must not decrease; " + std::to_string(v) + " follows " +
                      std::to_string(previous));
    previous = v;
    return v;
}

void SceneReader::check_entry_count(const pugi::xml_node& node, PatternKind kind,
                                    size_t count) const {
    const size_t list = size_t(pattern_list_size(kind));
    if (list > 0 && count != list)
        ctx_.fail(node, "the " + std::string(name_of(kind)) + " pattern picks from " +
                            std::to_string(list) + " entries; " + tag(node) + " has " +
                            std::to_string(count) +
                            (count == 1 ? " <entry>" : " <entry> elements"));
    if (count == 0) ctx_.fail(node, tag(node) + " needs <entry> elements");
}

} // namespace sheaf::io::xml

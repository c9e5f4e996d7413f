// XML scene errors: each names the file, line and column of what is wrong and what was
// expected; unknown elements and attributes are errors; nothing bad crashes or is ignored.
#include "io/xml/xml_scene.h"

#include "core/base/error.h"
#include "tests/support/mesh_test_files.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace sheaf {
namespace {

std::string error_of(const std::string& text, const std::string& path = "scene.xml") {
    try {
        io::parse_xml_scene(text, path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

#define EXPECT_ERROR(text, where, what)                                                            \
    do {                                                                                           \
        const std::string e_ = error_of(text);                                                     \
        EXPECT_EQ(e_.rfind(std::string("scene.xml:") + where + ": error: ", 0), 0u) << e_;         \
        EXPECT_NE(e_.find(what), std::string::npos) << e_;                                         \
    } while (0)

TEST(XmlErrors, SyntaxErrorsCarryLineAndColumn) {
    EXPECT_ERROR("<scene>\n  <sphere radius=\"1\">\n</scene>\n", "3:3", "XML syntax");
    EXPECT_ERROR("<scene>\n  <sphere radius=1/>\n</scene>\n", "2:18", "XML syntax");
    EXPECT_ERROR("", "1:1", "XML syntax");
    EXPECT_ERROR("<!-- nothing -->", "1:17", "XML syntax");
    EXPECT_ERROR("<scene/><scene/>", "1:9", "more than one root element");
    EXPECT_ERROR("<?xml version=\"1.0\"?>\n<preset/>", "2:1", "expected <scene>");
}

TEST(XmlErrors, UnknownElementsAndAttributesAreNamed) {
    EXPECT_ERROR("<scene>\n  <sphear/>\n</scene>", "2:3",
                 "unknown element <sphear> in <scene>; expected one of <settings>");
    EXPECT_ERROR("<scene>\n  <sphere radius=\"1\" colour=\"1 0 0\"/>\n</scene>", "2:30",
                 "unknown attribute 'colour' on <sphere>; expected one of");
    EXPECT_ERROR("<scene>\n <sphere><twist/></sphere></scene>", "2:10",
                 "unknown element <twist> in <sphere>; expected one of <translate>");
    EXPECT_ERROR("<scene><camera fov=\"40\" fov=\"50\"/></scene>", "1:30", "given twice");
    // An attribute that only another kind takes.
    EXPECT_ERROR("<scene><light type=\"point\" radius=\"10\"/></scene>", "1:36",
                 "unknown attribute 'radius' on <light>");
    EXPECT_ERROR("<scene><camera projection=\"orthographic\" fov=\"40\"/></scene>", "1:47",
                 "unknown attribute 'fov'");
    EXPECT_ERROR("<scene>text</scene>", "1:8", "unexpected text in <scene>");
}

TEST(XmlErrors, BadValuesPointAtTheValue) {
    // Columns count characters from 1: the 'x' is the 37th.
    EXPECT_ERROR("<scene><sphere radius=\"2\" center=\"1 x 3\"/></scene>", "1:37",
                 "'x' is not a number");
    EXPECT_ERROR("<scene>\n<mesh name=\"m\">\n  <positions>0 0 0\n 1 0 nan</positions>\n"
                 "</mesh></scene>",
                 "4:6", "'nan' is not a finite number");
    EXPECT_ERROR("<scene><sphere center=\"1 2\"/></scene>", "1:24", "expected three numbers");
    EXPECT_ERROR("<scene><sphere radius=\"-1\"/></scene>", "1:24", "the radius must be > 0");
    EXPECT_ERROR("<scene><light type=\"laser\"/></scene>", "1:21",
                 "'laser' is not one of point, spot, parallel");
    EXPECT_ERROR("<scene><subdivision name=\"s\" level=\"9\"/></scene>", "1:37",
                 "expected an integer in 0..8");
    EXPECT_ERROR("<scene><settings><set key=\"hierarchy.arity\" value=\"1\"/></settings></scene>",
                 "1:52", "setting 'hierarchy.arity'");
    EXPECT_ERROR("<scene><settings><set key=\"nokey\" value=\"1\"/></settings></scene>", "1:28",
                 "unknown setting 'nokey'");
    EXPECT_ERROR("<scene><material name=\"m\" ior=\"0\"/></scene>", "1:32",
                 "expected a number > 0");
    EXPECT_ERROR("<scene><sphere><scale value=\"1 0 1\"/></sphere></scene>", "1:30",
                 "must not be 0");
    EXPECT_ERROR("<scene><camera position=\"0 0 0\" look_at=\"0 0 0\"/></scene>", "1:42",
                 "looks at its own position");
    EXPECT_ERROR("<scene><camera projection=\"fisheye\" angle=\"0\"/></scene>", "1:44",
                 "the angle must lie in (0, 3600] degrees");
    EXPECT_ERROR("<scene><camera projection=\"cylinder1\" lengths=\"1 0 1\"/></scene>", "1:48",
                 "lengths of right, up and direction");
    EXPECT_ERROR("<scene><camera projection=\"perspective\" angle=\"90\"/></scene>", "1:48",
                 "unknown attribute 'angle'");
    EXPECT_ERROR("<scene><camera lens_radius=\"0.5\"/></scene>", "1:29",
                 "a camera with a lens needs a focal_distance > 0");
    EXPECT_ERROR("<scene><camera projection=\"fisheye\" lens_radius=\"0.5\"/></scene>", "1:50",
                 "unknown attribute 'lens_radius'");
    EXPECT_ERROR("<scene><poly order=\"3\" coefficients=\"1 2 3\"/></scene>", "1:38",
                 "order 3 needs 20 coefficients, not 3");
    EXPECT_ERROR("<scene><poly order=\"5\" coefficients=\"1\"/></scene>", "1:21",
                 "expected an integer in 2..4");
    EXPECT_ERROR("<scene><poly/></scene>", "1:8", "coefficients");
    EXPECT_ERROR("<scene><superellipsoid e=\"0\"/></scene>", "1:27", "at least 0.001");
    EXPECT_ERROR("<scene><julia/></scene>", "1:8", "'c'");
    EXPECT_ERROR("<scene><julia c=\"1 2 3\"/></scene>", "1:18", "four numbers are needed");
    EXPECT_ERROR("<scene><julia c=\"0 0 0 0\" slice=\"1 0 0 0\"/></scene>", "1:34",
                 "w component must not be zero");
    EXPECT_ERROR("<scene><julia c=\"0 0 0 0\" iterations=\"65\"/></scene>", "1:39",
                 "expected an integer in 1..64");
    EXPECT_ERROR("<scene><julia c=\"0 0 0 0\" function=\"exp\"/></scene>", "1:37", "sqr, cube");
    EXPECT_ERROR("<scene><poly coefficients=\"0 0 0 0 0 0 0 0 0 0\"/></scene>", "1:28",
                 "every coefficient is zero");
}

TEST(XmlErrors, PolyLoadsInPovRaysTermOrder) {
    // x^2, xy, xz, x, y^2, yz, y, z^2, z, 1: a unit sphere.
    const io::SceneFile f = io::parse_xml_scene(
        "<scene><poly coefficients=\"1 0 0 0 1 0 0 1 0 -1\"/></scene>", "scene.xml");
    const Scene& s = f.scene;
    ASSERT_EQ(s.shape_objects.size(), 1u);
    const CsgNode& n = s.shape_objects[0].nodes[0];
    ASSERT_EQ(n.shape.kind, ShapeKind::Poly);
    ASSERT_TRUE(n.poly);
    EXPECT_EQ(n.poly->c[poly_term(2, 0, 0)], 1);
    EXPECT_EQ(n.poly->c[poly_term(0, 2, 0)], 1);
    EXPECT_EQ(n.poly->c[poly_term(0, 0, 2)], 1);
    EXPECT_EQ(n.poly->c[poly_term(0, 0, 0)], -1);
    EXPECT_NO_THROW(s.validate());
}

TEST(XmlErrors, TextIsAUnionOfGlyphsInItsFont) {
    const std::string font = "/usr/share/povray-3.7/include/timrom.ttf";
    EXPECT_ERROR("<scene><text string=\"A\"/></scene>", "1:8", "'font'");
    EXPECT_ERROR("<scene>\n <text font=\"missing.ttf\" string=\"A\"/></scene>", "2:14",
                 "cannot read font 'missing.ttf': cannot open resource");
    if (!std::filesystem::exists(font)) GTEST_SKIP() << "povray-includes is not installed";
    // Relative to the scene's folder; timrom's "I" and "A" (POV-Ray's metrics: the first
    // character's ink at x = 0, kerning), extruded from z = 0 to the thickness.
    const io::SceneFile f = io::parse_xml_scene(
        "<scene><text font=\"timrom.ttf\" string=\"I A\" thickness=\"0.25\" offset=\"0 0.5 0\">"
        "<translate value=\"1 0 0\"/></text></scene>",
        "/usr/share/povray-3.7/include/scene.xml");
    const Scene& s = f.scene;
    ASSERT_EQ(s.shape_objects.size(), 1u);
    const ShapeObject& o = s.shape_objects[0];
    ASSERT_EQ(o.nodes.size(), 3u);
    EXPECT_EQ(o.nodes[0].op, CsgOp::Union);
    ASSERT_EQ(o.nodes[1].shape.kind, ShapeKind::Glyph);
    ASSERT_TRUE(o.nodes[1].glyph);
    const Vec3 a = o.transform.point(o.nodes[2].transform.point({0, 0, 1}));
    EXPECT_NEAR(a.x, 1 - 0.023f + 0.342f + 0.254f, 1e-5);
    EXPECT_NEAR(a.y, 1.0f, 1e-6); // two offsets: after the I and after the space
    EXPECT_NEAR(a.z, 0.25f, 1e-6);
    EXPECT_NO_THROW(s.validate());
    const std::string at = "<scene><text font=\"" + font + "\" ";
    EXPECT_ERROR(at + "string=\"A\" thickness=\"0\"/></scene>",
                 "1:" + std::to_string(at.size() + 23),
                 "thickness must be a finite number other than 0");
    EXPECT_ERROR(at + "string=\" \"/></scene>", "1:" + std::to_string(at.size() + 9),
                 "no visible character");
}

TEST(XmlErrors, LatheAndSorTurnTheirPointsAboutY) {
    // A ring of square section (radius 1 to 2, height 0 to 1), closed: a solid about y.
    Scene s = io::parse_xml_scene("<scene><lathe points=\"1 0 2 0 2 1 1 1 1 0\"/>"
                                  "<lathe spline=\"quadratic\" points=\"0 0 1 0 1 1\"/>"
                                  "<sor points=\"1 -1 1 0 1 1 1 2\" open=\"true\"/></scene>",
                                  "scene.xml")
                  .scene;
    ASSERT_EQ(s.shape_objects.size(), 3u);
    const CsgNode& ring = s.shape_objects[0].nodes[0];
    EXPECT_EQ(ring.shape.kind, ShapeKind::Revolution);
    EXPECT_FALSE(ring.shape.open);
    ASSERT_TRUE(ring.revolution);
    EXPECT_EQ(ring.revolution->segments.size(), 4u);
    const Vec3 top = ring.transform.point({1.5f, 0, 1}); // the profile's height is y
    EXPECT_FLOAT_EQ(top.y, 1);
    EXPECT_FLOAT_EQ(top.x, 1.5f);
    EXPECT_TRUE(s.shape_objects[1].nodes[0].shape.open); // from the axis, not back to it
    const CsgNode& sor = s.shape_objects[2].nodes[0];
    EXPECT_TRUE(sor.revolution->squared);
    EXPECT_TRUE(sor.shape.open);
    EXPECT_EQ(sor.revolution->segments.size(), 1u); // open: no caps
    EXPECT_NO_THROW(s.validate());
    EXPECT_ERROR("<scene><lathe points=\"0 0 -1 0.5 0 1\"/></scene>", "1:23",
                 "<lathe>: the lathe's point 2 has a negative radius (x < 0)");
    EXPECT_ERROR("<scene><lathe points=\"0 0 1\"/></scene>", "1:23",
                 "pairs of numbers (radius, height)");
    EXPECT_ERROR("<scene><lathe spline=\"cubic\" points=\"0 0 1 0 1 1\"/></scene>", "1:38",
                 "needs at least 4 points");
    EXPECT_ERROR("<scene><sor points=\"0 0 1 1 1 3 1 2 0 4\"/></scene>", "1:21",
                 "point 4 is not above point 3");
}

TEST(XmlErrors, BlobReadsItsComponentsAsNumbers) {
    Scene s =
        io::parse_xml_scene("<scene><blob threshold=\"0.5\" spheres=\"0 0 0 1 1  0 1 0 0.5 -2\" "
                            "cylinders=\"0 0 0 0 0 2 1 1\"/></scene>",
                            "scene.xml")
            .scene;
    ASSERT_EQ(s.shape_objects.size(), 1u);
    const CsgNode& b = s.shape_objects[0].nodes[0];
    EXPECT_EQ(b.shape.kind, ShapeKind::Blob);
    ASSERT_TRUE(b.blob);
    EXPECT_EQ(b.blob->elements.size(), 3u);
    EXPECT_FLOAT_EQ(b.blob->threshold, 0.5f);
    EXPECT_FLOAT_EQ(b.blob->elements[1].strength, -2);
    EXPECT_FLOAT_EQ(b.blob->elements[2].len, 2);
    EXPECT_NO_THROW(s.validate());
    EXPECT_ERROR("<scene><blob spheres=\"0 0 0 1\"/></scene>", "1:23",
                 "each sphere is 5 numbers: x y z radius strength");
    EXPECT_ERROR("<scene><blob cylinders=\"0 0 0 1 1 1 0 1\"/></scene>", "1:25",
                 "radius must be a positive number");
    EXPECT_ERROR("<scene><blob threshold=\"-1\" spheres=\"0 0 0 1 1\"/></scene>", "1:25",
                 "the threshold must be a positive number");
    EXPECT_ERROR("<scene><blob/></scene>", "1:8", "a blob needs at least one sphere or cylinder");
}

TEST(XmlErrors, ReferencesMustBeDefinedFirstAndOnce) {
    EXPECT_ERROR("<scene>\n<object mesh=\"m\"/>\n</scene>", "2:15",
                 "unknown mesh 'm'; none is defined before this point");
    EXPECT_ERROR("<scene><material name=\"a\"/><sphere material=\"b\"/></scene>", "1:46",
                 "unknown material 'b'; defined before this point: 'a'");
    EXPECT_ERROR("<scene><material name=\"a\"/>\n<material name=\"a\"/></scene>", "2:1",
                 "material 'a' is defined twice (first at scene.xml:1:8)");
    EXPECT_ERROR("<scene><material name=\"a\" texture=\"t\"/></scene>", "1:36",
                 "unknown texture 't'");
    EXPECT_ERROR("<scene><material color=\"1\"/></scene>", "1:8", "needs the attribute 'name'");
    EXPECT_ERROR("<scene><object/></scene>", "1:8", "an <object> needs a mesh");
}

TEST(XmlErrors, BadGeometryIsAnErrorAtItsElement) {
    EXPECT_ERROR("<scene>\n<mesh name=\"m\"><positions>0 0 0 1 0 0 0 1 0</positions>"
                 "<triangles>0 1 5</triangles></mesh></scene>",
                 "2:1", "names vertex 5, out of range (3 vertices)");
    EXPECT_ERROR("<scene><mesh name=\"m\"><positions>0 0 0 1 0 0</positions></mesh></scene>", "1:8",
                 "no faces");
    EXPECT_ERROR("<scene><mesh name=\"m\"><positions>0 0 0 1</positions></mesh></scene>", "1:23",
                 "expected three per vertex");
    EXPECT_ERROR("<scene><mesh name=\"m\"><triangles>0 -1 2</triangles></mesh></scene>", "1:36",
                 "'-1' is not a vertex index");
    EXPECT_ERROR("<scene><subdivision name=\"s\" scheme=\"loop\"><positions>0 0 0 1 0 0 1 1 0 0 1 "
                 "0</positions><face_sizes>4</face_sizes><face_indices>0 1 2 3</face_indices>"
                 "</subdivision></scene>",
                 "1:8", "Loop subdivision needs a cage of triangles");
    EXPECT_ERROR("<scene><subdivision name=\"s\"><positions>0 0 0 1 0 0 1 1 0</positions>"
                 "<face_sizes>3</face_sizes><face_indices>0 1 2</face_indices>"
                 "<crease edge=\"0 5\"/></subdivision></scene>",
                 "1:8", "out of range");
    EXPECT_ERROR("<scene><difference><sphere/></difference></scene>", "1:8",
                 "<difference> needs at least 2 shapes");
    EXPECT_ERROR("<scene><object><mesh file=\"nothere.obj\"/></object></scene>", "1:28",
                 "nothere.obj: no such file");
    EXPECT_ERROR("<scene><texture name=\"t\" file=\"nothere.png\"/></scene>", "1:32",
                 "texture file 'nothere.png' does not exist");
}

TEST(XmlErrors, ProceduralTexturesAreCheckedLikeTheRest) {
    // The four the schema must catch: an unknown pattern, an entry naming a later (or its own,
    // or no) pigment, a switch without entries, a bad wave.
    EXPECT_ERROR("<scene>\n  <pigment name=\"p\" pattern=\"marbel\"/>\n</scene>", "2:30",
                 "unknown pattern 'marbel' on <pigment>; expected one of gradient, marble,");
    EXPECT_ERROR(
        "<scene>\n<pigment name=\"a\" pattern=\"checker\">\n  <entry color=\"1\"/>\n"
        "  <entry pigment=\"b\"/>\n</pigment>\n<pigment name=\"b\" color=\"0\"/>\n</scene>",
        "4:19", "unknown pigment 'b'; none is defined before this point");
    EXPECT_ERROR("<scene>\n<pigment name=\"a\" pattern=\"bozo\">\n  <entry value=\"0\" "
                 "pigment=\"a\"/>\n</pigment></scene>",
                 "3:29", "unknown pigment 'a'");
    EXPECT_ERROR("<scene><material name=\"r\"/>\n<switch name=\"s\" pattern=\"checker\">\n"
                 "  <scale value=\"2\"/>\n</switch></scene>",
                 "2:1", "the checker pattern picks from 2 entries; <switch> has 0");
    EXPECT_ERROR("<scene><material name=\"r\"/><switch name=\"s\" pattern=\"bozo\"/></scene>",
                 "1:28", "<switch> needs <entry> elements");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"bozo\">\n<entry value=\"0.5\"/> <entry "
                 "value=\"0.2\"/></normal></scene>",
                 "2:36", "entry values must not decrease");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"checker\">\n<entry/></normal></scene>", "2:1",
                 "a slope map needs a continuous pattern");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"bozo\">\n<entry value=\"0\" "
                 "color=\"1\"/></normal></scene>",
                 "2:25",
                 "unknown attribute 'color' on <entry>; expected one of value, height, slope");
    EXPECT_ERROR("<scene><normal name=\"a\" pattern=\"bumps\"/><normal name=\"n\" "
                 "pattern=\"bozo\">\n<entry value=\"0\" normal=\"a\"/><entry value=\"1\" "
                 "height=\"1\"/></normal></scene>",
                 "2:30", "a <normal>'s entries are a slope map (height, slope) or a normal map");
    EXPECT_ERROR("<scene><normal name=\"a\" pattern=\"bumps\"/><normal name=\"m\" "
                 "pattern=\"bozo\"><entry value=\"0\" normal=\"a\"/></normal>\n<normal "
                 "name=\"n\" average=\"true\"><entry normal=\"m\"/></normal></scene>",
                 "2:48", "normal 'm' has a normal map of its own");
    EXPECT_ERROR("<scene><normal name=\"a\" pattern=\"bumps\"/>\n<normal name=\"n\" "
                 "average=\"true\"><entry normal=\"a\" weight=\"1\"/><entry normal=\"\" "
                 "weight=\"-1\"/></normal></scene>",
                 "2:1", "the weights of an average's entries sum to 0");
    EXPECT_ERROR("<scene>\n<normal name=\"n\" average=\"true\" pattern=\"bozo\"/></scene>", "2:42",
                 "an average=\"true\" <normal> averages its entries");
    EXPECT_ERROR("<scene>\n<camera normal=\"later\"/><normal name=\"later\" pattern=\"bumps\"/>"
                 "</scene>",
                 "2:17", "unknown normal 'later'; none is defined before this point");
    EXPECT_ERROR("<scene><material name=\"a\"/><material name=\"b\" inside=\"a\"/>\n<material "
                 "name=\"c\" inside=\"b\"/></scene>",
                 "2:28", "material 'b' has an inside material of its own");
    EXPECT_ERROR("<scene>\n<normal name=\"n\" pattern=\"ripples\" wave=\"sawtooth\"/></scene>",
                 "2:42", "'sawtooth' is not one of ramp, triangle, sine, scallop, cubic, poly");
    EXPECT_ERROR("<scene>\n<normal name=\"n\" pattern=\"bumps\" mapping=\"uv\"/></scene>", "2:43",
                 "normals are evaluated in space");
    EXPECT_ERROR("<scene>\n<pigment name=\"n\" pattern=\"bumps\" mapping=\"st\"/></scene>", "2:44",
                 "'st' is not one of space, uv");

    // Entries: counts, values, colours or pigments.
    EXPECT_ERROR("<scene><pigment name=\"c\" pattern=\"checker\"><entry color=\"1\"/></pigment>"
                 "</scene>",
                 "1:8", "the checker pattern picks from 2 entries; <pigment> has 1 <entry>");
    EXPECT_ERROR("<scene><pigment name=\"g\" pattern=\"gradient\">\n<entry value=\"0.5\" "
                 "color=\"1\"/>\n<entry value=\"0.25\" color=\"0\"/></pigment></scene>",
                 "3:15", "entry values must not decrease");
    EXPECT_ERROR("<scene><pigment name=\"g\" pattern=\"gradient\"><entry color=\"1\"/></pigment>"
                 "</scene>",
                 "1:45", "an <entry> of a continuous pattern needs the attribute 'value'");
    EXPECT_ERROR("<scene><pigment name=\"c\" pattern=\"checker\"><entry value=\"0\" color=\"1\"/>"
                 "<entry color=\"0\"/></pigment></scene>",
                 "1:58", "an <entry> of a list pattern takes no 'value'");
    EXPECT_ERROR("<scene><pigment name=\"p\" color=\"1\"/><pigment name=\"q\" pattern=\"bozo\">"
                 "<entry value=\"0\" pigment=\"p\" transmit=\"1\"/></pigment></scene>",
                 "1:109", "'transmit' goes with 'color'");
    EXPECT_ERROR("<scene><pigment name=\"p\" color=\"1\" filter=\"2\"/></scene>", "1:44",
                 "attribute 'filter' of <pigment>: expected a number in 0..1");

    // Pattern attributes belong to some patterns only.
    EXPECT_ERROR("<scene><pigment name=\"m\" pattern=\"marble\" octaves=\"3\"><entry value=\"0\" "
                 "color=\"1\"/></pigment></scene>",
                 "1:52",
                 "attribute 'octaves' of <pigment> shapes the turbulence; give 'turbulence' too");
    EXPECT_ERROR(
        "<scene><pigment name=\"m\" pattern=\"marble\" vector=\"0 1 0\"><entry value=\"0\" "
        "color=\"1\"/></pigment></scene>",
        "1:51", "belongs to the gradient pattern; this pattern is 'marble'");
    EXPECT_ERROR("<scene><pigment name=\"m\" pattern=\"checker\" wave=\"sine\"><entry color=\"1\"/>"
                 "<entry color=\"0\"/></pigment></scene>",
                 "1:50", "attribute 'wave' of <pigment> belongs to continuous patterns");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"image\"/></scene>", "1:34",
                 "only a <pigment> takes it");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"bozo\" iterations=\"9\"/></scene>", "1:52",
                 "belongs to the mandel and julia patterns; this pattern is 'bozo'");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"mandel\" c=\"0 1\"/></scene>", "1:45",
                 "belongs to the julia pattern");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"julia\"/></scene>", "1:8",
                 "needs the attribute 'c'");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"mandel\" interior=\"7 1\"/></scene>", "1:52",
                 "attribute 'interior' of <normal>: the interior type must be a whole number from "
                 "0 to 6");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"mandel\" exterior=\"7 0.5\"/></scene>",
                 "1:52", "type 7 needs a factor of 1 or more");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"mandel\" exponent=\"40\"/></scene>", "1:52",
                 "attribute 'exponent' of <normal>");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"mandel\" magnet=\"1\" exponent=\"3\"/>"
                 "</scene>",
                 "1:63", "does not apply to the magnet formulas");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"slope\"/></scene>", "1:8",
                 "a slope pattern needs a direction or an altitude other than zero");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"slope\" point_at=\"0 1 0\" "
                 "altitude=\"0 1 0\"/></scene>",
                 "1:68", "a slope towards a point (point_at) takes no altitude");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"bozo\" direction=\"0 1 0\"/></scene>", "1:51",
                 "belongs to the slope pattern; this pattern is 'bozo'");
    EXPECT_ERROR("<scene><normal name=\"n\" pattern=\"slope\" direction=\"0 1 0\" "
                 "range=\"1 1\"/></scene>",
                 "1:66", "attribute 'range' of <normal>: the low and high ends must differ");

    // What a pigment is, and what uses pigments, normals and switches.
    EXPECT_ERROR("<scene><pigment name=\"p\"/></scene>", "1:8",
                 "a solid <pigment> needs the attribute 'color'");
    EXPECT_ERROR("<scene><pigment name=\"p\" pattern=\"bozo\" layers=\"true\"/></scene>", "1:8",
                 "this one has more than one");
    EXPECT_ERROR("<scene><pigment name=\"p\" layers=\"true\"><entry color=\"1\"/><scale "
                 "value=\"2\"/></pigment></scene>",
                 "1:58", "layers and averages have no pattern to place");
    EXPECT_ERROR("<scene><pigment name=\"p\" pattern=\"image\" texture=\"t\"/></scene>", "1:51",
                 "unknown texture 't'");
    EXPECT_ERROR("<scene><pigment name=\"p\" color=\"1\"/><material name=\"m\" pigment=\"p\" "
                 "color=\"1 0 0\"/></scene>",
                 "1:75", "'color' of <material> is not used with a pigment");
    EXPECT_ERROR("<scene><material name=\"a\"/><switch name=\"s\" pattern=\"checker\"><entry "
                 "material=\"a\"/><entry material=\"a\"/></switch><material name=\"m\" "
                 "switch=\"s\" diffuse=\"1\"/></scene>",
                 "1:153", "'diffuse' of <material> is not used with a switch");
    EXPECT_ERROR("<scene><material name=\"m\" normal=\"n\"/></scene>", "1:35",
                 "unknown normal 'n'");
    EXPECT_ERROR("<scene><sky pigment=\"nope\"/></scene>", "1:22", "unknown pigment 'nope'");
    EXPECT_ERROR("<scene><background color=\"0\"/><pigment name=\"p\" color=\"1\"/><sky "
                 "pigment=\"p\"/></scene>",
                 "1:60", "a <background> or a <sky>, not both");
    EXPECT_ERROR("<scene><fog distance=\"0\" color=\"1\"/></scene>", "1:23",
                 "the fog's distance must be > 0");
    EXPECT_ERROR("<scene><fog distance=\"10\"/></scene>", "1:8", "needs the attribute 'color'");
}

TEST(XmlErrors, DeepNestingIsBounded) {
    std::string deep = "<scene>";
    for (int i = 0; i < 200; ++i) deep += "<union>";
    deep += "<sphere/>";
    for (int i = 0; i < 200; ++i) deep += "</union>";
    deep += "</scene>";
    const std::string e = error_of(deep);
    EXPECT_NE(e.find("nested deeper than"), std::string::npos) << e;
}

TEST(XmlErrors, MeshFileErrorsNameBothFiles) {
    const auto dir = test::temp_folder("xml_mesh_error");
    test::write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n");
    const std::string xml = (dir / "scene.xml").string();
    try {
        io::parse_xml_scene("<scene>\n<mesh name=\"m\" file=\"bad.obj\"/></scene>", xml);
        FAIL() << "expected an error";
    } catch (const SceneError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(xml + ":2:22: error: ", 0), 0u) << m;
        EXPECT_NE(m.find((dir / "bad.obj").string()), std::string::npos) << m;
        EXPECT_NE(m.find("not finite"), std::string::npos) << m;
    }
}

} // namespace
} // namespace sheaf

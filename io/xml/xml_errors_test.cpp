// XML scene errors: each names the file, line and column of what is wrong and what was
// expected; unknown elements and attributes are errors; nothing bad crashes or is ignored.
#include "io/xml/xml_scene.h"

#include "core/base/error.h"
#include "io/mesh/mesh_test_files.h"

#include <gtest/gtest.h>

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

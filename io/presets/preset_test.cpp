// Tests of the XML presets: a good file, unknown keys and values with file:line, XML errors,
// lookup by name.
#include "io/presets/preset.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace sheaf {
namespace {

namespace fs = std::filesystem;

class PresetTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() / ("sheaf_preset_" + std::to_string(rd()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    /// The SettingsError message of load_preset(path), or "" when it did not throw.
    static std::string error_of(const std::string& path) {
        try {
            load_preset(path);
        } catch (const SettingsError& e) {
            return e.what();
        }
        return "";
    }
    static bool contains(const std::string& s, const std::string& part) {
        return s.find(part) != std::string::npos;
    }

    fs::path dir_;
};

TEST_F(PresetTest, GoodPreset) {
    const std::string path = write("good.xml", R"(<?xml version="1.0"?>
<!-- a comment -->
<preset name="fast" description="A fast one">
  <set key="accel" value="crsh"/>
  <set key="hierarchy.depth" value="03"/>
  <set key="cull.objects" value="on"/>
</preset>
)");
    const Preset p = load_preset(path);
    EXPECT_EQ(p.name, "fast");
    EXPECT_EQ(p.description, "A fast one");
    ASSERT_EQ(p.values.size(), 3u);
    EXPECT_EQ(p.values[0], (std::pair<std::string, std::string>{"accel", "crsh"}));
    EXPECT_EQ(p.values[1], (std::pair<std::string, std::string>{"hierarchy.depth", "3"}));
    EXPECT_EQ(p.values[2], (std::pair<std::string, std::string>{"cull.objects", "true"}));
}

TEST_F(PresetTest, NameDefaultsToTheFileStem) {
    const std::string path =
        write("mine.xml", "<preset><set key=\"accel\" value=\"rah\"/></preset>");
    EXPECT_EQ(load_preset(path).name, "mine");
}

TEST_F(PresetTest, UnknownKeyHasFileLineAndKey) {
    const std::string path = write("bad_key.xml", R"(<?xml version="1.0"?>
<preset name="x">
  <set key="accel" value="brute"/>
  <set key="nokey" value="1"/>
</preset>
)");
    const std::string e = error_of(path);
    EXPECT_TRUE(contains(e, path + ":4:")) << e;
    EXPECT_TRUE(contains(e, "nokey")) << e;
}

TEST_F(PresetTest, BadValueNamesKeyAndAllowedValues) {
    const std::string path = write("bad_value.xml", R"(<preset name="x">
  <set key="hash.mode" value="bogus"/>
</preset>
)");
    const std::string e = error_of(path);
    EXPECT_TRUE(contains(e, path + ":2:")) << e;
    EXPECT_TRUE(contains(e, "hash.mode")) << e;
    EXPECT_TRUE(contains(e, "none, crsh, hash32, hash192")) << e;

    const std::string range = write("bad_range.xml", R"(<preset>

  <set key="hierarchy.arity" value="1"/>
</preset>)");
    const std::string e2 = error_of(range);
    EXPECT_TRUE(contains(e2, range + ":3:")) << e2;
    EXPECT_TRUE(contains(e2, "hierarchy.arity")) << e2;
    EXPECT_TRUE(contains(e2, "2..64")) << e2;
}

TEST_F(PresetTest, MalformedXmlHasALine) {
    const std::string path = write("broken.xml", R"(<?xml version="1.0"?>
<preset name="x">
  <set key="accel" value="crsh"/>
  <set key="hash.mode" value="crsh"
</preset>
)");
    const std::string e = error_of(path);
    EXPECT_TRUE(contains(e, path + ":")) << e;
    EXPECT_TRUE(contains(e, "XML error")) << e;
    // pugixml reports the error where the tag breaks off: line 4 or 5.
    EXPECT_TRUE(contains(e, path + ":4:") || contains(e, path + ":5:")) << e;
}

TEST_F(PresetTest, UnknownElementAndAttribute) {
    const std::string elem =
        write("elem.xml", "<preset>\n  <get key=\"accel\" value=\"crsh\"/>\n</preset>\n");
    std::string e = error_of(elem);
    EXPECT_TRUE(contains(e, elem + ":2:")) << e;
    EXPECT_TRUE(contains(e, "<get>")) << e;

    const std::string attr = write(
        "attr.xml", "<preset>\n\n  <set key=\"accel\" value=\"crsh\" why=\"x\"/>\n</preset>\n");
    e = error_of(attr);
    EXPECT_TRUE(contains(e, attr + ":3:")) << e;
    EXPECT_TRUE(contains(e, "why")) << e;

    const std::string root = write("root.xml", "<presets/>\n");
    e = error_of(root);
    EXPECT_TRUE(contains(e, root + ":1:")) << e;

    const std::string root_attr = write("root_attr.xml", "<preset nam=\"x\"/>\n");
    e = error_of(root_attr);
    EXPECT_TRUE(contains(e, "nam")) << e;
}

TEST_F(PresetTest, MissingFile) {
    const std::string path = (dir_ / "nosuch.xml").string();
    const std::string e = error_of(path);
    EXPECT_TRUE(contains(e, path)) << e;
    EXPECT_TRUE(contains(e, "cannot open")) << e;
}

TEST_F(PresetTest, FindPresetByNameOrPath) {
    const fs::path a = dir_ / "a", b = dir_ / "b";
    fs::create_directories(a);
    fs::create_directories(b);
    std::ofstream(b / "fast.xml") << "<preset/>";
    std::ofstream(b / "slow.xml") << "<preset/>";
    std::ofstream(a / "slow.xml") << "<preset/>";
    const std::vector<std::string> dirs = {a.string(), b.string()};
    EXPECT_EQ(find_preset("fast", dirs), (b / "fast.xml").string());
    EXPECT_EQ(find_preset("slow", dirs), (a / "slow.xml").string());
    EXPECT_EQ(find_preset("x/y", dirs), "x/y");
    EXPECT_EQ(find_preset("other.xml", dirs), "other.xml");
    EXPECT_EQ(list_presets(dirs), (std::vector<std::string>{"fast", "slow"}));
    try {
        find_preset("nosuch", dirs);
        FAIL() << "expected SettingsError";
    } catch (const SettingsError& e) {
        const std::string m = e.what();
        EXPECT_TRUE(contains(m, "nosuch")) << m;
        EXPECT_TRUE(contains(m, a.string())) << m;
        EXPECT_TRUE(contains(m, b.string())) << m;
        EXPECT_TRUE(contains(m, "fast, slow")) << m;
    }
}

} // namespace
} // namespace sheaf

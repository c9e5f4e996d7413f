// Passes in files: a rendered frame's OpenEXR carries every pass as named channels that read
// back exactly; each pass writes as a false-colour picture; the display settings reach 8-bit
// files.
#include "io/image/image_io.h"

#include "core/backend/backend.h"
#include "core/base/error.h"
#include "core/scenes/builtin.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace sheaf {
namespace {

namespace fs = std::filesystem;

Frame small_cornell(std::vector<std::pair<std::string, std::string>> extra = {}) {
    const PreparedScene scene = prepare_scene(make_builtin_scene("cornell"));
    Settings s;
    s.set("width", "24"), s.set("height", "16");
    for (auto& [k, v] : extra) s.set(k, v);
    Frame f = render_frame(scene, RenderSettings::resolve(s, scene.settings));
    f.settings = RenderSettings::effective(s, scene.settings);
    return f;
}

std::string temp(const std::string& name) {
    return (fs::temp_directory_path() / ("sheaf_passes_" + name)).string();
}

TEST(Passes, ExrCarriesEveryPassAsNamedChannels) {
    const Frame f = small_cornell({{"output.exr", "float"}});
    const std::string path = temp("all.exr");
    write_image(f, path);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    const std::vector<std::string> want = {"R",        "G",         "B",    "A",        "Z",
                                           "N.X",      "N.Y",       "N.Z",  "albedo.R", "albedo.G",
                                           "albedo.B", "object_id", "tests"};
    ASSERT_EQ(spec.nchannels, int(want.size()));
    // OpenEXR stores channels sorted by name; find each by name.
    auto channel = [&](const std::string& name) {
        for (int c = 0; c < spec.nchannels; ++c)
            if (spec.channelnames[size_t(c)] == name) return c;
        ADD_FAILURE() << "no channel " << name;
        return 0;
    };
    std::vector<float> data(size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()));
    const size_t n = size_t(f.width) * f.height;
    for (size_t p = 0; p < n; ++p) {
        const float* px = &data[p * size_t(spec.nchannels)];
        EXPECT_EQ(px[channel("R")], f.rgba[4 * p]);
        EXPECT_EQ(px[channel("Z")], f.depth[p]);
        EXPECT_EQ(px[channel("N.Y")], f.normal[p].y);
        EXPECT_EQ(px[channel("albedo.G")], f.albedo[p].y);
        EXPECT_EQ(px[channel("object_id")], float(f.object_id[p]));
        EXPECT_EQ(px[channel("tests")], float(f.tests[p]));
    }
    EXPECT_NE(spec.get_string_attribute("sheaf:stats").find("rays.shadow"), std::string::npos);
    EXPECT_NE(spec.get_string_attribute("sheaf:settings").find("accel=bvh"), std::string::npos);
}

TEST(Passes, HalfExrKeepsExactIdsAndCounts) {
    const Frame f = small_cornell();
    const std::string path = temp("half.exr");
    write_image(f, path);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec spec = in->spec();
    int tests = -1, r = -1;
    for (int c = 0; c < spec.nchannels; ++c) {
        if (spec.channelnames[size_t(c)] == "tests") tests = c;
        if (spec.channelnames[size_t(c)] == "R") r = c;
    }
    ASSERT_GE(tests, 0);
    EXPECT_EQ(spec.channelformat(r), OIIO::TypeDesc::HALF);
    EXPECT_EQ(spec.channelformat(tests), OIIO::TypeDesc::FLOAT);
}

TEST(Passes, EveryPassWritesAFalseColourPicture) {
    const Frame f = small_cornell();
    for (const std::string& pass : pass_names()) {
        const std::string path = temp(pass + ".png");
        write_pass_image(f, pass, path);
        auto in = OIIO::ImageInput::open(path);
        ASSERT_TRUE(in) << pass;
        std::vector<unsigned char> px(size_t(f.width) * f.height * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
        EXPECT_GT(*std::max_element(px.begin(), px.end()) - *std::min_element(px.begin(), px.end()),
                  20)
            << pass;
    }
    EXPECT_THROW(write_pass_image(f, "velocity", temp("x.png")), RenderError);
    EXPECT_THROW(write_pass_image(f, "depth", temp("x.exr")), RenderError);
}

TEST(Passes, DisplaySettingsReachEightBitFiles) {
    Frame f = small_cornell();
    f.rgba.assign(f.rgba.size(), 0.25f);
    write_image(f, temp("srgb.png"));
    for (auto& [k, v] : f.settings)
        if (k == "output.display") v = "Rec.709";
    write_image(f, temp("rec709.png"));
    auto read = [](const std::string& p) {
        auto in = OIIO::ImageInput::open(p);
        std::vector<unsigned char> row(size_t(in->spec().width) * in->spec().nchannels);
        in->read_scanline(0, 0, OIIO::TypeDesc::UINT8, row.data());
        return int(row[0]);
    };
    EXPECT_EQ(read(temp("srgb.png")), int(std::lround(srgb_encode(0.25f) * 255)));
    EXPECT_EQ(read(temp("rec709.png")), int(std::lround(std::pow(0.25f, 1 / 2.4f) * 255)));
    for (auto& [k, v] : f.settings)
        if (k == "output.display") v = "P3";
    EXPECT_THROW(write_image(f, temp("p3.png")), RenderError);
}

} // namespace
} // namespace sheaf

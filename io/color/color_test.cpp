// Colour management: the shipped config loads and validates, its sRGB display matches the
// sRGB formula, Rec.709 is BT.1886, looks apply, $OCIO and explicit configs replace it, and
// unknown names are clear errors.
#include "io/color/color.h"

#include "core/base/error.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sheaf::io {
namespace {

float srgb_encode(float v) {
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

std::vector<float> ramp() {
    std::vector<float> px;
    for (int i = 0; i <= 200; ++i) {
        const float v = float(i) / 200.0f;
        px.insert(px.end(), {v, v * v, v * 0.01f, 0.5f});
    }
    return px;
}

TEST(Color, ShippedConfigLoadsAndValidates) {
    std::istringstream in(shipped_ocio_config());
    auto config = OCIO_NAMESPACE::Config::CreateFromStream(in);
    EXPECT_NO_THROW(config->validate());
    EXPECT_STREQ(config->getDefaultDisplay(), "sRGB");
    EXPECT_TRUE(config->getColorSpace("acescg"));
    EXPECT_TRUE(config->getColorSpace("srgb_texture"));
    EXPECT_EQ(ocio_displays({}), (std::vector<std::string>{"sRGB", "Rec.709"}));
}

TEST(Color, SrgbDisplayMatchesTheFormula) {
    std::vector<float> px = ramp();
    const std::vector<float> in = px;
    apply_display_transform(px.data(), in.size() / 4, {});
    for (size_t i = 0; i < in.size(); i += 4) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(px[i + c], srgb_encode(in[i + c]), 1e-4f) << in[i + c];
        EXPECT_EQ(px[i + 3], 0.5f); // alpha untouched
    }
}

TEST(Color, Rec709IsGamma24AndLooksApply) {
    std::vector<float> px = ramp();
    const std::vector<float> in = px;
    apply_display_transform(px.data(), in.size() / 4, {"", "Rec.709", "Standard", ""});
    for (size_t i = 0; i < in.size(); i += 4) EXPECT_NEAR(px[i], std::pow(in[i], 1 / 2.4f), 1e-4f);
    px = in;
    apply_display_transform(px.data(), in.size() / 4, {"", "sRGB", "Standard", "Bright"});
    EXPECT_NEAR(px[4 * 50], srgb_encode(2 * in[4 * 50]), 1e-4f);
}

TEST(Color, UnknownNamesAreClearErrors) {
    float px[4] = {0.5f, 0.5f, 0.5f, 1};
    try {
        apply_display_transform(px, 1, {"", "P3", "", ""});
        FAIL();
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("display 'P3'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("sRGB, Rec.709"), std::string::npos) << e.what();
    }
    EXPECT_THROW(apply_display_transform(px, 1, {"", "sRGB", "Filmic", ""}), RenderError);
    EXPECT_THROW(apply_display_transform(px, 1, {"", "sRGB", "", "Nope"}), RenderError);
    EXPECT_THROW(apply_display_transform(px, 1, {"/nonexistent/config.ocio", "", "", ""}),
                 RenderError);
}

TEST(Color, OcioVariableAndExplicitConfigsReplaceTheShippedOne) {
    // A copy of the shipped config with its sRGB display renamed.
    std::string text = shipped_ocio_config();
    const std::string from = "  sRGB:\n", to = "  Office sRGB:\n";
    text.replace(text.find(from), from.size(), to);
    text.replace(text.find("active_displays: [sRGB"), 22, "active_displays: [Office sRGB");
    const std::string path =
        (std::filesystem::temp_directory_path() / "sheaf_test_config.ocio").string();
    std::ofstream(path) << text;
    EXPECT_EQ(ocio_displays({path, "", "", ""}).front(), "Office sRGB");
    setenv("OCIO", path.c_str(), 1);
    EXPECT_EQ(ocio_displays({}).front(), "Office sRGB");
    unsetenv("OCIO");
    EXPECT_EQ(ocio_displays({}).front(), "sRGB");
}

} // namespace
} // namespace sheaf::io

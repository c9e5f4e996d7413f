// Tests of write_image: EXR and PNG round trips through OpenImageIO, metadata, bad extensions.
#include "io/image/image_io.h"

#include "core/base/error.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

namespace sheaf {
namespace {

namespace fs = std::filesystem;

class ImageIoTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() / ("sheaf_image_io_" + std::to_string(rd()));
        fs::create_directories(dir_);
        frame_.width = 5;
        frame_.height = 3;
        frame_.rgba.resize(5 * 3 * 4);
        for (size_t p = 0; p < 15; ++p) {
            // Values below, inside and above [0, 1], including the linear toe of sRGB.
            frame_.rgba[p * 4 + 0] = float(p) / 10.0f;
            frame_.rgba[p * 4 + 1] = 0.002f * float(p);
            frame_.rgba[p * 4 + 2] = 1.0f - float(p) / 7.0f;
            frame_.rgba[p * 4 + 3] = 1.0f;
        }
        frame_.stats.set("rays.shadow", 42);
        frame_.settings = {{"accel", "crsh"}, {"width", "5"}};
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    std::vector<float> read_back(const std::string& path, OIIO::TypeDesc type, int* channels,
                                 OIIO::ImageSpec* spec_out = nullptr) {
        auto in = OIIO::ImageInput::open(path);
        EXPECT_TRUE(in) << OIIO::geterror();
        if (!in) return {};
        const OIIO::ImageSpec& spec = in->spec();
        EXPECT_EQ(spec.width, frame_.width);
        EXPECT_EQ(spec.height, frame_.height);
        *channels = spec.nchannels;
        if (spec_out) *spec_out = spec;
        std::vector<float> data(size_t(spec.width) * spec.height * spec.nchannels);
        if (type == OIIO::TypeDesc::UINT8) {
            std::vector<uint8_t> bytes(data.size());
            EXPECT_TRUE(
                in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, bytes.data()));
            for (size_t i = 0; i < bytes.size(); ++i) data[i] = float(bytes[i]);
        } else {
            EXPECT_TRUE(
                in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()));
        }
        in->close();
        return data;
    }

    fs::path dir_;
    Frame frame_;
};

TEST_F(ImageIoTest, ExrIsSceneLinearWithinHalfPrecision) {
    const std::string path = (dir_ / "frame.exr").string();
    write_image(frame_, path);
    int nc = 0;
    OIIO::ImageSpec spec;
    std::vector<float> data = read_back(path, OIIO::TypeDesc::FLOAT, &nc, &spec);
    ASSERT_EQ(nc, 4);
    for (size_t i = 0; i < frame_.rgba.size(); ++i) {
        const float want = frame_.rgba[i];
        EXPECT_NEAR(data[i], want, std::fabs(want) * 1e-3f + 1e-4f) << "value " << i;
    }
    EXPECT_NE(spec.get_string_attribute("sheaf:stats").find("rays.shadow"), std::string::npos);
    EXPECT_NE(spec.get_string_attribute("sheaf:settings").find("accel=crsh"), std::string::npos);
}

TEST_F(ImageIoTest, PngIsSrgbEncodedWithinOneStep) {
    const std::string path = (dir_ / "frame.png").string();
    write_image(frame_, path);
    int nc = 0;
    std::vector<float> data = read_back(path, OIIO::TypeDesc::UINT8, &nc);
    ASSERT_EQ(nc, 4);
    for (size_t p = 0; p < 15; ++p) {
        for (int c = 0; c < 3; ++c) {
            float want = std::clamp(srgb_encode(frame_.rgba[p * 4 + c]), 0.0f, 1.0f) * 255.0f;
            EXPECT_NEAR(data[p * 4 + c], want, 1.0f) << "pixel " << p << " channel " << c;
        }
        EXPECT_EQ(data[p * 4 + 3], 255.0f);
    }
}

TEST_F(ImageIoTest, HdrIsFloatRgb) {
    const std::string path = (dir_ / "frame.hdr").string();
    write_image(frame_, path);
    int nc = 0;
    std::vector<float> data = read_back(path, OIIO::TypeDesc::FLOAT, &nc);
    ASSERT_EQ(nc, 3);
    // RGBE keeps 8 bits of mantissa relative to the largest channel of each pixel.
    for (size_t p = 0; p < 15; ++p)
        for (int c = 0; c < 3; ++c) {
            const float want = std::max(frame_.rgba[p * 4 + c], 0.0f);
            EXPECT_NEAR(data[p * 3 + c], want, 0.02f) << "pixel " << p << " channel " << c;
        }
}

TEST_F(ImageIoTest, SrgbTransferFunction) {
    EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
    EXPECT_NEAR(srgb_encode(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgb_encode(0.18f), 0.4613f, 1e-3f);
    EXPECT_NEAR(srgb_encode(0.001f), 0.01292f, 1e-6f);
}

TEST_F(ImageIoTest, UnknownExtensionNamesThePath) {
    const std::string path = (dir_ / "frame.bogusext").string();
    try {
        write_image(frame_, path);
        FAIL() << "expected RenderError";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(".bogusext"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(is_supported_image_path(path));
    EXPECT_TRUE(is_supported_image_path("a/B.PNG"));
}

TEST_F(ImageIoTest, UnwritableDirectoryIsARenderError) {
    const std::string path = (dir_ / "no" / "such" / "dir" / "frame.png").string();
    try {
        write_image(frame_, path);
        FAIL() << "expected RenderError";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace sheaf

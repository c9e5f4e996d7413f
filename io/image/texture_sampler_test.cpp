// Image textures end to end: a checker PNG on a quad shows as a checker (mean and contrast),
// 8-bit files are linearised, and a missing texture is an error naming the file and where the
// scene asked for it.
#include "io/image/texture_sampler.h"

#include "core/backend/backend.h"
#include "core/base/error.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace sheaf {
namespace {

std::string write_checker(const std::string& name) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    const int n = 64, cell = 8;
    std::vector<unsigned char> px(n * n * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c)
                px[(y * n + x) * 3 + c] = ((x / cell + y / cell) % 2) ? 255 : 0;
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(n, n, 3, OIIO::TypeDesc::UINT8)));
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    return path;
}

// A quad with texture coordinates filling an orthographic view.
Scene quad_scene(int32_t texture) {
    Scene s;
    Material m;
    m.color = Vec3(1.0f), m.ambient = 0.2f, m.diffuse = 0.8f;
    m.texture = texture;
    s.add_material(m);
    Mesh q;
    q.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    q.uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    q.indices = {0, 1, 2, 0, 2, 3};
    s.add_mesh_object("quad", std::move(q), 0);
    Light sun; // a parallel light straight down the view: the same light everywhere
    sun.type = LightType::Parallel, sun.direction = Vec3(0, 0, -1);
    s.add_light(sun);
    s.camera.position = Vec3(0, 0, 3);
    s.camera.projection = Projection::Orthographic;
    s.camera.ortho_height = 2.0f;
    return s;
}

void mean_and_spread(const Frame& f, double& mean, double& spread) {
    double sum = 0, sum2 = 0;
    const size_t n = size_t(f.width) * f.height;
    for (size_t i = 0; i < n; ++i)
        sum += f.rgba[4 * i], sum2 += double(f.rgba[4 * i]) * f.rgba[4 * i];
    mean = sum / double(n);
    spread = std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
}

TEST(Textures, ACheckerTextureShowsAsAChecker) {
    Scene s = quad_scene(0);
    s.textures.push_back(Texture{write_checker("sheaf_checker.png")});
    PreparedScene p = prepare_scene(s);
    io::attach_texture_sampler(p);
    ASSERT_TRUE(p.sampler);
    RenderSettings rs;
    rs.width = rs.height = 64;
    const Frame f = render_frame(p, rs);
    double mean, spread;
    mean_and_spread(f, mean, spread);
    // Half the squares black, half white (sRGB 1.0 = linear 1.0): ambient + diffuse = 1 or 0.
    EXPECT_NEAR(mean, 0.5, 0.05);
    EXPECT_GT(spread, 0.45);
    // The untextured quad is uniform.
    PreparedScene plain = prepare_scene(quad_scene(-1));
    const Frame g = render_frame(plain, rs);
    mean_and_spread(g, mean, spread);
    EXPECT_NEAR(mean, 1.0, 1e-3);
    EXPECT_LT(spread, 1e-3);
    // Texture coordinates (0, 0) are the image's bottom-left, a white cell (its 8th row of
    // cells from the top starts white); the next cell to the right is black.
    EXPECT_GT(f.rgba[4 * (63 * 64 + 0)], 0.95f);
    EXPECT_LT(f.rgba[4 * (63 * 64 + 9)], 0.05f);
}

TEST(Textures, EightBitTexturesAreLinearised) {
    const std::string path = (std::filesystem::temp_directory_path() / "sheaf_grey.png").string();
    std::vector<unsigned char> px(4 * 4 * 3, 128);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::UINT8)));
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    Scene s = quad_scene(0);
    s.textures.push_back(Texture{path});
    PreparedScene p = prepare_scene(s);
    io::attach_texture_sampler(p);
    const Vec3 c = p.sampler->sample(0, 0.5f, 0.5f);
    EXPECT_NEAR(c.x, 0.2158f, 2e-3f); // sRGB 128/255 in linear light
    s.textures[0].colorspace = "linear";
    p = prepare_scene(s);
    io::attach_texture_sampler(p);
    EXPECT_NEAR(p.sampler->sample(0, 0.5f, 0.5f).x, 128.0f / 255.0f, 2e-3f);
}

TEST(Textures, AMissingTextureNamesTheFileAndThePlace) {
    Scene s = quad_scene(0);
    s.textures.push_back(
        Texture{"/nonexistent/wood.png", TextureMapping::Uv, {}, "", "scene.xml:7:5"});
    PreparedScene p = prepare_scene(s);
    try {
        io::attach_texture_sampler(p);
        FAIL() << "expected an error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/wood.png"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("scene.xml:7:5"), std::string::npos) << e.what();
    }
}

// Found by the C ABI fuzzer: OpenImageIO handed the folder "/" to libheif, which read without
// end and took gigabytes. A folder or a device is an error before any reader sees it.
TEST(Textures, AFolderOrADeviceIsNotATexture) {
    for (const char* path : {"/", "/dev/zero"}) {
        Scene s = quad_scene(0);
        s.textures.push_back(Texture{path, TextureMapping::Uv, {}, "", ""});
        PreparedScene p = prepare_scene(s);
        try {
            io::attach_texture_sampler(p);
            FAIL() << "expected an error for " << path;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("not an image file (a folder or a device)"),
                      std::string::npos)
                << e.what();
        }
    }
}

} // namespace
} // namespace sheaf

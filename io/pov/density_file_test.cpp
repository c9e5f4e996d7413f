// density_file df3 "file": the voxels read from POV-Ray's df3 files, as a pattern of pigments,
// normals and media densities; bad files are errors at the file's name.
#include "tests/support/pov_test_util.h"

#include <fstream>

namespace sheaf::io::pov {
namespace {

using test::error_of;

// A df3 file of 2 x 1 x 1 voxels of `width` bytes each: 0 and the largest value, or `bytes`.
std::string df3(test::TempDir& d, const std::string& name, int width,
                std::vector<unsigned char> bytes = {}) {
    if (bytes.empty()) {
        bytes = {0, 2, 0, 1, 0, 1};
        bytes.insert(bytes.end(), size_t(width), 0);
        bytes.insert(bytes.end(), size_t(width), 0xff);
    }
    const std::string path = d.path() + "/" + name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

TEST(PovDensityFile, VoxelsOfOneTwoOrFourBytesBecomeAGrid) {
    test::TempDir d;
    for (int width : {1, 2, 4}) {
        const std::string file = df3(d, "v" + std::to_string(width) + ".df3", width);
        const PovResult r = load_pov_scene(
            d.write("scene.pov", "sphere { 0, 1 pigment { density_file df3 \"" + file +
                                     "\" interpolate 1 } normal { density_file df3 \"" + file +
                                     "\", 0.5 } }\n"));
        EXPECT_TRUE(r.warnings.empty());
        ASSERT_EQ(r.scene.density_grids.size(), 2u); // one each, sharing the voxels
        ASSERT_EQ(r.scene.density_voxels.size(), 2u);
        EXPECT_FLOAT_EQ(r.scene.density_voxels[0], 0);
        EXPECT_FLOAT_EQ(r.scene.density_voxels[1], 1);
        const DensityGrid& g = r.scene.density_grids[0];
        EXPECT_EQ(g.nx, 2u);
        EXPECT_EQ(g.ny, 1u);
        EXPECT_EQ(g.nz, 1u);
        EXPECT_EQ(g.interpolation, 1u);
        EXPECT_EQ(r.scene.density_grids[1].interpolation, 0u);
        const Pigment& pg = r.scene.pigments.at(r.scene.materials.at(0).pigment);
        EXPECT_EQ(pg.pattern.kind, PatternKind::DensityFile);
        EXPECT_EQ(pg.pattern.grid, 0);
        EXPECT_NO_THROW(r.scene.validate());
    }
}

TEST(PovDensityFile, MediaReadTheirDensityFromTheFile) {
    test::TempDir d;
    const std::string file = df3(d, "m.df3", 1);
    const PovResult r = load_pov_scene(
        d.write("scene.pov", "box { 0, 1 pigment { rgbt 1 } hollow interior { media { emission 1 "
                             "density { density_file df3 \"" +
                                 file + "\" } } } }\n"));
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0);
    ASSERT_EQ(r.scene.media.size(), 1u);
    ASSERT_EQ(r.scene.medium_densities.size(), 1u);
    const Pigment& density = r.scene.pigments.at(r.scene.medium_densities[0]);
    EXPECT_EQ(density.pattern.kind, PatternKind::DensityFile);
}

TEST(PovDensityFile, BadFilesAndSettingsAreErrorsAtTheirPlace) {
    test::TempDir d;
    const std::string shorter = df3(d, "short.df3", 1, {0, 2, 0});
    const std::string odd = df3(d, "odd.df3", 1, {0, 2, 0, 1, 0, 1, 7, 7, 7});
    const std::string empty = df3(d, "empty.df3", 1, {0, 0, 0, 1, 0, 1});
    const std::string good = df3(d, "good.df3", 1);
    struct Case {
        std::string text, want;
    };
    for (const Case& c :
         {Case{"sphere { 0, 1 pigment { density_file df3 \"" + shorter + "\" } }",
               "1:42: error: density file '" + shorter + "' is shorter than its 6-byte header"},
          Case{"sphere { 0, 1 pigment { density_file df3 \"" + odd + "\" } }",
               "holds 3 bytes of voxels, not 1, 2 or 4 for each of its 2 x 1 x 1"},
          Case{"sphere { 0, 1 pigment { density_file df3 \"" + empty + "\" } }", "has a size of 0"},
          Case{"sphere { 0, 1 pigment { density_file df3 \"missing.df3\" } }",
               "1:42: error: cannot find density file 'missing.df3'"},
          Case{"sphere { 0, 1 pigment { density_file df3 \"" + good + "\" interpolate 3 } }",
               "error: a density_file's interpolate is 0 (none), 1 (trilinear) or 2"}}) {
        const std::string e = error_of(c.text);
        EXPECT_NE(e.find(c.want), std::string::npos) << e;
    }
}

} // namespace
} // namespace sheaf::io::pov

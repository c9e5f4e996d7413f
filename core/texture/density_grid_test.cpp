#include "core/texture/density_grid.h"

#include <gtest/gtest.h>

#include <vector>

namespace sheaf {
namespace {

// A 2 x 2 x 2 grid whose voxel (x, y, z) holds x + 2y + 4z over 8 (x fastest), after two
// leading values another grid would own.
struct Grid {
    std::vector<float> v{0.9f, 0.9f};
    DensityGrid g;
    Grid(uint32_t interpolation) {
        for (int i = 0; i < 8; ++i) v.push_back(float(i) / 8);
        g.first = 2, g.nx = g.ny = g.nz = 2, g.interpolation = interpolation;
    }
    float at(Vec3 p) const { return density_value(g, v.data(), p); }
};

TEST(DensityGrid, NearestVoxelInsideTheUnitCubeAndZeroOutside) {
    const Grid n(0);
    EXPECT_FLOAT_EQ(n.at({0.1f, 0.1f, 0.1f}), 0);
    EXPECT_FLOAT_EQ(n.at({0.6f, 0.1f, 0.1f}), 1.0f / 8);
    EXPECT_FLOAT_EQ(n.at({0.1f, 0.6f, 0.1f}), 2.0f / 8);
    EXPECT_FLOAT_EQ(n.at({0.9f, 0.9f, 0.9f}), 7.0f / 8);
    for (const Vec3 p : {Vec3(-0.01f, 0.5f, 0.5f), Vec3(0.5f, 1.0f, 0.5f), Vec3(0.5f, 0.5f, 2)})
        EXPECT_EQ(n.at(p), 0) << p.x << ' ' << p.y << ' ' << p.z;
}

TEST(DensityGrid, TrilinearBlendsTheEightNeighboursWrappingAtTheFarFaces) {
    const Grid t(1);
    EXPECT_FLOAT_EQ(t.at({0, 0, 0}), 0);                       // on voxel (0, 0, 0)
    EXPECT_NEAR(t.at({0.25f, 0, 0}), 0.5f / 8, 1e-6f);         // halfway to (1, 0, 0)
    EXPECT_NEAR(t.at({0.25f, 0.25f, 0.25f}), 3.5f / 8, 1e-6f); // the mean of all eight
    // From voxel (1, 0, 0) toward x = 2, which wraps to voxel (0, 0, 0).
    EXPECT_NEAR(t.at({0.75f, 0, 0}), 0.5f / 8, 1e-6f);
}

TEST(DensityGrid, TricubicPassesThroughTheVoxelsAndStaysInRange) {
    const Grid c(2);
    EXPECT_NEAR(c.at({0.5f, 0.5f, 0.5f}), 7.0f / 8, 1e-6f); // on voxel (1, 1, 1)
    EXPECT_NEAR(c.at({0.5f, 0, 0}), 1.0f / 8, 1e-6f);
    for (float x = 0; x < 1; x += 0.07f) {
        const float v = c.at({x, 0.3f, 0.8f});
        EXPECT_GE(v, 0);
        EXPECT_LE(v, 1);
    }
}

} // namespace
} // namespace sheaf

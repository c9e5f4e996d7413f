// Ray generation: the shadow layout of gathered points (each light taken with the same chance,
// weighted by the stride, so the mean is every light), and the 32-bit bound of a batch.
#include "core/rays/ray_gen.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <vector>

namespace sheaf {
namespace {

TEST(RayGen, GatheredPointsTakeEveryLightWithTheSameChance) {
    // 5 points with gather 0 take all 10 lights; 20,000 gathered points take about 4 each.
    std::vector<SurfaceHit> hits(20005);
    for (size_t i = 0; i < hits.size(); ++i) {
        hits[i].pixel = uint32_t(i / 7);
        hits[i].gather = i < 5 ? 0u : uint32_t(((i % 7) << 8) | 1);
    }
    ShadowLayout layout;
    layout.hits = hits.size(), layout.camera = 5, layout.lights = 10;
    ASSERT_EQ(layout.stride(), 3u);
    ASSERT_EQ(layout.elements(), 5u * 10u + 20000u * 4u);
    std::vector<double> taken(10, 0.0);
    std::vector<int> camera_pairs(5, 0);
    for (size_t e = 0; e < layout.elements(); ++e) {
        size_t hit;
        uint32_t light;
        float scale;
        if (!layout.pair(hits.data(), e, hit, light, scale)) continue;
        ASSERT_LT(light, 10u);
        if (hit < 5) {
            EXPECT_EQ(scale, 1.0f);
            ++camera_pairs[hit];
        } else {
            EXPECT_EQ(scale, 3.0f);
            taken[light] += scale;
        }
    }
    for (int c : camera_pairs) EXPECT_EQ(c, 10);
    // Each light reaches each gathered point once on average (1 / stride of them, x stride).
    for (double t : taken) EXPECT_NEAR(t / 20000.0, 1.0, 0.05);
    // Four lights or fewer: every gathered point takes them all, unweighted.
    layout.lights = 4;
    EXPECT_EQ(layout.stride(), 1u);
    size_t hit;
    uint32_t light;
    float scale;
    for (uint32_t j = 0; j < 4; ++j) {
        ASSERT_TRUE(layout.pair(hits.data(), 5 * 4 + j, hit, light, scale));
        EXPECT_EQ(hit, 5u);
        EXPECT_EQ(light, j);
        EXPECT_EQ(scale, 1.0f);
    }
    layout.lights = 0;
    EXPECT_EQ(layout.elements(), 0u);
}

TEST(RayGen, ABatchBeyond32BitIndicesIsRefusedBeforeItIsMade) {
    EXPECT_NO_THROW(check_batch_bound(0xFFFFFFFFull, RayType::Shadow));
    try {
        check_batch_bound(uint64_t(2048) * 2048 * 1024, RayType::Diffuse);
        ADD_FAILURE() << "no error";
    } catch (const OutOfMemory& e) {
        EXPECT_NE(std::string(e.what()).find("4294967296 diffuse rays"), std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace sheaf

namespace sheaf {
namespace {

// POV-Ray's total internal reflection: the ray that cannot leave is reflected whole and
// unfiltered, and the finish's own reflection is left out (interior/caustic2.pov's ceiling,
// seen from inside its glass); elsewhere the glass passes its filtered colour and reflects
// its finish's share.
TEST(RayGen, TotalInternalReflectionReflectsEverythingAsPovRay) {
    Material glass;
    glass.fresnel_split = false; // POV-Ray's: reflection from the finish only
    glass.ior = 1.1f;
    glass.mirror = 0.7f;
    SceneView view;
    view.materials = &glass;
    SurfaceHit h;
    h.material = 0;
    h.albedo = Vec3(0.7f, 0.7f, 1.0f);
    h.filter = 0.9f;
    h.throughput = Vec3(0.5f);
    h.front = false; // leaving the glass (ior 1.1) into air
    h.normal = h.geo_normal = Vec3(0, -1, 0);
    // Steep: it leaves, filtered; the mirror takes 0.7.
    h.incoming = normalize(Vec3(0.2f, 1, 0));
    const BounceSplit steep = bounce_split(view, h);
    EXPECT_NEAR(steep.refract_weight.z, 0.5f * 0.9f, 1e-6);
    EXPECT_NEAR(steep.reflect_weight.x, 0.5f * 0.7f, 1e-6);
    // Grazing (past asin(1 / 1.1), 65 degrees from the normal): all of it comes back.
    h.incoming = normalize(Vec3(3, 1, 0));
    const BounceSplit grazing = bounce_split(view, h);
    EXPECT_EQ(max_component(grazing.refract_weight), 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(grazing.reflect_weight[c], 0.5f);
}

} // namespace
} // namespace sheaf

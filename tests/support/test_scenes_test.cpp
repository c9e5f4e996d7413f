// The test helpers' own checks: expect_same_frame finds what differs, exactly or within the
// tolerance it is given for the shaded passes.
#include "tests/support/test_scenes.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

namespace sheaf {
namespace {

Frame small_frame() {
    Frame f;
    f.width = 2, f.height = 1;
    f.rgba = {0.5f, 0.25f, 0.125f, 1, 0, 0, 0, 1};
    f.depth = {1, 2};
    f.normal = {Vec3(0, 1, 0), Vec3(1, 0, 0)};
    f.albedo = {Vec3(0.5f), Vec3(0.25f)};
    f.object_id = {3, 0xFFFFFFFFu};
    f.tests = {10, 20};
    f.stats.set("rays.ao", 4);
    return f;
}

TEST(ExpectSameFrame, ShadedPassesWithinTheTolerance) {
    const Frame a = small_frame();
    Frame b = a;
    b.normal[1].y = 1e-5f;
    EXPECT_NONFATAL_FAILURE(test::expect_same_frame(a, b, "exact"), "normals differ");
    b.rgba[1] += 2e-4f;
    b.albedo[0].z += 1e-4f;
    test::expect_same_frame(a, b, "within", {}, 1e-3f);
    b.rgba[1] += 1e-2f;
    EXPECT_NONFATAL_FAILURE(test::expect_same_frame(a, b, "beyond", {}, 1e-3f),
                            "the images differ");
}

TEST(ExpectSameFrame, DepthIdsTestsAndStatisticsStayExact) {
    const Frame a = small_frame();
    Frame b = a;
    b.depth[0] += 1e-6f;
    EXPECT_NONFATAL_FAILURE(test::expect_same_frame(a, b, "depth", {}, 1e-3f), "depth differs");
    b = a;
    b.tests[1] += 1;
    EXPECT_NONFATAL_FAILURE(test::expect_same_frame(a, b, "tests", {}, 1e-3f),
                            "per-pixel tests differ");
    b = a;
    b.stats.set("rays.ao", 5);
    EXPECT_NONFATAL_FAILURE(test::expect_same_frame(a, b, "stats", {}, 1e-3f), "rays.ao");
    b.stats.set("rays.ao", 4);
    test::expect_same_frame(a, b, "same again");
}

} // namespace
} // namespace sheaf

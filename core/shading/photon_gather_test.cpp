// Photon maps: the kd-tree's searches against counting every photon, the capped search, and
// the radius estimated from a known density.
#include "core/backend/backend.h"
#include "core/frame/render_frame.h"
#include "core/scene/photon_gather.h"
#include "core/frame/photon_pass.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace sheaf {
namespace {

std::vector<Photon> random_photons(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Photon> p(n);
    for (Photon& ph : p) ph.position = Vec3(u(rng), 0.1f * u(rng), u(rng));
    return p;
}

TEST(PhotonGather, TheTreeFindsWhatCountingEveryPhotonFinds) {
    std::vector<Photon> tree = random_photons(5000, 7);
    const std::vector<Photon> all = tree;
    build_photon_tree(tree);
    PhotonMapView m;
    m.photons = tree.data(), m.count = uint32_t(tree.size());
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.2f, 1.2f);
    const Vec3 n(0, 1, 0);
    for (int q = 0; q < 200; ++q) {
        const Vec3 p(u(rng), 0.05f * u(rng), u(rng));
        const float r2 = 0.01f + 0.1f * std::fabs(u(rng));
        uint32_t expected = 0;
        for (const Photon& ph : all)
            expected += photon_detail::flat_distance2(ph.position - p, n) < r2 ? 1 : 0;
        EXPECT_EQ(photons_within(m, p, n, r2), expected) << q;
    }
}

TEST(PhotonGather, ASearchKeepsAboutGatherMaxAndTheRadiusFollowsTheDensity) {
    // A flat grid, 100 photons per unit square: a search of radius 1 holds about 314, so one
    // capped at 50 shrinks to about sqrt(50 / (100 pi)) = 0.40.
    std::vector<Photon> tree;
    for (int i = -200; i < 200; ++i)
        for (int j = -200; j < 200; ++j) {
            Photon ph;
            ph.position = Vec3(0.1f * i + 0.05f, 0.0f, 0.1f * j + 0.05f);
            tree.push_back(ph);
        }
    build_photon_tree(tree);
    PhotonMapView m;
    m.photons = tree.data(), m.count = uint32_t(tree.size());
    m.gather_max = 50;
    float r2 = 0;
    const uint32_t c = photon_search(m, Vec3(0, 0, 0), Vec3(0, 1, 0), 1.0f, r2);
    EXPECT_NEAR(float(c), 50.0f, 5.0f);
    EXPECT_NEAR(std::sqrt(r2), 0.40f, 0.03f);
    // POV-Ray's estimate: the radius that holds gather_max at the mean density. On a sphere
    // of radius 10 (no edges, where the density halves and POV-Ray's rule widens the radius),
    // 40000 photons evenly spread: 31.8 per unit square, so 100 lie within 1.0.
    std::vector<Photon> ball(40000);
    for (size_t i = 0; i < ball.size(); ++i) { // a Fibonacci sphere
        const float z = 1.0f - (2.0f * float(i) + 1.0f) / float(ball.size());
        const float a = 2.39996323f * float(i), s = std::sqrt(1.0f - z * z);
        ball[i].position = Vec3(std::cos(a) * s, std::sin(a) * s, z) * 10.0f;
    }
    build_photon_tree(ball);
    EXPECT_NEAR(estimate_photon_radius(ball, 100), 1.0f, 0.05f);
    // Fewer photons than gather_max: the density of all of them, not none (a caustic of a
    // few photons must not vanish). 50 photons over a 0.9 x 0.9 grid: about 1.1 units.
    std::vector<Photon> few;
    for (int i = 0; i < 50; ++i) {
        Photon ph;
        ph.position = Vec3(0.1f * float(i % 10), 0.0f, 0.1f * float(i / 10));
        few.push_back(ph);
    }
    build_photon_tree(few);
    const float r = estimate_photon_radius(few, 100);
    EXPECT_GT(r, 0.5f);
    EXPECT_LT(r, 3.0f);
    EXPECT_EQ(estimate_photon_radius({}, 100), 0.0f);
    // A point with no photons near: nothing, even after the wider search.
    m.radius = 0.5f, m.step = 1.0f, m.steps = 2;
    EXPECT_EQ(photon_gather(m, Vec3(50, 0, 50), Vec3(0, 1, 0), r2), 0u);
}

TEST(PhotonGather, FramesAgreeOnEveryAccelAndTheWavefront) {
    // The photon pass runs before both pipelines on the host; the wavefront gathers the same
    // map on the executing side.
    const PreparedScene scene = prepare_scene(test::photon_scene());
    const RenderSettings rs = test::settings_for(scene, {}, 64, 48);
    const Frame crsh = render_frame(scene, rs);
    EXPECT_GT(crsh.stats.get("photons.stored"), 1000.0);
    const PreparedScene plain = prepare_scene([] {
        Scene s = test::photon_scene();
        s.photons = PhotonSettings();
        return s;
    }());
    const Frame without = render_frame(plain, rs);
    double changed = 0;
    for (size_t i = 0; i < crsh.rgba.size(); ++i)
        changed += std::fabs(crsh.rgba[i] - without.rgba[i]);
    EXPECT_GT(changed, 5.0); // the caustics show
    for (const test::SettingList& kv :
         {test::SettingList{{"accel", "brute"}}, test::SettingList{{"accel", "rah"}}}) {
        const Frame other = render_frame(scene, test::settings_for(scene, kv, 64, 48));
        EXPECT_EQ(0, std::memcmp(crsh.rgba.data(), other.rgba.data(), crsh.rgba.size() * 4))
            << kv[0].second;
    }
    EXPECT_EQ(wavefront_unsupported(scene), "");
    test::expect_same_frame(render_frame_cpu(scene, rs), render_frame_wavefront_cpu(scene, rs),
                            "photons");
}

} // namespace
} // namespace sheaf

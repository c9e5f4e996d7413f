// The frame pipeline with the wavefront tracer under StrictExec, a CPU policy that keeps a
// GPU's rules: no host access to device memory outside copies, fresh buffers full of garbage,
// nothing past a buffer's end, no dependence on the order of a launch's elements. Frames must
// still equal the CPU backend's, and the policy itself must catch what it claims to.
#include "tests/support/strict_exec.h"

#include "core/frame/buffer.h"
#include "core/frame/frame_pipeline.h"
#include "core/frame/steps.h"
#include "core/scenes/builtin.h"
#include "core/sort/radix_sort.h"
#include "tests/support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace sheaf {
namespace {

using test::SettingList;
using wavefront::DeviceBuffer;
using wavefront::StrictExec;

TEST(StrictExec, FreshBuffersHoldGarbage) {
    StrictExec ex;
    DeviceBuffer<uint32_t, StrictExec> b(ex, 5);
    for (uint32_t v : b.download()) EXPECT_EQ(v, 0xA5A5A5A5u);
}

TEST(StrictExec, LaunchesRunEveryElementAndCountAsTheCpuPolicy) {
    StrictExec ex;
    const size_t n = 1000;
    DeviceBuffer<uint32_t, StrictExec> b(ex, n);
    uint32_t* p = b.data();
    ex.launch("iota", n, [=](size_t i) { p[i] = uint32_t(i); });
    const std::vector<uint32_t> v = b.download();
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(v[i], i);
    EXPECT_EQ(ex.exclusive_scan(p, n), n * (n - 1) / 2);
    EXPECT_EQ(b.get(3), 0u + 1 + 2);
    EXPECT_EQ(ex.launches(), 2u); // the launch and the scan
    EXPECT_EQ(ex.host_waits(), 3u); // the download, the scan's total, get
    EXPECT_EQ(ex.peak_bytes(), int64_t(n * sizeof(uint32_t)));
}

TEST(StrictExec, WritesIntoThePaddingAreReported) {
    StrictExec ex;
    {
        DeviceBuffer<uint32_t, StrictExec> b(ex, 3); // 12 bytes, 4 of padding
        uint32_t* p = b.data();
        ex.launch("one past the end", 1, [=](size_t) { p[3] = 7; });
    }
    ASSERT_EQ(ex.violations().size(), 1u);
    EXPECT_NE(ex.violations()[0].find("past its end"), std::string::npos);
    EXPECT_EQ(ex.live_buffers(), 0u);
}

void read_device_memory_on_the_host() {
    StrictExec ex;
    DeviceBuffer<uint32_t, StrictExec> b(ex, 8);
    volatile uint32_t v = b.data()[0];
    (void)v;
}

void write_past_the_end() {
    StrictExec ex;
    DeviceBuffer<uint32_t, StrictExec> b(ex, 1024); // one page, no padding
    uint32_t* p = b.data();
    ex.launch("past the end", 1, [=](size_t) { p[1024] = 1; });
}

TEST(StrictExecDeathTest, HostAccessToDeviceMemoryFaults) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(read_device_memory_on_the_host(),
                 "between device operations: the host touched device memory");
}

TEST(StrictExecDeathTest, IndexPastTheGuardPageFaults) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(write_past_the_end(), "inside device operation 'past the end'");
}

TEST(StrictExec, SealedLaunchesCatchACapturedHostPointer) {
    if (const char* why = wavefront::sealing_unavailable()) GTEST_SKIP() << why;
    StrictExec ex;
    ex.seal_host(1000);
    const size_t n = 1000;
    std::vector<uint32_t> host(n, 1);
    DeviceBuffer<uint32_t, StrictExec> b(ex, n);
    uint32_t* p = b.data();
    const uint32_t* h = host.data();
    EXPECT_THROW(ex.launch("reads host", n, [=](size_t i) { p[i] = h[i]; }), std::runtime_error);
    EXPECT_THROW(ex.transform_reduce(
                     "reduces host", n, 0u, [=](size_t i) { return h[i]; },
                     [](uint32_t a, uint32_t c) { return a + c; }),
                 std::runtime_error);
    // What a sealed child writes to device memory is the parent's.
    ex.launch("iota", n, [=](size_t i) { p[i] = uint32_t(i); });
    const std::vector<uint32_t> v = b.download();
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(v[i], i);
    const auto sum = [](uint64_t a, uint64_t c) { return a + c; };
    EXPECT_EQ(ex.transform_reduce("sum", n, uint64_t(5), [=](size_t i) { return uint64_t(p[i]); },
                                  sum),
              5 + n * (n - 1) / 2);
    DeviceBuffer<uint64_t, StrictExec> acc(ex, 1);
    uint64_t* a = acc.data();
    ex.launch("zero", 1, [=](size_t) { *a = 7; });
    ex.reduce_into("sum into", n, a, uint64_t(0), [=](size_t i) { return uint64_t(p[i]); }, sum);
    EXPECT_EQ(acc.get(0), 7 + n * (n - 1) / 2);
}

// The CUDA policy's sort of keys of more than one word (sort_pairs_by_word_pairs over CUB's
// 64-bit radix sort) with a host stable sort in CUB's place, which leaves its result in the
// alternate buffers every other pass, as CUB may: the CPU radix sort's order, keys and values.
TEST(StrictExec, WordPairSortGivesTheCpuOrder) {
    std::mt19937 g(11);
    for (int words : {2, 3, 6, 7})
        for (size_t n : {size_t(2), size_t(3), size_t(1000), size_t(4099)}) {
            std::vector<uint32_t> keys(n * words), values(n);
            for (size_t i = 0; i < n; ++i) {
                values[i] = uint32_t(i * 7 + 3);
                for (int w = 0; w < words; ++w) // few distinct words: many ties
                    keys[i * words + w] = w % 2 ? g() % 3 : (g() % 4) << 30 | g() % 2;
            }
            std::vector<uint32_t> cpu_keys = keys, cpu_values = values;
            radix_sort_pairs(cpu_keys.data(), words, cpu_values.data(), n);

            StrictExec ex;
            DeviceBuffer<uint32_t, StrictExec> dk(ex, keys.size()), dv(ex, n);
            dk.upload(keys.data(), keys.size()), dv.upload(values.data(), n);
            int passes = 0;
            wavefront::sort_pairs_by_word_pairs(
                ex, dk.data(), words, dv.data(), n,
                [&](uint64_t* k, uint64_t* k_alt, uint32_t* v, uint32_t* v_alt, size_t m,
                    int bits) {
                    const bool to_alt = passes++ % 2 == 0;
                    ex.launch("sort64", 1, [=](size_t) {
                        const uint64_t mask = bits == 64 ? ~uint64_t(0) : 0xffffffffu;
                        std::vector<uint32_t> idx(m);
                        std::iota(idx.begin(), idx.end(), 0u);
                        std::stable_sort(idx.begin(), idx.end(), [&](uint32_t a, uint32_t b) {
                            return (k[a] & mask) < (k[b] & mask);
                        });
                        std::vector<uint64_t> ks(m);
                        std::vector<uint32_t> vs(m);
                        for (size_t j = 0; j < m; ++j) ks[j] = k[idx[j]], vs[j] = v[idx[j]];
                        std::copy(ks.begin(), ks.end(), to_alt ? k_alt : k);
                        std::copy(vs.begin(), vs.end(), to_alt ? v_alt : v);
                    });
                    return to_alt;
                });
            EXPECT_EQ(passes, (words + 1) / 2);
            EXPECT_EQ(dk.download(), cpu_keys) << words << " words, n = " << n;
            EXPECT_EQ(dv.download(), cpu_values) << words << " words, n = " << n;
            EXPECT_TRUE(ex.violations().empty());
        }
}

Frame render_strict(const PreparedScene& scene, const RenderSettings& s, StrictExec& ex) {
    Frame f;
    wavefront::FramePipeline<StrictExec>(ex, scene, s, {}, f).run();
    return f;
}

void expect_strict_matches_cpu(const PreparedScene& scene, const std::string& name,
                               const SettingList& kv, int seal_runs = 0, int w = 24,
                               int h = 18) {
    const RenderSettings s = test::settings_for(scene, kv, w, h);
    const std::string what = test::label(name, kv);
    StrictExec ex;
    ex.seal_host(seal_runs);
    const Frame strict = render_strict(scene, s, ex);
    test::expect_same_frame(render_frame_cpu(scene, s), strict, what);
    EXPECT_TRUE(ex.violations().empty()) << what << ": " << ex.violations().front();
    EXPECT_EQ(ex.live_buffers(), 0u) << what;
}

const std::vector<SettingList>& strict_variants() {
    static const std::vector<SettingList> v = {
        {},
        {{"accel", "brute"}},
        {{"hash.mode", "hash192"}, {"sort.mode", "csd"}, {"ao.samples", "2"}},
        {{"hash.mode", "hash32"}, {"sort.algorithm", "bitonic"}, {"hierarchy.depth", "4"}},
        {{"cull.cluster", "3"}, {"aa.samples", "2"}, {"traversal.batch", "1024"}},
        {{"cull.cluster", "0"}, {"cull.objects", "false"}, {"hash.mode", "static1d"}},
    };
    return v;
}

TEST(StrictExec, BuiltinScenesMatchTheCpuRenderer) {
    for (const std::string& name : builtin_scene_names()) {
        const PreparedScene scene = prepare_scene(make_builtin_scene(name));
        for (const SettingList& kv : strict_variants()) expect_strict_matches_cpu(scene, name, kv);
    }
}

// A scene kept between frames (SceneKeep) stays in device memory, is bound by the next frame
// without a host access to it (the second frame sealed), and is freed by clear().
TEST(StrictExec, AKeptSceneServesTheNextFrame) {
    if (const char* why = wavefront::sealing_unavailable()) GTEST_SKIP() << why;
    const PreparedScene scene = prepare_scene(make_builtin_scene("office"));
    const RenderSettings s = test::settings_for(scene, {{"ao.samples", "2"}}, 24, 18);
    StrictExec ex;
    wavefront::SceneKeep<StrictExec> keep;
    const Frame cpu = render_frame_cpu(scene, s);
    for (int frame = 0; frame < 2; ++frame) {
        ex.seal_host(frame);
        Frame f;
        wavefront::FramePipeline<StrictExec>(ex, scene, s, {}, f, &keep).run();
        test::expect_same_frame(cpu, f, "frame " + std::to_string(frame));
        EXPECT_EQ(f.stats.get("device.scene_kept"), frame == 0 ? 0.0 : 1.0);
        EXPECT_TRUE(ex.violations().empty()) << ex.violations().front();
        EXPECT_GT(ex.live_buffers(), 0u) << "the kept scene";
    }
    keep.clear();
    EXPECT_EQ(ex.live_buffers(), 0u);
}

// Launches and reductions in a child process sealed from host memory: the first run of
// each launch site in a frame (a fork each: milliseconds), in small frames under two settings.
TEST(StrictExec, NoLaunchReadsHostMemory) {
    if (const char* why = wavefront::sealing_unavailable()) GTEST_SKIP() << why;
    std::vector<std::pair<std::string, Scene>> scenes = {{"glass", test::glass_mirror_scene()},
                                                         {"lights", test::lights_scene(false)},
                                                         {"csg", test::csg_scene()},
                                                         {"procedural", test::procedural_scene()},
                                                         {"photons", test::photon_scene()}};
    for (const std::string& name : builtin_scene_names())
        scenes.emplace_back(name, make_builtin_scene(name));
    for (const auto& [name, s] : scenes) {
        const PreparedScene scene = prepare_scene(s);
        for (const SettingList& kv :
             {SettingList{}, SettingList{{"hash.mode", "hash192"}, {"sort.mode", "csd"},
                                         {"ao.samples", "1"}, {"cull.cluster", "5"}}})
            expect_strict_matches_cpu(scene, name, kv, 1, 12, 10);
    }
}

TEST(StrictExec, TestScenesMatchTheCpuRenderer) {
    const std::pair<const char*, Scene> scenes[] = {
        {"glass", test::glass_mirror_scene()},
        {"lights", test::lights_scene(false)},
        {"ortho", test::lights_scene(true)},
        {"csg", test::csg_scene()},
        {"procedural", test::procedural_scene()},
    };
    for (const auto& [name, s] : scenes) {
        const PreparedScene scene = prepare_scene(s);
        for (const SettingList& kv : strict_variants()) expect_strict_matches_cpu(scene, name, kv);
    }
}

} // namespace
} // namespace sheaf

// The settings dictionary: canonical values, errors that name the key and what is allowed,
// and the resolution order explicit > scene > default.
#include "core/settings/settings.h"

#include "core/base/error.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace sheaf {
namespace {

// The message of the SettingsError that canonical_setting throws ("" when it does not).
std::string error_of(std::string_view key, std::string_view value) {
    try {
        canonical_setting(key, value);
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

TEST(Settings, CanonicalValues) {
    EXPECT_EQ(canonical_setting("cull.objects", "on"), "true");
    EXPECT_EQ(canonical_setting("cull.objects", "yes"), "true");
    EXPECT_EQ(canonical_setting("cull.objects", "1"), "true");
    EXPECT_EQ(canonical_setting("cull.objects", "true"), "true");
    EXPECT_EQ(canonical_setting("cull.objects", "off"), "false");
    EXPECT_EQ(canonical_setting("cull.objects", "no"), "false");
    EXPECT_EQ(canonical_setting("cull.objects", "0"), "false");
    EXPECT_EQ(canonical_setting("hierarchy.arity", "8"), "8");
    EXPECT_EQ(canonical_setting("hierarchy.arity", "08"), "8");
    EXPECT_EQ(canonical_setting("hierarchy.arity", "2"), "2");
    EXPECT_EQ(canonical_setting("hierarchy.arity", "64"), "64");
    EXPECT_EQ(canonical_setting("hierarchy.depth", "1"), "1");
    EXPECT_EQ(canonical_setting("trace.depth", "0"), "0");
    EXPECT_EQ(canonical_setting("traversal.batch", "1073741824"), "1073741824");
    EXPECT_EQ(canonical_setting("ao.distance", "0.5"), "0.5");
    EXPECT_EQ(canonical_setting("ao.distance", "1"), "1");
    EXPECT_EQ(canonical_setting("ao.distance", "2.50"), "2.5");
    EXPECT_EQ(canonical_setting("ao.distance", "1e3"), "1000");
    EXPECT_EQ(canonical_setting("hash.mode", "hash192"), "hash192");
    EXPECT_EQ(canonical_setting("accel", "rah"), "rah");
    EXPECT_EQ(canonical_setting("sort.mode", "full"), "full");
    EXPECT_EQ(canonical_setting("backend", "cpu"), "cpu");
}

TEST(Settings, EveryDefaultIsCanonicalAndAccepted) {
    std::set<std::string> keys;
    for (const SettingSpec& s : setting_specs()) {
        EXPECT_TRUE(keys.insert(s.key).second) << "duplicate key " << s.key;
        EXPECT_EQ(canonical_setting(s.key, s.default_value), s.default_value) << s.key;
        EXPECT_EQ(find_setting(s.key), &s);
        EXPECT_FALSE(s.help.empty()) << s.key;
        EXPECT_FALSE(describe_allowed(s).empty()) << s.key;
    }
    EXPECT_EQ(find_setting("no.such.key"), nullptr);
}

TEST(Settings, OutOfRangeIntegersNameKeyAndRange) {
    std::string m = error_of("hierarchy.arity", "1");
    EXPECT_TRUE(contains(m, "hierarchy.arity")) << m;
    EXPECT_TRUE(contains(m, "2..64")) << m;
    EXPECT_THROW(canonical_setting("hierarchy.arity", "65"), SettingsError);
    EXPECT_THROW(canonical_setting("hierarchy.arity", "-8"), SettingsError);
    m = error_of("hierarchy.depth", "0");
    EXPECT_TRUE(contains(m, "hierarchy.depth")) << m;
    EXPECT_TRUE(contains(m, "1..8")) << m;
    EXPECT_THROW(canonical_setting("width", "0"), SettingsError);
    EXPECT_THROW(canonical_setting("width", "16385"), SettingsError);
    EXPECT_THROW(canonical_setting("traversal.batch", "1073741825"), SettingsError);
    // Integers beyond long long are rejected, not wrapped.
    EXPECT_THROW(canonical_setting("threads", "99999999999999999999999"), SettingsError);
}

// The allowed range is printed exactly, also for bounds with more than 9 digits.
TEST(Settings, DescribeAllowedPrintsExactBounds) {
    EXPECT_EQ(describe_allowed(*find_setting("hierarchy.arity")), "an integer in 2..64");
    EXPECT_EQ(describe_allowed(*find_setting("traversal.batch")), "an integer in 0..1073741824");
    const std::string m = error_of("traversal.batch", "-5");
    EXPECT_TRUE(contains(m, "0..1073741824")) << m;
    EXPECT_EQ(describe_allowed(*find_setting("hash.mode")), "one of none, crsh, hash32, hash192, static1d, static3d");
}

TEST(Settings, RejectsMalformedValues) {
    for (const char* v : {"8x", "x8", "", " 8", "8 ", "+8", "8.0", "0x8", "8e0"})
        EXPECT_THROW(canonical_setting("hierarchy.arity", v), SettingsError) << "'" << v << "'";
    const std::string m = error_of("hierarchy.arity", "8x");
    EXPECT_TRUE(contains(m, "hierarchy.arity") && contains(m, "8x")) << m;
    for (const char* v : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "0.5x", "", "0,5", "0",
                          "-1", "1e-7", "1e31"})
        EXPECT_THROW(canonical_setting("ao.distance", v), SettingsError) << "'" << v << "'";
    for (const char* v : {"maybe", "TRUE", "On", "2", ""})
        EXPECT_THROW(canonical_setting("cull.objects", v), SettingsError) << "'" << v << "'";
}

TEST(Settings, UnknownChoicesListTheChoices) {
    const std::string m = error_of("hash.mode", "md5");
    EXPECT_TRUE(contains(m, "hash.mode")) << m;
    EXPECT_TRUE(contains(m, "none, crsh, hash32, hash192")) << m;
    EXPECT_THROW(canonical_setting("accel", "CRSH"), SettingsError); // case matters
    EXPECT_THROW(canonical_setting("backend", "gpu"), SettingsError);
}

TEST(Settings, PassListsAreSubsetsInCanonicalOrder) {
    EXPECT_EQ(canonical_setting("output.passes", "all"), "all");
    EXPECT_EQ(canonical_setting("output.passes", "depth, combined"), "combined,depth");
    EXPECT_EQ(canonical_setting("output.passes", "tests,tests"), "tests");
    EXPECT_EQ(canonical_setting("output.passes", "tests,object_id,albedo,normal,depth,combined"),
              "all");
    for (const char* bad : {"", ",", "combined,", "colour", "combined,,depth", "Combined"})
        EXPECT_THROW(canonical_setting("output.passes", bad), SettingsError) << "'" << bad << "'";
    const std::string m = error_of("output.passes", "combined,zdepth");
    EXPECT_TRUE(contains(m, "output.passes")) << m;
    EXPECT_TRUE(contains(m, "a comma-separated list of combined, depth, normal, albedo, "
                            "object_id, tests; or all"))
        << m;

    Settings s;
    EXPECT_EQ(RenderSettings::resolve(s).passes, uint32_t(kAllPasses));
    s.set("output.passes", "tests, combined");
    const RenderSettings r = RenderSettings::resolve(s);
    EXPECT_EQ(r.passes, uint32_t(kPassCombined | kPassTests));
    EXPECT_TRUE(r.keeps(kPassTests));
    EXPECT_FALSE(r.keeps(kPassDepth));
    EXPECT_EQ(RenderSettings::resolve({}, {{"output.passes", "normal"}}).passes,
              uint32_t(kPassNormal));
}

TEST(Settings, UnknownKeys) {
    const std::string m = error_of("hierarchy.arty", "8");
    EXPECT_TRUE(contains(m, "unknown setting")) << m;
    EXPECT_TRUE(contains(m, "hierarchy.arty")) << m;
    EXPECT_TRUE(contains(m, "hierarchy.arity")) << m; // the known keys are listed
    Settings s;
    EXPECT_THROW(s.set("nope", "1"), SettingsError);
    EXPECT_THROW(s.unset("nope"), SettingsError);
    EXPECT_THROW(s.get("nope"), SettingsError);
}

TEST(Settings, SetGetUnset) {
    Settings s;
    EXPECT_FALSE(s.has("hierarchy.arity"));
    EXPECT_EQ(s.get("hierarchy.arity"), "8"); // the default
    s.set("hierarchy.arity", "016");
    EXPECT_TRUE(s.has("hierarchy.arity"));
    EXPECT_EQ(s.get("hierarchy.arity"), "16"); // stored canonical
    s.set("cull.objects", "off");
    EXPECT_EQ(s.get("cull.objects"), "false");
    // A rejected value leaves the old one in place.
    EXPECT_THROW(s.set("hierarchy.arity", "1"), SettingsError);
    EXPECT_EQ(s.get("hierarchy.arity"), "16");
    s.unset("hierarchy.arity");
    EXPECT_FALSE(s.has("hierarchy.arity"));
    EXPECT_EQ(s.get("hierarchy.arity"), "8");
    s.unset("hierarchy.arity"); // unsetting twice is fine
    EXPECT_EQ(s.values().size(), 1u);
}

TEST(RenderSettings, Defaults) {
    const RenderSettings r = RenderSettings::resolve(Settings{});
    const RenderSettings d;
    EXPECT_EQ(r.accel, Accel::Bvh);
    EXPECT_EQ(r.hierarchy_depth, 2);
    EXPECT_EQ(r.hierarchy_arity, 8);
    EXPECT_EQ(r.hash, HashMode::Crsh);
    EXPECT_EQ(r.sort, SortMode::Csd);
    EXPECT_TRUE(r.cull_objects);
    EXPECT_EQ(r.trace_depth, 5);
    EXPECT_EQ(r.backend, Backend::Auto);
    EXPECT_EQ(r.width, 512);
    EXPECT_EQ(r.height, 512);
    EXPECT_EQ(r.aa_samples, 1);
    EXPECT_EQ(r.threads, 0);
    EXPECT_EQ(r.ao_samples, 0);
    EXPECT_EQ(r.ao_distance, 1.0f);
    EXPECT_EQ(r.batch_pairs, 0); // the backend's choice
    // The struct's own defaults agree with the dictionary's.
    EXPECT_EQ(r.accel, d.accel);
    EXPECT_EQ(r.hierarchy_depth, d.hierarchy_depth);
    EXPECT_EQ(r.hierarchy_arity, d.hierarchy_arity);
    EXPECT_EQ(r.hash, d.hash);
    EXPECT_EQ(r.sort, d.sort);
    EXPECT_EQ(r.cull_objects, d.cull_objects);
    EXPECT_EQ(r.trace_depth, d.trace_depth);
    EXPECT_EQ(r.backend, d.backend);
    EXPECT_EQ(r.width, d.width);
    EXPECT_EQ(r.height, d.height);
    EXPECT_EQ(r.aa_samples, d.aa_samples);
    EXPECT_EQ(r.threads, d.threads);
    EXPECT_EQ(r.ao_samples, d.ao_samples);
    EXPECT_EQ(r.ao_distance, d.ao_distance);
    EXPECT_EQ(r.batch_pairs, d.batch_pairs);
}

// traversal.batch 0 is the backend's choice: the CPU's 4M pairs, or sized to a device's memory.
TEST(RenderSettings, BatchPairsFollowTheBackendWhenZero) {
    RenderSettings r;
    EXPECT_EQ(r.batch_or(kCpuBatchPairs), size_t(4194304));
    r.batch_pairs = 65536;
    EXPECT_EQ(r.batch_or(kCpuBatchPairs), size_t(65536));
    const uint64_t GiB = uint64_t(1) << 30;
    EXPECT_EQ(device_batch_pairs(141 * GiB), size_t(1) << 26); // H200: 64M, the cap
    EXPECT_EQ(device_batch_pairs(80 * GiB), size_t(1) << 26);  // H100
    EXPECT_EQ(device_batch_pairs(24 * GiB), size_t(1) << 24);  // 24 GiB / 1024 = 24M: 16M
    EXPECT_EQ(device_batch_pairs(8 * GiB), size_t(1) << 23);
    EXPECT_EQ(device_batch_pairs(4 * GiB), size_t(1) << 22);
    EXPECT_EQ(device_batch_pairs(1 * GiB), size_t(1) << 22); // never below the CPU's
    EXPECT_EQ(device_batch_pairs(0), size_t(1) << 22);
}

// Found by the C ABI fuzzer: a subnormal is in radiosity.brightness's range, and std::stof
// threw std::out_of_range on its canonical text.
TEST(RenderSettings, ResolvesSubnormalFloats) {
    Settings s;
    s.set("radiosity.brightness", "1e-45");
    const RenderSettings r = RenderSettings::resolve(s, {});
    EXPECT_GE(r.radiosity_brightness, 0.0f);
    EXPECT_LT(r.radiosity_brightness, 1e-37f);
}

TEST(RenderSettings, ExplicitBeatsSceneBeatsDefault) {
    Settings s;
    s.set("hierarchy.arity", "16");
    s.set("hash.mode", "hash32");
    const std::map<std::string, std::string> scene = {
        {"hierarchy.arity", "4"}, {"hierarchy.depth", "3"}, {"cull.objects", "off"},
        {"hash.mode", "none"},    {"ao.distance", "2.5"},   {"accel", "rah"}};
    const RenderSettings r = RenderSettings::resolve(s, scene);
    EXPECT_EQ(r.hierarchy_arity, 16);    // explicit beats scene
    EXPECT_EQ(r.hash, HashMode::Hash32); // explicit beats scene
    EXPECT_EQ(r.hierarchy_depth, 3);     // scene beats default
    EXPECT_FALSE(r.cull_objects);        // scene, canonicalised
    EXPECT_EQ(r.ao_distance, 2.5f);      // scene
    EXPECT_EQ(r.accel, Accel::Rah);      // scene
    EXPECT_EQ(r.sort, SortMode::Csd);    // default
    EXPECT_EQ(r.width, 512);             // default

    const auto eff = RenderSettings::effective(s, scene);
    ASSERT_EQ(eff.size(), setting_specs().size());
    for (size_t i = 0; i < eff.size(); ++i) EXPECT_EQ(eff[i].first, setting_specs()[i].key);
    const std::map<std::string, std::string> by_key(eff.begin(), eff.end());
    EXPECT_EQ(by_key.at("hierarchy.arity"), "16");
    EXPECT_EQ(by_key.at("cull.objects"), "false");
    EXPECT_EQ(by_key.at("sort.mode"), "csd");

    // Every enum value resolves.
    for (const char* a : {"brute", "rah", "crsh"}) {
        Settings x;
        x.set("accel", a);
        EXPECT_STREQ(to_string(RenderSettings::resolve(x).accel), a);
    }
    for (const char* h : {"none", "crsh", "hash32", "hash192"}) {
        Settings x;
        x.set("hash.mode", h);
        EXPECT_STREQ(to_string(RenderSettings::resolve(x).hash), h);
    }
    for (const char* o : {"none", "full", "csd"}) {
        Settings x;
        x.set("sort.mode", o);
        EXPECT_STREQ(to_string(RenderSettings::resolve(x).sort), o);
    }
    for (const char* b : {"auto", "cpu", "cuda"}) {
        Settings x;
        x.set("backend", b);
        EXPECT_STREQ(to_string(RenderSettings::resolve(x).backend), b);
    }
}

TEST(RenderSettings, BadSceneValuesAreSceneErrors) {
    const Settings none;
    EXPECT_THROW(RenderSettings::resolve(none, {{"hierarchy.arity", "1"}}), SceneError);
    EXPECT_THROW(RenderSettings::resolve(none, {{"hash.mode", "md5"}}), SceneError);
    EXPECT_THROW(RenderSettings::resolve(none, {{"ao.distance", "nan"}}), SceneError);
    EXPECT_THROW(RenderSettings::resolve(none, {{"no.such.key", "1"}}), SceneError);
    try {
        RenderSettings::resolve(none, {{"hierarchy.arity", "1"}});
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string m = e.what();
        EXPECT_TRUE(contains(m, "hierarchy.arity") && contains(m, "2..64")) << m;
    }
    // An explicit value overrides a bad scene value for the same key: it is never read.
    Settings s;
    s.set("hierarchy.arity", "8");
    EXPECT_EQ(RenderSettings::resolve(s, {{"hierarchy.arity", "1"}}).hierarchy_arity, 8);
}

} // namespace
} // namespace sheaf

// Ray hash keys: ranges, the fixed TRANSLATE of paper 003, and locality of the Morton orders.
#include "core/hash/ray_hash.h"

#include <gtest/gtest.h>

#include <random>

namespace sheaf {
namespace {

Vec3 random_dir(std::mt19937& g) {
    std::normal_distribution<float> n;
    return normalize(Vec3(n(g), n(g), n(g)));
}

TEST(RayHash, TranslateMapsTheBoxMinimumToZero) {
    // Paper 003's Algorithm 1 subtracts aabb_max (a slip): the minimum must map to 0.
    const Aabb box{Vec3(-2, 1, 4), Vec3(2, 3, 8)};
    const Vec3 lo = translate_to_unit(box, box.lo), hi = translate_to_unit(box, box.hi);
    EXPECT_EQ(lo, Vec3(0, 0, 0));
    EXPECT_EQ(hi, Vec3(1, 1, 1));
    const Vec3 mid = translate_to_unit(box, Vec3(0, 2, 6));
    EXPECT_FLOAT_EQ(mid.x, 0.5f);
    EXPECT_FLOAT_EQ(mid.y, 0.5f);
    EXPECT_FLOAT_EQ(mid.z, 0.5f);
}

TEST(RayHash, QuantizeStaysInRange) {
    for (int bits : {1, 4, 8, 21, 24})
        for (float v : {-1.0f, 0.0f, 0.3f, 0.999999f, 1.0f, 2.0f})
            EXPECT_LT(quantize(v, bits), 1u << bits);
    EXPECT_EQ(quantize(0.0f, 8), 0u);
    EXPECT_EQ(quantize(1.0f, 8), 255u);
}

TEST(RayHash, MortonInterleavesBits) {
    EXPECT_EQ(morton3(1, 0, 0), 1u);
    EXPECT_EQ(morton3(0, 1, 0), 2u);
    EXPECT_EQ(morton3(0, 0, 1), 4u);
    EXPECT_EQ(morton3(3, 0, 0), 9u);
    EXPECT_EQ(morton2(1, 0), 2u);
    EXPECT_EQ(morton2(0, 1), 1u);
    EXPECT_EQ(morton2(0xFFFF, 0xFFFF), 0xFFFFFFFFu);
}

TEST(RayHash, ShadowKeyPutsTheLightInTheHighBits) {
    std::mt19937 g(1);
    const int lb = light_bits(5);
    EXPECT_EQ(lb, 3);
    EXPECT_EQ(light_bits(1), 0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 d = random_dir(g);
        const uint32_t l = uint32_t(i % 5);
        EXPECT_EQ(crsh_shadow_key(l, lb, d) >> (32 - lb), l);
    }
    // Every ray of light 2 sorts after every ray of light 1.
    EXPECT_LT(crsh_shadow_key(1, lb, Vec3(0, 0, -1)), crsh_shadow_key(2, lb, Vec3(0, 0, 1)));
}

TEST(RayHash, NearbyDirectionsShareHighBits) {
    // Locality: tiny perturbations rarely change the top bits of the key.
    std::mt19937 g(2);
    int same = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 d = random_dir(g);
        const Vec3 e = normalize(d + Vec3(1e-4f, -1e-4f, 1e-4f));
        same += (crsh_shadow_key(0, 0, d) >> 20) == (crsh_shadow_key(0, 0, e) >> 20);
    }
    EXPECT_GT(same, 900);
}

TEST(RayHash, SecondaryKeyUsesOriginAndDirection) {
    const Aabb box{Vec3(0.0f), Vec3(1.0f)};
    const Vec3 d(0, 0, 1);
    EXPECT_NE(crsh_secondary_key(box, Vec3(0.1f, 0.1f, 0.1f), d),
              crsh_secondary_key(box, Vec3(0.9f, 0.9f, 0.9f), d));
    EXPECT_NE(crsh_secondary_key(box, Vec3(0.5f), Vec3(0, 0, 1)),
              crsh_secondary_key(box, Vec3(0.5f), Vec3(1, 0, 0)));
    EXPECT_LT(crsh_secondary_key(box, Vec3(0.9f), d), 1u << 30); // 30 bits used
}

TEST(RayHash, Hash32LayoutFollowsAlgorithm1) {
    const Aabb box{Vec3(0.0f), Vec3(1.0f)};
    // Origin in the low 24 bits: the same direction from the box minimum gives 0 there.
    const uint32_t k = hash32_key(box, Vec3(0.0f), Vec3(0, 0, 1));
    EXPECT_EQ(k & 0xFFFFFFu, 0u);
    // The top 8 bits depend on the direction only.
    EXPECT_EQ(hash32_key(box, Vec3(0.3f), Vec3(0, 1, 0)) >> 24,
              hash32_key(box, Vec3(0.7f), Vec3(0, 1, 0)) >> 24);
    EXPECT_NE(hash32_key(box, Vec3(0.3f), Vec3(0, 1, 0)) >> 24,
              hash32_key(box, Vec3(0.3f), Vec3(0, -1, 0)) >> 24);
}

TEST(RayHash, Hash192InterleavesSixComponents) {
    const Aabb box{Vec3(0.0f), Vec3(1.0f)};
    uint32_t a[6], b[6];
    hash192_key(box, Vec3(0.0f), Vec3(-1, -1, -1), a);
    for (uint32_t w : a) EXPECT_EQ(w, 0u);
    // The most significant bit of origin x is bit 23 of its 24-bit value: position 0 + 6 * 23.
    hash192_key(box, Vec3(0.5f, 0, 0), Vec3(-1, -1, -1), b);
    EXPECT_EQ(b[(6 * 23) / 32], 1u << ((6 * 23) % 32));
    // Direction z's top bit (bit 20 of 21): position 5 + 6 * 20.
    hash192_key(box, Vec3(0.0f), Vec3(-1, -1, 0.0f), b);
    EXPECT_EQ(b[(5 + 6 * 20) / 32], 1u << ((5 + 6 * 20) % 32));
}

} // namespace
} // namespace sheaf

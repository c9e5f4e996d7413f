// Two frames of one scene under different accel modes: the same image and primary passes,
// value for value (their statistics differ: each mode counts its own tests).
#pragma once

#include "core/frame/frame.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace sheaf::test {

inline void expect_same_image(const Frame& a, const Frame& b, const std::string& what) {
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() &&
               (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    EXPECT_TRUE(same(a.rgba, b.rgba)) << what << ": image";
    EXPECT_TRUE(same(a.depth, b.depth)) << what << ": depth";
    EXPECT_TRUE(same(a.normal, b.normal)) << what << ": normal";
    EXPECT_TRUE(same(a.albedo, b.albedo)) << what << ": albedo";
    EXPECT_TRUE(same(a.object_id, b.object_id)) << what << ": object ids";
}

} // namespace sheaf::test

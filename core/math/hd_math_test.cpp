// The shared transcendental functions against the C library: within an ulp or two of
// float (the C library's own float functions are not correctly rounded either), the C
// library's special cases, and the double versions to about 1e-15 relative.
#include "core/math/hd_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace sheaf {
namespace {

// Distance in representable floats (ulps), for finite values of one sign.
int64_t ulps(float a, float b) {
    if (a == b) return 0;
    int32_t ia, ib;
    std::memcpy(&ia, &a, 4), std::memcpy(&ib, &b, 4);
    if (ia < 0) ia = int32_t(0x80000000u) - ia;
    if (ib < 0) ib = int32_t(0x80000000u) - ib;
    return std::llabs(int64_t(ia) - int64_t(ib));
}

// Within `max_ulps` of the double-precision C library result rounded to float, or within an
// absolute `floor` (results near zero of functions like sin at multiples of pi).
template <class F, class G>
void expect_close(const char* name, F ours, G reference, float x, int max_ulps = 1,
                  double floor = 1e-7) {
    const float got = ours(x);
    const double want = reference(double(x));
    if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << name << "(" << x << ") = " << got;
        return;
    }
    if (std::fabs(double(got) - want) <= floor) return;
    EXPECT_LE(ulps(got, float(want)), max_ulps)
        << name << "(" << x << ") = " << got << ", the C library: " << want;
}

TEST(HdMath, SinCosTanAcrossTheirRange) {
    std::mt19937 g(11);
    std::uniform_real_distribution<float> small(-10.0f, 10.0f), big(-1e5f, 1e5f);
    for (int i = 0; i < 200000; ++i) {
        const float x = i % 4 == 0 ? big(g) : small(g);
        expect_close(
            "sin", hdm::sinf, [](double v) { return std::sin(v); }, x);
        expect_close(
            "cos", hdm::cosf, [](double v) { return std::cos(v); }, x);
        expect_close(
            "tan", hdm::tanf, [](double v) { return std::tan(v); }, x, 2);
        if (testing::Test::HasFailure()) return;
    }
    EXPECT_EQ(hdm::sinf(0.0f), 0.0f);
    EXPECT_EQ(hdm::cosf(0.0f), 1.0f);
    EXPECT_TRUE(std::isnan(hdm::sinf(std::numeric_limits<float>::infinity())));
    EXPECT_TRUE(std::isnan(hdm::cosf(std::numeric_limits<float>::quiet_NaN())));
    // Huge arguments stay finite and bounded (reduced with fmod).
    const float huge = hdm::sinf(3e30f);
    EXPECT_TRUE(huge >= -1.0f && huge <= 1.0f);
}

TEST(HdMath, InverseTrigonometry) {
    std::mt19937 g(12);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), wide(-100.0f, 100.0f);
    for (int i = 0; i < 200000; ++i) {
        const float u = unit(g), y = wide(g), x = i % 3 ? wide(g) : unit(g);
        expect_close(
            "asin", hdm::asinf, [](double v) { return std::asin(v); }, u);
        expect_close(
            "acos", hdm::acosf, [](double v) { return std::acos(v); }, u);
        const float got = hdm::atan2f(y, x);
        EXPECT_LE(ulps(got, float(std::atan2(double(y), double(x)))), 1) << y << ", " << x;
        if (testing::Test::HasFailure()) return;
    }
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(hdm::acosf(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(hdm::acosf(-1.0f), 3.14159265f);
    EXPECT_TRUE(std::isnan(hdm::asinf(1.5f)));
    for (float y : {0.0f, -0.0f, 1.0f, -1.0f, inf, -inf})
        for (float x : {0.0f, -0.0f, 1.0f, -1.0f, inf, -inf}) {
            const float want = std::atan2(y, x), got = hdm::atan2f(y, x);
            EXPECT_EQ(want, got) << "atan2(" << y << ", " << x << ")";
            EXPECT_EQ(std::signbit(want), std::signbit(got)) << "atan2(" << y << ", " << x << ")";
        }
}

// The host's ldexp and frexp from bits give the library's own results, subnormals included.
TEST(HdMath, LdexpAndFrexpFromBitsAreTheLibrarys) {
    std::mt19937 g(17);
    std::uniform_real_distribution<double> unit(0.5, 2.0);
    std::uniform_int_distribution<int> power(-1100, 1100);
    for (int i = 0; i < 200000; ++i) {
        const double p = unit(g);
        const int k = power(g);
        const double got = hdm::detail::ldexp_unit(p, k), want = std::ldexp(p, k);
        ASSERT_TRUE(got == want || (std::isnan(got) && std::isnan(want))) << p << " " << k;
    }
    std::uniform_real_distribution<double> exponent(-1070, 1020);
    for (int i = 0; i < 200000; ++i) {
        const double x = std::exp2(exponent(g)) * unit(g);
        int e1 = 0, e2 = 0;
        const double m1 = hdm::detail::frexp_positive(x, &e1), m2 = std::frexp(x, &e2);
        ASSERT_EQ(m1, m2) << x;
        ASSERT_EQ(e1, e2) << x;
    }
    for (double x : {4.9e-324, 2.2250738585072014e-308, 2.2250738585072009e-308, 1.0, 0.5,
                     1.7976931348623157e308}) {
        int e1 = 0, e2 = 0;
        EXPECT_EQ(hdm::detail::frexp_positive(x, &e1), std::frexp(x, &e2)) << x;
        EXPECT_EQ(e1, e2) << x;
    }
}

TEST(HdMath, ExpLogPow) {
    std::mt19937 g(13);
    std::uniform_real_distribution<float> e(-80.0f, 80.0f), base(0.0f, 4.0f), power(-40.0f, 40.0f);
    for (int i = 0; i < 200000; ++i) {
        expect_close(
            "exp", hdm::expf, [](double v) { return std::exp(v); }, e(g), 1, 0);
        const float b = base(g), p = power(g);
        const float got = hdm::powf(b, p), want = float(std::pow(double(b), double(p)));
        if (std::isfinite(want) && want > 1e-37f) EXPECT_LE(ulps(got, want), 1) << b << "^" << p;
        if (testing::Test::HasFailure()) return;
    }
    for (double x : {1e-300, 1e-10, 0.1, 0.5, 0.75, 1.0, 1.5, 2.0, 1e10, 1e300}) {
        EXPECT_NEAR(hdm::log2(x), std::log2(x), 1e-15 * std::fabs(std::log2(x)) + 1e-16) << x;
        EXPECT_NEAR(hdm::log(x), std::log(x), 1e-15 * std::fabs(std::log(x)) + 1e-16) << x;
    }
    for (double x : {-1000.0, -256.0, -1.0, -1e-5, 0.0, 0.5, 3.0, 700.0})
        EXPECT_NEAR(hdm::exp2(x), std::exp2(x), 1e-14 * std::exp2(x)) << x;
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(hdm::powf(0.0f, 2.0f), 0.0f);
    EXPECT_EQ(hdm::powf(0.0f, 0.0f), 1.0f);
    EXPECT_EQ(hdm::powf(0.0f, -1.0f), inf);
    EXPECT_EQ(hdm::powf(-2.0f, 3.0f), -8.0f);
    EXPECT_EQ(hdm::powf(-2.0f, 2.0f), 4.0f);
    EXPECT_TRUE(std::isnan(hdm::powf(-2.0f, 0.5f)));
    EXPECT_EQ(hdm::powf(2.0f, 10.0f), 1024.0f);
    EXPECT_EQ(hdm::expf(0.0f), 1.0f);
    EXPECT_EQ(hdm::expf(-inf), 0.0f);
    EXPECT_EQ(hdm::expf(inf), inf);
    EXPECT_EQ(hdm::log(0.0), -double(inf));
    EXPECT_TRUE(std::isnan(hdm::log(-1.0)));
}

} // namespace
} // namespace sheaf

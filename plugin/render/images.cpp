// Exact image comparison, difference images and test-count heat maps.
#include "images.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace render {

namespace {

struct Rgb {
    float r, g, b;
};

// An inferno-like colour map, evenly spaced stops.
constexpr Rgb kStops[] = {{0.00f, 0.00f, 0.02f},
                          {0.34f, 0.06f, 0.43f},
                          {0.74f, 0.22f, 0.33f},
                          {0.98f, 0.56f, 0.04f},
                          {0.99f, 1.00f, 0.64f}};
constexpr int kStopCount = int(sizeof kStops / sizeof kStops[0]);

Rgb colour_map(double v) {
    v = std::clamp(v, 0.0, 1.0) * (kStopCount - 1);
    const int i = std::min(int(v), kStopCount - 2);
    const float f = float(v - i);
    const Rgb &a = kStops[i], &b = kStops[i + 1];
    return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

} // namespace

ImageDiff compare_images(const RunResult& a, const RunResult& b, size_t keep) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) {
        d.size_differs = true;
        return d;
    }
    const size_t pixels = a.rgba.size() / 4;
    for (size_t p = 0; p < pixels; ++p) {
        const float* x = &a.rgba[p * 4];
        const float* y = &b.rgba[p * 4];
        if (std::memcmp(x, y, 4 * sizeof(float)) == 0) continue;
        ++d.count;
        for (int c = 0; c < 4; ++c) {
            const double diff = std::fabs(double(x[c]) - double(y[c]));
            if (std::isnan(diff))
                d.max_diff = diff;
            else if (!std::isnan(d.max_diff))
                d.max_diff = std::max(d.max_diff, diff);
        }
        if (d.first.size() < keep)
            d.first.emplace_back(int(p % size_t(a.width)), int(p / size_t(a.width)));
    }
    return d;
}

std::string describe(const ImageDiff& d, const RunResult& a, const RunResult& b) {
    if (d.size_differs)
        return b.name + ": image size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
               " differs from " + a.name + "'s " + std::to_string(a.width) + "x" +
               std::to_string(a.height);
    char max[64];
    std::snprintf(max, sizeof max, "%.6g", d.max_diff);
    std::string out = b.name + ": " + std::to_string(d.count) + " pixel" +
                      (d.count == 1 ? "" : "s") + " differ from " + a.name + " (max difference " +
                      max + ") at";
    for (const auto& [x, y] : d.first)
        out += " (" + std::to_string(x) + "," + std::to_string(y) + ")";
    if (d.count > d.first.size()) out += " ...";
    return out;
}

std::vector<float> difference_image(const RunResult& a, const RunResult& b, float gain) {
    const size_t pixels = size_t(b.width) * size_t(b.height);
    std::vector<float> out(pixels * 3, 0.0f);
    if (a.rgba.size() != b.rgba.size()) return out;
    for (size_t p = 0; p < pixels; ++p) {
        const float* x = &a.rgba[p * 4];
        const float* y = &b.rgba[p * 4];
        if (std::memcmp(x, y, 4 * sizeof(float)) == 0) continue;
        float diff = 0.0f;
        for (int c = 0; c < 4; ++c) {
            const float d = std::fabs(x[c] - y[c]);
            diff = std::isnan(d) ? 1.0f : std::max(diff, d);
        }
        out[p * 3] = std::clamp(diff * gain, 0.25f, 1.0f);
    }
    return out;
}

std::vector<float> heat_map(const std::vector<float>& tests, double min_tests, double max_tests) {
    std::vector<float> out(tests.size() * 3, 0.0f);
    const double lo = std::log(std::max(min_tests, 1.0));
    const double range = std::log(std::max(max_tests, 1.0)) - lo;
    for (size_t p = 0; p < tests.size(); ++p) {
        if (!(tests[p] > 0)) continue; // black: no tests
        const double v = range > 0 ? (std::log(double(tests[p])) - lo) / range : 1.0;
        const Rgb c = colour_map(0.08 + 0.92 * v);
        out[p * 3] = c.r;
        out[p * 3 + 1] = c.g;
        out[p * 3 + 2] = c.b;
    }
    return out;
}

std::string heat_colour(double v) {
    const Rgb c = colour_map(v);
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(c.r * 255)),
                  int(std::lround(c.g * 255)), int(std::lround(c.b * 255)));
    return buf;
}

} // namespace render

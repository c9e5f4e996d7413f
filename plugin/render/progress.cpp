// The progress bar: "[#####-----]  42%  crsh (2/3)  0:12 left" redrawn in place on stderr.
#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace render {

namespace {

constexpr int kBarWidth = 30;

std::string format_seconds(double s) {
    char buf[32];
    const long total = std::lround(std::max(0.0, s));
    std::snprintf(buf, sizeof buf, "%ld:%02ld", total / 60, total % 60);
    return buf;
}

} // namespace

Progress::Progress(bool enabled, int runs)
    : enabled_(enabled), runs_(std::max(runs, 1)), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
    clear();
}

bool Progress::wanted(bool quiet) {
    return !quiet && isatty(STDERR_FILENO);
}

void Progress::start_run(SheafRenderer renderer, int index, const std::string& label) {
    index_ = index;
    label_ = runs_ > 1
                 ? label + " (" + std::to_string(index + 1) + "/" + std::to_string(runs_) + ")"
                 : label;
    if (!enabled_) return;
    sheafRendererSetProgressCallback(renderer, &Progress::callback, this);
    draw(0.0f, true);
}

void Progress::finish_run(SheafRenderer renderer) {
    if (!enabled_) return;
    sheafRendererSetProgressCallback(renderer, nullptr, nullptr);
    draw(1.0f, true);
    if (index_ + 1 >= runs_) clear();
}

int Progress::callback(void* user, float done) {
    static_cast<Progress*>(user)->draw(done, false);
    return 1;
}

void Progress::draw(float done, bool force) {
    const auto now = std::chrono::steady_clock::now();
    if (!force && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    const double overall =
        std::clamp((index_ + double(std::clamp(done, 0.0f, 1.0f))) / runs_, 0.0, 1.0);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::string left = "--:-- left";
    if (overall >= 1.0)
        left = "0:00 left";
    else if (overall > 0.02 && elapsed > 0.2)
        left = format_seconds(elapsed * (1.0 - overall) / overall) + " left";
    const int filled = int(std::lround(overall * kBarWidth));
    std::string bar(size_t(filled), '#');
    bar.append(size_t(kBarWidth - filled), '-');
    std::fprintf(stderr, "\r\033[K[%s] %3d%%  %s  %s", bar.c_str(), int(std::lround(overall * 100)),
                 label_.c_str(), left.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::clear() {
    if (!enabled_ || !drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
}

} // namespace render

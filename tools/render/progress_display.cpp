#include "tools/render/progress_display.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace wt {

namespace {

constexpr double redraw_seconds = 0.25;

std::string clock_time(double seconds) {
    const long s = long(std::lround(std::max(0.0, seconds)));
    char text[32];
    if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

std::string rate(double per_second) {
    char text[32];
    if (per_second >= 1e6) std::snprintf(text, sizeof text, "%.2f M", per_second / 1e6);
    else if (per_second >= 1e3) std::snprintf(text, sizeof text, "%.1f k", per_second / 1e3);
    else std::snprintf(text, sizeof text, "%.0f ", per_second);
    return text;
}

}  // namespace

ProgressStyle progress_style_for_stderr(bool quiet) {
    if (quiet) return ProgressStyle::off;
    return isatty(STDERR_FILENO) ? ProgressStyle::terminal : ProgressStyle::log;
}

ProgressDisplay::ProgressDisplay(ProgressStyle style, uint64_t pixels, uint32_t first_spp, uint32_t target_spp,
                                 double time_limit)
    : style_(style), total_samples_(pixels * (target_spp - first_spp)), target_spp_(target_spp), time_limit_(time_limit),
      start_(std::chrono::steady_clock::now()), film_spp_(first_spp) {}

double ProgressDisplay::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string ProgressDisplay::line(uint32_t film_spp) const {
    const double t = elapsed();
    const double done = double(done_.load());
    const double fraction = total_samples_ ? std::min(1.0, done / double(total_samples_)) : 1.0;
    const double per_second = t > 0.0 ? done / t : 0.0;
    double left = per_second > 0.0 ? (double(total_samples_) - done) / per_second : 0.0;
    if (time_limit_ > 0.0) left = std::min(left, std::max(0.0, time_limit_ - t));
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(1);
    s << 100.0 * fraction << "% | " << film_spp << "/" << target_spp_ << " spp | " << rate(per_second) << "samples/s | "
      << clock_time(t) << " elapsed | " << (per_second > 0.0 ? clock_time(left) : std::string("?")) << " left";
    return s.str();
}

void ProgressDisplay::samples_done(uint64_t samples) {
    done_ += samples;
    if (style_ != ProgressStyle::terminal) return;
    const double t = elapsed();
    double last = last_draw_.load();
    if (t - last < redraw_seconds || !last_draw_.compare_exchange_strong(last, t)) return;
    std::lock_guard<std::mutex> lock(draw_);
    std::fprintf(stderr, "\r%s\033[K", line(film_spp_.load()).c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressDisplay::pass_done(const PassReport& report) {
    film_spp_ = report.film_spp;
    if (style_ == ProgressStyle::off) return;
    std::lock_guard<std::mutex> lock(draw_);
    if (style_ == ProgressStyle::terminal) {
        std::fprintf(stderr, "\r%s\033[K", line(report.film_spp).c_str());
        drawn_ = true;
    } else {
        std::fprintf(stderr, "wavetrace: pass %u done: %s\n", report.pass + 1, line(report.film_spp).c_str());
    }
    std::fflush(stderr);
}

void ProgressDisplay::finish() {
    std::lock_guard<std::mutex> lock(draw_);
    if (style_ == ProgressStyle::terminal && drawn_) std::fputc('\n', stderr);
    drawn_ = false;
}

}  // namespace wt

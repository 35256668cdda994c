#include "core/camera/pixel_filter.h"

#include <algorithm>
#include <cmath>

namespace wt {

namespace {

// The filter's profile along one axis at offset d from the centre, |d| < r, up to a constant.
double profile(FilterKind kind, double d, double r) {
    if (kind == FilterKind::gaussian) {
        // sigma = width / 6 puts the edge at 3 sigma; subtracting the edge value makes the filter
        // go to zero there instead of stopping at a step (pbrt-v4's GaussianFilter).
        const double sigma = r / 3.0;
        const auto g = [&](double x) { return std::exp(-x * x / (2.0 * sigma * sigma)); };
        return std::max(0.0, g(d) - g(r));
    }
    if (kind == FilterKind::mitchell) {
        // Mitchell & Netravali 1988, "Reconstruction Filters in Computer Graphics", eq. 8, with
        // B = C = 1/3 (their recommendation): a cubic over |x| < 2, here stretched over |d| < r.
        constexpr double B = 1.0 / 3.0, C = 1.0 / 3.0;
        const double x = std::fabs(2.0 * d / r);
        if (x < 1.0) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6.0;
        return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6.0;
    }
    // Blackman-Harris, four terms (Harris 1978): t in [0, 1] across the support.
    const double t = (d + r) / (2.0 * r), tau = 2.0 * 3.14159265358979323846 * t;
    return 0.35875 - 0.48829 * std::cos(tau) + 0.14128 * std::cos(2.0 * tau) - 0.01168 * std::cos(3.0 * tau);
}

}  // namespace

float default_filter_width(FilterKind kind) {
    if (kind == FilterKind::box) return 1.0f;
    return kind == FilterKind::mitchell ? 4.0f : 1.5f;
}

const char* name_of(FilterKind k) {
    switch (k) {
        case FilterKind::box: return "box";
        case FilterKind::gaussian: return "gaussian";
        case FilterKind::blackman_harris: return "blackman_harris";
        case FilterKind::mitchell: return "mitchell";
    }
    return "?";
}

std::optional<FilterKind> parse_filter_kind(const std::string& s) {
    for (FilterKind k : {FilterKind::box, FilterKind::gaussian, FilterKind::blackman_harris, FilterKind::mitchell})
        if (s == name_of(k)) return k;
    return std::nullopt;
}

PixelFilter::PixelFilter(const PixelFilterSettings& settings) : width_(settings.width), shift_(0.5f - 0.5f * settings.width) {
    if (settings.kind == FilterKind::box) return;
    tabulated_ = true;
    const double r = 0.5 * double(settings.width), bin = 2.0 * r / kBins;
    bin_width_ = float(bin);
    std::array<double, kBins> values{};
    double total = 0.0, total_abs = 0.0;
    for (int i = 0; i < kBins; ++i) {
        values[i] = profile(settings.kind, -r + (i + 0.5) * bin, r);
        total += values[i];
        total_abs += std::fabs(values[i]);
    }
    // Exactly 1 for a non-negative filter, so its samples' weights multiply nothing.
    abs_over_signed_ = float(total_abs / total);
    double cumulative = 0.0;
    for (int i = 0; i < kBins; ++i) {
        density_[i] = float(std::fabs(values[i]) / (total_abs * bin));
        weight_[i] = values[i] < 0.0 ? -abs_over_signed_ : abs_over_signed_;
        cdf_[i] = float(cumulative / total_abs);
        cumulative += std::fabs(values[i]);
    }
    cdf_[kBins] = 1.0f;
}

PixelFilter::AxisSample PixelFilter::sample_axis(float u) const {
    // The last bin whose cdf is <= u; u < 1, so it is below kBins.
    const int i = int(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()) - 1;
    const float span = cdf_[i + 1] - cdf_[i];
    const float within = span > 0.0f ? std::min((u - cdf_[i]) / span, 0x1.fffffep-1f) : 0.5f;
    return {(float(i) + within) * bin_width_ - radius(), weight_[i]};
}

float PixelFilter::density(float d) const {
    const float r = radius();
    if (!(d >= -r && d < r)) return 0.0f;
    if (!tabulated_) return 1.0f / width_;
    return density_[bin_of(d)];
}

float PixelFilter::value(float d) const {
    const float r = radius();
    if (!(d >= -r && d < r)) return 0.0f;
    if (!tabulated_) return 1.0f / width_;
    return density_[bin_of(d)] * weight_[bin_of(d)];
}

PixelFilter::AxisChoice PixelFilter::choose_pixel(float x, float u) const {
    // Pixel P's centre is P + 0.5 and its samples' offsets lie in [-r, r): the candidates are the
    // P with x - r < P + 0.5 <= x + r.
    const float r = radius();
    const int first = int(std::floor(x - r - 0.5f)) + 1, last = int(std::floor(x + r - 0.5f));
    float sum = 0.0f;
    for (int p = first; p <= last; ++p) sum += density(x - (float(p) + 0.5f));
    const float target = u * sum;
    float running = 0.0f;
    int chosen = last;
    for (int p = first; p <= last; ++p) {
        running += density(x - (float(p) + 0.5f));
        if (target < running) {
            chosen = p;
            break;
        }
    }
    if (!has_negative_lobes()) return {chosen, sum};
    return {chosen, sum * weight_[bin_of(x - (float(chosen) + 0.5f))]};
}

}  // namespace wt

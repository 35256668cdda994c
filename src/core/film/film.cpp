#include "core/film/film.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>

namespace wt {

namespace {
bool ends_in_splat_channels(const std::vector<std::string>& names) {
    const std::size_t n = names.size();
    return n >= 3 && names[n - 3] == Film::splat_channels[0] && names[n - 2] == Film::splat_channels[1] &&
           names[n - 1] == Film::splat_channels[2];
}
}  // namespace

Film::Film(int width, int height, std::vector<std::string> extra_channels)
    : width_(width), height_(height), extra_channels_(std::move(extra_channels)), stride_(6 + extra_channels_.size()),
      splats_(ends_in_splat_channels(extra_channels_)), sample_extras_(extra_channels_.size() - (splats_ ? 3 : 0)),
      sums_(stride_ * std::size_t(width) * std::size_t(height), FixedPoint(0)),
      count_(std::size_t(width) * std::size_t(height), 0) {
    if (extra_channels_.size() > max_extra_channels) throw std::invalid_argument("film: too many extra channels");
    for (std::size_t c = 0; c < sample_extras_; ++c)
        if (extra_channels_[c].rfind("splat.", 0) == 0)
            throw std::invalid_argument("film: splat channels must be the last three, in R, G, B order");
}

bool Film::add_splat(uint32_t pixel, const glm::vec3& value) {
    const float values[3] = {value.x, value.y, value.z};
    return add_fixed_point(&sums_[std::size_t(pixel) * stride_ + stride_ - 3], values, 3);
}

glm::dvec3 Film::pixel_sum(uint32_t pixel) const {
    const FixedPoint* s = &sums_[std::size_t(pixel) * stride_];
    return {from_fixed_point(s[0]), from_fixed_point(s[1]), from_fixed_point(s[2])};
}

glm::dvec3 Film::pixel_splat_mean(uint32_t pixel) const {
    if (!splats_ || splat_samples_ == 0) return glm::dvec3(0.0);
    const FixedPoint* s = &sums_[std::size_t(pixel) * stride_ + stride_ - 3];
    return glm::dvec3(from_fixed_point(s[0]), from_fixed_point(s[1]), from_fixed_point(s[2])) / double(splat_samples_);
}

glm::dvec3 Film::pixel_mean(uint32_t pixel) const {
    const glm::dvec3 own = count_[pixel] ? pixel_sum(pixel) / double(count_[pixel]) : glm::dvec3(0.0);
    return splats_ ? own + pixel_splat_mean(pixel) : own;
}

glm::dvec3 Film::pixel_sample_variance(uint32_t pixel) const {
    const double n = count_[pixel];
    if (n < 2) return glm::dvec3(0.0);
    const FixedPoint* q = &sums_[std::size_t(pixel) * stride_ + 3];
    const glm::dvec3 mean = pixel_sum(pixel) / n;
    const glm::dvec3 mean_of_squares(from_fixed_point(q[0]) / n, from_fixed_point(q[1]) / n, from_fixed_point(q[2]) / n);
    // max(0, .) because the one-pass formula can round below zero for near-constant pixels.
    return glm::max(glm::dvec3(0.0), (mean_of_squares - mean * mean) * (n / (n - 1)));
}

double Film::extra_mean(uint32_t pixel, std::size_t channel) const {
    if (!count_[pixel]) return 0.0;
    return from_fixed_point(sums_[std::size_t(pixel) * stride_ + 6 + channel]) / double(count_[pixel]);
}

std::vector<float> Film::resolve() const {
    std::vector<float> rgb(3 * count_.size(), 0.0f);
    for (std::size_t p = 0; p < count_.size(); ++p) {
        if (count_[p] == 0 && !splats_) continue;
        const glm::dvec3 mean = pixel_mean(uint32_t(p));
        for (int c = 0; c < 3; ++c) rgb[3 * p + c] = float(mean[c]);
    }
    return rgb;
}

void Film::add_film(const Film& other) {
    if (other.width_ != width_ || other.height_ != height_ || other.extra_channels_ != extra_channels_)
        throw std::invalid_argument("films differ in size or channels");
    if (!adaptive_.empty() || !other.adaptive_.empty())
        throw std::invalid_argument("films of an adaptive render cannot be added: its stopping decisions need every "
                                    "sample before them in one film");
    // Checked in full first, so a failed add leaves this film as it was.
    for (std::size_t p = 0; p < count_.size(); ++p)
        if (count_[p] > std::numeric_limits<uint32_t>::max() - other.count_[p])
            throw std::overflow_error("film: a pixel's sample count would overflow");
    for (std::size_t i = 0; i < sums_.size(); ++i) {
        FixedPoint s = sums_[i];
        if (!add_fixed_point(s, other.sums_[i])) throw std::overflow_error("film: a pixel's sum would overflow");
    }
    for (std::size_t i = 0; i < sums_.size(); ++i) sums_[i] += other.sums_[i];
    for (std::size_t p = 0; p < count_.size(); ++p) count_[p] += other.count_[p];
    splat_samples_ += other.splat_samples_;
}

bool Film::operator==(const Film& other) const {
    return width_ == other.width_ && height_ == other.height_ && extra_channels_ == other.extra_channels_ &&
           splat_samples_ == other.splat_samples_ && sums_ == other.sums_ && count_ == other.count_ &&
           adaptive_ == other.adaptive_;
}

}  // namespace wt

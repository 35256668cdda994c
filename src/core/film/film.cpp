#include "core/film/film.h"

#include <glm/common.hpp>

namespace wt {

Film::Film(int width, int height)
    : width_(width), height_(height), sum_(3 * std::size_t(width) * std::size_t(height), 0.0),
      sum_squares_(sum_.size(), 0.0),
      count_(std::size_t(width) * std::size_t(height), 0) {}

glm::dvec3 Film::pixel_sum(uint32_t pixel) const {
    const double* s = &sum_[3 * std::size_t(pixel)];
    return {s[0], s[1], s[2]};
}

glm::dvec3 Film::pixel_mean(uint32_t pixel) const {
    return count_[pixel] ? pixel_sum(pixel) / double(count_[pixel]) : glm::dvec3(0.0);
}

glm::dvec3 Film::pixel_sample_variance(uint32_t pixel) const {
    const double n = count_[pixel];
    if (n < 2) return glm::dvec3(0.0);
    const double* q = &sum_squares_[3 * std::size_t(pixel)];
    const glm::dvec3 mean = pixel_sum(pixel) / n;
    const glm::dvec3 mean_of_squares(q[0] / n, q[1] / n, q[2] / n);
    // max(0, .) because the one-pass formula can round below zero for near-constant pixels.
    return glm::max(glm::dvec3(0.0), (mean_of_squares - mean * mean) * (n / (n - 1)));
}

std::vector<float> Film::resolve() const {
    std::vector<float> rgb(sum_.size(), 0.0f);
    for (std::size_t p = 0; p < count_.size(); ++p) {
        if (count_[p] == 0) continue;
        const double inv = 1.0 / double(count_[p]);
        for (int c = 0; c < 3; ++c) rgb[3 * p + c] = float(sum_[3 * p + c] * inv);
    }
    return rgb;
}

}  // namespace wt

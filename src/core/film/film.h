#pragma once
// Per-pixel sums (and sums of squares, for the per-pixel variance that statistical tests and
// error estimates need) in double, and sample counts. Each pixel belongs to exactly one tile and each
// tile to one worker, so adds need no atomics; samples arrive in sample-index order whatever
// the tiling, which makes the sums bit-identical for any thread count and tile size.

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/ext/vector_double3.hpp>

namespace wt {

class Film {
public:
    Film(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds one sample. A non-finite sample is dropped and false returned: the caller counts it,
    // and it never reaches the image.
    bool add_sample(uint32_t pixel, const glm::vec3& radiance) {
        if (!std::isfinite(radiance.x) || !std::isfinite(radiance.y) || !std::isfinite(radiance.z)) return false;
        const std::size_t i = 3 * std::size_t(pixel);
        double* s = &sum_[i];
        double* q = &sum_squares_[i];
        const double r = radiance.x, g = radiance.y, b = radiance.z;
        s[0] += r, s[1] += g, s[2] += b;
        q[0] += r * r, q[1] += g * g, q[2] += b * b;
        ++count_[pixel];
        return true;
    }

    glm::dvec3 pixel_sum(uint32_t pixel) const;
    glm::dvec3 pixel_mean(uint32_t pixel) const;
    // Unbiased sample variance of one sample's radiance (divide by the count for the variance
    // of the pixel's mean). Zero with fewer than two samples.
    glm::dvec3 pixel_sample_variance(uint32_t pixel) const;
    uint32_t pixel_count(uint32_t pixel) const { return count_[pixel]; }
    // Mean radiance per pixel, RGB interleaved, rows top to bottom. A pixel with no valid sample is black.
    std::vector<float> resolve() const;

    // Memory the film needs, so callers can refuse an image that cannot fit before allocating.
    static double bytes_needed(int width, int height) { return double(width) * double(height) * (6 * sizeof(double) + sizeof(uint32_t)); }

private:
    int width_, height_;
    std::vector<double> sum_, sum_squares_;
    std::vector<uint32_t> count_;
};

}  // namespace wt

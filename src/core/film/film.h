#pragma once
// Per-pixel sums of the samples' radiance and of its square (for the per-pixel variance that
// statistical tests, error estimates and the variance AOV need), optional extra channels (AOVs)
// and sample counts. Sums are exact fixed point (fixed_point.h), so a film is the same bits
// however its samples were split over passes, processes or partial renders, and two films of
// disjoint sample ranges add (`add_film`) to exactly the film of both ranges.
//
// Each pixel belongs to exactly one tile and each tile to one worker, so adds need no atomics.
//
// Splats: a film whose last three extra channels are `splat_channels` also sums contributions
// that are not samples of the pixel they land in: light paths connected to the camera (light
// tracing, kernels/caustics). Their estimate is normalised by the number of samples whose light
// paths were traced (`splat_samples`, the same for every pixel), not by the pixel's own count,
// and a pixel's mean is its samples' mean plus that. Those sums are exact too, so splats added
// from many threads in any order give the same bits.
// A film of an adaptive render also holds where each pixel stopped (adaptive_state.h).

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/film/adaptive_state.h"
#include "core/film/fixed_point.h"

namespace wt {

class Film {
public:
    static constexpr std::size_t max_extra_channels = 16;
    static constexpr const char* splat_channels[3] = {"splat.R", "splat.G", "splat.B"};

    // `extra_channels`: names of per-sample values averaged like the radiance (AOVs), added
    // with each sample in that order; ending in `splat_channels`, the film also takes splats.
    Film(int width, int height, std::vector<std::string> extra_channels = {});

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixel_total() const { return count_.size(); }

    // Adds one sample and, when the film has extra channels, `extra` (one value per channel).
    // A sample with a non-finite or unrepresentably large value (fixed_point.h) is dropped and
    // false returned: the caller counts it, and it never reaches the image.
    bool add_sample(uint32_t pixel, const glm::vec3& radiance, const float* extra = nullptr) {
        const double r = radiance.x, g = radiance.y, b = radiance.z;
        const double values[6] = {r, g, b, r * r, g * g, b * b};  // squares of floats are exact in double
        FixedPoint* sums = &sums_[std::size_t(pixel) * stride_];
        if (!add_fixed_point(sums, values, 6)) return false;
        // Without `extra` the extra channels gain zeros, which changes nothing.
        if (sample_extras_ > 0 && extra && !add_fixed_point(sums + 6, extra, sample_extras_)) {
            subtract_fixed_point(sums, values, 6);
            return false;
        }
        ++count_[pixel];
        return true;
    }

    // Asks for the cache lines of the pixel's sums and count, ahead of an add_sample.
    void prefetch_pixel(uint32_t pixel) const {
        const char* sums = reinterpret_cast<const char*>(&sums_[std::size_t(pixel) * stride_]);
        for (std::size_t b = 0; b < stride_ * sizeof(FixedPoint); b += 64) __builtin_prefetch(sums + b, 1);
        __builtin_prefetch(&count_[pixel], 1);
    }

    // Adds a splat (films with splat channels only). False, and nothing added, for a value that
    // is not finite or would overflow the pixel's sum: the caller counts it, as a dropped sample.
    bool add_splat(uint32_t pixel, const glm::vec3& value);
    // The samples whose light paths have been splatted: what the splat sums are divided by.
    void add_splat_samples(uint64_t samples) { splat_samples_ += samples; }
    void set_splat_samples(uint64_t samples) { splat_samples_ = samples; }
    uint64_t splat_samples() const { return splat_samples_; }
    bool has_splats() const { return splats_; }

    // The sum of the pixel's own samples (splats not included).
    glm::dvec3 pixel_sum(uint32_t pixel) const;
    // The pixel's estimate: its samples' mean, plus its splats' sum over splat_samples().
    glm::dvec3 pixel_mean(uint32_t pixel) const;
    // The splats' part of pixel_mean alone (zero without splat channels).
    glm::dvec3 pixel_splat_mean(uint32_t pixel) const;
    // Unbiased sample variance of one sample's radiance (divide by the count for the variance
    // of the pixel's mean). Zero with fewer than two samples. The pixel's own samples only:
    // splats have no per-pixel sample of their own to take a variance of.
    glm::dvec3 pixel_sample_variance(uint32_t pixel) const;
    uint32_t pixel_count(uint32_t pixel) const { return count_[pixel]; }
    // Mean radiance per pixel, RGB interleaved, rows top to bottom. A pixel with no valid sample is black.
    std::vector<float> resolve() const;

    // Every extra channel, splats included: the film's layout, as checkpoints store it.
    const std::vector<std::string>& extra_channels() const { return extra_channels_; }
    // The per-sample extra channels (AOVs) come first; `channel` indexes them.
    double extra_mean(uint32_t pixel, std::size_t channel) const;

    // Adds another film of the same size and channels (the samples of a disjoint range):
    // exact, so the order films are added in does not matter. Throws std::invalid_argument on
    // a different layout or when either film has adaptive state (an adaptive render is never
    // split into ranges: its decisions need all samples before them), and std::overflow_error
    // if a sum or count would overflow (this film is then unchanged).
    void add_film(const Film& other);
    bool operator==(const Film& other) const;
    bool operator!=(const Film& other) const { return !(*this == other); }

    // The raw state, for checkpoints: per pixel `channels_per_pixel()` sums (radiance RGB, its
    // squares RGB, then the extra channels) in units of 2^-40, and the sample counts.
    std::size_t channels_per_pixel() const { return stride_; }
    AlignedVector<FixedPoint>& raw_sums() { return sums_; }
    const AlignedVector<FixedPoint>& raw_sums() const { return sums_; }
    std::vector<uint32_t>& raw_counts() { return count_; }
    const std::vector<uint32_t>& raw_counts() const { return count_; }

    // Empty unless the film is of an adaptive render; the renderer fills it.
    AdaptiveState& adaptive() { return adaptive_; }
    const AdaptiveState& adaptive() const { return adaptive_; }

    // Memory the film needs, so callers can refuse an image that cannot fit before allocating.
    static double bytes_needed(int width, int height, std::size_t extra_channels = 0) {
        return double(width) * double(height) * (double(6 + extra_channels) * sizeof(FixedPoint) + sizeof(uint32_t));
    }

private:
    int width_, height_;
    std::vector<std::string> extra_channels_;
    std::size_t stride_;
    bool splats_;                // the last three extra channels are splat_channels
    std::size_t sample_extras_;  // extra channels added with each sample (the AOVs)
    uint64_t splat_samples_ = 0;
    // Aligned: a large film is mapped in huge pages (aligned_vector.h), and each sample of a
    // batch sweeps all of it.
    AlignedVector<FixedPoint> sums_;
    std::vector<uint32_t> count_;
    AdaptiveState adaptive_;
};

}  // namespace wt

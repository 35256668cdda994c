#pragma once
// The error of a render against a reference image, per channel and over all three: what
// `wavetrace compare`, `render --reference` and `tradeoff` report. Linear radiance in, no tone
// mapping: the error is of the estimator, not of a display.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/image_io/rgb_image.h"

namespace wt {

struct ErrorMetrics {
    double rmse = 0.0;        // sqrt(mean (x - r)^2)
    // mean (x - r)^2 / (r^2 + 0.01): squared error relative to the reference's brightness, so dark
    // and bright regions count alike; the 0.01 keeps near-black pixels from dominating the mean.
    double rel_mse = 0.0;
    // 20 log10(1 / rmse), +inf when equal. Peak 1 always, so PSNR is RMSE in decibels and compares
    // across images; OpenImageIO's compare takes the largest pixel value as the peak when it exceeds 1.
    // RMSE and the worst pixel are computed as OpenImageIO's compare computes them (tested).
    double psnr = 0.0;
    double mean_ratio = 0.0;  // sum x / sum r: 1 for a render that is right on average; NaN if the reference sums to 0
    double max_error = 0.0;   // the worst |x - r|, at pixel (max_x, max_y) in channel max_channel
    int max_x = 0, max_y = 0, max_channel = 0;
};

struct ImageErrorReport {
    std::array<ErrorMetrics, 3> channel;  // R, G, B
    ErrorMetrics overall;                 // every channel of every compared pixel
    std::size_t pixels = 0;               // pixels compared (all, or those the mask keeps)
};

// 1 where the mask image's first channel is non-zero: the pixels to compare.
std::vector<uint8_t> pixels_kept_by(const RgbImage& mask);

// Throws std::invalid_argument when the sizes differ (saying both) or the mask keeps no pixel.
ImageErrorReport image_error(const RgbImage& image, const RgbImage& reference,
                             const std::vector<uint8_t>* kept = nullptr);

}  // namespace wt

#pragma once
// The per-pixel error adaptive sampling stops on: Dammertz et al. 2010 ("A hierarchical
// automatic stopping condition for Monte Carlo global illumination", sec. 2.1), as Cycles uses
// it, with the noise measured by the standard error of the pixel's mean instead of by the
// difference between the image and a second image of every other sample:
//
//   error = (SE_R + SE_G + SE_B) / (1e-4 + N(I)),  SE_c = sqrt(s_c^2 / n),  I = R + G + B (means)
//   N(I) = sqrt(I) below 1, I from 1 up (Cycles' normalisation: relative error where a display
//          saturates, the square root's perceptual weight below)
//
// Why the standard error: the film's exact sums of squares give the sample variance s^2 at no
// cost per sample and no memory, and it estimates the noise with n - 1 degrees of freedom per
// channel, where |image - half image| (whose mean is sqrt(2/pi) SE for Gaussian noise) has
// one, so fewer pixels stop early by chance: on the hexroom it reaches the same error with
// 30-50 % fewer samples (README, "Adaptive sampling", the experiment). Cycles compares its
// error with 5 times its threshold, so for the same noise its threshold is about
// sqrt(2/pi) / 5 = 0.16 of this one: its default 0.01 is about 0.06 here.

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/film/film.h"

namespace wt {

inline double pixel_error(const Film& film, uint32_t pixel) {
    const uint32_t n = film.pixel_count(pixel);
    if (n < 2) return std::numeric_limits<double>::infinity();  // no variance yet: never converged
    const glm::dvec3 variance = film.pixel_sample_variance(pixel);
    // The pixel's own samples, as the variance is: with light tracing the splats' part of the
    // mean depends on whether a range's light paths were traced before this decision or after,
    // which must not change a decision.
    const glm::dvec3 mean = film.pixel_sum(pixel) / double(n);
    const double standard_error =
        std::sqrt(variance.x / n) + std::sqrt(variance.y / n) + std::sqrt(variance.z / n);
    const double intensity = std::max(0.0, mean.x + mean.y + mean.z);
    const double normalise = intensity < 1.0 ? std::sqrt(intensity) : intensity;
    return standard_error / (1e-4 + normalise);
}

}  // namespace wt

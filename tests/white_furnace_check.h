#pragma once
// The white-furnace verdict on a rendered film: every pixel of a closed room whose surfaces all
// have albedo rho and emit Le must converge to Le / (1 - rho). Shared by the furnace tests of
// the flat cube (furnace_test.cpp) and of smooth-shaded meshes (shading_normals_test.cpp).

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "render_helpers.h"
#include "statistics.h"

namespace wt::test {

inline void expect_white_furnace(const RenderedFilm& r, const SceneDescription& d, double expected) {
    const int pixels = d.settings.width * d.settings.height;

    // Secondary vertices can land near concave edges, where next-event estimation has a heavy
    // tail; a pixel's own samples rarely contain a tail event and underestimate its variance.
    // All pixels estimate the same quantity with about the same spread, so the per-sample
    // variance is pooled over the image, which does contain the tail events.
    double pooled_variance = 0.0;
    for (uint32_t p = 0; p < uint32_t(pixels); ++p) pooled_variance += r.film.pixel_sample_variance(p).y;
    pooled_variance /= pixels;
    const double pixel_stderr = std::sqrt(pooled_variance / d.settings.spp);

    // Per pixel, below: mean - expected > -z standard errors, z from a per-pixel false-alarm
    // rate; chance alone allows a binomially bounded number of failures. Energy loss, the usual
    // bug, shows up here. Above: the heavy right tail puts the few pixels that caught an edge
    // sample above the band, so only a small fraction may exceed it; a real gain of energy would
    // move every pixel and the image mean below.
    const double per_pixel_alpha = 1e-3;
    const double z = normal_two_sided_quantile(2.0 * per_pixel_alpha);
    const int allowed_low = binomial_upper_bound(pixels, per_pixel_alpha, 1e-6);
    const int allowed_high = pixels / 20;
    int low = 0, high = 0;
    double image_sum = 0.0;
    for (uint32_t p = 0; p < uint32_t(pixels); ++p) {
        const glm::dvec3 mean = r.film.pixel_mean(p);
        EXPECT_TRUE(mean.x == mean.y && mean.y == mean.z) << "grey room, pixel " << p;
        const double deviation = (mean.y - expected) / pixel_stderr;
        if (deviation < -z) {
            ++low;
            std::cerr << "pixel " << p << " low: " << mean.y << " vs " << expected << " (stderr " << pixel_stderr << ")\n";
        }
        high += deviation > z;
        image_sum += mean.y;
    }
    EXPECT_LE(low, allowed_low);
    EXPECT_LE(high, allowed_high);
    // The image mean pools every sample: a much tighter check of the same expectation.
    const double image_mean = image_sum / pixels;
    std::cout << "furnace image mean " << image_mean << ", expected " << expected << " (stderr "
              << pixel_stderr / std::sqrt(double(pixels)) << ")\n";
    EXPECT_NEAR(image_mean, expected, 4.5 * pixel_stderr / std::sqrt(double(pixels)));
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
}

}  // namespace wt::test

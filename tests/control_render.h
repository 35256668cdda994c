#pragma once
// A render compared with a reference render the way chance allows on the hexroom: against a
// control, the reference integrator with the tested render's spp and another independent seed
// (see RenderRegression in statistical_test.cpp for why a nominal per-pixel bound does not hold
// there: caustic paths make a pixel's mean of a few dozen samples far from normal).

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "render_helpers.h"

namespace wt::test {

// Per pixel, the two-sample z-test of the means of films a and b, per channel at per-test
// alpha 1e-3, with the per-sample variance pooled from both (under the hypothesis that both
// estimate the same per-sample distribution, the larger sample estimates it best). Returns,
// per pixel, whether any channel failed; prints the failures.
inline std::vector<bool> failing_pixels(const Film& a, const Film& b, const char* label, const SceneDescription& replay_desc) {
    const double z = normal_two_sided_quantile(1e-3);
    const uint32_t width = uint32_t(a.width());
    std::vector<bool> failing(std::size_t(a.width() * a.height()), false);
    for (uint32_t p = 0; p < failing.size(); ++p) {
        const double n1 = a.pixel_count(p), n2 = b.pixel_count(p);
        const glm::dvec3 d = a.pixel_mean(p) - b.pixel_mean(p);
        const glm::dvec3 pooled = ((n1 - 1.0) * a.pixel_sample_variance(p) + (n2 - 1.0) * b.pixel_sample_variance(p)) / (n1 + n2 - 2.0);
        const glm::dvec3 v = pooled * (1.0 / n1 + 1.0 / n2);
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(d[c]) > z * std::sqrt(v[c]) + 1e-9) {
                failing[p] = true;
                std::printf("%s: pixel (%u, %u) channel %d: %.5f vs %.5f (sd of the difference %.4f); replay: %s\n", label,
                            p % width, p / width, c, a.pixel_mean(p)[c], b.pixel_mean(p)[c], std::sqrt(v[c]),
                            replay_command("scenes/hexroom.json", replay_desc, p, 0).c_str());
            }
        }
    }
    return failing;
}

// z of the difference of two films' image sums, per channel (every sample pooled).
inline glm::dvec3 image_sum_z(const Film& a, const Film& b) {
    glm::dvec3 diff(0.0), var(0.0);
    for (uint32_t p = 0; p < uint32_t(a.width() * a.height()); ++p) {
        diff += a.pixel_mean(p) - b.pixel_mean(p);
        var += a.pixel_sample_variance(p) / double(a.pixel_count(p)) + b.pixel_sample_variance(p) / double(b.pixel_count(p));
    }
    return diff / glm::sqrt(var);
}

// Given the reference, the tested and the control films are independent and, if the tested
// renderer is right, identically distributed, so of the pixels failing in exactly one of them
// each is equally likely the tested one: the count failing for it alone is Binomial(discordant,
// 1/2) (McNemar's exact test), held below its bound at one-sided alpha 1e-3. The image sums,
// which pool every sample, must agree within 4.5 standard deviations.
inline void expect_agrees_as_well_as_the_control(const Film& tested, const Film& control, const Film& ref,
                                                 const SceneDescription& tested_desc, const SceneDescription& control_desc) {
    const int pixels = tested.width() * tested.height();
    const std::vector<bool> tested_fails = failing_pixels(tested, ref, "tested vs reference", tested_desc);
    const std::vector<bool> control_fails = failing_pixels(control, ref, "control vs reference", control_desc);
    int tested_only = 0, control_only = 0, tested_total = 0, control_total = 0;
    for (int p = 0; p < pixels; ++p) {
        tested_total += tested_fails[p], control_total += control_fails[p];
        tested_only += tested_fails[p] && !control_fails[p];
        control_only += control_fails[p] && !tested_fails[p];
    }
    const int bound = binomial_upper_bound(tested_only + control_only, 0.5, 1e-3);
    std::printf("failing pixels: tested %d, control %d (of %d); tested only %d, control only %d, bound %d "
                "(the nominal binomial bound, which the control shows does not hold here: %d)\n",
                tested_total, control_total, pixels, tested_only, control_only, bound,
                binomial_upper_bound(pixels, 3e-3, 1e-6));
    EXPECT_LT(tested_only, bound) << "the tested render fails more pixels than the reference integrator's own control";

    const glm::dvec3 z_tested = image_sum_z(tested, ref), z_control = image_sum_z(control, ref);
    for (int c = 0; c < 3; ++c) {
        EXPECT_LE(std::fabs(z_tested[c]), 4.5) << "image sum, tested vs reference, channel " << c;
        EXPECT_LE(std::fabs(z_control[c]), 4.5) << "image sum, control vs reference, channel " << c;
    }
}

}  // namespace wt::test

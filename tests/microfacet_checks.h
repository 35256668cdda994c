#pragma once
// What the microfacet BSDF tests share (microfacet_bsdf_test, principled_bsdf_test): a BSDF
// seen from a direction about +z, integrals over the sphere by quadrature, the chi-square test
// of a sampler against its pdf, and the directional albedo by the sampler.

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/materials/microfacet_bsdf.h"
#include "bsdf_helpers.h"
#include "statistics.h"

namespace wt::test {

// The BSDF seen from wo about +z; `front` as for glass (wo on the outside when true). A view
// from below is expressed by its mirror image about -z, as the vertices build it.
inline MicrofacetBsdfAtView view(const Material& m, const glm::vec3& wo, bool front = true,
                          FresnelModel fresnel = FresnelModel::exact) {
    const glm::vec3 n(0.0f, 0.0f, wo.z >= 0.0f ? 1.0f : -1.0f);
    return MicrofacetBsdfAtView(m, n, n, front, wo, fresnel);
}

// Integral of g(w) over the sphere by midpoint quadrature in (theta, phi), dw = sin dtheta dphi:
// uniform in theta, so the lobes peaked at the poles get many points.
template <typename G>
inline double sphere_integral(G&& g, int n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double theta = M_PI * (i + 0.5) / n, phi = M_PI * (j + 0.5) / n;
            sum += g(direction_at(theta, phi)) * std::sin(theta);
        }
    return sum * (M_PI / n) * (M_PI / n);
}

// Chi-square of a sampler against its pdf (pbrt-v4's and Mitsuba's BSDF tests): sample counts in
// an n x 2n grid over (theta, phi) covering the sphere, plus one cell for the invalid samples,
// against n_samples times the pdf integrated over each cell (sub x sub midpoints of
// pdf sin(theta)) and the missing mass. Uniform in theta, not in z, so the narrow refraction
// lobes at the poles span several cells and their integrals stay accurate.
struct Sampled {
    bool valid;
    glm::vec3 wi;
};
template <typename Sample, typename Pdf>
inline double sampling_p_value(Sample&& sample, Pdf&& pdf, int n_samples, uint32_t seed) {
    constexpr int n = 16, sub = 24;
    std::vector<double> observed(2 * n * n + 1, 0.0), expected(2 * n * n + 1, 0.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int s = 0; s < n_samples; ++s) {
        const float u0 = u(rng), u1 = u(rng), u2 = u(rng);
        const Sampled r = sample(u0, u1, u2);
        if (!r.valid) {
            observed.back() += 1.0;
            continue;
        }
        const double theta = std::acos(std::clamp(double(r.wi.z), -1.0, 1.0));
        const int i = std::min(n - 1, int(theta / M_PI * n));
        double phi = std::atan2(double(r.wi.y), double(r.wi.x));
        if (phi < 0) phi += 2.0 * M_PI;
        const int j = std::min(2 * n - 1, int(phi / (2.0 * M_PI) * 2 * n));
        observed[std::size_t(i * 2 * n + j)] += 1.0;
    }
    double total = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            double cell = 0.0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    const double theta = M_PI * (i + (a + 0.5) / sub) / n;
                    const double phi = 2.0 * M_PI * (j + (b + 0.5) / sub) / (2 * n);
                    cell += pdf(direction_at(theta, phi)) * std::sin(theta);
                }
            cell *= (M_PI / n) * (M_PI / n) / (sub * sub);
            expected[std::size_t(i * 2 * n + j)] = cell * n_samples;
            total += cell;
        }
    // The shape: the valid samples against the pdf normalised over the sphere. The mass (the
    // share of valid samples against the pdf's integral) is checked on its own, with room for
    // the quadrature's error, which a cell of the few invalid samples would magnify.
    const double valid = n_samples - observed.back();
    for (double& e : expected) e *= valid / (n_samples * total);
    observed.pop_back(), expected.pop_back();
    const double missing = 1.0 - total, lost = 1.0 - valid / n_samples;
    // (The quadrature's error is largest for rough glass seen at grazing angles, whose
    // refraction lobe hugs the horizon from below.)
    EXPECT_NEAR(lost, missing, 4.0 * std::sqrt(std::max(0.0, missing * (1.0 - missing)) / n_samples) + 5e-3);
    return chi_square_test(observed, expected).p_value;
}

// Directional albedo by the sampler: the mean weight, with its standard error.
struct Albedo {
    double mean, standard_error;
};
inline Albedo sampled_albedo(const MicrofacetBsdfAtView& bsdf, int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const BsdfSample s = bsdf.sample(u(rng), u(rng), u(rng));
        const double w = s.valid ? double(s.weight.x) : 0.0;
        sum += w, sum2 += w * w;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

}  // namespace wt::test

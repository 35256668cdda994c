// The samplers behind `sampler` (core/sampling/samplers.h): Owen-scrambled Sobol' points are a
// (0, m, 2)-net in every pixel and pad, uniform over many pixels, uncorrelated between pads and
// bounces, and integrate a smooth function with an error falling faster than N^-1/2; the
// independent sampler, the control, does none of the first and converges at N^-1/2.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "core/sampling/samplers.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kAlpha = 1e-4;  // false-alarm probability of each goodness-of-fit test

template <typename Sampler>
UniformPair draw(uint64_t seed, uint32_t pixel, uint32_t sample, uint32_t bounce, uint32_t dimension,
                 uint32_t shadow_rays = 1) {
    const PathSeed path{Sampler::key_of(seed, pixel, sample), sample};
    return Sampler(path, bounce, shadow_rays).pair(dimension);
}

// Points of one pixel in one pad, all `count` samples (light dimensions: sample * shadow_rays + j).
template <typename Sampler>
std::vector<UniformPair> pixel_points(uint32_t pixel, uint32_t bounce, uint32_t dimension, uint32_t count,
                                      uint32_t shadow_rays = 1) {
    std::vector<UniformPair> points;
    if (dimension >= dim::light_first) {
        for (uint32_t s = 0; s < count / shadow_rays; ++s)
            for (uint32_t j = 0; j < shadow_rays; ++j)
                points.push_back(draw<Sampler>(7, pixel, s, bounce, dimension + j * dim::per_shadow_ray, shadow_rays));
        return points;
    }
    for (uint32_t s = 0; s < count; ++s) points.push_back(draw<Sampler>(7, pixel, s, bounce, dimension));
    return points;
}

// Whether every elementary interval 2^-a x 2^-(m-a) holds exactly one of the 2^m points.
bool is_zero_m_2_net(const std::vector<UniformPair>& points, int m) {
    for (int a = 0; a <= m; ++a) {
        const uint32_t nx = 1u << a, ny = 1u << (m - a);
        std::vector<int> cells(std::size_t(nx) * ny, 0);
        for (const UniformPair& p : points) ++cells[std::size_t(p.first * float(nx)) * ny + std::size_t(p.second * float(ny))];
        for (int c : cells)
            if (c != 1) return false;
    }
    return true;
}

struct PadCase {
    uint32_t bounce, dimension, shadow_rays;
};
constexpr PadCase kPads[] = {{0, dim::camera_x, 1}, {0, dim::bsdf_u, 1}, {3, dim::bsdf_choice, 1},
                             {1, dim::light_first + dim::light_u, 1}, {2, dim::light_first + dim::light_u, 4}};

TEST(SobolSampler, EveryPixelAndPadIsAZeroM2Net) {
    for (int m : {4, 6, 8}) {
        for (uint32_t pixel : {0u, 1u, 517u, 90000u}) {
            for (const PadCase& pad : kPads) {
                const auto points = pixel_points<SobolSampler>(pixel, pad.bounce, pad.dimension, 1u << m, pad.shadow_rays);
                EXPECT_TRUE(is_zero_m_2_net(points, m)) << "2^" << m << " points, pixel " << pixel << ", bounce " << pad.bounce
                                                        << ", dimension " << pad.dimension;
            }
        }
    }
}

TEST(SobolSampler, TheIndependentControlIsNotANet) {
    // The check has power: random points are almost never a net (at 2^4 points, P ~ 16!/16^16).
    int nets = 0;
    for (uint32_t pixel = 0; pixel < 20; ++pixel)
        nets += is_zero_m_2_net(pixel_points<IndependentSampler>(pixel, 0, dim::bsdf_u, 16), 4);
    EXPECT_EQ(nets, 0);
}

// Pearson's statistic of one pixel's 64 points in an 8 x 8 grid: exactly 0 for a net, chi-square
// distributed (63 degrees of freedom) for independent points. Pooled over many pixels, the
// Sobol' points are uniform (each scrambled point is), the chi-square test of their union passes.
TEST(SobolSampler, ChiSquareOfEachPixelIsZeroAndOfAllPixelsUniform) {
    const int bins = 8, n = 64;
    std::vector<double> pooled(bins * bins, 0.0);
    double independent_statistic = 0.0;
    const int pixels = 400;
    for (uint32_t pixel = 0; pixel < uint32_t(pixels); ++pixel) {
        for (const bool sobol : {true, false}) {
            const auto points = sobol ? pixel_points<SobolSampler>(pixel, 1, dim::bsdf_u, n)
                                      : pixel_points<IndependentSampler>(pixel, 1, dim::bsdf_u, n);
            std::vector<double> cells(bins * bins, 0.0);  // expected: n / bins^2 = 1 each
            for (const UniformPair& p : points) cells[std::size_t(p.first * bins) * bins + std::size_t(p.second * bins)] += 1.0;
            double statistic = 0.0;
            for (int c = 0; c < bins * bins; ++c) statistic += (cells[c] - 1.0) * (cells[c] - 1.0);
            if (sobol) {
                EXPECT_EQ(statistic, 0.0) << "pixel " << pixel;
                for (int c = 0; c < bins * bins; ++c) pooled[c] += cells[c];
            } else {
                independent_statistic += statistic;
            }
        }
    }
    // Independent points: mean statistic 63 per pixel, far from 0.
    EXPECT_GT(independent_statistic / pixels, 50.0);
    // Pooled Sobol' cells hold exactly `pixels` points each: uniform, and the test passes.
    std::vector<double> expected(bins * bins, double(pixels) * n / (bins * bins));
    EXPECT_GT(test::chi_square_test(pooled, expected).p_value, kAlpha);
}

TEST(SobolSampler, EachCoordinateIsUniformOverPixels) {
    // One sample index of many pixels: the scrambles make every point uniform (unbiasedness).
    const int bins = 64, pixels = 100000;
    for (const PadCase& pad : kPads) {
        std::vector<double> x(bins, 0.0), y(bins, 0.0), expected(bins, double(pixels) / bins);
        for (uint32_t pixel = 0; pixel < uint32_t(pixels); ++pixel) {
            const UniformPair p = draw<SobolSampler>(3, pixel, 5, pad.bounce, pad.dimension, pad.shadow_rays);
            ASSERT_GE(p.first, 0.0f);
            ASSERT_LT(p.first, 1.0f);
            ASSERT_GE(p.second, 0.0f);
            ASSERT_LT(p.second, 1.0f);
            x[std::size_t(p.first * bins)] += 1.0;
            y[std::size_t(p.second * bins)] += 1.0;
        }
        EXPECT_GT(test::chi_square_test(x, expected).p_value, kAlpha) << "dimension " << pad.dimension;
        EXPECT_GT(test::chi_square_test(y, expected).p_value, kAlpha) << "dimension " << pad.dimension + 1;
    }
}

// Padding: dimensions of different pads, or of the same pad at different bounces, are
// independent. Joint histogram of one coordinate of each, over every sample of many pixels.
TEST(SobolSampler, PadsAndBouncesAreUncorrelated) {
    struct Pair {
        uint32_t bounce_a, dimension_a, bounce_b, dimension_b;
    };
    const Pair pairs[] = {{0, dim::camera_x, 0, dim::bsdf_u},
                          {1, dim::bsdf_u, 2, dim::bsdf_u},
                          {1, dim::bsdf_u, 1, dim::bsdf_choice},
                          {1, dim::bsdf_v, 1, dim::light_first + dim::light_u},
                          {1, dim::light_first + dim::light_u, 1, dim::light_first + dim::light_choice}};
    const int bins = 16, pixels = 3000, spp = 16;
    for (const Pair& q : pairs) {
        std::vector<double> observed(bins * bins, 0.0), expected(bins * bins, double(pixels) * spp / (bins * bins));
        for (uint32_t pixel = 0; pixel < uint32_t(pixels); ++pixel) {
            for (uint32_t s = 0; s < uint32_t(spp); ++s) {
                const PathSeed path{SobolSampler::key_of(11, pixel, s), s};
                const float a = SobolSampler(path, q.bounce_a, 1)(q.dimension_a);
                const float b = SobolSampler(path, q.bounce_b, 1)(q.dimension_b);
                observed[std::size_t(a * bins) * bins + std::size_t(b * bins)] += 1.0;
            }
        }
        EXPECT_GT(test::chi_square_test(observed, expected).p_value, kAlpha)
            << "bounce " << q.bounce_a << " dimension " << q.dimension_a << " against bounce " << q.bounce_b << " dimension "
            << q.dimension_b;
    }
}

TEST(SobolSampler, SingleDimensionsAreTheCoordinatesOfTheirPair) {
    for (uint32_t s = 0; s < 64; ++s) {
        const SobolSampler sampler(PathSeed{SobolSampler::key_of(2, 40, s), s}, 2, 3);
        for (uint32_t d : {dim::camera_x, dim::bsdf_u, dim::bsdf_choice, dim::light_first, dim::light_first + 4u}) {
            const UniformPair p = sampler.pair(d);
            EXPECT_EQ(sampler(d), p.first);
            EXPECT_EQ(sampler(d + 1), p.second);
        }
    }
}

// Root-mean-square error, over independently scrambled pixels, of the N-point estimate of the
// integral of a smooth function over the unit square, and the slope of log error against log N.
template <typename Sampler>
double convergence_slope(uint32_t dimension) {
    const auto f = [](double x, double y) { return std::exp(x) * (1.0 + y * y) + std::cos(3.0 * x * y); };
    // Integral of exp(x)(1 + y^2) is (e - 1) 4/3; of cos(3xy), Si(3)/3 (Si(3) = 1.848652527999468).
    const double exact = (std::exp(1.0) - 1.0) * 4.0 / 3.0 + 1.848652527999468 / 3.0;
    const int pixels = 256;
    std::vector<double> log_n, log_error;
    for (int m = 2; m <= 10; ++m) {
        const uint32_t n = 1u << m;
        double squared = 0.0;
        for (uint32_t pixel = 0; pixel < uint32_t(pixels); ++pixel) {
            double sum = 0.0;
            for (uint32_t s = 0; s < n; ++s) {
                const UniformPair p = draw<Sampler>(21, pixel, s, 1, dimension);
                sum += f(p.first, p.second);
            }
            const double e = sum / n - exact;
            squared += e * e;
        }
        log_n.push_back(std::log(double(n)));
        log_error.push_back(0.5 * std::log(squared / pixels));
    }
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < log_n.size(); ++i) mx += log_n[i], my += log_error[i];
    mx /= double(log_n.size()), my /= double(log_n.size());
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < log_n.size(); ++i) sxy += (log_n[i] - mx) * (log_error[i] - my), sxx += (log_n[i] - mx) * (log_n[i] - mx);
    return sxy / sxx;
}

TEST(SobolSampler, ErrorOnASmoothIntegrandFallsFasterThanOneOverSqrtN) {
    // Owen-scrambled nets: N^-3/2 for smooth integrands (Owen 1997); independent points: N^-1/2.
    const double sobol = convergence_slope<SobolSampler>(dim::bsdf_u);
    const double independent = convergence_slope<IndependentSampler>(dim::bsdf_u);
    std::cout << "fitted slopes of RMSE against N: sobol " << sobol << ", independent " << independent << "\n";
    EXPECT_LT(sobol, -1.2);
    EXPECT_GT(independent, -0.6);
    EXPECT_LT(independent, -0.4);
}

TEST(Samplers, HashSamplersKeepTheRendererOriginalNumbers) {
    // The independent and stratified samplers draw today's numbers (VertexRandom) everywhere but
    // the pixel position, so a scene that keeps the default renders the same bits.
    for (uint32_t s = 0; s < 32; ++s) {
        const uint64_t key = path_key(9, 1234, s);
        const PathSeed path{StratifiedSampler::key_of(9, 1234, s), s};
        EXPECT_EQ(path.key, key);
        for (uint32_t d = 0; d < 20; ++d) {
            EXPECT_EQ(StratifiedSampler(path, 2, 3)(d), random_float(key, 2, d));
            EXPECT_EQ(IndependentSampler(path, 2, 3)(d), random_float(key, 2, d));
        }
        const UniformPair jitter = VertexRandom(key, 0).pair(dim::camera_x);
        EXPECT_EQ(IndependentSampler(path, 0, 3).pixel_offset(9, 1234, s).x, jitter.first);
    }
}

TEST(Sobol, DimensionOneIsThePascalMatrixRecurrence) {
    // The columns v_k = v_(k-1) xor (v_(k-1) >> 1) from v_0 = 2^31 (Joe & Kuo's first
    // polynomial), applied bit by bit: the definition the five-step transform must equal.
    uint32_t columns[32];
    columns[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) columns[k] = columns[k - 1] ^ (columns[k - 1] >> 1);
    uint32_t state = 7;
    for (uint32_t i = 0; i < 200000; ++i) {
        state = state * 1664525u + 1013904223u;
        const uint32_t index = i < 100000 ? i : state;
        uint32_t expected = 0;
        for (int k = 0; k < 32; ++k)
            if (index >> k & 1u) expected ^= columns[k];
        ASSERT_EQ(sobol_dimension1(index), expected) << "index " << index;
    }
}

// The pixel positions of the stratified sampler, per pixel: point s of a scrambled (0, 2)-sequence.
std::vector<glm::vec2> stratified_positions(uint64_t seed, uint32_t pixel, uint32_t count) {
    std::vector<glm::vec2> points;
    for (uint32_t s = 0; s < count; ++s) {
        const PathSeed path{StratifiedSampler::key_of(seed, pixel, s), s};
        points.push_back(StratifiedSampler(path, 0, 3).pixel_offset(seed, pixel, s));
    }
    return points;
}

TEST(StratifiedSampler, EveryPowerOfTwoPrefixOfAPixelHasOneSampleInEachElementaryInterval) {
    for (uint32_t pixel = 0; pixel < 40; ++pixel) {
        const std::vector<glm::vec2> points = stratified_positions(3, pixel, 256);
        for (int m : {2, 4, 5, 8}) {
            const uint32_t n = 1u << m;
            for (int a = 0; a <= m; ++a) {  // cells 2^-a wide and 2^-(m-a) tall
                std::vector<int> cells(n, 0);
                for (uint32_t s = 0; s < n; ++s) {
                    const uint32_t cx = uint32_t(points[s].x * float(1u << a)), cy = uint32_t(points[s].y * float(1u << (m - a)));
                    ASSERT_LT(cx, 1u << a);
                    ASSERT_LT(cy, 1u << (m - a));
                    ++cells[(cy << a) | cx];
                }
                for (uint32_t c = 0; c < n; ++c)
                    ASSERT_EQ(cells[c], 1) << "pixel " << pixel << ", first " << n << " samples, cells 2^-" << a
                                           << " x 2^-" << (m - a) << ", cell " << c;
            }
        }
    }
}

// What a stopped or time-limited render relies on: each sample alone is uniform over the pixel,
// so any number of samples is an unbiased estimate. The jittered k x k grid the renderer used
// before (sized from the spp, cells in scanline order) fails it: both sides are asserted.
TEST(StratifiedSampler, AnyPrefixIsUniformOverThePixelUnlikeAGridSizedFromTheSpp) {
    const int g = 6, pixels = 20000;
    const uint32_t prefix = 3;
    std::vector<double> observed(g * g, 0.0), expected(g * g, double(pixels) * prefix / (g * g));
    for (int p = 0; p < pixels; ++p)
        for (const glm::vec2 o : stratified_positions(11, uint32_t(p), prefix))
            observed[std::size_t(std::min(g - 1, int(o.y * g)) * g + std::min(g - 1, int(o.x * g)))] += 1.0;
    EXPECT_GT(test::chi_square_test(observed, expected).p_value, 1e-4);

    const auto grid_offset = [](uint32_t sample, uint32_t spp, float jx, float jy) {
        const uint32_t k = uint32_t(std::sqrt(double(spp)));
        return glm::vec2((float(sample % k) + jx) / float(k), (float(sample / k) + jy) / float(k));
    };
    float grid_highest = 0.0f;
    for (uint32_t s = 0; s < 16; ++s) grid_highest = std::max(grid_highest, grid_offset(s, 64, 0.999f, 0.999f).y);
    EXPECT_LT(grid_highest, 0.25f) << "the grid's first 16 of 64 samples all lie in the top quarter";
    float strata_highest = 0.0f;
    for (const glm::vec2 o : stratified_positions(11, 0, 16)) strata_highest = std::max(strata_highest, o.y);
    EXPECT_GT(strata_highest, 0.75f) << "the sequence's first 16 reach the bottom quarter";
}

}  // namespace
}  // namespace wt

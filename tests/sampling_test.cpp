// Chi-square goodness-of-fit tests of the sampling routines against their densities, plus the
// exact properties of the stratified pixel pattern and the light table.

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "core/base/float_minmax.h"
#include "core/lights/light_table.h"
#include "core/sampling/rng.h"
#include "core/sampling/sampling.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kAlpha = 1e-4;  // false-alarm probability of each goodness-of-fit test

float uniform(uint64_t key, uint32_t i, uint32_t d) { return random_float(key, i, d); }

TEST(RandomFloat, IsUniformOnTheUnitInterval) {
    const int bins = 64, n = 200000;
    std::vector<double> observed(bins, 0.0), expected(bins, double(n) / bins);
    for (int i = 0; i < n; ++i) {
        const float x = uniform(12345, uint32_t(i), 0);
        ASSERT_GE(x, 0.0f);
        ASSERT_LT(x, 1.0f);
        observed[std::size_t(x * bins)] += 1.0;
    }
    EXPECT_GT(test::chi_square_test(observed, expected).p_value, kAlpha);
}

TEST(RandomFloat, DimensionsAndBouncesAreUncorrelated) {
    // Joint histogram of consecutive dimensions must be uniform on the square.
    const int bins = 16, n = 200000;
    std::vector<double> observed(bins * bins, 0.0), expected(bins * bins, double(n) / (bins * bins));
    for (int i = 0; i < n; ++i) {
        const uint64_t key = path_key(3, uint32_t(i), 0);
        const int a = int(uniform(key, 1, dim::bsdf_u) * bins);
        const int b = int(uniform(key, 1, dim::bsdf_v) * bins);
        observed[std::size_t(a * bins + b)] += 1.0;
    }
    EXPECT_GT(test::chi_square_test(observed, expected).p_value, kAlpha);
}

TEST(RandomFloat, PairsAreTheSameNumbersAsSingleDimensions) {
    for (uint32_t i = 0; i < 1000; ++i) {
        const uint64_t key = path_key(5, i, 0);
        for (uint32_t d = 0; d < 20; d += 2) {
            const UniformPair p = VertexRandom(key, i % 7).pair(d);
            ASSERT_EQ(p.first, random_float(key, i % 7, d));
            ASSERT_EQ(p.second, random_float(key, i % 7, d + 1));
        }
    }
}

// The contract the shading code relies on, not one libm's choices: the larger (smaller)
// operand when they differ, the other operand when exactly one is NaN, and for two zeros of
// opposite sign (where C leaves the sign unspecified, and glibc builds differ) a zero; ours
// is then y, as documented, so a render does not depend on which libm it links.
TEST(FloatMinMax, MaxAndMinOfOrderedValuesTheNonNanOperandAndYOnTies) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // volatile: compared with libm at run time, not with the compiler's constant folding.
    volatile float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 1e-7f, 1e-45f, -1e-45f, 0.95f, 3e38f, inf, -inf, 0.5f};
    auto bits = [](float f) { uint32_t b; std::memcpy(&b, &f, sizeof b); return b; };
    for (float x : values) {
        for (float y : values) {
            const float larger = x > y ? x : y, smaller = x < y ? x : y;
            if (x != y) {
                EXPECT_EQ(bits(fmax_float(x, y)), bits(larger)) << x << " " << y;
                EXPECT_EQ(bits(fmin_float(x, y)), bits(smaller)) << x << " " << y;
                EXPECT_EQ(bits(fmax_float(x, y)), bits(std::fmax(x, y))) << x << " " << y;
                EXPECT_EQ(bits(fmin_float(x, y)), bits(std::fmin(x, y))) << x << " " << y;
            } else {
                // Equal: the same value as libm's (a zero of either sign for +0, -0), and y.
                EXPECT_EQ(fmax_float(x, y), std::fmax(x, y)) << x << " " << y;
                EXPECT_EQ(fmin_float(x, y), std::fmin(x, y)) << x << " " << y;
                EXPECT_EQ(bits(fmax_float(x, y)), bits(y)) << x << " " << y;
                EXPECT_EQ(bits(fmin_float(x, y)), bits(y)) << x << " " << y;
            }
        }
        EXPECT_EQ(bits(fmax_float(x, nan)), bits(x));
        EXPECT_EQ(bits(fmax_float(nan, x)), bits(x));
        EXPECT_EQ(bits(fmin_float(x, nan)), bits(x));
        EXPECT_EQ(bits(fmin_float(nan, x)), bits(x));
        EXPECT_TRUE(std::isnan(std::fmax(nan, nan)) && std::isnan(fmax_float(nan, nan)));
    }
}

// The inline octant sin/cos against double precision, on a dense grid of the whole range
// and its end points: within 2 ulp of the correctly rounded value.
TEST(QuarterPiTrig, WithinTwoUlpOfDoublePrecisionOnTheWholeOctant) {
    auto ulps = [](float got, double want) {
        const float w = float(want);
        return std::fabs(double(got) - want) / double(std::nextafter(std::fabs(w), 2.0f) - std::fabs(w));
    };
    const float edge = kPi / 4.0f;
    double worst_sin = 0.0, worst_cos = 0.0;
    const int n = 1 << 20;
    for (int i = 0; i <= n; ++i) {
        const float x = -edge + 2.0f * edge * float(i) / float(n);
        const SinCos t = sin_cos_quarter_pi(x);
        worst_sin = std::max(worst_sin, ulps(t.sin, std::sin(double(x))));
        worst_cos = std::max(worst_cos, ulps(t.cos, std::cos(double(x))));
    }
    for (float x : {0.0f, -0.0f, edge, -edge, 1e-30f, -1e-20f}) {
        const SinCos t = sin_cos_quarter_pi(x);
        worst_sin = std::max(worst_sin, ulps(t.sin, std::sin(double(x))));
        worst_cos = std::max(worst_cos, ulps(t.cos, std::cos(double(x))));
    }
    EXPECT_LE(worst_sin, 2.0);
    EXPECT_LE(worst_cos, 2.0);
    EXPECT_EQ(sin_cos_quarter_pi(0.0f).cos, 1.0f);
    EXPECT_EQ(sin_cos_quarter_pi(0.0f).sin, 0.0f);
}

TEST(CosineHemisphere, MatchesItsPdf) {
    // Under pdf cos(theta)/pi, cos^2(theta) and phi are independent and uniform: equal-probability
    // bins are a grid in (cos^2 theta, phi).
    const int nt = 10, np = 20, n = 200000;
    std::vector<double> observed(nt * np, 0.0), expected(nt * np, double(n) / (nt * np));
    for (int i = 0; i < n; ++i) {
        const glm::vec3 w = sample_cosine_hemisphere(uniform(99, uint32_t(i), 0), uniform(99, uint32_t(i), 1));
        ASSERT_GT(w.z, 0.0f);
        ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
        const double phi = std::atan2(w.y, w.x) + M_PI;
        const int it = std::min(nt - 1, int(w.z * w.z * nt));
        const int ip = std::min(np - 1, int(phi / (2 * M_PI) * np));
        observed[std::size_t(it * np + ip)] += 1.0;
    }
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, kAlpha) << "chi2 " << r.statistic << " dof " << r.degrees_of_freedom;
}

TEST(UniformTriangle, MatchesItsPdf) {
    // Unit right triangle (0,0) (1,0) (0,1): cell (i,j) of an n x n grid covers area 1/n^2 below
    // the diagonal, half that on it, none above.
    const int g = 12, n = 200000;
    std::vector<double> observed(g * g, 0.0), expected(g * g, 0.0);
    for (int i = 0; i < g; ++i)
        for (int j = 0; j < g; ++j) expected[std::size_t(i * g + j)] = i + j < g - 1 ? 2.0 * n / (g * g) : i + j == g - 1 ? 1.0 * n / (g * g) : 0.0;
    for (int k = 0; k < n; ++k) {
        const glm::vec2 b = sample_uniform_triangle(uniform(5, uint32_t(k), 0), uniform(5, uint32_t(k), 1));
        ASSERT_GE(b.x, 0.0f);
        ASSERT_GE(b.y, 0.0f);
        ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
        observed[std::size_t(std::min(g - 1, int(b.x * g)) * g + std::min(g - 1, int(b.y * g)))] += 1.0;
    }
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, kAlpha) << "chi2 " << r.statistic;
}

TEST(Frame, IsOrthonormalForEveryNormalIncludingStraightDown) {
    for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1, 2, 3)),
                              glm::normalize(glm::vec3(-1e-7f, 0, -1)), glm::vec3(1, 0, 0)}) {
        const Frame f(n);
        EXPECT_NEAR(glm::dot(f.tangent, f.bitangent), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(f.tangent, n), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(f.bitangent, n), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(f.tangent), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::length(f.bitangent), 1.0f, 1e-6f);
    }
}

TEST(LightTable, PicksLightsInProportionToAreaWithPdfOneOverTotalArea) {
    TriangleSoA tris;
    std::vector<Material> materials(2);
    materials[0].emission = glm::vec3(5.0f);
    materials[1].albedo = glm::vec3(0.5f);  // not a light
    tris.push_back({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);  // area 0.5
    tris.push_back({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, 1);  // not emissive
    tris.push_back({0, 0, 2}, {3, 0, 2}, {0, 1, 2}, 0);  // area 1.5
    const LightTable lights(tris, materials);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_FLOAT_EQ(lights.total_area(), 2.0f);
    const int n = 100000;
    std::vector<double> observed(2, 0.0);
    for (int i = 0; i < n; ++i) {
        const LightSample s = lights.sample(tris, uniform(8, uint32_t(i), 0), uniform(8, uint32_t(i), 1), uniform(8, uint32_t(i), 2));
        EXPECT_FLOAT_EQ(s.pdf_area, 0.5f);
        EXPECT_EQ(s.radiance, glm::vec3(5.0f));
        ASSERT_TRUE(s.position.z == 0.0f || s.position.z == 2.0f);
        observed[s.position.z == 0.0f ? 0 : 1] += 1.0;
    }
    EXPECT_GT(test::chi_square_test(observed, {0.25 * n, 0.75 * n}).p_value, kAlpha);
}

TEST(LightTable, PicksTheFirstLightWhoseCumulativeAreaExceedsTheChoice) {
    // Sizes on both sides of the switch from counting to bisecting (light_table.h).
    for (int count : {1, 2, 3, 8, 9, 30}) {
        SCOPED_TRACE(count);
        TriangleSoA tris;
        std::vector<Material> materials(1);
        materials[0].emission = glm::vec3(1.0f);
        std::vector<double> cumulative;
        double total = 0.0;
        for (int k = 0; k < count; ++k) {
            const float a = float(k % 4 + 1);  // area a / 2, exact
            tris.push_back({0, 0, float(k)}, {a, 0, float(k)}, {0, 1, float(k)}, 0);
            total += 0.5 * a;
            cumulative.push_back(total);
        }
        const LightTable lights(tris, materials);
        std::vector<float> cdf;
        for (double c : cumulative) cdf.push_back(float(c / total));
        cdf.back() = 1.0f;
        std::vector<float> choices;
        for (int i = 0; i < 1000; ++i) choices.push_back(float(i) / 1000.0f);
        for (float c : cdf) choices.insert(choices.end(), {std::nextafter(c, 0.0f), c, std::nextafter(c, 1.0f)});
        for (float u : choices) {
            if (!(u < 1.0f)) continue;
            int expected = 0;
            while (expected + 1 < count && !(u < cdf[std::size_t(expected)])) ++expected;
            EXPECT_EQ(lights.sample(tris, u, 0.25f, 0.5f).position.z, float(expected)) << "u " << u;
        }
    }
}

TEST(Statistics, ChiSquareSurvivalMatchesKnownQuantiles) {
    EXPECT_NEAR(test::chi_square_survival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(test::chi_square_survival(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(test::chi_square_survival(124.342, 100), 0.05, 1e-4);
    EXPECT_NEAR(test::normal_two_sided_quantile(0.05), 1.959964, 1e-5);
}

}  // namespace
}  // namespace wt

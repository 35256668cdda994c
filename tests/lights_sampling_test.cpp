// The environment map's importance sampling: the density integrates to one over the sphere,
// samples follow the texels' weights (chi-square), and every sample's pdf is the density at its
// direction; the piecewise-constant distributions and the selection by power.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/lights/environment_light.h"
#include "core/lights/piecewise_constant.h"
#include "core/lights/scene_lights.h"
#include "core/sampling/rng.h"
#include "core/sampling/sampling.h"
#include "lights_test_scenes.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kAlpha = 1e-4;  // false-alarm probability of each goodness-of-fit test
constexpr double kPiD = 3.14159265358979323846;

TEST(EnvironmentSampling, PdfIntegratesToOneOverTheSphere) {
    for (float rotation : {0.0f, 37.0f}) {
        const EnvironmentLight env(test::environment_light(test::test_environment_map(), 2.0f, rotation));
        // Midpoint rule in (u, v), dw = 2 pi^2 sin(theta) du dv; 16 x 16 points per texel, so
        // each texel's constant density is integrated exactly but for sin(theta)'s curvature.
        const int nu = 16 * 16, nv = 8 * 16;
        double integral = 0.0;
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const glm::vec2 p((float(i) + 0.5f) / float(nu), (float(j) + 0.5f) / float(nv));
                const double sin_theta = std::sin(kPiD * double(p.y));
                integral += double(env.pdf(env.direction(p))) * 2.0 * kPiD * kPiD * sin_theta / (double(nu) * double(nv));
            }
        EXPECT_NEAR(integral, 1.0, 2e-3) << "rotation " << rotation;
    }
    const EnvironmentLight constant(test::constant_environment(glm::vec3(1.0f)));
    EXPECT_FLOAT_EQ(constant.pdf(glm::vec3(0.0f, 0.0f, 1.0f)) * 4.0f * kPi, 1.0f);
}

TEST(EnvironmentSampling, SamplesFollowTheTexelWeights) {
    const auto map = test::test_environment_map();
    const EnvironmentLight env(test::environment_light(map, 1.0f, 90.0f));
    const int w = map->width, h = map->height, n = 400000;
    std::vector<double> weight(std::size_t(w * h));
    double total = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y * w + x);
            const glm::vec3 c(map->rgb[3 * i], map->rgb[3 * i + 1], map->rgb[3 * i + 2]);
            weight[i] = luminance(c) * std::sin(kPiD * (y + 0.5) / h);
            total += weight[i];
        }
    std::vector<double> observed(weight.size(), 0.0), expected(weight.size());
    for (std::size_t i = 0; i < weight.size(); ++i) expected[i] = double(n) * weight[i] / total;
    int zero_texel_hits = 0;
    for (int s = 0; s < n; ++s) {
        const EnvironmentSample e = env.sample(random_float(99, uint32_t(s), 0), random_float(99, uint32_t(s), 1));
        ASSERT_NEAR(glm::length(e.direction), 1.0f, 1e-5f);
        // The sample's pdf is the density at its direction, and its radiance the map's there.
        ASSERT_EQ(e.pdf, env.pdf(e.direction));
        const glm::vec2 p = env.map_point(e.direction);
        const int x = std::min(int(p.x * float(w)), w - 1), y = std::min(int(p.y * float(h)), h - 1);
        const std::size_t i = std::size_t(y * w + x);
        observed[i] += 1.0;
        zero_texel_hits += weight[i] == 0.0;
        ASSERT_EQ(e.radiance.x, map->rgb[3 * i]) << "texel " << x << ", " << y;
    }
    EXPECT_EQ(zero_texel_hits, 0);  // the black band is never sampled
    EXPECT_GT(test::chi_square_test(observed, expected).p_value, kAlpha);
}

TEST(EnvironmentSampling, RotationTurnsTheMapAboutZ) {
    const auto map = test::test_environment_map();
    const EnvironmentLight plain(test::environment_light(map));
    const EnvironmentLight turned(test::environment_light(map, 1.0f, 90.0f));
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.8f, 0.4f));
    const glm::vec3 d_turned(-d.y, d.x, d.z);  // d turned 90 degrees about +z
    EXPECT_EQ(plain.radiance(d), turned.radiance(d_turned));
    EXPECT_NE(plain.radiance(d), turned.radiance(d));
}

TEST(PiecewiseConstant1D, SamplesAreInTheirCellWithTheCellsDensity) {
    const PiecewiseConstant1D f({1.0, 0.0, 3.0, 0.0});
    EXPECT_FLOAT_EQ(f.density(0), 1.0f);  // weight / mean (mean 1)
    EXPECT_FLOAT_EQ(f.density(2), 3.0f);
    std::vector<double> observed(4, 0.0);
    const int n = 100000;
    for (int s = 0; s < n; ++s) {
        uint32_t cell = 9;
        const float x = f.sample(random_float(5, uint32_t(s), 0), cell);
        ASSERT_LT(x, 1.0f);
        ASSERT_EQ(uint32_t(x * 4.0f), cell);
        observed[cell] += 1.0;
    }
    EXPECT_EQ(observed[1], 0.0);
    EXPECT_EQ(observed[3], 0.0);
    EXPECT_GT(test::chi_square_test({observed[0], observed[2]}, {0.25 * n, 0.75 * n}).p_value, kAlpha);
}

TEST(LightSelection, ProbabilitiesFollowPowerAndSumToOne) {
    // A point light of 4 pi I = 4 pi, a directional light of E pi r^2 = 2 pi (r = 1), area lights of 6 pi.
    const std::vector<LightDescription> lights = {test::point_light({0, 0, 1}, glm::vec3(1.0f)),
                                                  test::directional_light({0, 0, -1}, glm::vec3(2.0f), 0.0f)};
    const SceneLights s(lights, 6.0 * kPiD, BoundingSphere{glm::vec3(0.0f), 1.0f});
    EXPECT_NEAR(s.area_probability(), 0.5f, 1e-6f);
    EXPECT_NEAR(s.punctual_probability(0), 1.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(s.punctual_probability(1), 1.0f / 6.0f, 1e-6f);
    EXPECT_NEAR(s.area_probability() + s.punctual_probability(0) + s.punctual_probability(1), 1.0f, 1e-6f);
    float rescaled = 0.0f;
    EXPECT_EQ(s.pick(0.25f, rescaled), -1);
    EXPECT_NEAR(rescaled, 0.5f, 1e-6f);
    EXPECT_EQ(s.pick(0.6f, rescaled), 0);
    EXPECT_EQ(s.pick(0.9f, rescaled), 1);
}

TEST(LightSelection, AFaintLightKeepsASampleShare) {
    // Without the floor this point light's share would round to zero in float, and with nee
    // nothing would count its light.
    const std::vector<LightDescription> lights = {test::point_light({0, 0, 1}, glm::vec3(1e-12f))};
    const SceneLights s(lights, 1e6, BoundingSphere{glm::vec3(0.0f), 1.0f});
    EXPECT_GT(s.punctual_probability(0), 1e-4f);
}

}  // namespace
}  // namespace wt

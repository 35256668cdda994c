// Light paths' emission from the listed lights (core/lights/light_emission.h): the rays'
// directions against emission_pdf (chi-square), their power's mean against each light's power
// integrated here from its definition, and the infinite lights' origins on the disk that covers
// the scene.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/lights/light_emission.h"
#include "core/sampling/sampling.h"
#include "lights_test_scenes.h"
#include "statistics.h"

namespace wt {
namespace {

constexpr double kPiD = 3.14159265358979323846;
const BoundingSphere kSphere{glm::vec3(1.0f, -2.0f, 0.5f), 3.0f};

struct Uniforms {
    std::mt19937_64 rng{12345};
    std::uniform_real_distribution<float> u{0.0f, 1.0f};
    float operator()() {
        const float x = u(rng);
        return x < 1.0f ? x : 0.99999994f;
    }
};

// The mean of the rays' power (green channel) with its standard error, over n rays.
template <typename Light>
void expect_mean_power(const Light& light, double expected, int n, const char* what) {
    Uniforms u;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const float a = u(), b = u(), c = u(), d = u();
        const EmittedRay e = sample_emission(light, kSphere, a, b, c, d);
        const double p = e.valid ? double(e.power.y) : 0.0;
        ASSERT_TRUE(std::isfinite(p)) << what;
        sum += p, sum2 += p * p;
    }
    const double mean = sum / n, var = std::max(0.0, sum2 / n - mean * mean);
    const double se = std::sqrt(var / n);
    // 5 standard errors, and a float's rounding over the sum for a constant estimator.
    EXPECT_NEAR(mean, expected, 5.0 * se + 1e-5 * expected) << what;
}

TEST(LightEmission, MeanPowerIsEachLightsPower) {
    const int n = 200000;
    const double I = 2.0, E = 1.5;
    expect_mean_power(make_punctual_light(test::point_light({0, 0, 1}, glm::vec3(1, I, 1))), 4.0 * kPiD * I, n, "point");
    // A spot's power: 2 pi I times its falloff integrated over cos, by the midpoint rule.
    const double cone = 100.0, blend = 0.4;
    double integral = 0.0;
    const int steps = 200000;
    for (int k = 0; k < steps; ++k) integral += test::spot_falloff(-1.0 + 2.0 * (k + 0.5) / steps, cone, blend) * 2.0 / steps;
    expect_mean_power(make_punctual_light(test::spot_light({0, 0, 1}, {0.2f, 0.3f, -1.0f}, glm::vec3(1, I, 1), float(cone),
                                                           float(blend))),
                      2.0 * kPiD * I * integral, n, "spot");
    const double disk = kPiD * double(kSphere.radius) * kSphere.radius;
    expect_mean_power(make_punctual_light(test::directional_light({0.3f, -0.2f, -1.0f}, glm::vec3(1, E, 1), 0.0f)),
                      E * disk, n, "directional");
    // With an angle: radiance E / (pi sin^2 h) over the cone's solid angle 2 pi (1 - cos h).
    const double h = 0.5 * 8.0 * kPiD / 180.0;
    expect_mean_power(make_punctual_light(test::directional_light({0.3f, -0.2f, -1.0f}, glm::vec3(1, E, 1), 8.0f)),
                      E / (kPiD * std::sin(h) * std::sin(h)) * 2.0 * kPiD * (1.0 - std::cos(h)) * disk, n, "sun");
    expect_mean_power(EnvironmentLight(test::constant_environment(glm::vec3(1, 0.7f, 1))), 0.7 * 4.0 * kPiD * disk, n,
                      "constant environment");
    // A map: each texel's radiance times its exact solid angle, (cos theta0 - cos theta1) 2 pi / w.
    const auto map = test::test_environment_map();
    double map_integral = 0.0;
    for (int y = 0; y < map->height; ++y)
        for (int x = 0; x < map->width; ++x) {
            const double solid_angle = (std::cos(kPiD * y / map->height) - std::cos(kPiD * (y + 1) / map->height)) * 2.0 *
                                       kPiD / map->width;
            map_integral += 0.5 * map->rgb[3 * (std::size_t(y) * map->width + x) + 1] * solid_angle;
        }
    expect_mean_power(EnvironmentLight(test::environment_light(map, 0.5f, 30.0f)), map_integral * disk, 400000,
                      "environment map");
}

// Directions in (1 - cos theta, phi) cells about `axis`, against emission_pdf integrated over
// each cell (a 6 x 6 midpoint rule per cell), by Pearson's chi-square.
template <typename Light>
void expect_directions_follow_the_pdf(const Light& light, const glm::vec3& axis, float one_minus_cos_max, const char* what) {
    constexpr int kTheta = 8, kPhi = 8, kSub = 6, n = 200000;
    const Frame frame(axis);
    std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
    Uniforms u;
    int outside = 0;
    for (int i = 0; i < n; ++i) {
        const float a = u(), b = u(), c = u(), d = u();
        const EmittedRay e = sample_emission(light, kSphere, a, b, c, d);
        const glm::vec3 l(glm::dot(e.direction, frame.tangent), glm::dot(e.direction, frame.bitangent), glm::dot(e.direction, axis));
        const double t = (1.0 - double(l.z)) / one_minus_cos_max;
        const double phi = std::atan2(double(l.y), double(l.x)) + kPiD;
        if (!(t >= 0.0 && t < 1.0)) {
            ++outside;
            continue;
        }
        observed[std::size_t(int(t * kTheta) * kPhi + std::min(kPhi - 1, int(phi / (2 * kPiD) * kPhi)))] += 1.0;
        // The ray's own pdf is the one emission_pdf gives its direction.
        const EmissionPdf p = emission_pdf(light, kSphere, e.direction);
        ASSERT_NEAR(p.direction, e.pdf_direction, 1e-4f * e.pdf_direction) << what;
        ASSERT_NEAR(p.position, e.pdf_position, 1e-4f * e.pdf_position) << what;
    }
    EXPECT_EQ(outside, 0) << what;
    for (int ct = 0; ct < kTheta; ++ct)
        for (int cp = 0; cp < kPhi; ++cp)
            for (int s = 0; s < kSub * kSub; ++s) {
                const double t = (ct + (s % kSub + 0.5) / kSub) / kTheta, phi = (cp + (s / kSub + 0.5) / kSub) / kPhi * 2 * kPiD - kPiD;
                const double cos_theta = 1.0 - t * one_minus_cos_max, sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
                const glm::vec3 d = frame.to_world(glm::vec3(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)), float(cos_theta)));
                // d(solid angle) = d(1 - cos theta) d phi = one_minus_cos_max dt dphi.
                const double cell = one_minus_cos_max / kTheta * 2 * kPiD / kPhi / (kSub * kSub);
                expected[std::size_t(ct * kPhi + cp)] += n * emission_pdf(light, kSphere, glm::normalize(d)).direction * cell;
            }
    const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
    EXPECT_GT(chi.p_value, 1e-4) << what << ": chi^2 " << chi.statistic << " with " << chi.degrees_of_freedom << " dof";
}

TEST(LightEmission, DirectionsFollowEmissionPdf) {
    const PunctualLight point = make_punctual_light(test::point_light({0, 0, 1}, glm::vec3(1)));
    expect_directions_follow_the_pdf(point, glm::vec3(0, 0, 1), 2.0f, "point");
    const PunctualLight spot = make_punctual_light(test::spot_light({0, 0, 1}, {0.2f, 0.3f, -1.0f}, glm::vec3(1), 100.0f, 0.4f));
    expect_directions_follow_the_pdf(spot, spot.axis, 1.0f - spot.cos_outer, "spot");
    const PunctualLight sun = make_punctual_light(test::directional_light({0.3f, -0.2f, -1.0f}, glm::vec3(1), 8.0f));
    expect_directions_follow_the_pdf(sun, sun.axis, sun.one_minus_cos_cone, "sun");
}

// An infinite light's rays start on the disk of the bounding sphere that faces the light,
// uniformly: the squared distance from the disk's centre over r^2 is uniform in [0, 1).
TEST(LightEmission, InfiniteLightsStartUniformlyOnTheDiskFacingThem) {
    const PunctualLight sun = make_punctual_light(test::directional_light({0.3f, -0.2f, -1.0f}, glm::vec3(1), 0.0f));
    const EnvironmentLight sky(test::environment_light(test::test_environment_map()));
    for (int which = 0; which < 2; ++which) {
        Uniforms u;
        constexpr int kCells = 10, n = 100000;
        std::vector<double> observed(kCells, 0.0), expected(kCells, double(n) / kCells);
        for (int i = 0; i < n; ++i) {
            const float a = u(), b = u(), c = u(), d = u();
            const EmittedRay e = which == 0 ? sample_emission(sun, kSphere, a, b, c, d) : sample_emission(sky, kSphere, a, b, c, d);
            if (!e.valid) continue;
            const glm::dvec3 offset = glm::dvec3(e.origin) - glm::dvec3(kSphere.center);
            const double along = glm::dot(offset, glm::dvec3(e.direction));
            ASSERT_NEAR(along, -double(kSphere.radius), 1e-4) << "the disk is a radius upstream of the centre";
            const double r2 = (glm::dot(offset, offset) - along * along) / (double(kSphere.radius) * kSphere.radius);
            ASSERT_LE(r2, 1.0 + 1e-5);
            observed[std::size_t(std::min(kCells - 1, int(r2 * kCells)))] += 1.0;
            EXPECT_FLOAT_EQ(e.pdf_position, float(1.0 / (kPiD * kSphere.radius * kSphere.radius)));
        }
        double total = 0.0;
        for (double o : observed) total += o;
        for (double& x : expected) x = total / kCells;
        const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
        EXPECT_GT(chi.p_value, 1e-4) << (which == 0 ? "sun" : "sky") << ": chi^2 " << chi.statistic;
    }
}

}  // namespace
}  // namespace wt

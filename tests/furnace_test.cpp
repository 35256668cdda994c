// White furnace: inside a closed room whose every surface has albedo rho and emits Le, the
// radiance everywhere is Le / (1 - rho) (the Neumann series Le * sum rho^k). Any energy lost or
// gained by a BSDF, light sampler, Russian roulette or the scheduling shows up as a bias here.

#include <cmath>

#include <gtest/gtest.h>

#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"

namespace wt {
namespace {

struct FurnaceCase {
    const char* name;
    Integrator integrator;
    MaterialType type;
    float rho;
};

class WhiteFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(WhiteFurnace, EveryPixelConvergesToLeOverOneMinusRho) {
    const FurnaceCase c = GetParam();
    const float le = 1.0f;
    // Oren-Nayar loses energy by design (its albedo is below rho), so it runs at sigma 0 here;
    // its roughness is tested against quadrature in bsdf_test.
    const SceneDescription d = test::furnace_cube(c.rho, le, c.type, 0.0f);
    const test::RenderedFilm r = test::render_film(d, c.integrator);
    const double expected = le / (1.0 - c.rho);
    const int pixels = d.settings.width * d.settings.height;

    // Secondary vertices can land near the cube's concave edges, where next-event estimation
    // has a heavy tail; a pixel's own 64 samples rarely contain a tail event and underestimate
    // its variance. All pixels estimate the same quantity with about the same spread, so the
    // per-sample variance is pooled over the image, which does contain the tail events.
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
    const double z = test::normal_two_sided_quantile(2.0 * per_pixel_alpha);
    const int allowed_low = test::binomial_upper_bound(pixels, per_pixel_alpha, 1e-6);
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
    EXPECT_NEAR(image_mean, expected, 4.5 * pixel_stderr / std::sqrt(double(pixels)));
    EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, WhiteFurnace,
    ::testing::Values(FurnaceCase{"wavefront_lambert_half", Integrator::wavefront, MaterialType::lambertian, 0.5f},
                      FurnaceCase{"wavefront_lambert_bright", Integrator::wavefront, MaterialType::lambertian, 0.8f},
                      FurnaceCase{"wavefront_oren_nayar", Integrator::wavefront, MaterialType::oren_nayar, 0.5f},
                      FurnaceCase{"reference_lambert_half", Integrator::reference, MaterialType::lambertian, 0.5f},
                      FurnaceCase{"reference_lambert_bright", Integrator::reference, MaterialType::lambertian, 0.8f}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(WhiteFurnace, BlackRoomShowsOnlyEmission) {
    // rho = 0: the answer is Le exactly, with zero variance, on every sample.
    const SceneDescription d = test::furnace_cube(0.0f, 1.5f);
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) {
        EXPECT_NEAR(r.film.pixel_mean(p).y, 1.5, 1e-6) << "pixel " << p;
    }
}

}  // namespace
}  // namespace wt

// The estimator options (core/path/estimator.h) in the whole renderer: each one in the white
// furnace, bit-identical between the integrators and for any thread count, in statistical
// agreement with the default on the hexroom; MIS against an analytic answer and the variance of
// its two strategies; the indirect clamp's bias where it should be and nowhere else.

#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"
#include "white_furnace_check.h"

namespace wt {
namespace {

SceneDescription with_estimator(SceneDescription d, SamplerKind sampler, LightSampling lights, float clamp = 0.0f) {
    d.settings.estimator.sampler = sampler;
    d.settings.estimator.light_sampling = lights;
    d.settings.estimator.clamp_indirect = clamp;
    return d;
}

std::string describe(const EstimatorSettings& e) {
    return std::string(name_of(e.sampler)) + "/" + name_of(e.light_sampling) + "/clamp " + std::to_string(e.clamp_indirect);
}

struct OptionCase {
    SamplerKind sampler;
    LightSampling lights;
    float clamp;
};
constexpr OptionCase kOptions[] = {{SamplerKind::independent, LightSampling::nee, 0.0f},
                                   {SamplerKind::sobol, LightSampling::nee, 0.0f},
                                   {SamplerKind::stratified, LightSampling::mis, 0.0f},
                                   {SamplerKind::sobol, LightSampling::mis, 0.0f},
                                   {SamplerKind::stratified, LightSampling::nee, 1.0f},
                                   {SamplerKind::sobol, LightSampling::mis, 1.0f}};

TEST(EstimatorOptions, WhiteFurnaceWithEveryUnbiasedOption) {
    for (const OptionCase& o : kOptions) {
        if (o.clamp > 0.0f) continue;  // biased by design
        for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
            const SceneDescription d = with_estimator(test::furnace_cube(0.5f, 1.0f), o.sampler, o.lights);
            SCOPED_TRACE(describe(d.settings.estimator) + (integrator == Integrator::wavefront ? " wavefront" : " reference"));
            test::expect_white_furnace(test::render_film(d, integrator), d, 1.0 / (1.0 - 0.5));
        }
    }
}

TEST(EstimatorOptions, BothIntegratorsAndAnyThreadCountGiveTheSameBits) {
    for (const OptionCase& o : kOptions) {
        const SceneDescription d = with_estimator(test::hexroom(21, 19, 8, 5), o.sampler, o.lights, o.clamp);
        SCOPED_TRACE(describe(d.settings.estimator));
        const test::RenderedFilm ref = test::render_film(d, Integrator::reference, 2);
        const test::RenderedFilm wave = test::render_film(d, Integrator::wavefront, 2);
        const test::RenderedFilm wave_other = test::render_film(d, Integrator::wavefront, 3, 5, 7);
        EXPECT_TRUE(test::films_bit_identical(wave.film, ref.film));
        EXPECT_TRUE(test::films_bit_identical(wave.film, wave_other.film));
        EXPECT_EQ(wave.result.counts.shadow_rays, ref.result.counts.shadow_rays);
        EXPECT_EQ(wave.result.counts.nonfinite_samples, 0u);
        // And the option changes the image: it is not the default under another name. Compared
        // with the caustics left to the camera paths, where the clamp has fireflies to cut (with
        // the default photons this small render has none above 1).
        SceneDescription option_alone = d, plain = test::hexroom(21, 19, 8, 5);
        option_alone.settings.estimator.caustics = plain.settings.estimator.caustics = CausticPaths::path;
        EXPECT_FALSE(test::films_bit_identical(test::render_film(option_alone, Integrator::wavefront, 2).film,
                                               test::render_film(plain, Integrator::wavefront, 2).film));
    }
}

// The unbiased options estimate the default's image: per-pixel two-sample z-tests (variances
// from each film's own samples) with a binomial allowance, and the same over the image.
// The hexroom with its caustics left to the camera paths: these tests are about the camera
// paths' estimators, and their per-pixel tests need each pixel's own variance, which splats
// (light tracing's) do not have.
SceneDescription hexroom_camera_paths(int width, int height, int spp, uint64_t seed) {
    SceneDescription d = test::hexroom(width, height, spp, seed);
    d.settings.estimator.caustics = CausticPaths::path;
    return d;
}

TEST(EstimatorOptions, UnbiasedOptionsAgreeWithTheDefaultOnHexroom) {
    const SceneDescription base_desc = hexroom_camera_paths(24, 24, 128, /*seed=*/1);
    const test::RenderedFilm base = test::render_film(base_desc, Integrator::wavefront);
    for (const OptionCase& o : kOptions) {
        if (o.clamp > 0.0f) continue;
        const SceneDescription d = with_estimator(hexroom_camera_paths(24, 24, 128, /*seed=*/2), o.sampler, o.lights);
        SCOPED_TRACE(describe(d.settings.estimator));
        const test::RenderedFilm other = test::render_film(d, Integrator::wavefront);
        test::expect_films_agree(base.film, other.film, [&](uint32_t pixel) {
            return test::replay_command("scenes/hexroom.json", d, pixel, 0) + " --sampler " + name_of(o.sampler) +
                   " --light-sampling " + name_of(o.lights);
        });
    }
}

// A diffuse floor (albedo rho) under a square light of side a at height h, emitting Le
// downwards, seen at the point below the light's centre through a 1x1 image with a tiny field of
// view. Only direct light reaches it: L = rho Le F, F the form factor from the point to the
// square. BSDF sampling alone would score rho Le with probability F: variance (rho Le)^2 F (1 - F).
struct FloorUnderLight {
    SceneDescription scene;
    double expected, bsdf_only_variance;
};

FloorUnderLight floor_under_light(float side, float height, int spp) {
    const float rho = 0.5f, le = 4.0f;
    SceneDescription d;
    Material floor;
    floor.name = "floor";
    floor.albedo = glm::vec3(rho);
    Material light;
    light.name = "light";
    light.emission = glm::vec3(le);
    d.materials = {floor, light};
    const float f = 100.0f, s = 0.5f * side;
    TriangleMesh ground;  // facing up
    ground.vertices = {{-f, -f, 0}, {f, -f, 0}, {f, f, 0}, {-f, f, 0}};
    ground.triangles = {{0, 1, 2}, {0, 2, 3}};
    ground.parallelogram = true;
    TriangleMesh lamp;  // facing down: clockwise seen from above
    lamp.vertices = {{-s, -s, height}, {-s, s, height}, {s, s, height}, {s, -s, height}};
    lamp.triangles = {{0, 1, 2}, {0, 2, 3}};
    lamp.parallelogram = true;
    lamp.material = 1;
    d.meshes = {ground, lamp};
    d.camera.eye = glm::vec3(0.3f * height, 0.0f, 0.2f * height);
    d.camera.look_at = glm::vec3(0.0f);
    d.camera.up = glm::vec3(0, 0, 1);
    d.camera.fov_degrees = 0.001f;
    d.settings.width = d.settings.height = 1;
    d.settings.spp = spp;
    d.settings.shadow_rays = 1;
    // Point to a parallel rectangle with a corner above it (e.g. Howell's catalogue, B-2), four times.
    const double x = double(s) / height;
    const double corner = (x / std::sqrt(1 + x * x) * std::atan(x / std::sqrt(1 + x * x))) * 2.0 / (2.0 * M_PI);
    const double form_factor = 4.0 * corner;
    const double hit = rho * le;
    return {d, hit * form_factor, hit * hit * form_factor * (1.0 - form_factor)};
}

TEST(MultipleImportance, BeatsTheWorseStrategyOnSmallAndLargeLights) {
    for (const bool large : {false, true}) {
        const FloorUnderLight c = floor_under_light(large ? 40.0f : 0.2f, 1.0f, 1 << 15);
        SCOPED_TRACE(large ? "large light" : "small light");
        double variance[2];
        for (const LightSampling lights : {LightSampling::nee, LightSampling::mis}) {
            const SceneDescription d = with_estimator(c.scene, SamplerKind::independent, lights);
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront);
            const double mean = r.film.pixel_mean(0).y;
            const double v = r.film.pixel_sample_variance(0).y;
            variance[lights == LightSampling::mis] = v;
            std::cout << (large ? "large" : "small") << " light, " << name_of(lights) << ": mean " << mean << " (exact "
                      << c.expected << "), variance " << v << " (BSDF sampling alone " << c.bsdf_only_variance << ")\n";
            EXPECT_NEAR(mean, c.expected, 5.0 * std::sqrt(v / d.settings.spp) + 1e-4 * c.expected) << name_of(lights);
        }
        const double nee = variance[0], mis = variance[1];
        EXPECT_LT(mis, std::max(nee, c.bsdf_only_variance));
        // Each light size has a clearly worse strategy, and MIS is far below it.
        if (large) {
            EXPECT_GT(nee, c.bsdf_only_variance);
            EXPECT_LT(mis, 0.5 * nee);
        } else {
            EXPECT_GT(c.bsdf_only_variance, nee);
            EXPECT_LT(mis, 0.5 * c.bsdf_only_variance);
        }
    }
}

// The clamp touches indirect light only (see clamp_indirect in core/path/estimator.h).
TEST(ClampIndirect, ANeverBindingClampGivesTheSameBits) {
    const SceneDescription d = test::hexroom(24, 24, 8, 3);
    const test::RenderedFilm off = test::render_film(d, Integrator::wavefront);
    const test::RenderedFilm huge = test::render_film(with_estimator(d, SamplerKind::stratified, LightSampling::nee, 1e30f),
                                                      Integrator::wavefront);
    EXPECT_TRUE(test::films_bit_identical(off.film, huge.film));
}

TEST(ClampIndirect, DirectLightIsNeverClamped) {
    // On the floor under a light every contribution is direct: even a tiny clamp changes nothing.
    for (const LightSampling lights : {LightSampling::nee, LightSampling::mis}) {
        const SceneDescription d = with_estimator(floor_under_light(2.0f, 1.0f, 256).scene, SamplerKind::stratified, lights);
        const test::RenderedFilm off = test::render_film(d, Integrator::wavefront);
        const test::RenderedFilm tiny =
            test::render_film(with_estimator(d, SamplerKind::stratified, lights, 1e-6f), Integrator::wavefront);
        EXPECT_TRUE(test::films_bit_identical(off.film, tiny.film)) << name_of(lights);
        EXPECT_GT(off.film.pixel_mean(0).y, 1e-3);
    }
}

TEST(ClampIndirect, LowersTheMeanAndTheVarianceWhereCausticsMakeFireflies) {
    // The hexroom's glass spheres focus the light into caustics, found only by rare paths with
    // large weights. The same seed draws the same paths, so every clamped sample is at most the
    // unclamped one: the mean can only drop, and must drop measurably (the bias), and the
    // variance with it.
    const SceneDescription d = hexroom_camera_paths(32, 32, 32, 7);
    const test::RenderedFilm off = test::render_film(d, Integrator::wavefront);
    const test::RenderedFilm on =
        test::render_film(with_estimator(d, SamplerKind::stratified, LightSampling::nee, 1.0f), Integrator::wavefront);
    double mean_off = 0.0, mean_on = 0.0, variance_off = 0.0, variance_on = 0.0;
    int brighter = 0;
    for (uint32_t p = 0; p < 32u * 32u; ++p) {
        for (int c = 0; c < 3; ++c) {
            brighter += on.film.pixel_sum(p)[c] > off.film.pixel_sum(p)[c];
            mean_off += off.film.pixel_mean(p)[c], mean_on += on.film.pixel_mean(p)[c];
            variance_off += off.film.pixel_sample_variance(p)[c], variance_on += on.film.pixel_sample_variance(p)[c];
        }
    }
    std::cout << "image mean " << mean_off / (3 * 1024) << " -> " << mean_on / (3 * 1024) << ", mean variance "
              << variance_off / (3 * 1024) << " -> " << variance_on / (3 * 1024) << "\n";
    EXPECT_EQ(brighter, 0);
    EXPECT_LT(mean_on, 0.99 * mean_off);
    EXPECT_GT(mean_on, 0.5 * mean_off);
    EXPECT_LT(variance_on, 0.8 * variance_off);
}

}  // namespace
}  // namespace wt

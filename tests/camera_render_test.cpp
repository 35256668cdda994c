// The cameras in the renderer: the thin lens and the pixel filters estimated by light tracing
// agree with the camera paths' estimate of the same caustic, both integrators give the same bits
// with them, a pinhole of aperture 0 renders the pinhole's bits, and Mitchell's signed sample
// weights reach the film and keep a constant image's mean.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "mirror_caustic.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

// The mirror caustic (mirror_caustic.h) with a light large enough for the camera paths to find
// it by chance, through a wide lens focused near the light, well in front of the floor: the
// caustic and the light's shadow in it are blurred over several pixels.
SceneDescription lens_caustic(int spp, uint64_t seed, CausticPaths caustics, float aperture, PixelFilterSettings filter) {
    SceneDescription d = test::MirrorCaustic().scene(spp, seed, caustics);
    const float h = 0.45f;
    d.meshes[2] = test::quad({-h, -h, 1}, {h, -h, 1}, {h, h, 1}, {-h, h, 1}, 2);  // emits +z
    d.camera.aperture_radius = aperture;
    d.camera.focus_distance = 0.8f;
    d.settings.filter = filter;
    return d;
}

constexpr int kBlock = 4;

// Each kBlock x kBlock block's mean radiance (or its splats' part alone), one vector per seed.
std::vector<std::vector<double>> block_means(int spp, CausticPaths caustics, float aperture, PixelFilterSettings filter,
                                             int seeds, bool splats_only = false) {
    std::vector<std::vector<double>> out;
    for (int s = 0; s < seeds; ++s) {
        const SceneDescription d = lens_caustic(spp, uint64_t(100 + s), caustics, aperture, filter);
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        const int w = d.settings.width, bw = w / kBlock;
        std::vector<double> blocks(size_t(bw * (d.settings.height / kBlock)), 0.0);
        for (uint32_t p = 0; p < r.film.pixel_total(); ++p) {
            const glm::dvec3 v = splats_only ? r.film.pixel_splat_mean(p) : r.film.pixel_mean(p);
            blocks[size_t((int(p) / w / kBlock) * bw + (int(p) % w) / kBlock)] += (v.x + v.y + v.z) / (3.0 * kBlock * kBlock);
        }
        out.push_back(blocks);
    }
    return out;
}

struct BlockStats {
    std::vector<double> mean, variance_of_mean;
};
BlockStats stats(const std::vector<std::vector<double>>& per_seed) {
    const size_t n = per_seed.size(), blocks = per_seed[0].size();
    BlockStats s{std::vector<double>(blocks, 0.0), std::vector<double>(blocks, 0.0)};
    for (size_t b = 0; b < blocks; ++b) {
        for (const auto& v : per_seed) s.mean[b] += v[b] / double(n);
        for (const auto& v : per_seed) s.variance_of_mean[b] += (v[b] - s.mean[b]) * (v[b] - s.mean[b]) / double((n - 1) * n);
    }
    return s;
}

// How many blocks two estimates differ in by more than z standard errors of the difference.
int blocks_apart(const BlockStats& a, const BlockStats& b, double z) {
    int apart = 0;
    for (size_t i = 0; i < a.mean.size(); ++i)
        apart += std::fabs(a.mean[i] - b.mean[i]) > z * std::sqrt(a.variance_of_mean[i] + b.variance_of_mean[i]);
    return apart;
}

// Light tracing connects through a sampled point of the lens and splats by the filter; the camera
// paths sample the lens and the filter themselves. Every block agrees within 4.5 standard errors
// (36 blocks: a false alarm below 3e-4), and the light-traced part of the image (the splats)
// differs from the pinhole's: the lens's blur of the caustic is visible at this resolution, so
// the agreement means something (a connection to the lens's centre alone fails it).
void expect_light_tracing_agrees(PixelFilterSettings filter) {
    const int seeds = 8;
    const float aperture = 0.25f;
    const BlockStats path = stats(block_means(512, CausticPaths::path, aperture, filter, seeds));
    const BlockStats traced = stats(block_means(32, CausticPaths::light_tracing, aperture, filter, seeds));
    const BlockStats traced_splats = stats(block_means(32, CausticPaths::light_tracing, aperture, filter, seeds, true));
    const BlockStats pinhole_splats = stats(block_means(32, CausticPaths::light_tracing, 0.0f, filter, seeds, true));
    EXPECT_EQ(blocks_apart(path, traced, 4.5), 0) << name_of(filter.kind) << " " << filter.width;
    EXPECT_GE(blocks_apart(traced_splats, pinhole_splats, 6.0), 3) << "the lens should blur the caustic";
}

TEST(CameraRender, ThinLensLightTracingAgreesWithPathTracing) {
    expect_light_tracing_agrees(PixelFilterSettings{});
}

TEST(CameraRender, ThinLensAndGaussianFilterLightTracingAgreesWithPathTracing) {
    expect_light_tracing_agrees(PixelFilterSettings{FilterKind::gaussian, 2.5f});
}

// Mitchell's negative lobes: the camera samples' weights and light tracing's splat weights carry
// the sign, and the two estimates of the caustic still agree.
TEST(CameraRender, ThinLensAndMitchellFilterLightTracingAgreesWithPathTracing) {
    expect_light_tracing_agrees(PixelFilterSettings{FilterKind::mitchell, 4.0f});
}

// Each splat's expected total over the pixels is the filter's integral, 1, whatever its shape: the
// light-traced part of the image sums to the same with Mitchell as with the box (the same light
// paths, the caustic far from the border), within 5 standard errors of the difference between
// seeds. Splats by |f| without their sign would add (integral |f| / integral f)^2 = 1.145 times it.
TEST(CameraRender, MitchellSplatsKeepTheLightTracedTotal) {
    const int seeds = 6;
    std::vector<double> ratios;
    for (int s = 0; s < seeds; ++s) {
        double total[2] = {0.0, 0.0};
        for (const int mitchell : {0, 1}) {
            const PixelFilterSettings filter = mitchell ? PixelFilterSettings{FilterKind::mitchell, 4.0f} : PixelFilterSettings{};
            const SceneDescription d = lens_caustic(64, uint64_t(40 + s), CausticPaths::light_tracing, 0.0f, filter);
            const Film film = test::render_film(d, Integrator::wavefront, 2).film;
            for (uint32_t p = 0; p < film.pixel_total(); ++p) total[mitchell] += film.pixel_splat_mean(p).x;
        }
        ASSERT_GT(total[0], 0.0);
        ratios.push_back(total[1] / total[0]);
    }
    double mean = 0.0, variance = 0.0;
    for (double r : ratios) mean += r / seeds;
    for (double r : ratios) variance += (r - mean) * (r - mean) / (seeds - 1);
    const double standard_error = std::sqrt(variance / seeds);
    EXPECT_NEAR(mean, 1.0, 5.0 * standard_error) << "spread " << standard_error;
    EXPECT_LT(5.0 * standard_error, 0.05) << "too noisy to tell the sign";
}

// Both integrators, any threads, tiles, ISA and accelerator: the same bits with the lens, a wide
// filter and light tracing, for each sampler; and for the orthographic camera.
TEST(CameraRender, LensFilterAndOrthographicAreTheSameBitsForAnySchedule) {
    for (SamplerKind sampler : {SamplerKind::independent, SamplerKind::stratified, SamplerKind::sobol}) {
        SceneDescription d = lens_caustic(4, 7, CausticPaths::light_tracing, 0.2f, {FilterKind::blackman_harris, 3.0f});
        d.settings.estimator.sampler = sampler;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        EXPECT_GT(r.result.counts.camera_connections, 0u);
        test::expect_same_film_for_any_schedule(d, r.film);
    }
    for (SamplerKind sampler : {SamplerKind::independent, SamplerKind::sobol}) {
        SceneDescription d = lens_caustic(4, 7, CausticPaths::light_tracing, 0.2f, {FilterKind::mitchell, 4.0f});
        d.settings.estimator.sampler = sampler;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        EXPECT_GT(r.result.counts.camera_connections, 0u);
        test::expect_same_film_for_any_schedule(d, r.film);
    }
    SceneDescription ortho = test::hexroom(16, 12, 4, 3);
    ortho.camera.projection = Projection::orthographic;
    ortho.camera.width_world = 6.0f;
    ortho.settings.filter = {FilterKind::gaussian, 1.5f};
    const test::RenderedFilm r = test::render_film(ortho, Integrator::wavefront, 2);
    EXPECT_EQ(r.result.counts.light_paths, 0u);  // its caustics are the camera paths'
    test::expect_same_film_for_any_schedule(ortho, r.film);
}

// A thin lens of aperture 0 is the pinhole, whatever its focus; a real aperture is not; and an
// explicit box of width 1 is the default film.
TEST(CameraRender, ApertureZeroAndUnitBoxAreThePinholeBits) {
    const SceneDescription pinhole = test::hexroom(16, 12, 4, 5);
    const Film expected = test::render_film(pinhole, Integrator::wavefront, 2).film;
    SceneDescription zero = pinhole;
    zero.camera.focus_distance = 1.7f;
    zero.settings.filter = {FilterKind::box, 1.0f};
    EXPECT_TRUE(test::render_film(zero, Integrator::wavefront, 2).film == expected);
    EXPECT_TRUE(test::render_film(zero, Integrator::reference, 2).film == expected);
    SceneDescription lens = zero;
    lens.camera.aperture_radius = 0.01f;
    EXPECT_FALSE(test::render_film(lens, Integrator::wavefront, 2).film == expected);
    SceneDescription wide = pinhole;
    wide.settings.filter = {FilterKind::box, 1.5f};
    EXPECT_FALSE(test::render_film(wide, Integrator::wavefront, 2).film == expected);
}

// A scene whose every camera ray sees radiance 1 (a closed cube of emitters with albedo 0): with
// the box every sample is 1, so every pixel is exactly 1; with Mitchell each sample is its weight,
// +-(integral |f| / integral f)^2, whose mean is 1: the image's mean stays 1 within 5 standard
// errors (from the film's own per-pixel variances), the weights vary (they reach the film) and
// are negative in some samples (some pixel's variance needs values on both sides of 1 far
// enough apart), and both integrators give the same bits.
TEST(CameraRender, MitchellKeepsAConstantImagesMeanWithSignedWeights) {
    SceneDescription d = test::furnace_cube(0.0f, 1.0f);
    d.settings.spp = 64;
    const Film box = test::render_film(d, Integrator::wavefront, 2).film;
    for (uint32_t p = 0; p < box.pixel_total(); ++p) ASSERT_EQ(box.pixel_mean(p), glm::dvec3(1.0)) << p;

    d.settings.filter = {FilterKind::mitchell, 4.0f};
    const Film mitchell = test::render_film(d, Integrator::wavefront, 2).film;
    EXPECT_TRUE(mitchell == test::render_film(d, Integrator::reference, 3).film);
    double sum = 0.0, variance_of_sum = 0.0, largest_variance = 0.0;
    uint64_t samples = 0;
    for (uint32_t p = 0; p < mitchell.pixel_total(); ++p) {
        const uint32_t n = mitchell.pixel_count(p);
        sum += mitchell.pixel_sum(p).x;
        variance_of_sum += mitchell.pixel_sample_variance(p).x * n;
        largest_variance = std::max(largest_variance, mitchell.pixel_sample_variance(p).x);
        samples += n;
        EXPECT_EQ(mitchell.pixel_sum(p).x, mitchell.pixel_sum(p).y);
    }
    EXPECT_NEAR(sum / double(samples), 1.0, 5.0 * std::sqrt(variance_of_sum) / double(samples));
    // Weights of +c^2 and -c^2 (c a little above 1) in one pixel's 64 samples: variance near 4
    // times the negative share; positive weights alone would all be c^2 with variance 0.
    EXPECT_GT(largest_variance, 0.05);
}

}  // namespace
}  // namespace wt

// Light tracing of caustics (kernels/caustics): its estimate against an analytic caustic that
// shares no code with the renderer, against the camera paths' own estimate of the same paths,
// and its determinism (threads, integrators, ranges, checkpoints).

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/camera/camera.h"
#include "core/checkpoint/checkpoint.h"
#include "core/system/version.h"
#include "kernels/caustics/light_path.h"
#include "camera_importance.h"
#include "mirror_caustic.h"
#include "render_helpers.h"
#include "statistics.h"
#include "test_scenes.h"

namespace wt {
namespace {

// What the camera sees through film position (fx, fy) (test::view_direction): the floor point,
// or nothing.
std::optional<glm::dvec3> floor_point(const SceneDescription& d, double fx, double fy) {
    const glm::dvec3 eye(d.camera.eye), dir = test::view_direction(d, fx, fy);
    if (!(dir.z < 0.0)) return std::nullopt;
    const glm::dvec3 x = eye + (-eye.z / dir.z) * dir;
    // Not behind the light's black back, which the view crosses at z = 1.
    const glm::dvec3 at_light = eye + ((1.0 - eye.z) / dir.z) * dir;
    const double h = test::MirrorCaustic::half_side + 1e-3;
    if (eye.z > 1.0 && std::fabs(at_light.x) <= h && std::fabs(at_light.y) <= h) return std::nullopt;
    return x;
}

// Pixel blocks of the mirror-caustic image: the analytic mean radiance over each block's
// pixels, and the render's, per seed.
struct Block {
    int x0, y0;
    double analytic = 0.0;
    std::vector<double> rendered;  // one per seed
};
constexpr int kBlock = 6;

std::vector<Block> analytic_blocks(const SceneDescription& d) {
    std::vector<Block> blocks;
    const int n = 8;  // n x n points per pixel for the analytic mean
    for (int by = 0; by < d.settings.height; by += kBlock)
        for (int bx = 0; bx < d.settings.width; bx += kBlock) {
            Block b{bx, by, 0.0, {}};
            bool usable = true;
            for (int y = by; y < by + kBlock && usable; ++y)
                for (int x = bx; x < bx + kBlock && usable; ++x)
                    for (int j = 0; j < n * n && usable; ++j) {
                        const auto p = floor_point(d, x + (j % n + 0.5) / n, y + (j / n + 0.5) / n);
                        // Only the floor well away from the light's shadow and the view's horizon.
                        if (!p || test::MirrorCaustic::may_be_shadowed(*p) || std::fabs(p->x) > 5 || std::fabs(p->y) > 5) {
                            usable = false;
                            break;
                        }
                        b.analytic += test::MirrorCaustic::rho / M_PI * test::MirrorCaustic::reflectance *
                                      test::MirrorCaustic::image_irradiance(*p);
                    }
            if (!usable) continue;
            b.analytic /= double(kBlock * kBlock * n * n);
            blocks.push_back(b);
        }
    return blocks;
}

// Renders `seeds` independent seeds and holds every block's mean over them to the analytic
// value, within a Student-t bound of the seed-to-seed spread (Bonferroni over the blocks), and
// that bound to at most `resolution` of the value, so the test can see a bias that large.
void expect_mirror_caustic(CausticPaths caustics, int spp, float light_paths_per_pixel, int seeds, double resolution) {
    const test::MirrorCaustic m;
    std::vector<Block> blocks = analytic_blocks(m.scene(spp, 0, caustics));
    ASSERT_GE(blocks.size(), 4u) << "the view must hold blocks of unshadowed floor";
    for (int s = 0; s < seeds; ++s) {
        SceneDescription d = m.scene(spp, uint64_t(1000 + s), caustics);
        d.settings.estimator.light_paths_per_pixel = light_paths_per_pixel;
        const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
        for (Block& b : blocks) {
            double sum = 0.0;
            for (int y = b.y0; y < b.y0 + kBlock; ++y)
                for (int x = b.x0; x < b.x0 + kBlock; ++x) sum += r.film.pixel_mean(uint32_t(y * d.settings.width + x)).y;
            b.rendered.push_back(sum / (kBlock * kBlock));
        }
    }
    // Two-sided t quantile for 1e-4 per block (a dozen blocks: 1e-3 for the test) with
    // seeds - 1 = 11 degrees of freedom: 5.45.
    ASSERT_EQ(seeds, 12);
    const double t = 5.45;
    for (const Block& b : blocks) {
        double mean = 0.0, var = 0.0;
        for (double v : b.rendered) mean += v;
        mean /= seeds;
        for (double v : b.rendered) var += (v - mean) * (v - mean);
        const double standard_error = std::sqrt(var / (seeds - 1) / seeds);
        EXPECT_NEAR(mean, b.analytic, t * standard_error + 1e-3 * b.analytic)
            << "block at pixel (" << b.x0 << ", " << b.y0 << "), " << name_of(caustics) << ", " << seeds
            << " seeds from 1000 at " << spp << " spp (relative error " << mean / b.analytic - 1.0 << ")";
        EXPECT_LT(t * standard_error, resolution * b.analytic) << "block at pixel (" << b.x0 << ", " << b.y0 << ")";
    }
}

TEST(LightTracing, MirrorCausticMatchesTheAnalyticIrradianceOfTheLightsImage) {
    expect_mirror_caustic(CausticPaths::light_tracing, 32, 8.0f, 12, 0.08);
}

// The camera paths alone estimate the same caustic, with far more noise for the same work: the
// analytic answer holds both, so each estimator is checked against something neither computes.
TEST(LightTracing, MirrorCausticFromCameraPathsAloneMatchesTheSameAnswer) {
    expect_mirror_caustic(CausticPaths::path, 1024, 1.0f, 12, 0.3);
}

TEST(LightTracing, SceneWithoutSpecularSurfacesTracesNoLightPaths) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    d.settings.estimator.caustics = CausticPaths::light_tracing;
    EXPECT_FALSE(light_traces_caustics(d));
    const Scene scene = build_scene(d);
    EXPECT_FALSE(scene.light_traces_caustics);
    EXPECT_TRUE(render_film_channels(scene, AovSelection{}).empty());
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
    EXPECT_EQ(r.result.counts.light_paths, 0u);
    // And a scene with them does (the default), and only when asked.
    SceneDescription h = test::hexroom(8, 8, 1);
    EXPECT_TRUE(light_traces_caustics(h));
    h.settings.estimator.caustics = CausticPaths::path;
    EXPECT_FALSE(light_traces_caustics(h));
}

SceneDescription hexroom_light_traced(int w, int h, int spp, uint64_t seed) {
    SceneDescription d = test::hexroom(w, h, spp, seed);
    d.settings.estimator.caustics = CausticPaths::light_tracing;
    return d;
}

TEST(LightTracing, ImageIsTheSameBitsForAnyThreadCountIntegratorAndSampleRanges) {
    const SceneDescription d = hexroom_light_traced(20, 14, 6, 3);
    const test::RenderedFilm one = test::render_film(d, Integrator::wavefront, 1);
    EXPECT_GT(one.result.counts.camera_connections, 0u);
    EXPECT_EQ(one.film.splat_samples(), 6u);
    // The wavefront light paths' SIMD kernels, through the BVH too, against the scalar code.
    test::expect_same_film_for_any_schedule(d, one.film);

    const Scene scene = build_scene(d);
    RenderOptions options;
    options.threads = 2;
    RenderSession session(scene, options);
    Film pieces(d.settings.width, d.settings.height, render_film_channels(scene, options.aovs));
    session.render_samples(pieces, {0, 2});
    session.render_samples(pieces, {2, 3});
    session.render_samples(pieces, {3, 6});
    EXPECT_TRUE(pieces == one.film);
    // Split films merged in any order are the whole render.
    Film late(d.settings.width, d.settings.height, render_film_channels(scene, options.aovs));
    session.render_samples(late, {4, 6});
    Film early(d.settings.width, d.settings.height, render_film_channels(scene, options.aovs));
    session.render_samples(early, {0, 4});
    late.add_film(early);
    EXPECT_TRUE(late == one.film);
}

// Every light path replayed alone (what --debug-light-path runs) adds exactly the splats the
// render added: the splat sums of one sample, path by path, equal the rendered film's.
TEST(LightTracing, LightPathsReplayedOneByOneGiveTheRendersSplats) {
    const SceneDescription d = hexroom_light_traced(12, 10, 1, 4);
    const Scene scene = build_scene(d);
    const test::RenderedFilm rendered = test::render_film(d, Integrator::wavefront, 2);
    Film replayed(d.settings.width, d.settings.height, render_film_channels(scene, AovSelection{}));
    const LightPathTracer tracer(scene, nullptr);
    RayCounts counts;
    std::vector<LightPathVertexRecord> record;
    std::size_t recorded_splats = 0;
    for (uint64_t i = 0; i < light_paths_per_sample(d.settings); ++i) {
        std::vector<CameraSplat> splats;
        record.clear();
        tracer.trace(i, 0, counts, splats, &record);
        for (const CameraSplat& splat : splats) ASSERT_TRUE(replayed.add_splat(splat.pixel, splat.value));
        std::size_t splatted = 0;
        for (const LightPathVertexRecord& v : record) splatted += v.splat && !v.connection_blocked;
        ASSERT_EQ(splatted, splats.size()) << "light path " << i << ": the record shows what was splatted";
        recorded_splats += splatted;
    }
    ASSERT_GT(recorded_splats, 0u);
    const std::size_t stride = rendered.film.channels_per_pixel();
    for (std::size_t p = 0; p < rendered.film.pixel_total(); ++p)
        for (std::size_t c = stride - 3; c < stride; ++c)
            ASSERT_EQ(rendered.film.raw_sums()[p * stride + c], replayed.raw_sums()[p * stride + c]) << "pixel " << p;
}

TEST(LightTracing, CheckpointKeepsTheSplatsAndTheirSampleCount) {
    const SceneDescription d = hexroom_light_traced(10, 8, 3, 9);
    const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
    CheckpointHeader header;
    header.program_version = program_version();
    header.first_sample = 0, header.next_sample = header.target_sample = 3;
    const Checkpoint back = parse_checkpoint(checkpoint_bytes(header, r.film), "test.ckpt");
    EXPECT_TRUE(back.film.has_splats());
    EXPECT_EQ(back.film.splat_samples(), 3u);
    EXPECT_TRUE(back.film == r.film);
    EXPECT_EQ(back.film.resolve(), r.film.resolve());
}

// The hexroom's glass and mirror caustics, light-traced, against the camera paths' estimate of
// the same image: the image sums over independent seeds agree within their spread, and light
// tracing's spread is the smaller one.
TEST(LightTracing, HexroomAgreesWithPathTracingAndIsLessNoisy) {
    const int seeds = 8;
    std::vector<double> sums[2];
    for (int s = 0; s < seeds; ++s)
        for (int k = 0; k < 2; ++k) {
            SceneDescription d = test::hexroom(24, 24, 16, uint64_t(50 + s));
            d.settings.estimator.caustics = k ? CausticPaths::light_tracing : CausticPaths::path;
            const test::RenderedFilm r = test::render_film(d, Integrator::wavefront, 2);
            double sum = 0.0;
            for (uint32_t p = 0; p < r.film.pixel_total(); ++p) {
                const glm::dvec3 v = r.film.pixel_mean(p);
                sum += v.x + v.y + v.z;
            }
            sums[k].push_back(sum / double(r.film.pixel_total()));
        }
    double mean[2], var[2];
    for (int k = 0; k < 2; ++k) {
        mean[k] = var[k] = 0.0;
        for (double v : sums[k]) mean[k] += v / seeds;
        for (double v : sums[k]) var[k] += (v - mean[k]) * (v - mean[k]) / (seeds - 1);
    }
    const double se = std::sqrt(var[0] / seeds + var[1] / seeds);
    EXPECT_NEAR(mean[1], mean[0], 5.0 * se) << "path " << mean[0] << ", light tracing " << mean[1];
    EXPECT_LT(var[1], var[0]) << "light tracing's image-sum variance should be below the camera paths'";
}

TEST(Camera, FilmPointInvertsGenerateRayAndItsImportanceIntegratesToThePixelCount) {
    CameraDescription desc;
    desc.eye = {0.3f, -1.0f, 0.5f};
    desc.look_at = {1.0f, 0.2f, 0.1f};
    desc.fov_degrees = 55.0f;
    const int width = 40, height = 30;
    const Camera camera(desc, width, height);
    for (int i = 0; i < 200; ++i) {
        const float fx = float(width) * ((i * 37) % 200 + 0.5f) / 200.0f, fy = float(height) * ((i * 91) % 200 + 0.5f) / 200.0f;
        const Ray r = camera.generate_ray(fx, fy);
        const auto p = camera.film_point(r.origin + 3.7f * r.direction);
        ASSERT_TRUE(p.has_value());
        EXPECT_NEAR(p->x, fx, 1e-3f);
        EXPECT_NEAR(p->y, fy, 1e-3f);
    }
    EXPECT_FALSE(camera.film_point(camera.eye() - camera.forward()).has_value());  // behind the eye
    // The importance integrates over the directions to one per pixel.
    const double total = test::importance_over_the_sphere([&](const glm::vec3& dir) { return camera.film_point(camera.eye() + dir); });
    EXPECT_NEAR(total, double(width * height), 0.01 * width * height);
}

TEST(Film, SplatsAddToThePixelMeanOverTheSplatSamples) {
    Film film(2, 1, {"splat.R", "splat.G", "splat.B"});
    EXPECT_TRUE(film.has_splats());
    EXPECT_TRUE(film.add_sample(0, glm::vec3(1.0f)));
    EXPECT_TRUE(film.add_sample(0, glm::vec3(3.0f)));
    EXPECT_TRUE(film.add_splat(0, glm::vec3(1.0f, 2.0f, 4.0f)));
    EXPECT_TRUE(film.add_splat(1, glm::vec3(8.0f)));
    EXPECT_FALSE(film.add_splat(1, glm::vec3(NAN)));
    film.add_splat_samples(4);
    EXPECT_DOUBLE_EQ(film.pixel_mean(0).x, 2.0 + 0.25);
    EXPECT_DOUBLE_EQ(film.pixel_mean(0).z, 2.0 + 1.0);
    EXPECT_DOUBLE_EQ(film.pixel_mean(1).x, 2.0);  // no sample of its own, only splats
    EXPECT_DOUBLE_EQ(film.pixel_sample_variance(0).x, 2.0);  // its own samples only
    EXPECT_EQ(film.resolve()[3], 2.0f);
    // Without splat channels a film is as before, and splat names elsewhere are refused.
    Film plain(2, 1, {"Z"});
    EXPECT_FALSE(plain.has_splats());
    EXPECT_THROW(Film(1, 1, {"splat.R", "splat.G", "splat.B", "Z"}), std::invalid_argument);
}

}  // namespace
}  // namespace wt

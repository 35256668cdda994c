// The memory a render will take, estimated before it allocates: the wavefront queues sized to
// what a tile needs, and a render too large for the machine refused with the option to change.

#include <string>

#include <gtest/gtest.h>

#include "kernels/caustics/light_tracing_pass.h"
#include "kernels/memory_estimate.h"
#include "kernels/caustics/photon_memory.h"
#include "kernels/work/tiles.h"
#include "kernels/wavefront/wavefront_renderer.h"
#include "many_lights_scene.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace {

// The most paths any batch of any tile holds, as render_wavefront_tile cuts them.
std::size_t largest_batch(int width, int height, int spp, int tile_size, std::size_t batch_paths) {
    std::size_t most = 0;
    for (const wt::Tile& tile : wt::make_tiles(width, height, tile_size))
        most = std::max(most, std::size_t(tile.pixel_count()) * wt::samples_per_batch(tile, batch_paths, spp));
    return most;
}

TEST(MemoryEstimate, QueuesHoldExactlyTheLargestBatchOfAnyTile) {
    // --batch-paths 16777216 on a 16x16, 1-spp image allocated queues for 16M paths (4.4 GB).
    EXPECT_EQ(wt::workspace_paths(16, 16, 1, 16, std::size_t(1) << 24), 256u);
    EXPECT_EQ(wt::workspace_paths(800, 800, 64, 16, 2048), 2048u);
    // Edge tiles are narrower and take more samples per batch: 511 paths are one sample of a
    // 16x16 tile but 31 of the 16x1 tiles of a 17-pixel-wide image's last column.
    EXPECT_EQ(wt::workspace_paths(17, 16, 64, 16, 511), 16u * 31u);
    for (const int width : {1, 7, 16, 17, 100})
        for (const int height : {1, 5, 33})
            for (const int spp : {1, 3, 64})
                for (const int tile : {1, 4, 16, 512})
                    for (const std::size_t batch : {std::size_t(1), std::size_t(100), std::size_t(511), std::size_t(2048), std::size_t(1) << 24})
                        ASSERT_EQ(wt::workspace_paths(width, height, spp, tile, batch), largest_batch(width, height, spp, tile, batch))
                            << width << "x" << height << " spp " << spp << " tile " << tile << " batch " << batch;
}

TEST(MemoryEstimate, AHugeBatchOnATinyImageRendersTheSameBitsWithSmallQueues) {
    const wt::Scene scene = wt::build_scene(wt::test::hexroom(16, 16, 1));
    wt::RenderOptions small, huge;
    small.threads = huge.threads = 2;
    huge.batch_paths = std::size_t(1) << 24;
    EXPECT_LT(wt::estimate_render_memory(scene, huge).queues_per_worker, 1e6);
    // One sample of each of the 256 pixels, which the default batch of 2048 also holds.
    // The hexroom light-traces its caustics: its light paths' queues and splat buffer too.
    ASSERT_TRUE(scene.light_traces_caustics);
    EXPECT_EQ(wt::estimate_render_memory(scene, huge).queues_per_worker,
              double(wt::WavefrontWorkspace::bytes_needed(256, std::size_t(scene.settings.shadow_rays), false) +
                     wt::LightTracingPass::bytes_per_worker()));
    EXPECT_EQ(wt::estimate_render_memory(scene, huge).queues_per_worker, wt::estimate_render_memory(scene, small).queues_per_worker);
    wt::Film a = wt::test::film_for(scene), b = wt::test::film_for(scene);
    wt::render(scene, small, a);
    wt::render(scene, huge, b);
    EXPECT_EQ(a.resolve(), b.resolve());
}

TEST(MemoryEstimate, ARenderThatCannotFitIsRefusedNamingTheOptionToChange) {
    const wt::Scene scene = wt::build_scene(wt::test::hexroom(800, 800, 1));
    wt::RenderOptions options;
    options.threads = 2;
    options.tile_size = 512;
    wt::Scene many_shadow_rays = wt::build_scene(wt::test::hexroom(800, 800, 1));
    many_shadow_rays.settings.shadow_rays = 1024;
    const wt::MemoryEstimate e = wt::estimate_render_memory(many_shadow_rays, options);
    // 512x512 paths of 1024 shadow rays each: about 12 GB per worker.
    EXPECT_GT(e.queues_per_worker, 11e9);
    EXPECT_LT(e.queues_per_worker, 13e9);
    const std::string problem = wt::memory_problem(e, 16e9);
    EXPECT_NE(problem.find("2 workers x 12.1 GB of wavefront queues"), std::string::npos) << problem;
    EXPECT_NE(problem.find("lower --shadow-rays, --tile-size"), std::string::npos) << problem;
    EXPECT_EQ(wt::memory_problem(e, 30e9), "");
    // The film: width x height x its bytes per pixel, as Film says.
    options.tile_size = 16;
    const wt::MemoryEstimate film = wt::estimate_render_memory(scene, options);
    EXPECT_EQ(film.film, wt::Film::bytes_needed(800, 800, 3));  // with the light paths' splat channels
    EXPECT_NE(wt::memory_problem(film, film.to_allocate() / 2).find("lower --width and --height"), std::string::npos);
    // Adaptive sampling adds each pixel's stop and the rule's flag: 5 bytes.
    wt::Scene adaptive = scene;
    adaptive.settings.adaptive.threshold = 0.1f;
    EXPECT_EQ(wt::estimate_render_memory(adaptive, options).film, wt::Film::bytes_needed(800, 800, 3) + 800.0 * 800.0 * 5);
}

TEST(MemoryEstimate, TheBvhIsCountedOnlyWhenOneIsBuilt) {
    const wt::Scene scene = wt::build_scene(wt::test::hexroom(8, 8, 1));
    wt::RenderOptions options;
    options.accel = wt::Accel::brute;
    EXPECT_EQ(wt::estimate_render_memory(scene, options).bvh, 0.0);
    options.accel = wt::Accel::bvh;
    const double estimate = wt::estimate_render_memory(scene, options).bvh;
    const wt::Bvh bvh = wt::build_bvh(scene);
    // The estimate covers the built tree and the build's temporaries on top.
    EXPECT_GT(estimate, double(bvh.stats().node_bytes + bvh.stats().primitive_bytes));
}

// Photons counted against what the estimate expects per light path (photon_memory.h, an
// expectation from area averages, not a bound): it may err up to 2.5x on the safe side and a
// quarter below (bench/README.md has the counts of our scenes).
void expect_photon_count_near_estimate(const std::string& file) {
    wt::SceneDescription d = wt::load_scene_file(wt::test::scene_path(file));
    d.settings.width = d.settings.height = 64;
    d.settings.spp = 4;
    d.settings.estimator.caustics = wt::CausticPaths::photons;
    const wt::Scene scene = wt::build_scene(d);
    ASSERT_TRUE(scene.merges_photons) << file;
    wt::RenderOptions options;
    options.threads = 2;
    wt::Film film = wt::test::film_for(scene);
    const wt::RenderResult r = wt::render(scene, options, film);
    ASSERT_EQ(r.counts.light_paths, 4u * 64u * 64u) << file;
    const double counted = double(r.counts.photons) / double(r.counts.light_paths);
    const double expected = wt::expected_photons_per_light_path(scene);
    EXPECT_GT(counted, 0.1) << file;
    EXPECT_LE(counted, 1.25 * expected) << file << ": " << counted << " photons per light path, " << expected << " expected";
    EXPECT_GE(counted, expected / 2.5) << file << ": " << counted << " photons per light path, " << expected << " expected";
}

TEST(MemoryEstimate, PhotonsPerLightPathAreNearWhatTheEstimateExpects) {
    expect_photon_count_near_estimate("hexroom.json");
    expect_photon_count_near_estimate("caustic_mirror.json");
}

TEST(MemoryEstimate, PhotonMapsAreCountedOnlyWithPhotonsAndHoldWholeSamples) {
    wt::SceneDescription d = wt::test::hexroom(800, 800, 1);
    d.settings.estimator.caustics = wt::CausticPaths::photons;
    const wt::Scene photons = wt::build_scene(d);
    d.settings.estimator.caustics = wt::CausticPaths::light_tracing;
    const wt::Scene light_tracing = wt::build_scene(d);
    wt::RenderOptions options;
    EXPECT_EQ(wt::estimate_render_memory(light_tracing, options).photons, 0.0);
    const wt::MemoryEstimate e = wt::estimate_render_memory(photons, options);
    // 640,000 light paths per sample, more than the default batch of 2^18: one sample a batch.
    EXPECT_EQ(wt::photon_batch_light_paths(options.photon_batch_paths, 640000), 640000u);
    EXPECT_DOUBLE_EQ(e.photons, 640000.0 * wt::expected_photons_per_light_path(photons) * wt::photon_peak_bytes());
    EXPECT_EQ(e.to_allocate(), e.film + e.queues() + e.bvh + e.photons);
    // Smaller samples are gathered into a batch of up to 2^18 paths: 6 of 40,000.
    EXPECT_EQ(wt::photon_batch_light_paths(uint64_t(1) << 18, 40000), 240000u);
    EXPECT_EQ(wt::photon_batch_light_paths(1, 40000), 40000u);
    // More light paths per pixel than memory holds: refused, naming them.
    wt::Scene dense = photons;
    dense.settings.width = dense.settings.height = 4000;
    dense.settings.estimator.light_paths_per_pixel = 64.0f;  // the most a scene may ask for
    const wt::MemoryEstimate big = wt::estimate_render_memory(dense, options);
    EXPECT_GT(big.photons, 50e9);
    const std::string problem = wt::memory_problem(big, 24e9);
    EXPECT_NE(problem.find("photon maps"), std::string::npos) << problem;
    EXPECT_NE(problem.find("lower --light-paths-per-pixel"), std::string::npos) << problem;
    EXPECT_EQ(wt::memory_problem(e, 24e9), "");
}

// The lights' tables are counted: the emitters' own, and what a selection by power or by the
// light tree adds over area selection, which builds nothing (emitter_selection.h).
TEST(MemoryEstimate, CountsTheLightsAndWhatTheirSelectionBuilds) {
    wt::RenderOptions options;
    options.threads = 1;
    const auto lights_bytes = [&](wt::LightSelection selection) {
        const wt::Scene scene = wt::build_scene(wt::test::many_lights_room(24, wt::LightSampling::nee, selection));
        const wt::MemoryEstimate e = wt::estimate_render_memory(scene, options);
        EXPECT_DOUBLE_EQ(e.total(), e.to_allocate() + e.geometry + e.textures + e.lights);
        return e.lights;
    };
    const double area = lights_bytes(wt::LightSelection::area), power = lights_bytes(wt::LightSelection::power),
                 tree = lights_bytes(wt::LightSelection::bvh);
    // More than 24 x 24 emitters' sampling records of 16 floats each, and each selection adds at
    // least a float per emitter (power: its cdf and probability; the tree: a node per emitter).
    EXPECT_GT(area, 24.0 * 24.0 * 16.0 * sizeof(float));
    EXPECT_GT(power, area + 24.0 * 24.0 * 2.0 * sizeof(float));
    EXPECT_GT(tree, power);
    // The hexroom's lamp has a table; without its emission there is none.
    EXPECT_GT(wt::estimate_render_memory(wt::build_scene(wt::test::hexroom(8, 8, 1)), options).lights, 0.0);
    wt::SceneDescription unlit = wt::test::hexroom(8, 8, 1);
    for (wt::Material& m : unlit.materials) m.emission = glm::vec3(0.0f);
    EXPECT_EQ(wt::estimate_render_memory(wt::build_scene(unlit), options).lights, 0.0);
}

}  // namespace

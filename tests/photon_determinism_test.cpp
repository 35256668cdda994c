// Photons keep the image a function of (scene, seed, settings): the same bits for any thread
// count, integrator, kernel width, tile and batch, photon batch, sample ranges, merges and a
// resumed checkpoint; and a scene where no camera path sees a diffuse surface through a mirror or
// glass renders exactly light tracing's image, with no photon map built.

#include <gtest/gtest.h>

#include "core/checkpoint/checkpoint.h"
#include "core/system/version.h"
#include "kernels/caustics/light_path.h"
#include "mirror_caustic.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

SceneDescription hexroom_photons(int w, int h, int spp, uint64_t seed) {
    SceneDescription d = test::hexroom(w, h, spp, seed);
    d.settings.estimator.caustics = CausticPaths::photons;
    return d;
}

// A session rendering samples [0, spp) in the given pieces into a new film.
Film render_pieces(const Scene& scene, const RenderOptions& options, const std::vector<SampleRange>& pieces) {
    RenderSession session(scene, options);
    Film film = test::film_for(scene, options.aovs);
    for (const SampleRange& r : pieces) session.render_samples(film, r);
    return film;
}

TEST(PhotonDeterminism, ImageIsTheSameBitsForAnyThreadCountIntegratorBatchAndSampleRanges) {
    const SceneDescription d = hexroom_photons(20, 14, 6, 3);
    const test::RenderedFilm one = test::render_film(d, Integrator::wavefront, 1);
    ASSERT_GT(one.result.photon_maps_built, 0u) << "the hexroom's mirror and glass must show diffuse surfaces";
    test::expect_same_film_for_any_schedule(d, one.film);

    const Scene scene = build_scene(d);
    RenderOptions options;
    options.threads = 2;
    // One sample per photon batch, and two: the batches never show in the image.
    for (const uint64_t batch : {light_paths_per_sample(d.settings), 2 * light_paths_per_sample(d.settings)}) {
        options.photon_batch_paths = batch;
        EXPECT_TRUE(render_pieces(scene, options, {{0, 6}}) == one.film) << "batch of " << batch << " light paths";
    }
    options.integrator = Integrator::reference;
    EXPECT_TRUE(render_pieces(scene, options, {{0, 2}, {2, 3}, {3, 6}}) == one.film);
    options.integrator = Integrator::wavefront;
    EXPECT_TRUE(render_pieces(scene, options, {{0, 2}, {2, 3}, {3, 6}}) == one.film);
    // Split films merged are the whole render, and a checkpoint resumed continues it exactly.
    Film late = render_pieces(scene, options, {{4, 6}});
    late.add_film(render_pieces(scene, options, {{0, 4}}));
    EXPECT_TRUE(late == one.film);
    CheckpointHeader header;
    header.program_version = program_version();
    header.first_sample = 0, header.next_sample = 3, header.target_sample = 6;
    Checkpoint resumed = parse_checkpoint(checkpoint_bytes(header, render_pieces(scene, options, {{0, 3}})), "test.ckpt");
    RenderSession session(scene, options);
    session.render_samples(resumed.film, {3, 6});
    EXPECT_TRUE(resumed.film == one.film);
}

TEST(PhotonDeterminism, AdaptiveSamplingWithPhotonsIsTheSameBitsForAnyThreadCount) {
    SceneDescription d = hexroom_photons(16, 12, 12, 5);
    d.settings.adaptive.threshold = 0.2f;
    d.settings.adaptive.min_spp = 4;
    const test::RenderedFilm one = test::render_film(d, Integrator::wavefront, 1);
    EXPECT_TRUE(one.film == test::render_film(d, Integrator::wavefront, 3).film);
    EXPECT_TRUE(one.film == test::render_film(d, Integrator::reference, 2).film);
}

// The mirror caustic's camera sees only the floor and the light's back: no path reaches a
// diffuse surface through the mirror, so photons add nothing and build nothing. The same scene
// seen in a wall mirror (the other side) differs from light tracing, where photons are the point.
TEST(PhotonDeterminism, NoCameraPathThroughAMirrorMeansLightTracingsImageBitForBit) {
    const test::MirrorCaustic m;
    const test::RenderedFilm traced = test::render_film(m.scene(4, 7, CausticPaths::light_tracing), Integrator::wavefront, 2);
    const test::RenderedFilm photons = test::render_film(m.scene(4, 7, CausticPaths::photons), Integrator::wavefront, 2);
    EXPECT_TRUE(build_scene(m.scene(4, 7, CausticPaths::photons)).merges_photons);
    EXPECT_EQ(photons.result.photon_maps_built, 0u);
    EXPECT_GT(photons.result.counts.camera_connections, 0u);
    EXPECT_TRUE(photons.film == traced.film);

    const auto wall = [](CausticPaths c) {
        return test::render_film(test::WallMirrorCaustic::scene(4, 7, c), Integrator::wavefront, 2);
    };
    const test::RenderedFilm wall_photons = wall(CausticPaths::photons), wall_traced = wall(CausticPaths::light_tracing);
    EXPECT_GT(wall_photons.result.photon_maps_built, 0u);
    EXPECT_FALSE(wall_photons.film == wall_traced.film);
}

// A scene without a mirror or glass surface traces no light paths with photons either.
TEST(PhotonDeterminism, SceneWithoutSpecularSurfacesHasNoPhotons) {
    SceneDescription d = test::furnace_cube(0.5f, 1.0f);
    d.settings.estimator.caustics = CausticPaths::photons;
    const Scene scene = build_scene(d);
    EXPECT_FALSE(scene.light_traces_caustics);
    EXPECT_FALSE(scene.merges_photons);
    EXPECT_EQ(test::render_film(d, Integrator::wavefront, 2).result.counts.light_paths, 0u);
}

}  // namespace
}  // namespace wt

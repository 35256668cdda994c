// The renderer's settings at their edges: 1x1 images, 1 spp, idle threads, huge tiles.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- settings at the edges ----------------------------------------------------------------------

// 1 spp, 1x1 and 1xN images, tiles larger than the image, more threads than tiles, batches of
// one path: every render completes, every pixel gets exactly spp samples, the counts add up,
// and every variant gives the same bits as the reference integrator on one thread.
TEST(EdgeSettings, TinyImagesOneSampleIdleThreadsAndHugeTiles) {
    struct Variant {
        int width, height, spp;
        Integrator integrator;
        int threads, tile;
        std::size_t batch;
    };
    const Variant variants[] = {
        {1, 1, 1, Integrator::wavefront, 1, 16, 2048},  {1, 1, 1, Integrator::wavefront, 8, 16, 2048},
        {1, 1, 1, Integrator::wavefront, 3, 1, 1},      {1, 1, 1, Integrator::reference, 8, 4096, 1},
        {2, 2, 1, Integrator::wavefront, 8, 1, 2048},   {2, 2, 1, Integrator::wavefront, 8, 1000, 1},
        {2, 2, 1, Integrator::reference, 8, 1, 2048},   {2, 2, 3, Integrator::wavefront, 8, 1, 2},
        {2, 2, 3, Integrator::wavefront, 8, 2, 5},      {2, 2, 3, Integrator::reference, 5, 3, 1},
        {7, 1, 1, Integrator::wavefront, 8, 2, 3},      {1, 7, 2, Integrator::wavefront, 8, 4096, 1},
        {5, 3, 1, Integrator::wavefront, 2, 4096, 7},   {5, 3, 1, Integrator::wavefront, 8, 1, 1},
    };
    for (const Variant& v : variants) {
        const std::string label = std::to_string(v.width) + "x" + std::to_string(v.height) + ", " + std::to_string(v.spp) +
                                  " spp, " + (v.integrator == Integrator::wavefront ? "wavefront" : "reference") + ", " +
                                  std::to_string(v.threads) + " threads, tile " + std::to_string(v.tile) + ", batch " +
                                  std::to_string(v.batch);
        SCOPED_TRACE(label);
        const SceneDescription d = test::hexroom(v.width, v.height, v.spp, 9);
        const test::RenderedFilm baseline = test::render_film(d, Integrator::reference, 1);
        const uint64_t pixels = uint64_t(v.width) * uint64_t(v.height);
        // The wavefront with every ISA's kernels; the reference integrator uses none.
        std::vector<Isa> isas = supported_isas();
        if (v.integrator == Integrator::reference) isas = {Isa::scalar};
        for (Isa isa : isas) {
            SCOPED_TRACE(isa_name(isa));
            const test::RenderedFilm r = test::render_film(d, v.integrator, v.threads, v.tile, v.batch, isa);
            const test::RenderedFilm again = test::render_film(d, v.integrator, v.threads, v.tile, v.batch, isa);
            EXPECT_EQ(r.result.threads, v.threads);
            EXPECT_EQ(r.result.counts.camera_rays, pixels * uint64_t(v.spp));
            EXPECT_EQ(r.result.counts.samples, pixels * uint64_t(v.spp));
            EXPECT_EQ(r.result.counts.nonfinite_samples, 0u);
            for (uint32_t p = 0; p < uint32_t(pixels); ++p) EXPECT_EQ(r.film.pixel_count(p), uint32_t(v.spp)) << "pixel " << p;
            EXPECT_TRUE(test::films_bit_identical(r.film, again.film)) << "not deterministic";
            EXPECT_TRUE(test::films_bit_identical(r.film, baseline.film)) << "differs from the reference on one thread";
            EXPECT_EQ(r.result.counts.total_rays(), baseline.result.counts.total_rays());
            for (float c : r.film.resolve()) EXPECT_TRUE(std::isfinite(c));
        }
    }
}


}  // namespace
}  // namespace wt::extremes

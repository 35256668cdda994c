// Renders through the BVH against renders through the flat primitive list: the traversal
// returns the flat kernels' bits (bvh_test.cpp), so the images must be bit-identical, for both
// integrators, both node widths and any thread count. And `auto` picks what the crossover says.

#include <gtest/gtest.h>

#include "bvh_test_scenes.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

TEST(AccelRender, BvhAndBruteForceGiveBitIdenticalImagesOfTheHexroom) {
    const SceneDescription d = test::hexroom(40, 40, 8);
    const test::RenderedFilm brute = test::render_film(d, Integrator::wavefront, 2, 16, 2048, {}, Accel::brute);
    EXPECT_EQ(brute.result.accel, Accel::brute);
    for (int width : {4, 8}) {
        const test::RenderedFilm bvh = test::render_film(d, Integrator::wavefront, 2, 16, 2048, {}, Accel::bvh, width);
        EXPECT_EQ(bvh.result.accel, Accel::bvh);
        EXPECT_TRUE(test::films_bit_identical(brute.film, bvh.film)) << "width " << width;
    }
}

TEST(AccelRender, BvhAndBruteForceGiveBitIdenticalImagesOfAMeshedScene) {
    for (TriangleTest triangles : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        SceneDescription d = test::hexroom_with_meshes(32, 32, 4);
        d.settings.accuracy.triangles = triangles;
        const test::RenderedFilm brute = test::render_film(d, Integrator::wavefront, 2, 16, 2048, {}, Accel::brute);
        for (Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
            const test::RenderedFilm bvh = test::render_film(d, integrator, 2, 16, 2048, {}, Accel::bvh);
            EXPECT_TRUE(test::films_bit_identical(brute.film, bvh.film))
                << name_of(triangles) << ", " << (integrator == Integrator::wavefront ? "wavefront" : "reference");
        }
        EXPECT_EQ(brute.result.counts.nonfinite_samples, 0u);
    }
}

TEST(AccelRender, BvhRenderIsTheSameForAnyThreadCount) {
    const SceneDescription d = test::hexroom_with_meshes(24, 24, 4);
    const test::RenderedFilm one = test::render_film(d, Integrator::wavefront, 1, 16, 2048, {}, Accel::bvh);
    for (int threads : {2, 3}) {
        const test::RenderedFilm other = test::render_film(d, Integrator::wavefront, threads, 8, 512, {}, Accel::bvh);
        EXPECT_TRUE(test::films_bit_identical(one.film, other.film)) << threads << " threads";
    }
}

TEST(AccelRender, AutoUsesTheFlatListBelowTheCrossoverAndTheBvhAbove) {
    EXPECT_EQ(test::render_film(test::hexroom(8, 8, 1), Integrator::wavefront).result.accel, Accel::brute);
    const test::RenderedFilm meshed = test::render_film(test::hexroom_with_meshes(8, 8, 1), Integrator::wavefront);
    EXPECT_EQ(meshed.result.accel, Accel::bvh);
    EXPECT_GT(meshed.result.bvh.node_count, 0u);
    for (int width : {1, 4, 8, 16}) {
        EXPECT_EQ(resolve_accel(Accel::automatic, bvh_crossover(width) - 1, width), Accel::brute);
        EXPECT_EQ(resolve_accel(Accel::automatic, bvh_crossover(width), width), Accel::bvh);
        EXPECT_EQ(resolve_accel(Accel::brute, 1u << 20, width), Accel::brute);
        EXPECT_EQ(resolve_accel(Accel::bvh, 1, width), Accel::bvh);
    }
    EXPECT_LT(bvh_crossover(8), bvh_crossover(16));
}

}  // namespace
}  // namespace wt

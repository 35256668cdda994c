// Renders of a scene with instances: the same bits on any threads, tiles, ISA and integrator,
// and statistically the image of the same scene flattened. Not the flattened image's bits: the
// two scenes' floats differ (instanced_intersect_test.cpp bounds by how much), so a few paths
// take another turn; the pixel-by-pixel z-test (render_helpers.h) must still pass.

#include <gtest/gtest.h>

#include "instance_scenes.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "render_helpers.h"

namespace {

using namespace wt;

TEST(InstanceRender, SameBitsForAnyScheduleAndIsa) {
    const SceneDescription d = test::instanced_scene(test::test_placements(), true, 6);
    const test::RenderedFilm reference = test::render_film(d, Integrator::wavefront, 2);
    EXPECT_GT(reference.result.instance_count, 0u);
    test::expect_same_film_for_any_schedule(d, reference.film);
    for (Isa isa : {Isa::sse4, Isa::avx2, Isa::avx512}) {
        if (!cpu_supports(isa)) continue;
        EXPECT_TRUE(reference.film == test::render_film(d, Integrator::wavefront, 1, 16, 2048, isa).film) << isa_name(isa);
    }
}

TEST(InstanceRender, AgreesWithFlattenedScene) {
    SceneDescription d = test::instanced_scene(test::test_placements(), true, 6);
    d.settings.spp = 64;
    const Film instanced = test::render_film(d, Integrator::wavefront, 2).film;
    SceneDescription other_seed = test::flattened(d);
    other_seed.settings.seed = 1;  // independent samples, as the z-test assumes
    const Film flat = test::render_film(other_seed, Integrator::wavefront, 2).film;
    test::expect_films_agree(instanced, flat, [](uint32_t p) { return "pixel " + std::to_string(p); });
}

// --accel brute cannot trace instances: refused by name, not rendered wrong.
TEST(InstanceRender, BruteForceRefused) {
    const SceneDescription d = test::instanced_scene(test::test_placements(), false, 4);
    EXPECT_THROW(test::render_film(d, Integrator::wavefront, 1, 16, 2048, {}, Accel::brute), std::invalid_argument);
}

// The estimate counts the stored mesh once and bytes_per_instance() per placement: seven
// placements cost the one placement's geometry and BVH, and six more instances.
TEST(InstanceRender, MemoryEstimateCountsEachMeshOnce) {
    const std::vector<glm::dmat4> seven = test::test_placements();
    const Scene one = build_scene(test::instanced_scene({seven[0]}, true));
    const Scene all = build_scene(test::instanced_scene(seven, true));
    const Scene flat = build_scene(test::flattened(test::instanced_scene(seven, true)));
    RenderOptions options;
    options.threads = 1;
    const MemoryEstimate e1 = estimate_render_memory(one, options), e7 = estimate_render_memory(all, options);
    const MemoryEstimate ef = estimate_render_memory(flat, options);
    EXPECT_EQ(e7.geometry, e1.geometry);
    EXPECT_EQ(e7.bvh, e1.bvh);
    EXPECT_EQ(e7.instance_count, 7u);
    EXPECT_DOUBLE_EQ(e7.instances, 7.0 * bytes_per_instance(options.bvh.node_width));
    EXPECT_GT(ef.geometry, 6.0 * e1.geometry);  // the flattened scene pays per copy
    EXPECT_EQ(ef.instances, 0.0);
}

}  // namespace

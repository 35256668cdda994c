// Renders of a scene with instances: the same bits on any threads, tiles, ISA and integrator,
// and statistically the image of the same scene flattened. Not the flattened image's bits: the
// two scenes' floats differ (instanced_intersect_test.cpp bounds by how much), so a few paths
// take another turn; the pixel-by-pixel z-test (render_helpers.h) must still pass.

#include <gtest/gtest.h>

#include "instance_scenes.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "render_helpers.h"
#include "texture_test_images.h"

namespace {

using namespace wt;

// The scalar kernels shade every hit one at a time; the vector kernels' surface kernel takes the
// scene's own triangles and spheres and leaves the instances' hits to surface_at, in the camera
// paths and, with a glass ball and so caustics, in the light paths too.
TEST(InstanceRender, SameBitsForAnyScheduleAndIsa) {
    for (bool glass : {false, true}) {
        SceneDescription d = test::instanced_scene(test::test_placements(), true, 6);
        if (glass) {
            Material ball;
            ball.name = "glass", ball.type = MaterialType::glass, ball.ior = 1.5f;
            d.materials.push_back(ball);
            d.spheres.push_back({{5.0f, -3.5f, -1.0f}, 0.9f, uint32_t(d.materials.size() - 1)});
            d.spheres.push_back({{9.0f, 3.0f, 0.0f}, 0.6f, 0});
        }
        const test::RenderedFilm reference = test::render_film(d, Integrator::wavefront, 2);
        EXPECT_GT(reference.result.instance_count, 0u);
        if (glass) {
            EXPECT_GT(reference.result.counts.light_paths, 0u);
        }
        test::expect_same_film_for_any_schedule(d, reference.film);
        for (Isa isa : kAllIsas) {
            if (!cpu_supports(isa)) continue;
            EXPECT_TRUE(reference.film == test::render_film(d, Integrator::wavefront, 1, 16, 2048, isa).film)
                << isa_name(isa) << (glass ? ", with glass" : "");
        }
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

// A textured instanced mesh reads its own coordinates (object space), its tangents and its
// texel density taken into world space by the placement: the image agrees with the flattened
// scene's. Stripes of 0.05 and 0.95 around the sphere and a tilted normal map make a wrong
// coordinate (a sphere's, from the normal) or an unplaced tangent show in many pixels.
TEST(InstanceRender, TexturedAgreesWithFlattenedScene) {
    const int rings = 6, segments = 2 * rings;
    SceneDescription d = test::instanced_scene(test::test_placements(), true, rings);
    d.settings.width = d.settings.height = 48;
    d.settings.spp = 64;
    TriangleMesh& part = d.prototypes[0].parts[0];
    for (std::size_t k = 0; k < part.vertices.size(); ++k)
        part.uvs.push_back({float(k % segments) / float(segments), float(k / segments) / float(rings)});
    d.textures.push_back(test::texture_of(8, 8, [](int x, int) { return glm::vec4(x % 2 ? 0.95f : 0.05f); }));
    const float tilt = 0.5f + 0.5f * 0.6f;  // a normal 37 degrees from the surface's, towards +u
    d.textures.push_back(test::texture_of(2, 2, [&](int, int) { return glm::vec4(tilt, 0.5f, 0.5f + 0.5f * 0.8f, 1.0f); }));
    d.materials[1].color_texture = 0;
    d.materials[1].normal_texture = 1;
    const Film instanced = test::render_film(d, Integrator::wavefront, 2).film;
    SceneDescription other_seed = test::flattened(d);
    other_seed.settings.seed = 1;  // independent samples, as the z-test assumes
    const Film flat = test::render_film(other_seed, Integrator::wavefront, 2).film;
    test::expect_films_agree(instanced, flat, [](uint32_t p) { return "pixel " + std::to_string(p); });
    // The stripes are seen: many pixels of the untextured image differ from the textured one's by
    // more than 5 standard deviations.
    SceneDescription plain = d;
    plain.materials[1].color_texture = plain.materials[1].normal_texture = -1;
    const Film untextured = test::render_film(plain, Integrator::wavefront, 2).film;
    int differing = 0;
    for (uint32_t p = 0; p < uint32_t(d.settings.width * d.settings.height); ++p) {
        const double difference = instanced.pixel_mean(p).g - untextured.pixel_mean(p).g;
        const double variance =
            (instanced.pixel_sample_variance(p).g + untextured.pixel_sample_variance(p).g) / double(instanced.pixel_count(p));
        differing += std::fabs(difference) > 5.0 * std::sqrt(variance);
    }
    EXPECT_GE(differing, 30) << differing;
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

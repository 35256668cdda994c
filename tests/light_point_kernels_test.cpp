// The shade kernels that draw a chunk of diffuse vertices' random numbers
// (kernels/shading/diffuse_random.h) and turn their light samples' numbers into light points
// (kernels/shading/light_points.h), against the scalar code they replace, bit for bit, on every
// ISA this CPU runs: continuation_random and light_sample_point (core/path/path_vertex.h) and
// LightTable::sample (core/lights/light_table.h). On the hexroom's one light, on tables of
// several parallelograms and triangles up to the most the kernel takes, and on the choices that
// sit exactly on the table's cdf steps and the ends of [0, 1).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/path/path_vertex.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "test_scenes.h"

namespace wt {
namespace {

std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (Isa isa : kAllIsas)
        if (cpu_supports(isa)) isas.push_back(isa);
    return isas;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The hexroom with `extra` more emitters: its tetrahedron's four triangles made emissive (of
// another radiance), then emissive quads (parallelograms) on the floor, as many as asked.
Scene scene_with_emitters(int extra) {
    SceneDescription d = test::hexroom(8, 8, 1);
    Material glow;
    glow.name = "glow";
    glow.albedo = glm::vec3(0.0f);
    glow.emission = glm::vec3(3.0f, 5.0f, 7.0f);
    d.materials.push_back(glow);
    const uint32_t glow_id = uint32_t(d.materials.size() - 1);
    int added = 0;
    for (TriangleMesh& mesh : d.meshes)
        if (added < extra && d.materials[mesh.material].name == "orange") {  // the tetrahedron
            mesh.material = glow_id;
            added += int(mesh.triangles.size());
        }
    for (int q = 0; added < extra; ++q, ++added) {
        TriangleMesh quad;
        const float x = 1.0f + float(q), y = -5.0f + 0.5f * float(q);
        quad.vertices = {{x, y, -4.98f}, {x + 0.5f, y, -4.98f}, {x + 0.5f, y + 0.25f, -4.98f}, {x, y + 0.25f, -4.98f}};
        quad.triangles = {{0, 1, 2}, {0, 2, 3}};
        quad.parallelogram = true;
        quad.material = glow_id;
        d.meshes.push_back(quad);
    }
    return build_scene(d);
}

// Every light point field of entry i's sample j against `expected`.
void expect_light_point(const DiffuseVertexQueue& q, std::size_t i, uint32_t j, const LightSample& expected,
                        const std::string& reproduce) {
    const std::size_t k = j * q.stride + i;
    const float actual[] = {q.light_px[k], q.light_py[k], q.light_pz[k], q.light_ex[k], q.light_ey[k], q.light_ez[k],
                            q.light_nx[k], q.light_ny[k], q.light_nz[k], q.light_r[k],  q.light_g[k],  q.light_b[k],
                            q.light_pdf_area[k]};
    const float wanted[] = {expected.position.x, expected.position.y, expected.position.z, expected.error.x, expected.error.y,
                            expected.error.z,    expected.normal.x,   expected.normal.y,   expected.normal.z, expected.radiance.x,
                            expected.radiance.y, expected.radiance.z, expected.pdf_area};
    const char* names[] = {"px", "py", "pz", "ex", "ey", "ez", "nx", "ny", "nz", "r", "g", "b", "pdf_area"};
    for (int f = 0; f < 13; ++f)
        ASSERT_TRUE(same_bits(actual[f], wanted[f]))
            << reproduce << ": light sample " << j << " of entry " << i << ": " << names[f] << " is " << actual[f]
            << ", the scalar code gives " << wanted[f];
}

// `count` vertices pushed undrawn with random keys at `bounce`: the kernels' numbers, and the
// points the kernels pick (or, for a table they do not take, DiffuseVertexQueue::pick_light_points,
// as the shade loop does), against continuation_random and light_sample_point of the default
// estimator's sampler.
void expect_drawn_vertices_equal_the_sampler(const ShadeKernels& kernels, const Scene& scene, std::size_t count,
                                             uint32_t bounce, uint32_t light_samples, uint32_t seed) {
    using E = DefaultEstimator;
    std::mt19937_64 rng(seed);
    DiffuseVertexQueue q;
    q.reserve(count, light_samples);
    std::vector<PathSeed> paths;
    Material m;  // Lambertian
    SurfacePoint surface{};
    for (std::size_t i = 0; i < count; ++i) {
        paths.push_back({rng(), uint32_t(rng() % 4096)});
        const typename E::Sampler random(paths.back(), bounce, light_samples);
        q.push_undrawn(surface, m, glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(1.0f), random.base, uint32_t(i), false, true);
    }
    kernels.draw_diffuse_random(q, light_samples);
    if (scene.lights.few_untextured_emitters()) kernels.pick_light_points(q, scene.lights, light_samples);
    else q.pick_light_points(scene, light_samples);
    const std::string reproduce = std::string("isa ") + isa_name(kernels.isa) + ", " + std::to_string(scene.lights.size()) +
                                  " emitters, bounce " + std::to_string(bounce) + ", seed " + std::to_string(seed) +
                                  " (reproduce: kernels_test --gtest_filter='LightPointKernels.*')";
    std::vector<std::size_t> picked(scene.lights.size(), 0);
    for (std::size_t i = 0; i < count; ++i) {
        const typename E::Sampler random(paths[i], bounce, light_samples);
        const ContinuationRandom draws = continuation_random<E>(random);
        ASSERT_TRUE(same_bits(q.u0[i], draws.direction.first)) << reproduce << ", entry " << i;
        ASSERT_TRUE(same_bits(q.u1[i], draws.direction.second)) << reproduce << ", entry " << i;
        ASSERT_TRUE(same_bits(q.roulette[i], draws.choice_and_roulette.second)) << reproduce << ", entry " << i;
        for (uint32_t j = 0; j < light_samples; ++j) {
            const LightSample expected = light_sample_point<E>(scene, random, j);
            expect_light_point(q, i, j, expected, reproduce);
            for (std::size_t e = 0; e < scene.lights.size(); ++e)
                picked[e] += expected.radiance == scene.lights.emitters()[e].radiance &&
                             expected.normal == scene.lights.emitters()[e].normal;
        }
    }
    // Both kinds of emitter were picked where the table has both.
    for (std::size_t e = 0; e < scene.lights.size(); ++e) EXPECT_GT(picked[e], 0u) << reproduce << ", emitter " << e;
}

TEST(LightPointKernels, DrawnNumbersAndPointsEqualTheScalarSamplerBitForBit) {
    const Scene one = scene_with_emitters(0), mixed = scene_with_emitters(4), most = scene_with_emitters(7),
                many = scene_with_emitters(8);
    ASSERT_EQ(one.lights.size(), 1u);
    ASSERT_EQ(mixed.lights.size(), 5u);  // the light's parallelogram and four triangles
    ASSERT_EQ(most.lights.size(), LightTable::kCountedEmitters);
    ASSERT_EQ(many.lights.size(), LightTable::kCountedEmitters + 1);  // the loop's points
    for (Isa isa : supported_isas()) {
        const ShadeKernels& kernels = shade_kernels(isa);
        expect_drawn_vertices_equal_the_sampler(kernels, one, 1001, 0, 1, 1);  // not a multiple of any width
        expect_drawn_vertices_equal_the_sampler(kernels, mixed, 517, 3, 3, 2);
        expect_drawn_vertices_equal_the_sampler(kernels, most, 256, 9, 2, 3);
        expect_drawn_vertices_equal_the_sampler(kernels, many, 300, 1, 2, 4);
    }
}

// The kernel takes few emitters without textures; a ninth goes to the scalar loop.
TEST(LightPointKernels, TablesOfMoreEmittersAreNotTheKernels) {
    EXPECT_TRUE(scene_with_emitters(7).lights.few_untextured_emitters());
    EXPECT_FALSE(scene_with_emitters(8).lights.few_untextured_emitters());
}

// Choices on the table's cdf steps, just below and above them, 0, the largest float below 1,
// and NaN; points at the corners of the unit square: LightTable::sample's bits for each.
TEST(LightPointKernels, PointsAtTheCdfStepsAndTheSquaresCornersEqualLightTableSample) {
    const Scene scene = scene_with_emitters(7);
    std::vector<float> choices = {0.0f, std::nextafter(1.0f, 0.0f), std::numeric_limits<float>::quiet_NaN()};
    for (const LightTable::Emitter& e : scene.lights.emitters())
        for (float c : {e.cdf, std::nextafter(e.cdf, 0.0f), std::nextafter(e.cdf, 2.0f)}) choices.push_back(c);
    const float corners[] = {0.0f, std::nextafter(1.0f, 0.0f), 0.5f, 1e-30f};
    DiffuseVertexQueue q;
    const std::size_t count = choices.size() * 16;
    q.reserve(count, 1);
    q.count = count;
    for (std::size_t i = 0; i < count; ++i) {
        q.light_choice[i] = choices[i / 16];
        q.light_u[i] = corners[i % 4], q.light_v[i] = corners[(i / 4) % 4];
    }
    for (Isa isa : supported_isas()) {
        shade_kernels(isa).pick_light_points(q, scene.lights, 1);
        const std::string reproduce =
            std::string("isa ") + isa_name(isa) + " (reproduce: kernels_test --gtest_filter='LightPointKernels.*')";
        for (std::size_t i = 0; i < count; ++i)
            expect_light_point(q, i, 0, scene.lights.sample(scene.triangles, q.light_choice[i], q.light_u[i], q.light_v[i]),
                               reproduce + ", choice " + std::to_string(q.light_choice[i]));
    }
}

}  // namespace
}  // namespace wt

// The SIMD shade kernels against the scalar vertex code they replace, bit for bit, on every ISA
// this CPU runs, on random diffuse vertices about the hexroom's light, flat and smooth (shading
// normals tilted, tangent, opposite, equal to the geometric one), and on the extremes (poles of
// the frame, grazing directions, the disk's centre and diagonals, black and near-black paths,
// huge and tiny scales, zero coordinates): the surface kernel
// (kernels/shading/surface_points.h) against surface_at, the diffuse continuation kernel
// (kernels/shading/diffuse_continuation.h) against continue_path, the light sample kernel
// (kernels/shading/diffuse_light_samples.h) against DirectLightSampler (core/path/path_vertex.h).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/path/path_vertex.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/surface_chunk.h"
#include "instance_scenes.h"
#include "test_scenes.h"

namespace wt {
namespace {

struct Vertex {
    Material material;
    SurfacePoint surface;
    glm::vec3 d, throughput;
    PathSeed path;
    bool specular_light_elsewhere;
};

std::string describe(const Vertex& v) {
    std::ostringstream s;
    s.precision(9);
    s << "material " << int(v.material.type) << " sigma " << v.material.sigma << " albedo (" << v.material.albedo.x << ", "
      << v.material.albedo.y << ", " << v.material.albedo.z << "), position (" << v.surface.position.x << ", "
      << v.surface.position.y << ", " << v.surface.position.z << "), normal (" << v.surface.normal.x << ", " << v.surface.normal.y
      << ", " << v.surface.normal.z << "), shading normal (" << v.surface.shading_normal.x << ", "
      << v.surface.shading_normal.y << ", " << v.surface.shading_normal.z << (v.surface.smooth ? "), smooth" : "), flat")
      << ", d (" << v.d.x << ", " << v.d.y << ", " << v.d.z << "), key " << v.path.key
      << " sample " << v.path.sample;
    return s.str();
}

glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const glm::vec3 v(g(rng), g(rng), g(rng));
        if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
    }
}

// Random vertices, one in four at an extreme of one input.
std::vector<Vertex> random_vertices(std::size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Vertex> vertices;
    for (std::size_t i = 0; i < count; ++i) {
        Vertex v;
        v.material.type = unit(rng) < 0.5f ? MaterialType::lambertian : MaterialType::oren_nayar;
        const float sigmas[] = {0.0f, 0.3f, 1.0f, unit(rng)};
        v.material.sigma = sigmas[rng() % 4];
        v.material.albedo = glm::vec3(unit(rng), unit(rng), unit(rng));
        if (rng() % 16 == 0) v.material.albedo = glm::vec3(0.0f);        // black: the path ends
        if (rng() % 16 == 0) v.material.albedo = glm::vec3(0.0f, 0.5f, 0.0f);
        const float scale = std::pow(10.0f, float(int(rng() % 11) - 4));  // 1e-4 to 1e6
        v.surface.position = scale * (2.0f * glm::vec3(unit(rng), unit(rng), unit(rng)) - 1.0f);
        if (rng() % 8 == 0) v.surface.position.y = 0.0f;  // a wall through the origin
        v.surface.error = rounding_gamma(7) * magnitude(v.surface.position);
        v.surface.normal = random_unit(rng);
        switch (rng() % 8) {  // the frame's poles and axes
            case 0: v.surface.normal = glm::vec3(0.0f, 0.0f, -1.0f); break;
            case 1: v.surface.normal = glm::vec3(0.0f, 0.0f, 1.0f); break;
            case 2: v.surface.normal = glm::vec3(1.0f, 0.0f, 0.0f); break;
            default: break;
        }
        v.surface.shading_normal = v.surface.normal;
        switch (rng() % 8) {  // vertex normals: tilted, slightly or far, tangent, or wound the other way
            case 0: v.surface.shading_normal = glm::normalize(v.surface.normal + 0.2f * random_unit(rng)); break;
            case 1: v.surface.shading_normal = glm::normalize(v.surface.normal + random_unit(rng)); break;
            case 2: v.surface.shading_normal = glm::normalize(glm::cross(v.surface.normal, random_unit(rng))); break;
            case 3: v.surface.shading_normal = -glm::normalize(v.surface.normal + 0.5f * random_unit(rng)); break;
            default: break;
        }
        v.surface.smooth = v.surface.shading_normal != v.surface.normal;
        v.surface.material = 0;
        v.d = random_unit(rng);
        if (rng() % 8 == 0) {  // grazing: d in the surface's plane, give or take rounding
            v.d = glm::normalize(glm::cross(v.surface.normal, random_unit(rng)));
        }
        v.throughput = glm::vec3(unit(rng), unit(rng), unit(rng)) * std::pow(10.0f, float(int(rng() % 5) - 2));
        if (rng() % 16 == 0) v.throughput *= 1e-30f;  // Russian roulette's survival far below 1
        v.path = {uint64_t(rng()) << 32 | rng(), uint32_t(rng() % 4096)};
        v.specular_light_elsewhere = rng() % 4 == 0;
        vertices.push_back(v);
    }
    return vertices;
}

// The kernel's random numbers at the disk's centre and on its diagonals, where the concentric
// map's cases meet: vertices whose draws are replaced by these exact values.
struct FixedDraws {
    float u0, u1;
};
constexpr FixedDraws kFixedDraws[] = {{0.5f, 0.5f}, {0.0f, 0.0f}, {0.25f, 0.25f}, {0.25f, 0.75f}, {0.5f, 0.0f},
                                      {0.0f, 0.5f}, {1.0f - 0x1p-24f, 0.5f}, {0.5f, 1.0f - 0x1p-24f}};

template <typename E>
void expect_kernel_equals_continue_path(const ShadeKernels& kernels, uint32_t bounce, bool light_traces_caustics,
                                        bool merges_photons, uint32_t seed) {
    Scene scene = build_scene(test::hexroom(8, 8, 1));
    scene.settings.max_bounces = 8;
    scene.settings.rr_start_bounce = 2;
    scene.settings.shadow_rays = 2;
    scene.light_traces_caustics = light_traces_caustics;
    scene.merges_photons = merges_photons;
    const std::vector<Vertex> vertices = random_vertices(1003, seed);  // not a multiple of any width

    RayQueue expected, actual;
    expected.reserve(vertices.size());
    actual.reserve(vertices.size());
    DiffuseVertexQueue queue;
    queue.reserve(vertices.size(), 2);
    std::size_t smooth_as_sampled = 0, smooth_mirrored = 0;  // smooth vertices whose paths go on
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vertex& v = vertices[i];
        ASSERT_TRUE(continues_as_diffuse(v.material));
        ContinuationRandom random = continuation_random<E>(scene, v.path, bounce);
        if (i < std::size(kFixedDraws)) random.direction = {kFixedDraws[i].u0, kFixedDraws[i].u1};
        queue.push(v.surface, v.material, v.d, v.throughput, random.direction.first, random.direction.second,
                   random.choice_and_roulette.second, uint32_t(i), v.specular_light_elsewhere, false);

        // continue_path itself for the vertices with their own draws; its body, sample_bsdf and
        // all, for the others.
        std::optional<PathContinuation> next;
        if (i >= std::size(kFixedDraws)) {
            next = continue_path<E, false>(scene, v.material, v.surface, v.d, v.throughput, v.path, bounce,
                                           v.specular_light_elsewhere);
        } else {
            const BsdfSample s =
                v.surface.smooth ? sample_bsdf_about_shading_normal(v.material, v.surface.normal, v.surface.shading_normal, v.d,
                                                                    random.direction.first, random.direction.second,
                                                                    random.choice_and_roulette.first, FresnelModel::schlick)
                                 : sample_bsdf(v.material, v.surface.normal, v.d, random.direction.first, random.direction.second,
                                               random.choice_and_roulette.first);
            if (s.valid) {
                PathContinuation c;
                c.throughput = v.throughput * s.weight;
                c.specular_light_elsewhere = v.specular_light_elsewhere ||
                                             (bounce == 0 ? scene.light_traces_caustics : scene.merges_photons);
                c.count_emission = E::mis;
                c.bsdf_pdf = E::mis ? diffuse_direction_pdf(v.surface, v.d, s.direction) : 0.0f;
                bool alive = c.throughput.x > 0.0f || c.throughput.y > 0.0f || c.throughput.z > 0.0f;
                if (alive && int(bounce) >= scene.settings.rr_start_bounce) {
                    const float q = fmin_float(0.95f, fmax_float(c.throughput.x, fmax_float(c.throughput.y, c.throughput.z)));
                    alive = random.choice_and_roulette.second < q;
                    c.throughput /= q;
                }
                const glm::vec3 side = glm::dot(s.direction, v.surface.normal) > 0.0f ? v.surface.normal : -v.surface.normal;
                c.ray = {offset_ray_origin(v.surface.position, v.surface.error, side), s.direction};
                if (alive) next = c;
            }
        }
        if (next) expected.push<E::mis>(*next, uint32_t(i));
        if (next && v.surface.smooth) {  // the direction drawn about the shading normal, before the mirror
            const glm::vec3 n = glm::dot(v.d, v.surface.normal) < 0.0f ? v.surface.normal : -v.surface.normal;
            const BsdfSample drawn = sample_diffuse(v.material, shading_normal_facing(v.surface.shading_normal, n), v.d,
                                                    random.direction.first, random.direction.second);
            (glm::dot(drawn.direction, n) > 0.0f ? smooth_as_sampled : smooth_mirrored) += 1;
        }
    }
    const DiffuseContinuation settings{int(bounce) >= scene.settings.rr_start_bounce, E::mis,
                                       bounce == 0 ? light_traces_caustics : merges_photons};
    kernels.continue_diffuse(queue, settings, actual);

    const std::string reproduce = std::string("isa ") + isa_name(kernels.isa) + ", bounce " + std::to_string(bounce) +
                                  ", mis " + std::to_string(E::mis) + ", seed " + std::to_string(seed) +
                                  " (reproduce: kernels_test --gtest_filter='ShadeKernels.*')";
    // Both sides: paths end (black, roulette, the horizon) and paths go on; smooth vertices' paths
    // go on both as sampled and mirrored up through the geometric surface (below their shading
    // normal), and flat ones go on too.
    EXPECT_GT(expected.count, vertices.size() / 4) << reproduce;
    EXPECT_LT(expected.count, vertices.size()) << reproduce;
    std::size_t flat = 0;
    for (std::size_t k = 0; k < expected.count; ++k) flat += !vertices[expected.path[k]].surface.smooth;
    EXPECT_GT(flat, 0u) << reproduce;
    EXPECT_GT(smooth_as_sampled, 0u) << reproduce;
    EXPECT_GT(smooth_mirrored, 0u) << reproduce;
    ASSERT_EQ(actual.count, expected.count) << reproduce;
    const auto same_bits = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (std::size_t k = 0; k < expected.count; ++k) {
        const uint32_t slot = expected.path[k];
        ASSERT_EQ(actual.path[k], slot) << reproduce << ", ray " << k;
        const float* fields[][2] = {{&expected.ox[k], &actual.ox[k]},
                                    {&expected.oy[k], &actual.oy[k]},
                                    {&expected.oz[k], &actual.oz[k]},
                                    {&expected.dx[k], &actual.dx[k]},
                                    {&expected.dy[k], &actual.dy[k]},
                                    {&expected.dz[k], &actual.dz[k]},
                                    {&expected.throughput_r[k], &actual.throughput_r[k]},
                                    {&expected.throughput_g[k], &actual.throughput_g[k]},
                                    {&expected.throughput_b[k], &actual.throughput_b[k]},
                                    {&expected.bsdf_pdf[k], &actual.bsdf_pdf[k]}};
        const char* names[] = {"ox", "oy", "oz", "dx", "dy", "dz", "throughput r", "throughput g", "throughput b", "pdf"};
        for (int f = 0; f < (E::mis ? 10 : 9); ++f)
            ASSERT_TRUE(same_bits(*fields[f][0], *fields[f][1]))
                << reproduce << ": " << names[f] << " of vertex " << slot << " is " << *fields[f][1] << ", continue_path gives "
                << *fields[f][0] << "; " << describe(vertices[slot]);
        ASSERT_EQ(int(actual.count_emission[k]), int(expected.count_emission[k])) << reproduce << ", vertex " << slot;
    }
}

// The light samples of the same kind of vertices, `count` per vertex, against DirectLightSampler.
template <typename E>
void expect_light_kernel_equals_direct_light_sampler(const ShadeKernels& kernels, uint32_t bounce, uint32_t count, uint32_t seed) {
    Scene scene = build_scene(test::hexroom(8, 8, 1));
    scene.settings.max_bounces = 8;
    scene.settings.shadow_rays = int(count);
    scene.settings.estimator.clamp_indirect = E::clamps_indirect ? 0.05f : 0.0f;
    std::vector<Vertex> vertices = random_vertices(1001, seed);
    // About the room (its light is on the ceiling, near the origin): most samples reach a ray.
    for (std::size_t i = 0; i < vertices.size(); i += 2) {
        Vertex& v = vertices[i];
        v.surface.position = glm::vec3(v.surface.position.x, v.surface.position.y, v.surface.position.z) * (5.0f / (1.0f + glm::length(v.surface.position)));
        v.surface.error = rounding_gamma(7) * magnitude(v.surface.position);
    }

    ShadowQueue expected, actual;
    expected.reserve(vertices.size() * count);
    actual.reserve(vertices.size() * count);
    DiffuseVertexQueue queue;
    queue.reserve(vertices.size(), count);
    std::size_t sampled = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vertex& v = vertices[i];
        const bool samples_lights = gathers_direct_light(v.material);
        sampled += samples_lights;
        const typename E::Sampler random(v.path, bounce, count);
        queue.push(v.surface, v.material, v.d, v.throughput, 0.0f, 0.0f, 0.0f, uint32_t(i), false, samples_lights);
        if (!samples_lights) continue;
        for (uint32_t j = 0; j < count; ++j) queue.set_light_sample(i, j, light_sample_point<E>(scene, random, j));
        const DirectLightSampler<E> sampler(scene, v.material, v.surface, light_sampling_point(v.surface, v.d), v.d, v.throughput,
                                            v.path, bounce, count);
        sampler.sample_all([&](const ShadowRay& shadow) { expected.push(shadow, uint32_t(i)); });
    }
    const DiffuseLightSampling settings{count, E::mis && int(bounce) + 1 < scene.settings.max_bounces,
                                        light_sample_clamp_limit<E>(scene, bounce, count)};
    kernels.sample_diffuse_lights(queue, settings, actual);

    const std::string reproduce = std::string("isa ") + isa_name(kernels.isa) + ", bounce " + std::to_string(bounce) +
                                  ", mis " + std::to_string(E::mis) + ", clamps " + std::to_string(E::clamps_indirect) +
                                  ", seed " + std::to_string(seed) + " (reproduce: kernels_test --gtest_filter='ShadeKernels.*')";
    // Both sides: samples that trace a ray and samples that cannot contribute; rays from flat
    // vertices and from smooth ones (the folded BSDF).
    EXPECT_GT(expected.count, sampled * count / 4) << reproduce;
    EXPECT_LT(expected.count, sampled * count) << reproduce;
    std::size_t from_smooth = 0;
    for (std::size_t k = 0; k < expected.count; ++k) from_smooth += vertices[expected.path[k]].surface.smooth;
    EXPECT_GT(from_smooth, 0u) << reproduce;
    EXPECT_LT(from_smooth, expected.count) << reproduce;
    ASSERT_EQ(actual.count, expected.count) << reproduce;
    // The kernel pushes sample j of N neighbouring vertices together: compared path by path, each
    // path's samples in the order they were pushed (the order the shadow stage adds them in).
    const auto by_path = [](const ShadowQueue& q) {
        std::vector<std::size_t> order(q.count);
        for (std::size_t k = 0; k < q.count; ++k) order[k] = k;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return q.path[a] < q.path[b]; });
        return order;
    };
    const std::vector<std::size_t> expected_order = by_path(expected), actual_order = by_path(actual);
    const auto same_bits = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (std::size_t rank = 0; rank < expected.count; ++rank) {
        const std::size_t e = expected_order[rank], a = actual_order[rank];
        const uint32_t slot = expected.path[e];
        ASSERT_EQ(actual.path[a], slot) << reproduce << ", shadow ray " << rank << " in path order";
        const float* fields[][2] = {{&expected.ox[e], &actual.ox[a]},
                                    {&expected.oy[e], &actual.oy[a]},
                                    {&expected.oz[e], &actual.oz[a]},
                                    {&expected.dx[e], &actual.dx[a]},
                                    {&expected.dy[e], &actual.dy[a]},
                                    {&expected.dz[e], &actual.dz[a]},
                                    {&expected.tmax[e], &actual.tmax[a]},
                                    {&expected.contribution_r[e], &actual.contribution_r[a]},
                                    {&expected.contribution_g[e], &actual.contribution_g[a]},
                                    {&expected.contribution_b[e], &actual.contribution_b[a]}};
        const char* names[] = {"ox", "oy", "oz", "dx", "dy", "dz", "tmax", "contribution r", "contribution g", "contribution b"};
        for (int f = 0; f < 10; ++f)
            ASSERT_TRUE(same_bits(*fields[f][0], *fields[f][1]))
                << reproduce << ": " << names[f] << " of a sample of vertex " << slot << " is " << *fields[f][1]
                << ", DirectLightSampler gives " << *fields[f][0] << "; " << describe(vertices[slot]);
    }
}

std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (Isa isa : kAllIsas)
        if (cpu_supports(isa)) isas.push_back(isa);
    return isas;
}

TEST(ShadeKernels, DiffuseContinuationEqualsContinuePathBitForBit) {
    for (Isa isa : supported_isas()) {
        const ShadeKernels& kernels = shade_kernels(isa);
        EXPECT_EQ(kernels.isa, isa);
        // The first hit with light tracing, a bounce with photons, and two past the roulette's start.
        expect_kernel_equals_continue_path<DefaultEstimator>(kernels, 0, true, false, 1);
        expect_kernel_equals_continue_path<DefaultEstimator>(kernels, 1, false, true, 2);
        expect_kernel_equals_continue_path<DefaultEstimator>(kernels, 2, false, false, 3);
        expect_kernel_equals_continue_path<Estimator<SobolSampler, LightSampling::mis, false>>(kernels, 5, true, true, 4);
        expect_kernel_equals_continue_path<Estimator<IndependentSampler, LightSampling::mis, true>>(kernels, 0, false, false, 5);
    }
}

TEST(ShadeKernels, DiffuseLightSamplesEqualDirectLightSamplerBitForBit) {
    for (Isa isa : supported_isas()) {
        const ShadeKernels& kernels = shade_kernels(isa);
        expect_light_kernel_equals_direct_light_sampler<DefaultEstimator>(kernels, 0, 1, 11);
        expect_light_kernel_equals_direct_light_sampler<DefaultEstimator>(kernels, 2, 3, 12);
        // mis at the bounce cap (no BSDF sample competes) and before it; the clamp past the first hit.
        expect_light_kernel_equals_direct_light_sampler<Estimator<IndependentSampler, LightSampling::mis, false>>(kernels, 7, 2, 13);
        expect_light_kernel_equals_direct_light_sampler<Estimator<SobolSampler, LightSampling::mis, true>>(kernels, 1, 2, 14);
        expect_light_kernel_equals_direct_light_sampler<Estimator<StratifiedSampler, LightSampling::nee, true>>(kernels, 3, 1, 15);
    }
}

// Hits on every triangle and sphere of `scene` (its own and its instances'), then on random ones,
// at random barycentrics and distances, with misses among them, in chunks of every length: the
// surface kernel against surface_at on every ISA and both triangle tests, for the hits it
// computes (surface_kernel_ids; an instance's are surface_at's, and the kernel must still get
// the lanes beside them right); every 13th hit at the midpoint of an edge, on `edge_prim` where
// one is given. Returns the hits on the scene's own triangles that were smooth and those that
// were not.
std::pair<std::size_t, std::size_t> expect_surface_points_equal_surface_at(Scene& scene, uint32_t seed,
                                                                           uint32_t edge_prim = kNoHit) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const uint32_t own = surface_kernel_ids(scene);
    EXPECT_EQ(own, uint32_t(scene.triangles.size() + scene.spheres.size()));
    const uint32_t primitives = uint32_t(own + scene.instances.triangle_count);
    const std::size_t n = std::max<std::size_t>(3 * SurfaceChunk::kSize + 7, primitives + SurfaceChunk::kSize + 7);
    RayQueue rays;
    rays.reserve(n);
    HitQueue hits;
    hits.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 origin = 8.0f * glm::vec3(unit(rng), unit(rng), unit(rng)) - 4.0f;
        rays.push({origin, glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f)}, glm::vec3(1.0f), 0, 0);
        float u = unit(rng), v = (1.0f - u) * unit(rng);
        uint32_t prim = i >= primitives && i % 9 == 4 ? kNoHit : i < primitives ? uint32_t(i) : uint32_t(rng() % primitives);
        if (i % 13 == 5) {  // an edge's midpoint, where opposite vertex normals cancel
            u = 0.5f, v = 0.0f;
            if (i >= primitives && edge_prim != kNoHit) prim = edge_prim;
        }
        hits.set(i, {10.0f * unit(rng), prim, u, v});
    }
    std::size_t spheres = 0, smooth = 0, flat = 0, instanced = 0;
    for (TriangleTest test : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        scene.settings.accuracy.triangles = test;
        for (Isa isa : supported_isas()) {
            SurfaceChunk chunk;
            for (std::size_t first = 0; first < n; first += SurfaceChunk::kSize) {
                const std::size_t count = std::min(SurfaceChunk::kSize, n - first);
                shade_kernels(isa).surface_points(scene, rays, hits, first, count, chunk);
                for (std::size_t k = 0; k < count; ++k) {
                    const Hit hit = hits.hit(first + k);
                    if (!hit.found()) continue;
                    if (hit.prim >= own) {
                        ++instanced;
                        continue;
                    }
                    const SurfacePoint expected = surface_at(scene, rays.ray(first + k), hit), actual = chunk.at(k);
                    (hit.prim >= scene.triangles.size() ? spheres : expected.smooth ? smooth : flat) += 1;
                    const std::string where = std::string(isa_name(isa)) + ", " + name_of(test) + ", primitive " +
                                              std::to_string(hit.prim) + ", u " + std::to_string(hit.u) + ", v " +
                                              std::to_string(hit.v) + " (reproduce: kernels_test --gtest_filter='ShadeKernels.Surface*')";
                    EXPECT_EQ(std::memcmp(&expected.position, &actual.position, sizeof(glm::vec3)), 0) << where;
                    EXPECT_EQ(std::memcmp(&expected.error, &actual.error, sizeof(glm::vec3)), 0) << where;
                    EXPECT_EQ(std::memcmp(&expected.normal, &actual.normal, sizeof(glm::vec3)), 0) << where;
                    EXPECT_EQ(std::memcmp(&expected.shading_normal, &actual.shading_normal, sizeof(glm::vec3)), 0) << where;
                    EXPECT_EQ(expected.smooth, actual.smooth) << where;
                    EXPECT_EQ(expected.material, actual.material) << where;
                    if (::testing::Test::HasFailure()) return {smooth, flat};
                }
            }
        }
    }
    EXPECT_GT(spheres, 0u);
    EXPECT_EQ(instanced > 0, !scene.instances.empty());
    return {smooth, flat};
}

// The hexroom with triangles at every orientation and scale, and a sliver.
TEST(ShadeKernels, SurfacePointsEqualSurfaceAtBitForBit) {
    Scene scene = build_scene(test::hexroom(8, 8, 1));
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    // The room's walls are vertical: triangles at every orientation and scale too.
    for (int k = 0; k < 64; ++k) {
        const float scale = std::pow(10.0f, float(k % 7 - 3));
        const auto corner = [&] { return scale * (glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f); };
        scene.triangles.push_back(corner(), corner(), corner(), 0);
    }
    const glm::vec3 corner(1.0f, 2.0f, 3.0f);
    scene.triangles.push_back(corner, corner + glm::vec3(1e-30f, 0.0f, 0.0f), corner + glm::vec3(2e-30f, 0.0f, 0.0f), 0);
    ASSERT_TRUE(scene.shading_normals.empty());
    const auto [smooth, flat] = expect_surface_points_equal_surface_at(scene, 22);
    EXPECT_EQ(smooth, 0u);
    EXPECT_GT(flat, 0u);
    // The sliver's normal is 0, as TriangleSoA::normal gives it.
    EXPECT_EQ(scene.triangles.normal(scene.triangles.size() - 1), glm::vec3(0.0f));
}

// The hexroom with meshes that have vertex normals (random, some wound against the geometry, some
// opposite at an edge so they cancel at its midpoint, one huge and one tiny) beside one without:
// the shading normals, and which hits are smooth, as ShadingNormalTable::at gives them.
TEST(ShadeKernels, SurfacePointsWithVertexNormalsEqualSurfaceAtBitForBit) {
    SceneDescription d = test::hexroom(8, 8, 1);
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float scale : {1.0f, 1e-3f, 1e4f}) {
        TriangleMesh m = test::icosphere(1, scale, glm::vec3(5.0f, 0.0f, 0.0f));
        for (std::size_t k = 0; k < m.vertices.size(); ++k) {
            const glm::vec3 outward = glm::normalize(m.vertices[k] - glm::vec3(5.0f, 0.0f, 0.0f));
            m.normals.push_back(k % 5 == 0 ? -outward : k % 5 == 1 ? random_unit(rng) : outward);
        }
        d.meshes.push_back(m);
    }
    TriangleMesh cancelling;  // normals opposite at vertices 0 and 1: they cancel at u = 0.5, v = 0
    cancelling.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    cancelling.triangles = {{0, 1, 2}};
    cancelling.normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}};
    d.meshes.push_back(cancelling);
    d.meshes.push_back(test::icosphere(1, 0.5f, glm::vec3(2.0f, 1.0f, 0.0f)));  // flat: no normals
    Scene scene = build_scene(d);
    ASSERT_FALSE(scene.shading_normals.empty());
    uint32_t cancelling_prim = kNoHit;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const TriangleSoA::Corner c = scene.triangles.corner(i);
        if (c.v0 == glm::vec3(0.0f) && c.e1 == glm::vec3(1, 0, 0) && c.e2 == glm::vec3(0, 1, 0)) cancelling_prim = i;
    }
    ASSERT_NE(cancelling_prim, kNoHit);
    const glm::vec3 midpoint_normal = scene.shading_normals.at(scene.triangles, cancelling_prim, 0.5f, 0.0f, glm::vec3(0, 0, 1));
    EXPECT_EQ(midpoint_normal, glm::vec3(0, 0, 1));  // the geometric normal where the blend cancels
    const auto [smooth, flat] = expect_surface_points_equal_surface_at(scene, 24, cancelling_prim);
    // Both sides: hits the vertex normals shade, and hits on the room, the flat mesh and where
    // the normals cancel, which keep the geometric normal.
    EXPECT_GT(smooth, 0u);
    EXPECT_GT(flat, 0u);
}

// A scene with instances (placed with and without vertex normals) beside its own triangles, with
// vertex normals, and spheres: the kernel's lanes among the instances' hits.
TEST(ShadeKernels, SurfacePointsBesideInstancesEqualSurfaceAtBitForBit) {
    for (bool normals : {false, true}) {
        SceneDescription d = test::instanced_scene(test::test_placements(), normals, 6);
        d.spheres.push_back({{5.0f, 3.0f, 1.0f}, 0.7f, 0});
        d.spheres.push_back({{8.0f, -3.0f, 0.0f}, 1.2f, 1});
        TriangleMesh smooth_mesh = test::icosphere(1, 0.8f, glm::vec3(3.0f, -2.0f, 2.0f));
        for (const glm::vec3& v : smooth_mesh.vertices) smooth_mesh.normals.push_back(glm::normalize(v - glm::vec3(3.0f, -2.0f, 2.0f)));
        d.meshes.push_back(smooth_mesh);
        Scene scene = build_scene(d);
        ASSERT_FALSE(scene.instances.empty());
        ASSERT_GT(scene.instances.triangle_count, 0u);
        const auto [smooth, flat] = expect_surface_points_equal_surface_at(scene, normals ? 26 : 25);
        EXPECT_GT(smooth, 0u);
        EXPECT_GT(flat, 0u);
    }
}

// Vertices past the queue's count are never pushed, whatever the padding lanes hold.
TEST(ShadeKernels, DiffuseContinuationReadsOnlyTheQueuedVertices) {
    for (Isa isa : supported_isas()) {
        DiffuseVertexQueue queue;
        queue.reserve(40, 1);
        const std::vector<Vertex> vertices = random_vertices(40, 9);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const Vertex& v = vertices[i];
            queue.push(v.surface, v.material, v.d, glm::vec3(1.0f), 0.3f, 0.6f, 0.0f, uint32_t(i), false, false);
        }
        RayQueue next;
        next.reserve(40);
        for (std::size_t count : {0u, 1u, 3u, 17u, 40u}) {
            queue.count = count;
            next.count = 0;
            shade_kernels(isa).continue_diffuse(queue, {false, false, false}, next);
            std::size_t lit = 0;  // vertices with some albedo go on (1 throughput, no roulette)
            for (std::size_t i = 0; i < count; ++i) lit += vertices[i].material.albedo != glm::vec3(0.0f);
            EXPECT_EQ(next.count, lit) << isa_name(isa) << ", " << count << " queued";
            for (std::size_t k = 0; k < next.count; ++k) EXPECT_LT(next.path[k], count) << isa_name(isa);
        }
    }
}

}  // namespace
}  // namespace wt

// The SIMD shade kernels against the scalar vertex code they replace, bit for bit, on every ISA
// this CPU runs: the diffuse continuation kernel (kernels/shading/diffuse_continuation.h) against
// continue_path (core/path/path_vertex.h), on random flat diffuse vertices and on the extremes
// (poles of the frame, grazing directions, the disk's centre and diagonals, black and
// near-black paths, huge and tiny scales, zero coordinates).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/path/path_vertex.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/diffuse_vertex_queue.h"
#include "kernels/queues/ray_queues.h"

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
      << ", " << v.surface.normal.z << "), d (" << v.d.x << ", " << v.d.y << ", " << v.d.z << "), key " << v.path.key
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
        v.surface.smooth = false;
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
    Scene scene;
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
    queue.reserve(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vertex& v = vertices[i];
        ASSERT_TRUE(continues_as_flat_diffuse(v.material, v.surface));
        ContinuationRandom random = continuation_random<E>(scene, v.path, bounce);
        if (i < std::size(kFixedDraws)) random.direction = {kFixedDraws[i].u0, kFixedDraws[i].u1};
        queue.push(v.surface, v.material, v.d, v.throughput, random.direction.first, random.direction.second,
                   random.choice_and_roulette.second, uint32_t(i), v.specular_light_elsewhere);

        // continue_path itself for the vertices with their own draws; its body, sample_bsdf and
        // all, for the others.
        std::optional<PathContinuation> next;
        if (i >= std::size(kFixedDraws)) {
            next = continue_path<E, false>(scene, v.material, v.surface, v.d, v.throughput, v.path, bounce,
                                           v.specular_light_elsewhere);
        } else {
            const BsdfSample s = sample_bsdf(v.material, v.surface.normal, v.d, random.direction.first, random.direction.second,
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
    }
    const DiffuseContinuation settings{int(bounce) >= scene.settings.rr_start_bounce, E::mis,
                                       bounce == 0 ? light_traces_caustics : merges_photons};
    kernels.continue_diffuse(queue, settings, actual);

    const std::string reproduce = std::string("isa ") + isa_name(kernels.isa) + ", bounce " + std::to_string(bounce) +
                                  ", mis " + std::to_string(E::mis) + ", seed " + std::to_string(seed) +
                                  " (reproduce: kernels_test --gtest_filter='ShadeKernels.*')";
    // Both sides: paths end (black, roulette, the horizon) and paths go on.
    EXPECT_GT(expected.count, vertices.size() / 4) << reproduce;
    EXPECT_LT(expected.count, vertices.size()) << reproduce;
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

std::vector<Isa> supported_isas() {
    std::vector<Isa> isas;
    for (Isa isa : {Isa::scalar, Isa::sse4, Isa::avx2, Isa::avx512})
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

// Vertices past the queue's count are never pushed, whatever the padding lanes hold.
TEST(ShadeKernels, DiffuseContinuationReadsOnlyTheQueuedVertices) {
    for (Isa isa : supported_isas()) {
        DiffuseVertexQueue queue;
        queue.reserve(40);
        const std::vector<Vertex> vertices = random_vertices(40, 9);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const Vertex& v = vertices[i];
            queue.push(v.surface, v.material, v.d, glm::vec3(1.0f), 0.3f, 0.6f, 0.0f, uint32_t(i), false);
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

// The shade kernels' continuation of light paths at flat mirror and glass vertices
// (kernels/shading/specular_continuation.h) against LightPathTracer::at_vertex, bit for bit, on
// every ISA this CPU runs: the hexroom's mirror wall and glass spheres hit from outside and from
// inside (total internal reflection), with and without Russian roulette, by both Fresnel models,
// at an index of refraction of 1.5 and of 1 (where Schlick's reflectance is 0), and a mirror
// with a black channel.

#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "kernels/accel/scene_intersect.h"
#include "kernels/caustics/light_path.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "test_scenes.h"

namespace wt {
namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// One vertex asked of both: the scalar answer, and its place in the queue.
struct Asked {
    std::optional<LightRay> next;
    std::string name;
};

struct Tally {
    std::size_t continued = 0, ended = 0, transmitted = 0, reflected_inside = 0;
};

// Light paths meeting the scene's specular surfaces at `vertex`: rays from the light's first
// rays and from points inside and outside the glass spheres, weights of every kind.
void check_vertex(const Scene& scene, uint32_t vertex, const std::string& where, Tally& tally) {
    const LightPathTracer tracer(scene, nullptr);
    std::mt19937 rng(vertex * 7919u + 5u);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<LightRay> arriving;
    for (uint64_t index = 0; index < 30000; ++index)
        if (const auto r = tracer.start(light_path_key(9, index, 0))) arriving.push_back(*r);
    for (uint32_t s = 0; s < scene.spheres.size(); ++s)
        for (int k = 0; k < 4000; ++k) {
            // From inside (at 0.9 radii from the centre, any direction: oblique and grazing
            // incidence, refraction and total internal reflection) and from 2 radii out, aimed
            // anywhere at the sphere.
            const float radius = scene.spheres.radius[s];
            const auto any_direction = [&] { return glm::normalize(glm::vec3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f)); };
            const glm::vec3 offset = any_direction() * (radius * (k % 2 ? 0.9f : 2.0f));
            const glm::vec3 d = k % 2 ? any_direction() : glm::normalize(any_direction() * radius - offset);
            arriving.push_back({{scene.spheres.center(s) + offset, d}, glm::vec3(1.0f), glm::vec3(1.0f)});
        }
    SpecularVertexQueue q;
    q.reserve(arriving.size());
    std::vector<Asked> asked;
    std::optional<Material> textured;
    for (std::size_t i = 0; i < arriving.size(); ++i) {
        LightRay at = arriving[i];
        // Weights as light paths carry them: dim, bright, one channel black, all black (which
        // ends the path without roulette).
        at.weight = glm::vec3(u01(rng), 2.0f * u01(rng), i % 5 == 0 ? 0.0f : u01(rng));
        if (i % 7 == 0) at.weight = glm::vec3(0.0f);
        const Hit hit = intersect_closest(scene, at.ray);
        if (!hit.found()) continue;
        const uint64_t key = light_path_key(9, i, 1);
        if (!tracer.queue_specular(key, vertex, at, surface_at(scene, at.ray, hit), uint32_t(asked.size()), q)) continue;
        asked.push_back({tracer.at_vertex(key, vertex, at, hit, textured).next, where + ", vertex " + std::to_string(vertex) +
                                                                                 ", ray " + std::to_string(i)});
    }
    ASSERT_GT(asked.size(), 10000u) << where;
    for (const Isa isa : kAllIsas) {
        if (!cpu_supports(isa)) continue;
        RayQueue next;
        next.reserve(q.count);
        shade_kernels(isa).continue_specular(q, tracer.roulette_at(vertex), scene.settings.accuracy.fresnel, next);
        std::vector<int> pushed(asked.size(), -1);
        for (std::size_t k = 0; k < next.count; ++k) {
            ASSERT_LT(next.path[k], asked.size()) << where << ", " << isa_name(isa);
            pushed[next.path[k]] = int(k);
        }
        for (std::size_t a = 0; a < asked.size(); ++a) {
            const std::string name = std::string(isa_name(isa)) + " kernels, " + asked[a].name;
            ASSERT_EQ(pushed[a] >= 0, asked[a].next.has_value()) << name << ": the kernel and at_vertex disagree on whether the path goes on";
            if (!asked[a].next) {
                if (isa == Isa::scalar) ++tally.ended;
                continue;
            }
            const std::size_t k = std::size_t(pushed[a]);
            const LightRay& want = *asked[a].next;
            const float got[] = {next.ox[k], next.oy[k], next.oz[k], next.dx[k], next.dy[k], next.dz[k],
                                 next.throughput_r[k], next.throughput_g[k], next.throughput_b[k]};
            const float wanted[] = {want.ray.origin.x, want.ray.origin.y, want.ray.origin.z, want.ray.direction.x, want.ray.direction.y,
                                    want.ray.direction.z, want.weight.x, want.weight.y, want.weight.z};
            for (int c = 0; c < 9; ++c)
                ASSERT_TRUE(same_bits(got[c], wanted[c]))
                    << name << ": " << (c < 3 ? "origin" : c < 6 ? "direction" : "weight") << " component " << c % 3 << " is "
                    << got[c] << ", at_vertex gives " << wanted[c];
            if (isa != Isa::scalar) continue;
            ++tally.continued;
            const glm::vec3 d(q.dx[a], q.dy[a], q.dz[a]), n(q.nx[a], q.ny[a], q.nz[a]);
            const bool crossed = (glm::dot(d, n) < 0.0f) == (glm::dot(want.ray.direction, n) < 0.0f);
            if (q.glass[a] && crossed) ++tally.transmitted;
            if (q.glass[a] && !crossed && glm::dot(d, n) > 0.0f) ++tally.reflected_inside;
        }
    }
}

TEST(SpecularContinuation, EqualsAtVertexBitForBit) {
    for (const FresnelModel fresnel : {FresnelModel::schlick, FresnelModel::exact}) {
        for (const float ior : {1.5f, 1.0f}) {
            SceneDescription d = test::hexroom(8, 8, 1);
            d.settings.accuracy.fresnel = fresnel;
            for (Material& m : d.materials) {
                if (m.type == MaterialType::glass) m.ior = ior;
                if (m.type == MaterialType::mirror) m.reflectance = glm::vec3(0.9f, 0.5f, 0.0f);
            }
            const Scene scene = build_scene(d);
            const std::string where = std::string(fresnel == FresnelModel::exact ? "exact" : "schlick") + " Fresnel, ior " + std::to_string(ior);
            for (const uint32_t vertex : {1u, 5u}) {  // rr_start_bounce is 3: roulette at 5 alone
                Tally tally;
                ASSERT_NO_FATAL_FAILURE(check_vertex(scene, vertex, where, tally));
                // Both sides of every choice were asked about.
                EXPECT_GT(tally.continued, 1000u) << where << ", vertex " << vertex;
                EXPECT_GT(tally.ended, vertex == 5 ? 1000u : 100u) << where << ", vertex " << vertex;
                EXPECT_GT(tally.transmitted, 1000u) << where << ", vertex " << vertex;
                if (ior != 1.0f) {
                    EXPECT_GT(tally.reflected_inside, 100u) << where << ", vertex " << vertex;
                }
            }
        }
    }
}

}  // namespace
}  // namespace wt

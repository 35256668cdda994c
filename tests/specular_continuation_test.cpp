// The shade kernels' continuation at flat mirror and glass vertices
// (kernels/shading/specular_continuation.h), bit for bit on every ISA this CPU runs: of light
// paths against LightPathTracer::at_vertex, of camera paths against continue_path. Vertices: the
// hexroom's mirror wall and glass spheres hit from outside and from inside (total internal
// reflection), with and without Russian roulette, by both Fresnel models, at an index of
// refraction of 1.5 and of 1 (where Schlick's reflectance is 0), and a mirror with a black
// channel.

#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/path/estimator.h"
#include "core/path/path_vertex.h"
#include "kernels/accel/scene_intersect.h"
#include "kernels/caustics/light_path.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "kernels/wavefront/camera_specular_vertex.h"
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

// Rays meeting the scene's specular surfaces: the light's first rays, and rays from points
// inside and outside the glass spheres.
std::vector<LightRay> arriving_rays(const Scene& scene, const LightPathTracer& tracer, std::mt19937& rng) {
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
    return arriving;
}

// A weight as paths carry them: dim, bright, one channel black, all black (which ends the path
// without roulette).
glm::vec3 any_weight(std::size_t i, std::mt19937& rng) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const glm::vec3 w(u01(rng), 2.0f * u01(rng), i % 5 == 0 ? 0.0f : u01(rng));
    return i % 7 == 0 ? glm::vec3(0.0f) : w;
}

// Light paths meeting the scene's specular surfaces at `vertex`, weights of every kind.
void check_vertex(const Scene& scene, uint32_t vertex, const std::string& where, Tally& tally) {
    const LightPathTracer tracer(scene, nullptr);
    std::mt19937 rng(vertex * 7919u + 5u);
    const std::vector<LightRay> arriving = arriving_rays(scene, tracer, rng);
    SpecularVertexQueue q;
    q.reserve(arriving.size());
    std::vector<Asked> asked;
    std::optional<Material> textured;
    for (std::size_t i = 0; i < arriving.size(); ++i) {
        LightRay at = arriving[i];
        at.weight = any_weight(i, rng);
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

// Camera paths' mirror and glass vertices (queue_camera_specular_vertex, as the shade stage
// queues them) against continue_path, bit for bit on every ISA: the next ray, its throughput,
// its flags (count_emission and specular_light_elsewhere, both values of the arriving ray's) and,
// with mis, its pdf; with and without roulette, for nee and mis.
template <typename E>
void check_camera_vertices(const Scene& scene, uint32_t bounce, const std::string& where) {
    const LightPathTracer tracer(scene, nullptr);  // (for its rays only)
    std::mt19937 rng(bounce * 104729u + 3u);
    const std::vector<LightRay> arriving = arriving_rays(scene, tracer, rng);
    SpecularVertexQueue q;
    q.reserve(arriving.size());
    std::vector<std::optional<PathContinuation>> wanted;
    std::vector<std::string> names;
    std::size_t elsewhere_count = 0;
    for (std::size_t i = 0; i < arriving.size(); ++i) {
        const Ray& ray = arriving[i].ray;
        const Hit hit = intersect_closest(scene, ray);
        if (!hit.found()) continue;
        const SurfacePoint surface = surface_at(scene, ray, hit);
        const Material& m = scene.materials[surface.material];
        if (!continues_as_specular(m, surface)) continue;
        const glm::vec3 throughput = any_weight(i, rng);
        const PathSeed path{light_path_key(5, i, 2), uint32_t(i % 64)};
        const bool elsewhere = i % 3 == 0;
        elsewhere_count += elsewhere;
        queue_camera_specular_vertex<E>(scene, m, surface, ray.direction, throughput, path, bounce, elsewhere,
                                        uint32_t(wanted.size()), q);
        wanted.push_back(continue_path<E, false>(scene, m, surface, ray.direction, throughput, path, bounce, elsewhere));
        names.push_back(where + ", bounce " + std::to_string(bounce) + ", ray " + std::to_string(i));
    }
    ASSERT_GT(wanted.size(), 10000u) << where;
    ASSERT_GT(elsewhere_count, 3000u) << where;
    std::size_t continued = 0, ended = 0;
    for (const Isa isa : kAllIsas) {
        if (!cpu_supports(isa)) continue;
        RayQueue next;
        next.reserve(q.count);
        shade_kernels(isa).continue_specular(q, int(bounce) >= scene.settings.rr_start_bounce, scene.settings.accuracy.fresnel,
                                             next);
        std::vector<int> pushed(wanted.size(), -1);
        for (std::size_t k = 0; k < next.count; ++k) pushed[next.path[k]] = int(k);
        for (std::size_t a = 0; a < wanted.size(); ++a) {
            const std::string name = std::string(isa_name(isa)) + " kernels, " + names[a];
            ASSERT_EQ(pushed[a] >= 0, wanted[a].has_value()) << name << ": the kernel and continue_path disagree on whether the path goes on";
            if (!wanted[a]) {
                ended += isa == Isa::scalar;
                continue;
            }
            continued += isa == Isa::scalar;
            const std::size_t k = std::size_t(pushed[a]);
            const PathContinuation& want = *wanted[a];
            const float got[] = {next.ox[k], next.oy[k], next.oz[k], next.dx[k], next.dy[k], next.dz[k],
                                 next.throughput_r[k], next.throughput_g[k], next.throughput_b[k]};
            const float expected[] = {want.ray.origin.x, want.ray.origin.y, want.ray.origin.z, want.ray.direction.x,
                                      want.ray.direction.y, want.ray.direction.z, want.throughput.x, want.throughput.y,
                                      want.throughput.z};
            for (int c = 0; c < 9; ++c)
                ASSERT_TRUE(same_bits(got[c], expected[c]))
                    << name << ": " << (c < 3 ? "origin" : c < 6 ? "direction" : "throughput") << " component " << c % 3
                    << " is " << got[c] << ", continue_path gives " << expected[c];
            RayQueue one;
            one.reserve(1);
            one.push<E::mis>(want, 0);
            ASSERT_EQ(int(next.count_emission[k]), int(one.count_emission[0])) << name << ": the next ray's flags";
            if (E::mis) {
                ASSERT_TRUE(same_bits(next.bsdf_pdf[k], one.bsdf_pdf[0])) << name << ": the next ray's pdf";
            }
        }
    }
    EXPECT_GT(continued, 1000u) << where;
    EXPECT_GT(ended, 100u) << where;
}

TEST(SpecularContinuation, EqualsContinuePathBitForBit) {
    for (const FresnelModel fresnel : {FresnelModel::schlick, FresnelModel::exact}) {
        SceneDescription d = test::hexroom(8, 8, 1);
        d.settings.accuracy.fresnel = fresnel;
        for (Material& m : d.materials)
            if (m.type == MaterialType::mirror) m.reflectance = glm::vec3(0.9f, 0.5f, 0.0f);
        const Scene scene = build_scene(d);
        const std::string where = fresnel == FresnelModel::exact ? "exact Fresnel" : "schlick Fresnel";
        for (const uint32_t bounce : {0u, 5u}) {  // rr_start_bounce is 3: roulette at 5 alone
            ASSERT_NO_FATAL_FAILURE(check_camera_vertices<DefaultEstimator>(scene, bounce, where + ", nee"));
            ASSERT_NO_FATAL_FAILURE(
                (check_camera_vertices<Estimator<StratifiedSampler, LightSampling::mis, false>>(scene, bounce, where + ", mis")));
        }
    }
}

}  // namespace
}  // namespace wt

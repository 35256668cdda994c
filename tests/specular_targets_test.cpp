// The light paths' first-ray cull (kernels/caustics/specular_targets.h): every first ray whose
// closest hit (the flat reference loop) is a specular surface is kept, on the hexroom's mirror
// wall, glass spheres, either triangle test and either sphere test, and at grazing angles; most
// rays that would end at a wall are dropped; the any-hit kernels on the targets' view answer as
// may_hit does; a render with the cull gives the bits of one that traces every first ray, with
// fewer light rays.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "kernels/accel/scene_intersect.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/caustics/light_path.h"
#include "kernels/caustics/specular_targets.h"
#include "instance_scenes.h"
#include "render_helpers.h"
#include "test_scenes.h"

namespace wt {
namespace {

uint32_t first_specular_material(const SceneDescription& d) {
    for (uint32_t m = 0; m < d.materials.size(); ++m)
        if (d.materials[m].is_specular()) return m;
    ADD_FAILURE() << "no specular material";
    return 0;
}

struct Tally {
    std::size_t specular_hits = 0, dropped = 0, kept_other = 0;
};

// `ray` against the scene and the targets: a specular closest hit must be kept.
void check(const Scene& scene, const SpecularTargets& targets, const Ray& ray, Tally& tally, const std::string& where) {
    const Hit hit = intersect_closest(scene, ray);
    const uint32_t material = !hit.found() ? UINT32_MAX
                              : hit.prim < scene.triangles.size()
                                  ? scene.triangles.material[hit.prim]
                                  : scene.spheres.material[hit.prim - scene.triangles.size()];
    const bool specular = hit.found() && scene.materials[material].is_specular();
    const bool kept = targets.may_hit(ray);
    if (specular) {
        ++tally.specular_hits;
        ASSERT_TRUE(kept) << where << ": the ray from (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z
                          << ") along (" << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z
                          << ") hits specular primitive " << hit.prim << " at t = " << hit.t << " and was dropped";
    }
    (kept ? tally.kept_other : tally.dropped) += specular ? 0 : 1;
}

// The rays both tests below ask about: the light paths' own first rays, and rays from anywhere
// in the room in any direction, grazing ones among them.
struct NamedRay {
    Ray ray;
    std::string name;
};
std::vector<NamedRay> first_and_random_rays(const Scene& scene) {
    std::vector<NamedRay> rays;
    const LightPathTracer tracer(scene, nullptr);
    for (uint64_t index = 0; index < 40000; ++index)
        if (const auto r = tracer.start(light_path_key(7, index, 0))) rays.push_back({r->ray, "light path " + std::to_string(index)});
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const glm::vec3 eye = scene.camera.eye();
    for (int k = 0; k < 40000; ++k) {
        const glm::vec3 origin = eye + glm::vec3(8.0f * u01(rng), 6.0f * u01(rng) - 3.0f, 3.0f * u01(rng) - 2.0f);
        glm::vec3 d3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f);
        if (k % 4 == 0) d3.z *= 1e-4f;  // nearly parallel to the floor and ceiling
        if (!(glm::length(d3) > 0.0f)) continue;
        rays.push_back({Ray{origin, glm::normalize(d3)}, "random ray " + std::to_string(k)});
    }
    return rays;
}

// The hexroom at each combination of the primitive tests.
template <typename F>
void for_each_accuracy(F&& f) {
    for (const TriangleTest test : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        for (const SphereTest spheres : {SphereTest::quadratic, SphereTest::cancellation_free}) {
            SceneDescription d = test::hexroom(8, 8, 1);
            d.settings.accuracy.triangles = test;
            d.settings.accuracy.spheres = spheres;
            f(build_scene(d), std::string(name_of(test)) + ", " + name_of(spheres));
        }
    }
}

TEST(SpecularTargets, EveryFirstRayWhoseClosestHitIsSpecularIsKept) {
    for_each_accuracy([](const Scene& scene, const std::string& where) {
        const std::optional<SpecularTargets> targets = SpecularTargets::of(scene);
        ASSERT_TRUE(targets) << where;
        Tally tally;
        for (const NamedRay& r : first_and_random_rays(scene))
            ASSERT_NO_FATAL_FAILURE(check(scene, *targets, r.ray, tally, where + ", " + r.name));
        // Both sides: mirror and glass are hit and kept, and walls are hit and dropped.
        EXPECT_GT(tally.specular_hits, 4000u) << where;
        EXPECT_GT(tally.dropped, 20000u) << where;
    });
}

// The wavefront light pass asks the any-hit kernels about a batch against view(): every ISA's
// kernel answers as may_hit does, ray by ray.
TEST(SpecularTargets, TheAnyHitKernelsOnTheViewAnswerAsMayHit) {
    for_each_accuracy([](const Scene& scene, const std::string& where) {
        const std::optional<SpecularTargets> targets = SpecularTargets::of(scene);
        ASSERT_TRUE(targets) << where;
        const std::vector<NamedRay> rays = first_and_random_rays(scene);
        ShadowQueue queue;
        queue.reserve(rays.size());
        for (const NamedRay& r : rays) queue.push(ShadowRay{r.ray, std::numeric_limits<float>::infinity(), glm::vec3(1.0f)}, 0);
        std::size_t kept = 0;
        for (const NamedRay& r : rays) kept += targets->may_hit(r.ray);
        // Both answers are asked about.
        EXPECT_GT(kept, 4000u) << where;
        EXPECT_GT(rays.size() - kept, 20000u) << where;
        for (const Isa isa : kAllIsas) {
            if (!cpu_supports(isa)) continue;
            std::fill(queue.occluded.begin(), queue.occluded.end(), uint8_t(2));
            intersect_kernels(isa, scene.settings.accuracy).any_raypacket(targets->view(), ray_view(queue), queue.occluded.data());
            for (std::size_t i = 0; i < rays.size(); ++i)
                ASSERT_EQ(queue.occluded[i], uint8_t(targets->may_hit(rays[i].ray)))
                    << where << ", " << isa_name(isa) << " kernels, " << rays[i].name << " from (" << rays[i].ray.origin.x << ", "
                    << rays[i].ray.origin.y << ", " << rays[i].ray.origin.z << ") along (" << rays[i].ray.direction.x << ", "
                    << rays[i].ray.direction.y << ", " << rays[i].ray.direction.z << ")";
        }
    });
}

TEST(SpecularTargets, NoneWhereTheyWouldCostMore) {
    SceneDescription d = test::hexroom(8, 8, 1);
    const Scene few = build_scene(d);
    ASSERT_TRUE(SpecularTargets::of(few));
    // Past kMostPrimitives specular primitives: every first ray is traced.
    const uint32_t mirror = first_specular_material(d);
    for (std::size_t k = 0; k <= SpecularTargets::kMostPrimitives; ++k)
        d.spheres.push_back({glm::vec3(1000.0f + 3.0f * float(k), 1000.0f, 1000.0f), 0.5f, mirror});
    EXPECT_FALSE(SpecularTargets::of(build_scene(d)));
    // An instanced mesh with a specular part: likewise.
    SceneDescription instanced = test::instanced_scene({glm::dmat4(1.0)}, false);
    EXPECT_TRUE(SpecularTargets::of(build_scene(instanced)));
    instanced.materials[instanced.prototypes[0].parts.back().material].type = MaterialType::mirror;
    EXPECT_FALSE(SpecularTargets::of(build_scene(instanced)));
}

TEST(SpecularTargets, ARenderWithTheCullIsTheSameBitsWithFewerLightRays) {
    SceneDescription culled = test::hexroom(24, 24, 4);
    // The same room with more specular spheres than the cull keeps, hidden inside its opaque
    // white sphere, where no ray reaches them (nor do they move the scene's bounds, which the
    // photons' radius follows): that render traces every first ray.
    SceneDescription traced = culled;
    const uint32_t mirror = first_specular_material(culled);
    const Sphere* white = nullptr;
    for (const Sphere& s : culled.spheres)
        if (!culled.materials[s.material].is_specular() && culled.materials[s.material].type == MaterialType::lambertian) white = &s;
    ASSERT_NE(white, nullptr);
    for (std::size_t k = 0; k <= SpecularTargets::kMostPrimitives; ++k)
        traced.spheres.push_back({white->center + 0.02f * glm::vec3(float(k % 6), float(k / 6), 0.0f), 0.005f, mirror});
    ASSERT_TRUE(SpecularTargets::of(build_scene(culled)));
    ASSERT_FALSE(SpecularTargets::of(build_scene(traced)));
    for (const Integrator integrator : {Integrator::wavefront, Integrator::reference}) {
        const test::RenderedFilm a = test::render_film(culled, integrator), b = test::render_film(traced, integrator);
        EXPECT_TRUE(a.film == b.film) << "integrator " << int(integrator);
        EXPECT_EQ(a.result.counts.light_paths, b.result.counts.light_paths);
        EXPECT_EQ(a.result.counts.photons, b.result.counts.photons);
        EXPECT_EQ(a.result.counts.camera_connections, b.result.counts.camera_connections);
        EXPECT_GT(a.result.counts.camera_connections, 0u);
        EXPECT_LT(a.result.counts.light_rays, b.result.counts.light_rays);
        EXPECT_GT(a.result.counts.light_rays, 0u);
    }
}

}  // namespace
}  // namespace wt

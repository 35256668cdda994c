// The shade kernels' first rays of light paths from area lights (kernels/shading/area_light_rays.h)
// against LightPathTracer::start, bit for bit, on every ISA this CPU runs: the hexroom's light
// and an emissive icosphere and two quads beside it, so the lights face every way, straight up,
// straight down and sideways (a normal with z = 0) among them.

#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/caustics/light_path.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"
#include "kernels/queues/light_point_queue.h"
#include "kernels/queues/ray_queues.h"
#include "test_scenes.h"

namespace wt {
namespace {

SceneDescription lights_facing_every_way() {
    SceneDescription d = test::hexroom(8, 8, 1);
    Material glow;
    glow.name = "glow";
    glow.emission = glm::vec3(3.0f, 2.0f, 1.0f);
    d.materials.push_back(glow);
    const uint32_t material = uint32_t(d.materials.size() - 1);
    TriangleMesh ball = test::icosphere(1, 0.5f, glm::vec3(5.0f, 3.0f, 0.0f));
    ball.material = material;
    d.meshes.push_back(ball);
    TriangleMesh sideways;  // normal along +-x: n.z = 0
    sideways.vertices = {{2.0f, -1.0f, -1.0f}, {2.0f, -0.5f, -1.0f}, {2.0f, -0.5f, -0.5f}};
    sideways.triangles = {{0, 1, 2}};
    sideways.material = material;
    d.meshes.push_back(sideways);
    TriangleMesh up;  // normal along +-z
    up.vertices = {{3.0f, 1.0f, -4.0f}, {3.5f, 1.0f, -4.0f}, {3.0f, 1.5f, -4.0f}};
    up.triangles = {{0, 1, 2}};
    up.material = material;
    d.meshes.push_back(up);
    return d;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(AreaLightRays, EqualLightPathTracerStartBitForBit) {
    const Scene scene = build_scene(lights_facing_every_way());
    ASSERT_GT(scene.lights.size(), 80u);
    const LightPathTracer tracer(scene, nullptr);
    constexpr uint64_t kPaths = 20000;
    const auto key = [](uint64_t index) { return light_path_key(3, index, 0); };
    LightPointQueue points;
    points.reserve(kPaths);
    std::vector<std::optional<LightRay>> expected;
    for (uint64_t index = 0; index < kPaths; ++index) {
        const AreaLightStart s = tracer.area_light_start(key(index));
        points.push(s.light.position, s.light.error, s.light.normal, s.direction.first, s.direction.second, uint32_t(index));
        expected.push_back(tracer.start(key(index)));
    }
    std::size_t started = 0;
    for (const auto& r : expected) started += r.has_value();
    EXPECT_GT(started, kPaths * 9 / 10);
    for (const Isa isa : kAllIsas) {
        if (!cpu_supports(isa)) continue;
        ShadowQueue rays;
        rays.reserve(kPaths);
        shade_kernels(isa).aim_area_light_rays(points, rays);
        ASSERT_EQ(rays.count, started) << isa_name(isa);
        for (std::size_t i = 0; i < rays.count; ++i) {
            const uint32_t index = rays.path[i];
            const std::string reproduce = std::string(isa_name(isa)) + " kernels, light path " + std::to_string(index) +
                                          " (key light_path_key(3, " + std::to_string(index) + ", 0))";
            ASSERT_LT(index, kPaths) << reproduce;
            ASSERT_TRUE(expected[index]) << reproduce << ": the kernel starts a path start() does not";
            const Ray& want = expected[index]->ray;
            const float got[] = {rays.ox[i], rays.oy[i], rays.oz[i], rays.dx[i], rays.dy[i], rays.dz[i]};
            const float wanted[] = {want.origin.x, want.origin.y, want.origin.z, want.direction.x, want.direction.y, want.direction.z};
            for (int k = 0; k < 6; ++k)
                ASSERT_TRUE(same_bits(got[k], wanted[k]))
                    << reproduce << ": " << (k < 3 ? "origin" : "direction") << " component " << k % 3 << " is " << got[k]
                    << ", start() gives " << wanted[k];
            EXPECT_EQ(rays.tmax[i], std::numeric_limits<float>::infinity());
            EXPECT_EQ(rays.contribution(i), glm::vec3(1.0f));
            if (i > 0) {
                ASSERT_LT(rays.path[i - 1], index) << reproduce << ": out of the queue's order";
            }
        }
    }
}

}  // namespace
}  // namespace wt

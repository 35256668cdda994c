// The SIMD kernels against the scalar textbook intersection (primitive_intersect.h), for every
// ISA this CPU runs, both layouts and every accuracy variant: millions of random rays in the hexroom, rays through
// vertices and edges, rays in the planes of walls, origins on surfaces, every partial packet.
// The kernels do the textbook's arithmetic in the textbook's order without FMA, so the answer
// must be the same to the bit: same primitive, same t, u and v.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "kernels/isa/intersect_dispatch.h"
#include "kernels/accel/scene_intersect.h"
#include "kernel_test_helpers.h"
#include "sanitizer_scale.h"
#include "test_scenes.h"

namespace wt {
namespace {

using test::RayBatch;
using test::accuracy_variants;

glm::vec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> n;
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        if (glm::length(d) > 1e-3f) return glm::normalize(d);
    }
}

// Random rays inside the room, plus rays at every vertex, every edge's midpoint and along
// each triangle's plane, plus rays leaving surfaces from offset hit points.
RayBatch hexroom_rays(const Scene& scene, int random_count) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> ux(-2.5f, 12.5f), uy(-5.5f, 5.5f), uz(-4.9f, 4.9f), u01(0.0f, 1.0f);
    RayBatch b;
    for (int i = 0; i < random_count;) {
        const glm::vec3 o(ux(rng), uy(rng), uz(rng));
        // Inside the hexagon (P0(-3,0) P1(0,6) P2(10,6) P3(13,0) P4(10,-6) P5(0,-6)), as the
        // integrator's rays are.
        if (std::fabs(o.y) > 2.0f * o.x + 5.9f || std::fabs(o.y) > 25.9f - 2.0f * o.x) continue;
        b.push({o, random_direction(rng)}, 0.5f + 20.0f * u01(rng));
        ++i;
    }
    const glm::vec3 inside(5.0f, 0.5f, 0.3f);
    const TriangleSoA& t = scene.triangles;
    for (uint32_t i = 0; i < t.size(); ++i) {
        const glm::vec3 v0 = t.vertex0(i), v1 = v0 + t.edge1(i), v2 = v0 + t.edge2(i);
        for (const glm::vec3 target : {v0, v1, v2, 0.5f * (v0 + v1), 0.5f * (v1 + v2), 0.5f * (v0 + v2)})
            b.push({inside, glm::normalize(target - inside)}, 1e30f);
        // In the triangle's own plane, through its centroid: parallel to the surface.
        const glm::vec3 centroid = (v0 + v1 + v2) / 3.0f;
        b.push({centroid - t.edge1(i), glm::normalize(t.edge1(i))});
        // Leaving the surface from its centroid, both sides.
        for (float side : {1.0f, -1.0f}) {
            const glm::vec3 n = side * t.normal(i);
            b.push({offset_ray_origin(centroid, n), glm::normalize(n + 0.3f * random_direction(rng))});
        }
    }
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const glm::vec3 c = scene.spheres.center(i);
        const float r = scene.spheres.radius[i];
        b.push({c, random_direction(rng)});                                        // from the centre
        b.push({c - glm::vec3(0, 0, 3 * r) + glm::vec3(r, 0, 0), {0, 0, 1}});       // tangent
        const glm::vec3 n = random_direction(rng);
        b.push({offset_ray_origin(c + r * n, n), glm::normalize(n + 0.5f * random_direction(rng))});    // leaving outward
        b.push({offset_ray_origin(c + r * n, -n), glm::normalize(-n + 0.5f * random_direction(rng))});  // refracted inward
    }
    return b;
}

// Per accuracy variant, so 1M rays in all in CI; the `long` label runs 4M per variant.
#ifndef WT_LONG_TESTS
#define WT_LONG_TESTS 0
#endif
constexpr int kRandomRays = test::sanitizer_scaled(WT_LONG_TESTS ? 1 << 22 : 1 << 18);

class PacketIntersect : public ::testing::TestWithParam<Isa> {
protected:
    void SetUp() override {
        if (!cpu_supports(GetParam())) GTEST_SKIP() << "CPU lacks " << isa_name(GetParam());
        scene_ = build_scene(test::hexroom(8, 8, 1));
        rays_ = hexroom_rays(scene_, kRandomRays);
    }
    // The hexroom as built for these accuracy settings: quads become parallelograms for
    // Moller-Trumbore and triangle pairs for the watertight test.
    void rebuild_for(const AccuracySettings& accuracy) {
        SceneDescription d = test::hexroom(8, 8, 1);
        d.settings.accuracy = accuracy;
        scene_ = build_scene(d);
    }
    Scene scene_;
    RayBatch rays_;
};

TEST_P(PacketIntersect, ClosestHitEqualsScalarInBothLayouts) {
  for (const AccuracySettings& accuracy : accuracy_variants()) {
    SCOPED_TRACE(std::string(name_of(accuracy.triangles)) + " + " + name_of(accuracy.spheres));
    rebuild_for(accuracy);
    const IntersectKernels& k = intersect_kernels(GetParam(), accuracy);
    const FlatScene flat_scene(scene_);
    const SceneView view = flat_scene.view();
    const std::size_t n = rays_.ox.size();
    for (auto closest : {k.closest_raypacket, k.closest_primpacket}) {
        std::vector<float> t(n), u(n), v(n);
        std::vector<uint32_t> prim(n);
        closest(view, rays_.view(true), {t.data(), u.data(), v.data(), prim.data()});
        for (std::size_t i = 0; i < n; ++i) {
            const Hit expected = intersect_closest(scene_, rays_.ray(i), rays_.tmax[i]);
            ASSERT_EQ(prim[i], expected.prim) << "ray " << i;
            ASSERT_EQ(t[i], expected.found() ? expected.t : std::numeric_limits<float>::infinity()) << "ray " << i;
            if (expected.found()) {
                ASSERT_EQ(u[i], expected.u) << "ray " << i;
                ASSERT_EQ(v[i], expected.v) << "ray " << i;
            }
        }
    }
  }
}

TEST_P(PacketIntersect, AnyHitEqualsScalarInBothLayouts) {
    for (const AccuracySettings& accuracy : accuracy_variants()) {
        SCOPED_TRACE(std::string(name_of(accuracy.triangles)) + " + " + name_of(accuracy.spheres));
        rebuild_for(accuracy);
        const IntersectKernels& k = intersect_kernels(GetParam(), accuracy);
        const FlatScene flat_scene(scene_);
        const SceneView view = flat_scene.view();
        const std::size_t n = rays_.ox.size();
        for (auto any : {k.any_raypacket, k.any_primpacket}) {
            std::vector<uint8_t> occluded(n, 7);
            any(view, rays_.view(true), occluded.data());
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_EQ(occluded[i], uint8_t(intersect_any(scene_, rays_.ray(i), rays_.tmax[i]))) << "ray " << i;
        }
    }
}

TEST_P(PacketIntersect, EveryPartialPacketLengthAndNoWritesPastTheEnd) {
    const IntersectKernels& k = intersect_kernels(GetParam());
    const FlatScene flat_scene(scene_);
    const SceneView view = flat_scene.view();
    for (std::size_t count = 0; count <= 33; ++count) {
        const RayView rays = rays_.view(true, 100, count);
        std::vector<float> t(count + 1, -1.0f), u(count + 1), v(count + 1);
        std::vector<uint32_t> prim(count + 1, 12345);
        std::vector<uint8_t> occluded(count + 1, 9);
        for (auto closest : {k.closest_raypacket, k.closest_primpacket}) {
            closest(view, rays, {t.data(), u.data(), v.data(), prim.data()});
            EXPECT_EQ(prim[count], 12345u) << "wrote past the end, count " << count;
            EXPECT_EQ(t[count], -1.0f);
            for (std::size_t i = 0; i < count; ++i) {
                const Hit h = intersect_closest(scene_, rays_.ray(100 + i), rays_.tmax[100 + i]);
                EXPECT_EQ(prim[i], h.prim) << "count " << count << " lane " << i;
            }
        }
        for (auto any : {k.any_raypacket, k.any_primpacket}) {
            any(view, rays, occluded.data());
            EXPECT_EQ(occluded[count], 9) << "wrote past the end, count " << count;
        }
    }
}

TEST_P(PacketIntersect, SceneWithoutSpheresOrTriangles) {
    const IntersectKernels& k = intersect_kernels(GetParam());
    const FlatScene flat_scene(scene_);
    SceneView view = flat_scene.view();
    view.spheres.count = 0;
    std::vector<float> t(64), u(64), v(64);
    std::vector<uint32_t> prim(64);
    k.closest_raypacket(view, rays_.view(false, 0, 64), {t.data(), u.data(), v.data(), prim.data()});
    for (std::size_t i = 0; i < 64; ++i) EXPECT_LT(prim[i], scene_.triangles.size());  // closed room: always a wall
    view.triangles.count = 0;
    view.triangles.parallelogram_count = 0;
    view.spheres.count = 0;
    k.closest_primpacket(view, rays_.view(false, 0, 64), {t.data(), u.data(), v.data(), prim.data()});
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(prim[i], kNoHit);
        EXPECT_EQ(t[i], std::numeric_limits<float>::infinity());
    }
}

INSTANTIATE_TEST_SUITE_P(Isas, PacketIntersect, ::testing::ValuesIn(kAllIsas),
                         [](const auto& info) { return std::string(isa_name(info.param)); });

}  // namespace
}  // namespace wt

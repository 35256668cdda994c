// Instances against the same scene flattened, hit by hit: random rays (and rays aimed at random
// points of the instances' triangles) through the two-level BVH and through the flattened
// scene's BVH must find the same triangle at the same distance with the same normal, for
// rotated, scaled, sheared and mirrored placements; every ISA must give the scalar kernels' bits.
//
// Tolerances: the two scenes are not the same floats (the flattened vertices are M v rounded,
// the instanced ray is M^-1 o rounded), so distances agree to rounding: the hit points' distance
// along the normal, |dt| |cos|, within 1e-5 of the scene's size (some hundred float steps of it),
// and normals within 1e-5 plus 16 float steps of the flattened triangle's coordinates over its
// shortest edge (the flattened normal's own rounding; 2e-3 for the copy scaled by 1e-2). Which triangle is hit can differ only for a ray within
// rounding of an edge (a neighbour at the same distance, or at a silhouette the surface behind):
// at most 1 in 2,000 rays.

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "instance_scenes.h"
#include "kernels/accel/scene_bvh.h"
#include "kernels/isa/intersect_dispatch.h"

namespace {

using namespace wt;

struct Rays {
    std::vector<float> ox, oy, oz, dx, dy, dz, tmax;
    RayView view(bool with_tmax) const {
        return {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), with_tmax ? tmax.data() : nullptr,
                uint32_t(ox.size())};
    }
    void push(const glm::vec3& o, const glm::vec3& d, float t) {
        ox.push_back(o.x), oy.push_back(o.y), oz.push_back(o.z), dx.push_back(d.x), dy.push_back(d.y), dz.push_back(d.z);
        tmax.push_back(t);
    }
};

struct Hits {
    std::vector<float> t, u, v;
    std::vector<uint32_t> prim;
    std::vector<uint8_t> occluded;
    explicit Hits(std::size_t n) : t(n), u(n), v(n), prim(n), occluded(n) {}
    HitView view() { return {t.data(), u.data(), v.data(), prim.data()}; }
};

// Half the rays from random points of the room towards random points of random instanced
// triangles (nearly all hit something), half in random directions.
Rays make_rays(const Scene& flat, uint32_t first_instanced, std::size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(0.5f, 11.5f), y(-5.5f, 5.5f), z(-1.9f, 4.4f), unit(0.0f, 1.0f), signed_unit(-1.0f, 1.0f);
    std::uniform_int_distribution<uint32_t> tri(first_instanced, uint32_t(flat.triangles.size() - 1));
    Rays r;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 o(x(rng), y(rng), z(rng));
        glm::vec3 d;
        if (i % 2 == 0) {
            const uint32_t k = tri(rng);
            float a = unit(rng), b = unit(rng);
            if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
            d = flat.triangles.vertex0(k) + a * flat.triangles.edge1(k) + b * flat.triangles.edge2(k) - o;
        } else {
            do d = {signed_unit(rng), signed_unit(rng), signed_unit(rng)};
            while (glm::length(d) < 0.1f);
        }
        r.push(o, glm::normalize(d), 20.0f * unit(rng));
    }
    return r;
}

struct Outcome {
    Hits hits;
    explicit Outcome(std::size_t n) : hits(n) {}
};

Outcome trace(Isa isa, const Scene& scene, const BvhView& view, const Rays& rays, bool packets = false) {
    const IntersectKernels& k = intersect_kernels(isa, scene.settings.accuracy);
    Outcome out(rays.ox.size());
    (packets ? k.closest_bvh_packets : k.closest_bvh)(view, rays.view(false), out.hits.view());
    (packets ? k.any_bvh_packets : k.any_bvh)(view, rays.view(true), out.hits.occluded.data());
    return out;
}

void compare_with_flattened(TriangleTest test, std::size_t ray_count) {
    SceneDescription d = test::instanced_scene(test::test_placements(), true);
    d.settings.accuracy.triangles = test;
    const Scene instanced = build_scene(d);
    const Scene flat = build_scene(test::flattened(d));
    ASSERT_FALSE(instanced.instances.empty());
    ASSERT_EQ(instanced.instances.first_id + instanced.instances.triangle_count, flat.triangles.size());
    const SceneBvh instanced_bvh = build_scene_bvh(instanced, {}, nullptr);
    const SceneBvh flat_bvh = build_scene_bvh(flat, {}, nullptr);
    ASSERT_NE(instanced_bvh.view.instances, nullptr);
    ASSERT_EQ(flat_bvh.view.instances, nullptr);

    const Rays rays = make_rays(flat, instanced.instances.first_id, ray_count, 7);
    const Outcome a = trace(Isa::scalar, instanced, instanced_bvh.view, rays);
    const Outcome b = trace(Isa::scalar, flat, flat_bvh.view, rays);
    constexpr float kSceneSize = 12.0f;
    std::size_t other_triangle = 0, hits_compared = 0, occlusion_differs = 0;
    for (std::size_t i = 0; i < ray_count; ++i) {
        const Ray ray{{rays.ox[i], rays.oy[i], rays.oz[i]}, {rays.dx[i], rays.dy[i], rays.dz[i]}};
        const Hit ha{a.hits.t[i], a.hits.prim[i], a.hits.u[i], a.hits.v[i]};
        const Hit hb{b.hits.t[i], b.hits.prim[i], b.hits.u[i], b.hits.v[i]};
        if (ha.prim != hb.prim) {
            // A ray within rounding of an edge: the neighbour, or at a silhouette the triangle
            // behind (or nothing). Counted, below.
            ++other_triangle;
            std::printf("ray %zu: prim %u at %g instanced, %u at %g flattened\n", i, ha.prim, ha.t, hb.prim, hb.t);
            continue;
        }
        if (ha.found()) {
            ++hits_compared;
            const SurfacePoint sa = surface_at(instanced, ray, ha), sb = surface_at(flat, ray, hb);
            const float cosine = std::fabs(glm::dot(sb.normal, ray.direction));
            EXPECT_LE(std::fabs(ha.t - hb.t) * cosine, 1e-5f * kSceneSize) << "ray " << i << " prim " << hb.prim;
            EXPECT_LE(glm::length(sa.position - sb.position) * cosine, 1e-5f * kSceneSize) << "ray " << i;
            {
                // The flattened triangle's normal is the less precise one: its edges are
                // differences of world coordinates, each rounded to a step of |v0|.
                const TriangleSoA& ft = flat.triangles;
                const glm::vec3 v0 = ft.vertex0(hb.prim);
                const float largest = std::max({std::fabs(v0.x), std::fabs(v0.y), std::fabs(v0.z)});
                const float shortest = std::min(glm::length(ft.edge1(hb.prim)), glm::length(ft.edge2(hb.prim)));
                const float normal_tolerance = 1e-5f + 16.0f * 0x1p-24f * largest / shortest;
                EXPECT_LE(glm::length(sa.normal - sb.normal), normal_tolerance) << "ray " << i << " prim " << hb.prim;
                // Shading normals at the same point of the triangle (the instanced hit's
                // barycentrics, swapped where the flattened copy's winding was reversed), so
                // only the placement of the vertex normals is compared.
                // Only an instanced triangle has a placement (instance_of is for those ids alone).
                float det = 1.0f;
                if (ha.prim >= instanced.instances.first_id) {
                    const float (*m)[4] = instanced.instances.instance_of(ha.prim).to_world.m;
                    det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
                }
                Hit same_point = hb;
                same_point.u = det < 0.0f ? ha.v : ha.u, same_point.v = det < 0.0f ? ha.u : ha.v;
                const SurfacePoint sc = surface_at(flat, ray, same_point);
                EXPECT_LE(glm::length(sa.shading_normal - sc.shading_normal), 1e-5f) << "ray " << i;
                EXPECT_EQ(sa.material, sb.material);
                // Offsets clear the surface as each scene sees it.
                const glm::vec3 n = glm::dot(sa.normal, ray.direction) < 0.0f ? sa.normal : -sa.normal;
                const glm::vec3 start = offset_ray_origin(sa.position, sa.error, n);
                EXPECT_GE(glm::dot(start - sa.position, n), 0.0f);
            }
        }
        // Any hit: the same answer unless tmax lies within rounding of the closest hit.
        if (a.hits.occluded[i] != b.hits.occluded[i]) {
            ++occlusion_differs;
            EXPECT_LE(std::fabs(rays.tmax[i] - hb.t), 1e-4f * kSceneSize) << "ray " << i;
        }
        EXPECT_EQ(b.hits.occluded[i], uint8_t(hb.t < rays.tmax[i])) << "ray " << i;
    }
    std::printf("%zu rays, %zu hits compared, %zu on another triangle, %zu occlusions differ\n", ray_count, hits_compared,
                other_triangle, occlusion_differs);
    EXPECT_GT(hits_compared, ray_count / 2);
    EXPECT_LE(other_triangle, ray_count / 2000);
    EXPECT_LE(occlusion_differs, ray_count / 2000);

    // Every ISA, and the packet entry points, give the scalar kernels' bits.
    for (Isa isa : kAllIsas) {
        if (!cpu_supports(isa)) continue;
        for (bool packets : {false, true}) {
            const Outcome c = trace(isa, instanced, instanced_bvh.view, rays, packets);
            EXPECT_EQ(c.hits.t, a.hits.t) << isa_name(isa);
            EXPECT_EQ(c.hits.u, a.hits.u) << isa_name(isa);
            EXPECT_EQ(c.hits.v, a.hits.v) << isa_name(isa);
            EXPECT_EQ(c.hits.prim, a.hits.prim) << isa_name(isa);
            EXPECT_EQ(c.hits.occluded, a.hits.occluded) << isa_name(isa);
        }
    }
}

TEST(InstanceIntersect, MatchesFlattenedSceneMollerTrumbore) { compare_with_flattened(TriangleTest::moller_trumbore, 40000); }

TEST(InstanceIntersect, MatchesFlattenedSceneWatertight) { compare_with_flattened(TriangleTest::watertight, 40000); }

// The 4-wide tree and the 8-wide tree find the same hits.
TEST(InstanceIntersect, NodeWidthsAgree) {
    const SceneDescription d = test::instanced_scene(test::test_placements(), false);
    const Scene scene = build_scene(d);
    const Scene flat = build_scene(test::flattened(d));
    BvhBuildOptions four;
    four.node_width = 4;
    const SceneBvh wide = build_scene_bvh(scene, {}, nullptr), narrow = build_scene_bvh(scene, four, nullptr);
    const Rays rays = make_rays(flat, scene.instances.first_id, 5000, 11);
    const Outcome a = trace(Isa::scalar, scene, wide.view, rays), b = trace(Isa::scalar, scene, narrow.view, rays);
    EXPECT_EQ(a.hits.t, b.hits.t);
    EXPECT_EQ(a.hits.prim, b.hits.prim);
    EXPECT_EQ(a.hits.occluded, b.hits.occluded);
}

}  // namespace

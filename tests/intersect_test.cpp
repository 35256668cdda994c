// Scalar ray-primitive tests at the cases that break naive code: edges, vertices, parallel
// rays, origins inside and on spheres, tangent rays, primitives behind the ray.

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kernels/primitives/primitive_intersect.h"
#include "kernels/accel/scene_intersect.h"

namespace wt {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TriangleSoA unit_triangle() {  // in the plane z = 0
    TriangleSoA t;
    t.push_back({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    return t;
}

Hit hit_triangle(const TriangleSoA& t, glm::vec3 o, glm::vec3 d) {
    Hit h;
    intersect_triangle(t, 0, Ray{o, glm::normalize(d)}, h);
    return h;
}

TEST(TriangleIntersect, HitsInteriorWithBarycentricsAndDistance) {
    const Hit h = hit_triangle(unit_triangle(), {0.25f, 0.5f, 2.0f}, {0, 0, -1});
    ASSERT_TRUE(h.found());
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    EXPECT_FLOAT_EQ(h.u, 0.25f);
    EXPECT_FLOAT_EQ(h.v, 0.5f);
}

// ---- parallelograms: the same test with u <= 1 and v <= 1 in place of u + v <= 1 ----------

TriangleSoA unit_square() {  // (0,0)-(1,1) in the plane z = 0
    TriangleSoA t;
    t.push_parallelogram({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    return t;
}

TEST(ParallelogramIntersect, CoversTheHalfATriangleWouldMiss) {
    const Hit h = hit_triangle(unit_square(), {0.75f, 0.625f, 2.0f}, {0, 0, -1});
    ASSERT_TRUE(h.found());
    EXPECT_FLOAT_EQ(h.t, 2.0f);
    EXPECT_FLOAT_EQ(h.u, 0.75f);
    EXPECT_FLOAT_EQ(h.v, 0.625f);
    EXPECT_FALSE(hit_triangle(unit_triangle(), {0.75f, 0.625f, 2.0f}, {0, 0, -1}).found());
}

TEST(ParallelogramIntersect, FarEdgesAndCornerAreInsideAndJustBeyondIsNot) {
    const float beyond = std::nextafter(1.0f, 2.0f);
    for (glm::vec3 at : {glm::vec3(1, 0.5f, 0), glm::vec3(0.5f, 1, 0), glm::vec3(1, 1, 0)})
        EXPECT_TRUE(hit_triangle(unit_square(), at + glm::vec3(0, 0, 1), {0, 0, -1}).found()) << at.x << " " << at.y;
    for (glm::vec3 at : {glm::vec3(beyond, 0.5f, 0), glm::vec3(0.5f, beyond, 0), glm::vec3(beyond, beyond, 0)})
        EXPECT_FALSE(hit_triangle(unit_square(), at + glm::vec3(0, 0, 1), {0, 0, -1}).found()) << at.x << " " << at.y;
}

TEST(ParallelogramIntersect, MustComeBeforeEveryTriangle) {
    TriangleSoA t = unit_triangle();
    EXPECT_THROW(t.push_parallelogram({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0), std::logic_error);
}

TEST(TriangleIntersect, IsTwoSided) {
    EXPECT_TRUE(hit_triangle(unit_triangle(), {0.2f, 0.2f, -1.0f}, {0, 0, 1}).found());
}

TEST(TriangleIntersect, MissesOutsideEachEdge) {
    const TriangleSoA t = unit_triangle();
    EXPECT_FALSE(hit_triangle(t, {-0.01f, 0.5f, 1}, {0, 0, -1}).found());
    EXPECT_FALSE(hit_triangle(t, {0.5f, -0.01f, 1}, {0, 0, -1}).found());
    EXPECT_FALSE(hit_triangle(t, {0.51f, 0.51f, 1}, {0, 0, -1}).found());
}

TEST(TriangleIntersect, EdgesAndVerticesCountAsInside) {
    const TriangleSoA t = unit_triangle();
    EXPECT_TRUE(hit_triangle(t, {0.0f, 0.5f, 1}, {0, 0, -1}).found());
    EXPECT_TRUE(hit_triangle(t, {0.5f, 0.0f, 1}, {0, 0, -1}).found());
    EXPECT_TRUE(hit_triangle(t, {0.5f, 0.5f, 1}, {0, 0, -1}).found());
    EXPECT_TRUE(hit_triangle(t, {0.0f, 0.0f, 1}, {0, 0, -1}).found());
    EXPECT_TRUE(hit_triangle(t, {1.0f, 0.0f, 1}, {0, 0, -1}).found());
}

TEST(TriangleIntersect, ParallelRayNeverHitsEvenInThePlane) {
    const TriangleSoA t = unit_triangle();
    EXPECT_FALSE(hit_triangle(t, {-1.0f, 0.2f, 0.5f}, {1, 0, 0}).found());
    EXPECT_FALSE(hit_triangle(t, {-1.0f, 0.2f, 0.0f}, {1, 0, 0}).found());  // inside the plane
}

TEST(TriangleIntersect, TriangleBehindTheRayIsMissed) {
    EXPECT_FALSE(hit_triangle(unit_triangle(), {0.2f, 0.2f, 1.0f}, {0, 0, 1}).found());
}

TEST(TriangleIntersect, RespectsTmax) {
    Hit h;
    h.t = 1.5f;
    EXPECT_FALSE(intersect_triangle(unit_triangle(), 0, Ray{{0.2f, 0.2f, 2.0f}, {0, 0, -1}}, h));
    h.t = 2.5f;
    EXPECT_TRUE(intersect_triangle(unit_triangle(), 0, Ray{{0.2f, 0.2f, 2.0f}, {0, 0, -1}}, h));
}

TEST(TriangleIntersect, DegenerateTrianglesNeverHitNorProduceNaN) {
    TriangleSoA t;
    t.push_back({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0);  // a point
    t.push_back({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0);  // collinear
    for (uint32_t i = 0; i < t.size(); ++i) {
        for (const glm::vec3 d : {glm::vec3(0, 0, -1), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0)}) {
            // A miss must leave the record as it was (the closest hit so far): a sentinel shows
            // any write, NaN included.
            Hit h;
            h.t = 5.0f, h.prim = 77, h.u = 0.25f, h.v = 0.5f;
            EXPECT_FALSE(intersect_triangle(t, i, Ray{glm::vec3(0.5f, 0.0f, 1.0f) - d, d}, h)) << "triangle " << i;
            EXPECT_EQ(h.t, 5.0f);
            EXPECT_EQ(h.prim, 77u);
            EXPECT_EQ(h.u, 0.25f);
            EXPECT_EQ(h.v, 0.5f);
        }
    }
}

SphereSoA unit_sphere_at(glm::vec3 c, float r = 1.0f) {
    SphereSoA s;
    s.push_back(c, r, 0);
    return s;
}

Hit hit_sphere(const SphereSoA& s, glm::vec3 o, glm::vec3 d) {
    Hit h;
    intersect_sphere(s, 0, 7, Ray{o, glm::normalize(d)}, h);
    return h;
}

TEST(SphereIntersect, HitsNearSideFromOutside) {
    const Hit h = hit_sphere(unit_sphere_at({0, 0, 0}), {-5, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(h.found());
    EXPECT_EQ(h.prim, 7u);
    EXPECT_FLOAT_EQ(h.t, 4.0f);
}

TEST(SphereIntersect, OriginInsideHitsFarSide) {
    const Hit h = hit_sphere(unit_sphere_at({0, 0, 0}, 2.0f), {0.5f, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(h.found());
    EXPECT_FLOAT_EQ(h.t, 1.5f);
}

TEST(SphereIntersect, SphereBehindTheRayIsMissed) {
    EXPECT_FALSE(hit_sphere(unit_sphere_at({0, 0, 0}), {5, 0, 0}, {1, 0, 0}).found());
}

TEST(SphereIntersect, TangentRayGrazesAndNearTangentMisses) {
    const Hit tangent = hit_sphere(unit_sphere_at({0, 0, 0}), {-5, 1, 0}, {1, 0, 0});
    ASSERT_TRUE(tangent.found());
    EXPECT_NEAR(tangent.t, 5.0f, 1e-3f);
    EXPECT_FALSE(hit_sphere(unit_sphere_at({0, 0, 0}), {-5, 1.0001f, 0}, {1, 0, 0}).found());
}

TEST(SphereIntersect, RayLeavingTheSurfaceOutwardDoesNotHitItsSphere) {
    // A reflected ray starting just outside, going away: both roots behind it.
    EXPECT_FALSE(hit_sphere(unit_sphere_at({0, 0, 0}), {1.0001f, 0, 0}, {1, 0.2f, 0}).found());
}

TEST(SceneIntersect, ClosestOfSeveralAndAnyHitRespectTmax) {
    Scene scene;
    scene.triangles.push_back({3, -1, -1}, {3, 1, -1}, {3, 0, 2}, 0);  // plane x = 3
    scene.spheres.push_back({6, 0, 0}, 1.0f, 0);
    scene.spheres.push_back({1.5f, 0, 0}, 0.5f, 0);
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    const Hit h = intersect_closest(scene, ray);
    ASSERT_TRUE(h.found());
    EXPECT_EQ(h.prim, 2u);  // triangles first in the id space, then spheres: sphere #1
    EXPECT_FLOAT_EQ(h.t, 1.0f);
    EXPECT_TRUE(intersect_any(scene, ray, 1.01f));
    EXPECT_FALSE(intersect_any(scene, ray, 0.99f));
    EXPECT_FALSE(intersect_closest(scene, Ray{{0, 0, 0}, {-1, 0, 0}}).found());
    EXPECT_EQ(intersect_closest(scene, Ray{{0, 0, 0}, {-1, 0, 0}}).t, kInf);
}

}  // namespace
}  // namespace wt

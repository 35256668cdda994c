// Spheres at the extremes: far away, tiny and huge, origins on and inside them, with both sphere
// tests.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- spheres ----------------------------------------------------------------------------------

// A float step (ulp) at the magnitude of x.
double float_step(double x) {
    const float f = float(std::fabs(x));
    return double(std::nextafter(f, kInf)) - double(f);
}

// How far a computed t may be from the exact root: `steps` float steps at the largest
// magnitude in the problem (the origin, the centre, the radius, the distance). The inputs are
// only known to half a step there, and a dozen roundings with some cancellation cost tens of
// steps: the textbook quadratic is within 35 steps at room scale, the cancellation-free one
// within 4 (measured). Catastrophic cancellation is thousands of steps, or a false hit.
double root_tolerance(const Ray& ray, const glm::vec3& center, float radius, double t, int steps = 64) {
    const glm::vec3 o = glm::abs(ray.origin), c = glm::abs(center);
    const double magnitude = std::max({double(o.x), double(o.y), double(o.z), double(c.x), double(c.y), double(c.z),
                                       double(radius), std::fabs(t)});
    return steps * float_step(magnitude);
}

// Empty if t is the right root: within the tolerance of the expected one, and closer to it
// than to the other root.
std::string root_problem(double t, const SphereTruth& s, double tolerance) {
    const double expected = s.near_t > 0.0 ? s.near_t : s.far_t;
    const double other = s.near_t > 0.0 ? s.far_t : s.near_t;
    if (std::fabs(t - expected) <= tolerance && std::fabs(t - expected) < std::fabs(t - other)) return "";
    return "wrong root: expected t = " + hex(expected) + " = " + std::to_string(expected) + " (near " + std::to_string(s.near_t) +
           ", far " + std::to_string(s.far_t) + "), error " + std::to_string(t - expected) + ", tolerance " +
           std::to_string(tolerance);
}

// One sphere, rays aimed at it with impact parameters from 0 to 2 radii. A ray whose line
// passes within 0.9 r of the centre must hit, at the right root (the near one, or the far one
// from inside) to within root_tolerance(); one that passes beyond 1.1 r must miss.
void expect_sphere_hits_and_misses(const glm::vec3& center, float radius, const std::vector<glm::vec3>& origins,
                                   int rays_per_origin, uint32_t seed, const AccuracySettings& accuracy = {}) {
    Scene scene = scene_of({}, {{center, radius}});
    scene.settings.accuracy = accuracy;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Query> queries;
    std::vector<SphereTruth> truths;
    for (const glm::vec3& o : origins) {
        const glm::vec3 to_center = center - o;
        const Frame frame(glm::normalize(to_center));
        for (int i = 0; i < rays_per_origin; ++i) {
            // Aim at a point of the plane through the centre, square-root spaced in the impact
            // parameter so the silhouette region gets rays too.
            const float rho = 2.0f * radius * std::sqrt(u01(rng)), phi = 2.0f * kPi * u01(rng);
            const glm::vec3 target = center + rho * std::cos(phi) * frame.tangent + rho * std::sin(phi) * frame.bitangent;
            const Ray ray{o, glm::normalize(target - o)};
            queries.push_back({ray});
            truths.push_back(sphere_truth(ray, center, radius));
        }
    }
    expect_everywhere(scene, queries, [&](std::size_t i, const Query& q, const Answer& a) -> std::string {
        const SphereTruth& s = truths[i];
        const double expected = s.near_t > 0.0 ? s.near_t : s.far_t;
        const double tolerance = root_tolerance(q.ray, center, radius, expected);
        const bool clear_hit = s.line_hits && s.closest_distance < 0.9 * radius && s.far_t > tolerance;
        const bool clear_miss = !s.line_hits ? s.closest_distance > 1.1 * radius : s.far_t < -tolerance;
        if (clear_hit && !a.found())
            return "missed; the line passes " + std::to_string(s.closest_distance / radius) + " radii from the centre";
        if (clear_miss && a.found())
            return "false hit; the line passes " + std::to_string(s.closest_distance / radius) + " radii from the centre";
        return clear_hit ? root_problem(a.t, s, tolerance) : "";
    });
}

void far_away_spheres(const AccuracySettings& accuracy) {
    for (const glm::vec3 center : {glm::vec3(1e6f, 0, 0), glm::vec3(0, -1e6f, 0), glm::vec3(0, 0, 1e6f),
                                   glm::vec3(7e5f, 7e5f, 1e5f)}) {
        SCOPED_TRACE("centre " + hex(center));
        expect_sphere_hits_and_misses(center, 1.0f, {glm::vec3(0.0f), glm::vec3(0.5f, -0.25f, 1.0f)}, 500, 21, accuracy);
    }
}

void tiny_spheres_at_unit_distance(const AccuracySettings& accuracy) {
    for (const glm::vec3 center : {glm::vec3(1, 0.5f, -0.25f), glm::vec3(0, 0, -1), glm::vec3(-0.7f, 0.7f, 0.1f)}) {
        SCOPED_TRACE("centre " + hex(center));
        expect_sphere_hits_and_misses(center, 1e-4f, {glm::vec3(0.0f)}, 2000, 22, accuracy);
    }
}

AccuracySettings cancellation_free_spheres() {
    AccuracySettings a;
    a.spheres = SphereTest::cancellation_free;
    return a;
}

// LIMIT of the default quadratic sphere test (scalar and every SIMD kernel, bit for bit): a unit sphere
// 1e6 away is hit where it is not and at the wrong distance. b^2 and c are both about 1e12,
// where float steps are 65536 apart, so b^2 - c is rounding noise. Reproduction:
//   sphere centre (1e6, 0, 0) radius 1, ray origin (0,0,0) direction (1,0,0):
//     expected t = 999999 (the near root), got t = 1e6 (the centre: b^2 - c rounds to 0).
//   origin (0,0,0), direction (0x1p+0, 0x1.9a96cep-22, -0x1.bc2606p-20), whose line passes 1.7
//     radii from the centre: expected a miss, got a hit at t = 1e6. Every ray aimed 1.1 to 2
//     radii from the centre hits.
// The first ray of the reproduction above, exactly.
Answer one_sphere_answer(const glm::vec3& center, float radius, const Ray& ray, const AccuracySettings& accuracy = {}) {
    Scene scene = scene_of({}, {{center, radius}});
    scene.settings.accuracy = accuracy;
    return scalar_answer(scene, {ray});
}

TEST(SphereExtremes, TheQuadraticTestFailsOnAFarAwaySphereAndTheCancellationFreeOneDoesNot) {
    const glm::vec3 far(1e6f, 0.0f, 0.0f);
    const Ray on_axis{glm::vec3(0.0f), glm::vec3(1, 0, 0)};
    EXPECT_EQ(one_sphere_answer(far, 1.0f, on_axis).t, 1e6f) << "documented: b^2 - c rounds to 0, the root is the centre";
    EXPECT_EQ(one_sphere_answer(far, 1.0f, on_axis, cancellation_free_spheres()).t, 999999.0f);
    const Ray beside{glm::vec3(0.0f), glm::vec3(0x1p+0f, 0x1.9a96cep-22f, -0x1.bc2606p-20f)};  // 1.7 radii off
    EXPECT_TRUE(one_sphere_answer(far, 1.0f, beside).found()) << "documented: a false hit";
    EXPECT_FALSE(one_sphere_answer(far, 1.0f, beside, cancellation_free_spheres()).found());
}

// The same rays with the cancellation-free option (not the default): it passes.
TEST(SphereExtremes, FarAwaySphereWithTheCancellationFreeOption) { far_away_spheres(cancellation_free_spheres()); }

// LIMIT of the default quadratic test (all implementations): a sphere of radius 1e-4 one unit away. b^2 and
// c are about 1, float steps there are 1.2e-7, r^2 is 1e-8: the discriminant is noise.
// Reproduction: centre (0, 0, -1) radius 1e-4, origin (0,0,0), direction (0,0,-1): expected
// t = 1 - 1e-4, got t = 1 (the centre); rays whose line passes 1.1 to 2 radii from the centre
// hit, and the root is off by up to the radius, 800 float steps at 1.
TEST(SphereExtremes, TheQuadraticTestFailsOnATinySphereAtUnitDistanceAndTheCancellationFreeOneDoesNot) {
    const glm::vec3 tiny(0.0f, 0.0f, -1.0f);
    const Ray down{glm::vec3(0.0f), glm::vec3(0, 0, -1)};
    EXPECT_EQ(one_sphere_answer(tiny, 1e-4f, down).t, 1.0f) << "documented: the root is the centre";
    EXPECT_NEAR(one_sphere_answer(tiny, 1e-4f, down, cancellation_free_spheres()).t, 1.0f - 1e-4f, 2e-7f);
}

// The same rays with the cancellation-free option (not the default): it passes.
TEST(SphereExtremes, TinySphereAtUnitDistanceWithTheCancellationFreeOption) {
    tiny_spheres_at_unit_distance(cancellation_free_spheres());
}

// Where the textbook quadratic has the digits: a tiny sphere seen from close by (b^2 and c are
// both about 1e-6, r^2 = 1e-8: 14 bits to spare), and spheres at room scale, from outside and
// from inside (the far root).
TEST(SphereExtremes, TinySphereSeenFromCloseByAndRoomScaleSpheres) {
    {
        SCOPED_TRACE("radius 1e-4 from 1e-3 away");
        const glm::vec3 c(1e-3f, 2e-4f, -3e-4f);
        expect_sphere_hits_and_misses(c, 1e-4f, {glm::vec3(0.0f), glm::vec3(2e-3f, 0, 0)}, 2000, 23);
    }
    for (const auto& [center, radius] : {std::pair{glm::vec3(8, -3, -3.5f), 1.5f}, std::pair{glm::vec3(6, 2, -1.5f), 0.8f},
                                         std::pair{glm::vec3(0, 0, 0), 1.0f}}) {
        SCOPED_TRACE("centre " + hex(center) + " radius " + hex(radius));
        expect_sphere_hits_and_misses(center, radius,
                                      {center + glm::vec3(-5, 1, 2), center + glm::vec3(0, 0, 0.5f * radius),
                                       center + glm::vec3(0.3f, -0.2f, 0.1f) * radius},
                                      1000, 24);
    }
}

// A sphere of radius 1e5 used as a floor: its top at z = -1, the ray origins within 1.5 of it.
// Rays going down must hit near z = -1 (the near root, not the far one 2e5 away), to within
// root_tolerance() (64 float steps at 1e5: 0.5; both sphere tests are within 17 steps here);
// rays going up must miss; rays skimming the horizon within 1e-3 of tangent may go either way.
void huge_floor_sphere(const AccuracySettings& accuracy) {
    const glm::vec3 center(0.0f, 0.0f, -1e5f - 1.0f);
    const float radius = 1e5f;
    Scene scene = scene_of({}, {{center, radius}});
    scene.settings.accuracy = accuracy;
    std::mt19937 rng(25);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Query> queries;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 o(40.0f * u01(rng) - 20.0f, 40.0f * u01(rng) - 20.0f, 2.0f * u01(rng) - 0.5f);
        queries.push_back({{o, random_unit(rng)}});
    }
    expect_everywhere(scene, queries, [&](std::size_t, const Query& q, const Answer& a) -> std::string {
        const SphereTruth s = sphere_truth(q.ray, center, radius);
        const double expected = s.near_t > 0.0 ? s.near_t : s.far_t;
        const bool should_hit = s.line_hits && s.far_t > 0.0;
        if (s.line_hits && std::fabs(s.closest_distance - radius) < 1e-3 * radius) return "";
        if (should_hit != a.found()) return should_hit ? "missed the floor" : "false hit on the floor";
        return should_hit ? root_problem(a.t, s, root_tolerance(q.ray, center, radius, expected)) : "";
    });
}

TEST(SphereExtremes, HugeSphereAsAFloorIsHitAtTheNearRoot) { huge_floor_sphere({}); }

// Origins on the sphere moved off it, outward or inward, by offset_ray_origin(p, n) (its generic
// error bound; SpawnedRays below goes through the renderer's own vertex code), and inside it.
TEST(SphereExtremes, OriginsOnAndInsideSpheres) {
    for (const auto& [center, radius] : {std::pair{glm::vec3(0, 0, 0), 1.0f}, std::pair{glm::vec3(8, -3, -3.5f), 1.5f},
                                         std::pair{glm::vec3(6, 2, -1.5f), 0.8f}, std::pair{glm::vec3(100, -40, 3), 2.0f}}) {
        SCOPED_TRACE("centre " + hex(center) + " radius " + hex(radius));
        const Scene scene = scene_of({}, {{center, radius}});
        std::mt19937 rng(26);
        std::uniform_real_distribution<float> u01(0.0f, 1.0f);
        std::vector<Query> queries;
        enum Kind { outward, inward, inside };
        std::vector<Kind> kinds;
        for (int i = 0; i < 6000; ++i) {
            const glm::vec3 n = random_unit(rng);
            const glm::vec3 p = center + radius * n;
            glm::vec3 d = random_unit(rng);
            switch (i % 3) {
                case 0:  // leaving outward: a reflection or a diffuse bounce
                    if (glm::dot(d, n) < 0.0f) d = -d;
                    queries.push_back({{offset_ray_origin(p, n), d}});
                    kinds.push_back(outward);
                    break;
                case 1:  // entering: a refraction
                    if (glm::dot(d, n) > 0.0f) d = -d;
                    queries.push_back({{offset_ray_origin(p, -n), d}});
                    kinds.push_back(inward);
                    break;
                default:  // anywhere inside, down to 1e-3 of the radius from the surface
                    queries.push_back({{center + (0.999f * std::cbrt(u01(rng)) * radius) * n, d}});
                    kinds.push_back(inside);
                    break;
            }
        }
        // Copies: C++17 lets no lambda capture a structured binding (GCC allows it, clang refuses).
        const glm::vec3 c = center;
        const float r = radius;
        expect_everywhere(scene, queries, [&](std::size_t i, const Query& q, const Answer& a) -> std::string {
            const SphereTruth s = sphere_truth(q.ray, c, r);
            if (kinds[i] == outward) return a.found() ? "a ray leaving the sphere outward hit it again" : "";
            if (!a.found()) return "a ray starting inside the sphere missed it";
            // The far root, to within 1e-4 of the radius: never the spot the ray started from.
            if (std::fabs(double(a.t) - s.far_t) > 1e-4 * r)
                return "wrong root: expected the far root " + std::to_string(s.far_t) + " (near " + std::to_string(s.near_t) + ")";
            return "";
        });
    }
}


}  // namespace
}  // namespace wt::extremes

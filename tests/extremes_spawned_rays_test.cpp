// Rays spawned from hits never hit the primitive they leave, at any scale.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- spawned rays never hit the primitive they leave -----------------------------------------

// A random hit on one primitive, then the renderer's own vertex code (surface_at, and
// continue_path from path_vertex.h, whatever offset it applies) spawns the next rays: a
// diffuse bounce, a mirror reflection, glass reflections and refractions (shadow rays start
// from the same offset point as the diffuse bounce). Each is checked against the hit primitive alone, so
// a closer hit on something else cannot hide a self-hit: a triangle must not be hit again, a
// sphere only at the far end of a chord that goes inside it.
struct SpawnStats {
    int hits = 0, skipped = 0, spawned = 0, inward = 0;
};

// cap: for a sphere, hit points are drawn within this angle of its top (+z); pi for all over it.
void expect_spawned_rays_leave(const Scene& scene, uint32_t prim, int hit_count, uint32_t seed, Failures& failures,
                               SpawnStats& stats, double cap = M_PI) {
    Scene single;
    single.settings = scene.settings;
    const bool is_triangle = prim < scene.triangles.size();
    const bool is_parallelogram = scene.triangles.is_parallelogram(prim);
    if (is_triangle) {
        const glm::vec3 v0 = scene.triangles.vertex0(prim), v1 = v0 + scene.triangles.edge1(prim),
                        v2 = v0 + scene.triangles.edge2(prim);
        if (is_parallelogram)
            single.triangles.push_parallelogram(v0, v1, v2, 0);
        else
            single.triangles.push_back(v0, v1, v2, 0);
    } else {
        const uint32_t s = prim - uint32_t(scene.triangles.size());
        single.spheres.push_back(scene.spheres.center(s), scene.spheres.radius[s], 0);
    }
    Material lambert, mirror, glass;
    lambert.type = MaterialType::lambertian;
    lambert.albedo = glm::vec3(0.5f);
    mirror.type = MaterialType::mirror;
    glass.type = MaterialType::glass;
    glass.ior = 1.5f;
    single.materials = {lambert, mirror, glass};
    const glm::vec3 sphere_center = is_triangle ? glm::vec3(0.0f) : single.spheres.center(0);
    const float radius = is_triangle ? 0.0f : single.spheres.radius[0];

    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Query> queries;
    std::vector<double> expected_far;  // rays going into a sphere: the far root; otherwise -1
    for (int k = 0; k < hit_count; ++k) {
        // A random point on the primitive, hit by a ray from a random direction.
        const glm::vec3 d = random_unit(rng);
        Ray incoming;
        if (is_triangle) {
            const glm::vec2 b = is_parallelogram ? glm::vec2(u01(rng), u01(rng)) : sample_uniform_triangle(u01(rng), u01(rng));
            const glm::vec3 p = single.triangles.vertex0(0) + b.x * single.triangles.edge1(0) + b.y * single.triangles.edge2(0);
            if (std::fabs(glm::dot(d, single.triangles.normal(0))) < 1e-4f) continue;
            incoming = {p - (0.01f + 20.0f * u01(rng)) * d, d};
        } else {
            const double cos_theta = 1.0 - (1.0 - std::cos(cap)) * double(u01(rng));
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), phi = 2.0 * M_PI * double(u01(rng));
            const glm::vec3 n_out = glm::normalize(glm::vec3(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)), float(cos_theta)));
            const glm::vec3 p = sphere_center + radius * n_out;
            const float cos_d = glm::dot(d, n_out);
            if (std::fabs(cos_d) < 1e-4f) continue;
            // From outside when d points in (p is where the ray enters), from inside otherwise.
            const float distance = cos_d < 0.0f ? 0.01f + 20.0f * u01(rng) : (0.05f + 0.9f * u01(rng)) * 2.0f * radius * cos_d;
            incoming = {p - distance * d, d};
        }
        const Hit hit = intersect_closest(single, incoming);
        if (!hit.found()) {
            ++stats.skipped;  // the incoming ray slipped past an edge: nothing to spawn from
            continue;
        }
        ++stats.hits;
        const SurfacePoint surface = surface_at(single, incoming, hit);
        const uint64_t key = path_key(seed, uint32_t(k), 0);
        std::vector<Ray> spawned;
        // The next ray for each material; glass picks reflection or refraction at random, so
        // it gets three tries (and always reflects beyond the critical angle).
        int bounce = 0;
        for (uint32_t material : {0u, 1u, 2u, 2u, 2u}) {
            const auto next = continue_path<DefaultEstimator>(single, single.materials[material], surface, incoming.direction,
                                                              glm::vec3(1.0f), PathSeed{key, 0}, uint32_t(bounce++), false);
            if (next) spawned.push_back(next->ray);
        }
        for (std::size_t i = 0; i < spawned.size(); ++i) {
            queries.push_back({spawned[i]});
            double far = -1.0;
            if (!is_triangle && glm::dot(spawned[i].direction, surface.normal) < 0.0f) {
                far = sphere_truth(spawned[i], sphere_center, radius).far_t;
                ++stats.inward;
            }
            expected_far.push_back(far);
        }
    }
    stats.spawned += int(queries.size());
    const std::string what = (is_triangle ? "triangle " : "sphere ") + std::to_string(prim);
    expect_everywhere(
        single, queries,
        [&](std::size_t i, const Query&, const Answer& a) -> std::string {
            if (expected_far[i] < 0.0) return a.found() ? "the spawned ray hit the " + what + " it left" : "";
            // Going into a sphere: the far side, never the spot it left. A chord shorter than 1%
            // of the radius (grazing) cannot be told from a self-hit.
            if (expected_far[i] < 1e-2 * radius) return "";
            if (!a.found() || std::fabs(double(a.t) - expected_far[i]) > 1e-3 * radius)
                return "the spawned ray into " + what + " should hit its far side at t = " + std::to_string(expected_far[i]);
            return "";
        },
        failures);
}

TEST(SpawnedRays, NeverHitTheHexroomPrimitiveTheyLeave) {
    const Scene scene = build_scene(test::hexroom(8, 8, 1));
    const int primitives = int(scene.primitive_count());
    const int total_hits = 22000;  // about five spawned rays per hit: 100k rays
    Failures failures;
    SpawnStats stats;
    for (int prim = 0; prim < primitives; ++prim) {
        SCOPED_TRACE("primitive " + std::to_string(prim));
        expect_spawned_rays_leave(scene, uint32_t(prim), total_hits / primitives, 100 + uint32_t(prim), failures, stats);
    }
    EXPECT_GE(stats.spawned, 100000);
    EXPECT_GT(stats.inward, 5000);
    EXPECT_LT(stats.skipped, stats.hits / 100);
    std::printf("spawned %d rays (%d into spheres) from %d hits; %d incoming rays slipped past an edge\n", stats.spawned,
                stats.inward, stats.hits, stats.skipped);
}

// A sphere of radius 1e5 used as a floor (centre (0,0,-100001), top at z = -1), hit from above
// near its top and from inside: the spawned rays must not hit it again at their start.
TEST(SpawnedRays, NeverHitAHugeSphereUsedAsAFloor) {
    const Scene scene = scene_of({}, {{glm::vec3(0.0f, 0.0f, -1e5f - 1.0f), 1e5f}});
    Failures failures;
    SpawnStats stats;
    // Within 20 units of the top (2e-4 rad), where a camera standing on the floor looks.
    expect_spawned_rays_leave(scene, 0, 5000, 31, failures, stats, 2e-4);
    EXPECT_GT(stats.spawned, 20000);
}


}  // namespace
}  // namespace wt::extremes

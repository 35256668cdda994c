#include "workloads.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/path/path_vertex.h"
#include "core/sampling/rng.h"
#include "core/sampling/sampling.h"

namespace wt::bench {

namespace {

constexpr uint32_t kIncoherentRayCount = 1'000'000;
constexpr uint32_t kShadowRayCount = 1'000'000;
constexpr uint32_t kBounceRayCount = 1'000'000;
constexpr uint64_t kIncoherentSeed = 1;
constexpr uint64_t kLightSeed = 2;
constexpr uint64_t kBounceSeed = 3;

// The hexroom's floor polygon (scenes/hexroom.json), clockwise seen from above, and its
// floor and ceiling heights. Written out rather than recovered from the triangles: the room is
// what the incoherent rays are defined by, whatever else the scene file holds.
constexpr float kRoomPolygon[6][2] = {{-3, 0}, {0, 6}, {10, 6}, {13, 0}, {10, -6}, {0, -6}};
constexpr float kRoomMinX = -3, kRoomMaxX = 13, kRoomMinY = -6, kRoomMaxY = 6, kRoomMinZ = -5, kRoomMaxZ = 5;

bool inside_room(const glm::vec3& p) {
    if (!(p.z > kRoomMinZ && p.z < kRoomMaxZ)) return false;
    // Clockwise convex polygon: the point must be strictly right of every edge.
    for (int i = 0; i < 6; ++i) {
        const float* a = kRoomPolygon[i];
        const float* b = kRoomPolygon[(i + 1) % 6];
        const float cross = (b[0] - a[0]) * (p.y - a[1]) - (b[1] - a[1]) * (p.x - a[0]);
        if (!(cross < 0.0f)) return false;
    }
    return true;
}

bool inside_ball(const glm::vec3& centre, float radius, const glm::vec3& p) {
    const glm::vec3 offset = p - centre;
    return glm::dot(offset, offset) < radius * radius;
}

// Rays starting inside a glass sphere would measure a case the renderer meets only after a
// refraction; inside an opaque one or a closed mesh, never.
bool inside_a_solid(const Scene& scene, const std::optional<Ball>& solid, const glm::vec3& p) {
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (inside_ball(scene.spheres.center(i), scene.spheres.radius[i], p)) return true;
    return solid && inside_ball(solid->centre, solid->radius, p);
}

// The random numbers of incoherent ray i: the origin's three at "bounce" = attempt (rejection
// sampling may need several), the direction's two at bounce 0, in dimensions of their own.
constexpr uint32_t kOriginDimension = 0;     // then +1, +2
constexpr uint32_t kDirectionDimension = 3;  // then +1

glm::vec3 uniform_sphere_direction(float u0, float u1) {
    const float z = 1.0f - 2.0f * u0;
    const float r = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u1;
    return glm::normalize(glm::vec3(r * std::cos(phi), r * std::sin(phi), z));
}

Ray incoherent_ray(const Scene& scene, const std::optional<Ball>& solid, uint32_t index, uint64_t seed) {
    const uint64_t key = path_key(seed, index, 0);
    glm::vec3 origin;
    for (uint32_t attempt = 0;; ++attempt) {
        origin = {kRoomMinX + (kRoomMaxX - kRoomMinX) * random_float(key, attempt, kOriginDimension),
                  kRoomMinY + (kRoomMaxY - kRoomMinY) * random_float(key, attempt, kOriginDimension + 1),
                  kRoomMinZ + (kRoomMaxZ - kRoomMinZ) * random_float(key, attempt, kOriginDimension + 2)};
        if (inside_room(origin) && !inside_a_solid(scene, solid, origin)) break;
    }
    const glm::vec3 direction = uniform_sphere_direction(random_float(key, 0, kDirectionDimension),
                                                         random_float(key, 0, kDirectionDimension + 1));
    return {origin, direction};
}

struct ClosestHits {
    AlignedVector<float> t, u, v;
    AlignedVector<uint32_t> prim;

    explicit ClosestHits(std::size_t n) : t(n), u(n), v(n), prim(n) {}
    Hit at(std::size_t i) const {
        Hit hit;
        hit.t = t[i], hit.u = u[i], hit.v = v[i], hit.prim = prim[i];
        return hit;
    }
};

}  // namespace

const char* workload_name(Workload workload) {
    switch (workload) {
        case Workload::primary: return "primary";
        case Workload::incoherent: return "incoherent";
        case Workload::shadow: return "shadow";
        case Workload::bounce: return "bounce";
    }
    return "unknown";
}

void RaySet::push_back(const Ray& ray) {
    ox.push_back(ray.origin.x), oy.push_back(ray.origin.y), oz.push_back(ray.origin.z);
    dx.push_back(ray.direction.x), dy.push_back(ray.direction.y), dz.push_back(ray.direction.z);
}

void RaySet::push_back(const Ray& ray, float max_distance) {
    push_back(ray);
    tmax.push_back(max_distance);
}

RayView RaySet::view() const {
    return {ox.data(), oy.data(), oz.data(), dx.data(), dy.data(), dz.data(), tmax.empty() ? nullptr : tmax.data(),
            uint32_t(size())};
}

RaySet primary_rays(const Scene& scene) {
    RaySet rays;
    for (int y = 0; y < scene.settings.height; ++y)
        for (int x = 0; x < scene.settings.width; ++x) rays.push_back(scene.camera.generate_ray(float(x) + 0.5f, float(y) + 0.5f));
    return rays;
}

RaySet incoherent_rays(const Scene& scene, const std::optional<Ball>& solid, uint32_t first_index, uint32_t count,
                       uint64_t seed) {
    RaySet rays;
    for (uint32_t i = first_index; i < first_index + count; ++i) rays.push_back(incoherent_ray(scene, solid, i, seed));
    return rays;
}

namespace {

// visit(probe, surface, material, index) at each closest hit of the incoherent stream (seed
// `seed`) on a surface that gathers direct light (diffuse, not black: not the mirror, glass or
// the light itself), `index` the probe's place in the stream, until `enough()`.
template <typename Enough, typename Visit>
void for_each_diffuse_hit(const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest,
                          uint64_t seed, Enough&& enough, Visit&& visit) {
    // About 7 in 10 incoherent rays hit such a surface; the stream is read in chunks until enough have.
    constexpr uint32_t kChunk = 1u << 18;
    for (uint32_t first = 0; !enough(); first += kChunk) {
        const RaySet probes = incoherent_rays(scene, solid, first, kChunk, seed);
        ClosestHits hits(probes.size());
        closest(probes.view(), {hits.t.data(), hits.u.data(), hits.v.data(), hits.prim.data()});
        for (uint32_t i = 0; i < probes.size() && !enough(); ++i) {
            const Hit hit = hits.at(i);
            if (!hit.found()) continue;
            const Ray probe = probes.ray(i);
            const SurfacePoint surface = surface_at(scene, probe, hit);
            const Material& material = scene.materials[surface.material];
            if (gathers_direct_light(material)) visit(probe, surface, material, first + i);
        }
    }
}

}  // namespace

RaySet shadow_rays(const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest, uint32_t count,
                   uint64_t incoherent_seed, uint64_t light_seed) {
    const glm::vec3 unit_throughput(1.0f);  // the samples' contribution is not used here
    RaySet rays;
    for_each_diffuse_hit(
        scene, solid, closest, incoherent_seed, [&] { return rays.size() >= count; },
        [&](const Ray& probe, const SurfacePoint& surface, const Material& material, uint32_t index) {
            const DirectLightSampler<> lights(scene, material, surface, light_sampling_point(surface, probe.direction),
                                              probe.direction, unit_throughput, PathSeed{path_key(light_seed, index, 0), 0}, 0, 1);
            lights.sample_all([&](const ShadowRay& shadow) { rays.push_back(shadow.ray, shadow.tmax); });
        });
    return rays;
}

RaySet bounce_rays(const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest, uint32_t count,
                   uint64_t incoherent_seed, uint64_t bounce_seed) {
    RaySet rays;
    for_each_diffuse_hit(
        scene, solid, closest, incoherent_seed, [&] { return rays.size() >= count; },
        [&](const Ray& probe, const SurfacePoint& surface, const Material& material, uint32_t index) {
            // The first bounce, before the roulette: every path that reaches here goes on.
            const auto next = continue_path<DefaultEstimator>(scene, material, surface, probe.direction, glm::vec3(1.0f),
                                                              PathSeed{path_key(bounce_seed, index, 0), 0}, 0, false);
            if (next) rays.push_back(next->ray);
        });
    return rays;
}

RaySet workload_rays(Workload workload, const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest) {
    switch (workload) {
        case Workload::primary: return primary_rays(scene);
        case Workload::incoherent: return incoherent_rays(scene, solid, 0, kIncoherentRayCount, kIncoherentSeed);
        case Workload::shadow: return shadow_rays(scene, solid, closest, kShadowRayCount, kIncoherentSeed, kLightSeed);
        case Workload::bounce: break;
    }
    return bounce_rays(scene, solid, closest, kBounceRayCount, kIncoherentSeed, kBounceSeed);
}

}  // namespace wt::bench

#pragma once
// The ray sets bench_intersect traces through the hexroom and the meshes put in it. A benchmark is an experiment (the
// query and the kernel, chosen in bench_intersect.cpp) x a primitive set (the scene) x a ray
// distribution (here); the three are kept apart so each can change without touching the others.
//
// Every set is deterministic: random numbers come from the renderer's counter-based hash
// (core/sampling/rng.h) with fixed seeds, so the rays are the same on every machine and every run, and
// the checksums in bench/README.md can be compared.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include <glm/vec3.hpp>

#include "core/base/aligned_vector.h"
#include "core/base/ray.h"
#include "core/scene/scene.h"
#include "kernels/primitives/soa_views.h"

namespace wt::bench {

enum class Workload { primary, incoherent, shadow, bounce };
constexpr Workload kAllWorkloads[] = {Workload::primary, Workload::incoherent, Workload::shadow, Workload::bounce};
const char* workload_name(Workload workload);

// Rays in the SoA layout the kernels read.
struct RaySet {
    AlignedVector<float> ox, oy, oz, dx, dy, dz;
    AlignedVector<float> tmax;  // empty: every ray is unbounded

    std::size_t size() const { return ox.size(); }
    Ray ray(std::size_t i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
    void push_back(const Ray& ray);
    void push_back(const Ray& ray, float max_distance);
    RayView view() const;
};

// --- Ray distributions, for any scene ---

// A ball the incoherent rays' origins stay out of, besides the scene's spheres: the bounding
// ball of a mesh a benchmark scene puts in the room, so no ray starts inside a closed mesh (or
// in the middle of a model whose closedness nobody checked).
struct Ball {
    glm::vec3 centre;
    float radius;
};

// The closest hits of `rays` into `hits`, by whatever means the caller has (the BVH for big
// meshes: brute force over a million triangles would take hours for a million rays).
using ClosestHitFunction = std::function<void(const RayView& rays, const HitView& hits)>;

// One ray through the centre of every pixel of the scene's camera, row by row: the most
// coherent rays a renderer traces.
RaySet primary_rays(const Scene& scene);

// Rays first_index ... first_index + count - 1 of an endless, seeded stream: origins uniform
// in the hexroom's air (inside the hexagonal prism, outside every sphere and outside `solid`
// if given; the small tetrahedron is not excluded), directions uniform on the sphere,
// unbounded. Ray i does not depend on first_index, so a longer set starts with the same rays
// as a shorter one.
RaySet incoherent_rays(const Scene& scene, const std::optional<Ball>& solid, uint32_t first_index, uint32_t count,
                       uint64_t seed);

// `count` shadow rays exactly as the renderer builds them: the closest hits of the incoherent
// stream (seed incoherent_seed, the same `solid`), found by `closest`, are the shading points;
// at each one that gathers direct light (diffuse, not black: not the mirror, glass or the
// light itself) DirectLightSampler picks a uniform point on the lights and offsets both ends
// off their surfaces; samples it rejects (light behind the surface or seen from its back)
// trace no ray, as in the renderer. Bounded by the distance to the offset light point.
RaySet shadow_rays(const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest, uint32_t count,
                   uint64_t incoherent_seed, uint64_t light_seed);

// `count` closest rays as the renderer's diffuse bounces: at the same shading points as
// shadow_rays, continue_path's direction (cosine-weighted about the facing normal) from the
// point offset off its surface, unbounded. They start on the surfaces, a mesh's among them, where
// the incoherent rays start in the open: a ray leaving a dense mesh first walks the leaves about
// its origin.
RaySet bounce_rays(const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest, uint32_t count,
                   uint64_t incoherent_seed, uint64_t bounce_seed);

// --- The sets the benchmarks share ---

// primary: one ray per pixel of the scene's camera (800x800 = 640,000 in bench_intersect);
// incoherent, shadow and bounce: 1,000,000 rays each, with fixed seeds.
RaySet workload_rays(Workload workload, const Scene& scene, const std::optional<Ball>& solid, const ClosestHitFunction& closest);

}  // namespace wt::bench

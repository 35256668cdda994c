#pragma once
// One light path of light tracing (particle tracing; Veach 1997, sec. 10.2, the bidirectional
// strategy with one camera vertex): a ray leaving a light (an area light's point and a
// cosine-weighted direction, or a listed light's, core/lights/light_emission.h), and bounces
// (BSDF-sampled, Russian roulette) from surface to surface, each diffuse vertex connected to the
// camera. Only paths whose first bounce is a mirror or glass count: together they estimate
// exactly the paths camera -> diffuse -> anything -> specular -> light that the camera paths leave
// out when the scene light-traces its caustics (path_vertex.h, PathContinuation): the path space
// is split in two and each part has one estimator, so no weights are needed and the sum is
// unbiased. A caustic, and the light it throws on to other surfaces, is then found from the
// light's side, where the small light is where every path starts, not a target hit by chance.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/sampling/rng.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/caustics/specular_targets.h"
#include "kernels/photons/photon.h"
#include "kernels/queues/specular_vertex_queue.h"
#include "kernels/work/render_stats.h"

namespace wt {

// A light path's contribution to one pixel's estimate, for Film::add_splat.
struct CameraSplat {
    uint32_t pixel;
    glm::vec3 value;
};

// The random-number key of light path `index` of sample `sample`: any one path replays alone,
// and the paths do not depend on how they are shared among threads.
uint64_t light_path_key(uint64_t seed, uint64_t index, uint32_t sample);

// How many light paths each sample traces: light_paths_per_pixel x width x height, at least one.
uint64_t light_paths_per_sample(const RenderSettings& settings);

// A light path's ray: where it goes, the power the path started with, and the weight of its
// bounces so far (kept apart from the power for Russian roulette, which looks at the weight).
struct LightRay {
    Ray ray;
    glm::vec3 power;
    glm::vec3 weight;
};

// Where a path that starts at the area lights (LightPathTracer::start) leaves from: its point on a
// light, with the power it carries, and the random numbers of its direction. The wavefront light
// pass aims a batch of these at once (kernels/shading/area_light_rays.h).
struct AreaLightStart {
    LightSample light;
    glm::vec3 power;  // Le pi / pdf_area: Le cos / (pdf_area cos / pi) for the cosine-weighted direction
    UniformPair direction;
};

// A diffuse vertex's connection to the camera: the splat it adds if nothing blocks the ray.
struct CameraConnection {
    Ray ray;
    float tmax;
    CameraSplat splat;
};

// What a light path does at one vertex: the connection to the camera, if any, the photon it
// leaves (only for a tracer that records photons), and the ray that continues the path, if it
// goes on.
struct LightVertex {
    std::optional<CameraConnection> connection;
    std::optional<Photon> photon;
    std::optional<LightRay> next;
};

// One vertex of a traced light path, for --debug-light-path.
struct LightPathVertexRecord {
    uint32_t vertex;
    Hit hit;
    uint32_t material;
    glm::vec3 position;
    glm::vec3 carried;  // power x weight arriving at the vertex
    std::optional<CameraSplat> splat;  // the connection's splat, if it has one
    bool connection_blocked = false;
};

// The vertex code of a light path, written once and scheduled two ways: one path at a time
// (trace, for the reference integrator and --debug-sample) and as wavefront queues
// (light_tracing_pass.cpp, on the SIMD kernels). Both call these in the same order and the
// kernels return the scalar code's bits, so both give the same splats.
class LightPathTracer {
public:
    // `bvh`: the scene's BVH, or null for the flat list (kernels/accel/scene_intersect.h); trace() alone reads it.
    // `records_photons`: at_vertex also returns the photons (Scene::merges_photons).
    LightPathTracer(const Scene& scene, const BvhView* bvh, bool records_photons = false);

    // The first ray of the path with random-number key `key` (light_path_key), if it leaves its
    // light: in a scene whose lights are the area lights alone (starts_at_area_lights_only) by
    // start, else by start_at_listed_lights, which picks among every light by power
    // (SceneLights::pick) and the area lights' triangle by area. Two functions, chosen once per
    // batch of paths, so the area-light scenes run the start they always ran.
    bool starts_at_area_lights_only() const { return starts_at_area_lights_only_; }
    std::optional<LightRay> start(uint64_t key) const;
    std::optional<LightRay> start_at_listed_lights(uint64_t key) const;
    // start's point and power, before its direction is taken.
    AreaLightStart area_light_start(uint64_t key) const;
    // Whether a path's first ray can add anything: false where it misses every specular
    // primitive (specular_targets.h), so its first hit would end it. The image is the same
    // whether such a ray is traced or not.
    bool first_ray_counts(const Ray& ray) const { return !specular_targets_ || specular_targets_->may_hit(ray); }
    // The same test for a batch of rays, through the any-hit kernels: null where every first
    // ray counts.
    const SpecularTargets* specular_targets() const { return specular_targets_ ? &*specular_targets_ : nullptr; }
    // What the path does at the surface `hit` of `at`, its `vertex`-th (1 for the first hit).
    // `textured`: scratch for the hit's material with its textures looked up (material_at_hit.h),
    // the caller's, so that a loop over vertices constructs it once.
    LightVertex at_vertex(uint64_t key, uint32_t vertex, const LightRay& at, const Hit& hit,
                          std::optional<Material>& textured) const;
    // The same with the hit's surface point (surface_at) already computed: by the surface kernel
    // for a batch (kernels/shading/surface_points.h), the same bits.
    LightVertex at_vertex(uint64_t key, uint32_t vertex, const LightRay& at, const Hit& hit, SurfacePoint surface,
                          std::optional<Material>& textured) const;
    // at_vertex's work at a flat, untextured mirror or glass that the path can leave, left to the
    // shade kernels (kernels/shading/specular_continuation.h): queues the vertex in `q` with its
    // random numbers and returns true; false, and nothing queued, for any other vertex. Such a
    // vertex has no camera connection and no photon, only the next ray.
    bool queue_specular(uint64_t key, uint32_t vertex, const LightRay& at, const SurfacePoint& surface, uint32_t slot,
                        SpecularVertexQueue& q) const;
    // Whether the specular kernel's vertices at `vertex` play Russian roulette (as at_vertex's).
    bool roulette_at(uint32_t vertex) const { return int(vertex) > scene_.settings.rr_start_bounce; }

    // Light path `index` of sample `sample`, one ray at a time: appends a splat to `splats` for
    // each diffuse vertex the camera sees, if the path's first bounce was specular. The values are
    // already divided by the number of paths per sample, so the film divides the splat sums by
    // the samples alone.
    // `record`, if given, receives every vertex; `photons`, if given, the path's photons in
    // vertex order (a tracer that records them).
    void trace(uint64_t index, uint32_t sample, RayCounts& counts, std::vector<CameraSplat>& splats,
               std::vector<LightPathVertexRecord>* record = nullptr, PhotonList* photons = nullptr) const;

private:
    // `random`: the vertex's numbers, for the point on a thin lens and the pixel under a wide filter.
    std::optional<CameraConnection> connect_to_camera(const SurfacePoint& surface, const Material& m,
                                                      const glm::vec3& arriving, const glm::vec3& power,
                                                      const VertexRandom& random) const;
    std::optional<Photon> photon_at(const SurfacePoint& surface, const Material& m, uint32_t vertex,
                                    const glm::vec3& arriving, const glm::vec3& power) const;
    Hit closest(const Ray& ray) const;
    bool blocked(const Ray& ray, float tmax) const;

    const Scene& scene_;
    const BvhView* bvh_;
    bool records_photons_;
    bool starts_at_area_lights_only_;
    float inverse_path_count_;
    std::optional<SpecularTargets> specular_targets_;  // none: every first ray is traced
};

}  // namespace wt

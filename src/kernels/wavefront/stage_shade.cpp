#include "core/first_surface.h"
#include "core/path_vertex.h"
#include "kernels/wavefront/stages.h"

namespace wt {

namespace {

// `RecordAovs` is a template argument, not a run-time test, so a render without AOVs runs the
// loop it ran before they existed, instruction for instruction.
template <bool RecordAovs>
void shade_paths(const Scene& scene, uint32_t bounce, const RayQueue& rays, const HitQueue& hits, PathTable& paths,
                 RayQueue& next_rays, ShadowQueue& shadows) {
    const uint32_t shadow_ray_count = uint32_t(scene.settings.shadow_rays);
    const bool has_lights = !scene.lights.empty();
    next_rays.count = 0;
    shadows.count = 0;
    for (std::size_t i = 0; i < rays.count; ++i) {
        const Hit hit = hits.hit(i);
        if (!hit.found()) continue;  // no environment light: the path ends with what it has
        const Ray ray = rays.ray(i);
        const uint32_t slot = rays.path[i];
        const uint64_t key = paths.key[slot];
        const glm::vec3 throughput = rays.throughput(i);
        const SurfacePoint surface = surface_at(scene, ray, hit);
        const Material& m = scene.materials[surface.material];

        if constexpr (RecordAovs) {
            FirstSurface& first = paths.first_surface[slot];
            if (!first.found) record_first_surface(first, scene.camera, bounce, ray, hit, surface, m, throughput);
        }
        if (rays.count_emission[i]) paths.add_radiance(slot, throughput * emitted_towards(m, surface.normal, ray.direction));
        if (has_lights && gathers_direct_light(m)) {
            const DirectLightSampler lights(scene, m, surface, light_sampling_point(surface, ray.direction), ray.direction,
                                            throughput, key, bounce, shadow_ray_count);
            lights.sample_all([&](const ShadowRay& shadow) { shadows.push(shadow, slot); });
        }
        const auto next = continue_path(scene, m, surface, ray.direction, throughput, key, bounce);
        if (next) next_rays.push(next->ray, next->throughput, slot, next->specular);
    }
}

}  // namespace

// The same vertex logic as trace_reference_path, in the same order (emission, then light
// samples, then the continuation), so both integrators add a path's terms identically.
void shade_stage(const Scene& scene, uint32_t bounce, const RayQueue& rays, const HitQueue& hits, PathTable& paths,
                 RayQueue& next_rays, ShadowQueue& shadows) {
    if (paths.first_surface.empty())
        shade_paths<false>(scene, bounce, rays, hits, paths, next_rays, shadows);
    else
        shade_paths<true>(scene, bounce, rays, hits, paths, next_rays, shadows);
}

}  // namespace wt

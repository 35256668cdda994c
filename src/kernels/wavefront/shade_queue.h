#pragma once
// The shade stage's loop over a queue, for one estimator. Included by stage_shade.cpp, which
// instantiates the default estimator, and stage_shade_options.cpp, which instantiates the rest.

#include "core/path_vertex.h"
#include "kernels/wavefront/stages.h"

namespace wt {

// The same vertex logic as trace_reference_path, in the same order (emission, then light
// samples, then the continuation), so both integrators add a path's terms identically.
template <typename E>
void shade_queue(const Scene& scene, uint32_t bounce, const RayQueue& rays, const HitQueue& hits, PathTable& paths,
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
        const PathSeed path{paths.key[slot], paths.sample[slot]};
        const glm::vec3 throughput = rays.throughput(i);
        const SurfacePoint surface = surface_at(scene, ray, hit);
        const Material& m = scene.materials[surface.material];

        if (rays.count_emission[i])
            paths.add_radiance(slot, emission_added<E>(scene, m, surface, ray, hit.t, throughput,
                                                       E::mis ? rays.bsdf_pdf[i] : 0.0f, bounce));
        if (has_lights && gathers_direct_light(m)) {
            const DirectLightSampler<E> lights(scene, m, surface, light_sampling_point(surface, ray.direction),
                                               ray.direction, throughput, path, bounce, shadow_ray_count);
            lights.sample_all([&](const ShadowRay& shadow) { shadows.push(shadow, slot); });
        }
        const auto next = continue_path<E>(scene, m, surface, ray.direction, throughput, path, bounce);
        if (next) next_rays.push<E::mis>(*next, slot);
    }
}


#define WT_SHADE_QUEUE_SIGNATURE(E)                                                                                       \
    void shade_queue<E>(const Scene&, uint32_t, const RayQueue&, const HitQueue&, PathTable&, RayQueue&, ShadowQueue&)

}  // namespace wt

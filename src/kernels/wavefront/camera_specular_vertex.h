#pragma once
// A camera path's flat mirror or glass vertex, queued for the specular shade kernel
// (kernels/shading/specular_continuation.h) in place of continue_path (core/path/path_vertex.h):
// the same random numbers, and the flags continue_path gives the next ray. The shade stage
// queues them (shade_queue.h); tests/specular_continuation_test.cpp holds the kernel's rays to
// continue_path's through this.

#include <cstdint>

#include <glm/vec3.hpp>

#include "core/path/path_vertex.h"
#include "core/scene/scene.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/queues/specular_vertex_queue.h"

namespace wt {

// For a vertex that continues_as_specular, whose path goes on past it (bounce + 1 < max_bounces).
// No light sample precedes it: a specular BSDF meets no light point. The next ray keeps the
// arriving ray's specular_light_elsewhere and counts emission unless that is set (a specular
// sample's count_emission in continue_path).
template <typename E>
inline void queue_camera_specular_vertex(const Scene& scene, const Material& m, const SurfacePoint& surface,
                                         const glm::vec3& d, const glm::vec3& throughput, const PathSeed& path,
                                         uint32_t bounce, bool specular_light_elsewhere, uint32_t slot,
                                         SpecularVertexQueue& q) {
    const UniformPair draws =
        typename E::Sampler(path, bounce, uint32_t(scene.settings.shadow_rays)).pair(dim::bsdf_choice);  // continuation_random's
    q.push(surface.position, surface.error, surface.normal, d, throughput, m.type == MaterialType::glass, m.reflectance, m.ior,
           draws.first, draws.second, slot,
           specular_light_elsewhere ? RayQueue::kSpecularLightElsewhere : RayQueue::kCountEmission);
}

}  // namespace wt

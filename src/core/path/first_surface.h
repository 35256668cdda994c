#pragma once
// What a camera path records for the albedo, normal and depth AOVs, written once and called by
// both integrators (so the AOVs, like the radiance, are the same bits from either).
//
// Albedo and normal are those of the first non-specular surface, seen through mirrors and
// glass, which is what OIDN's documentation recommends for denoising guides ("follow perfect
// specular paths and store features for the first diffuse or glossy surface hit"): the albedo
// is the surface's times the throughput of the specular chain that reached it (a mirror's
// reflectance; glass picks reflection or refraction by Fresnel with weight 1, so over the
// samples it averages to OIDN's Fresnel blend of the two), clamped to 1 because Russian
// roulette's 1/q can lift a single sample past it. Depth is the first hit's, specular or not.

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/camera/camera.h"
#include "core/materials/shading_normal_bsdf.h"
#include "core/base/ray.h"
#include "core/scene/scene.h"

namespace wt {

struct FirstSurface {
    glm::vec3 albedo{0.0f};  // zero until a non-specular surface is reached (and if none is)
    glm::vec3 normal{0.0f};  // its shading normal facing the arriving ray, world space; zero if none
    float depth = 0.0f;      // first hit's distance along the camera's view axis; 0 for a miss
    float coverage = 0.0f;   // 1 when the camera ray hit anything: depth is averaged over these
    bool found = false;      // albedo and normal are final
};

// Call at every vertex of a path until `found`; `throughput` is the path's arriving at the vertex.
inline void record_first_surface(FirstSurface& record, const Camera& camera, uint32_t bounce, const Ray& ray,
                                 const Hit& hit, const SurfacePoint& surface, const Material& m,
                                 const glm::vec3& throughput) {
    if (bounce == 0) {
        record.depth = hit.t * glm::dot(ray.direction, camera.forward());
        record.coverage = 1.0f;
    }
    if (m.is_specular()) return;
    const glm::vec3 facing = glm::dot(ray.direction, surface.normal) < 0.0f ? surface.normal : -surface.normal;
    record.normal = surface.smooth ? shading_normal_facing(surface.shading_normal, facing) : facing;
    record.albedo = glm::min(glm::vec3(1.0f), throughput * m.albedo);
    record.found = true;
}

}  // namespace wt

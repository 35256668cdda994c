#pragma once
// What a render counts. Each worker keeps its own copy; they are summed once at the end.

#include <cstdint>

namespace wt {

struct RayCounts {
    uint64_t camera_rays = 0;
    uint64_t bounce_rays = 0;  // extension rays after the first hit
    uint64_t shadow_rays = 0;
    uint64_t samples = 0;
    uint64_t nonfinite_samples = 0;  // dropped by the film, never written
    // Light tracing (kernels/caustics): the paths, their rays from the lights and through the
    // specular bounces, the shadow rays of their connections to the camera, and the splats the
    // film dropped (not finite, or out of its range).
    uint64_t light_paths = 0;
    uint64_t light_rays = 0;
    uint64_t camera_connections = 0;
    uint64_t dropped_splats = 0;
    uint64_t photons = 0;  // deposited for the photon maps (kernels/photons), all batches together

    uint64_t total_rays() const { return camera_rays + bounce_rays + shadow_rays + light_rays + camera_connections; }
    RayCounts& operator+=(const RayCounts& o) {
        camera_rays += o.camera_rays, bounce_rays += o.bounce_rays, shadow_rays += o.shadow_rays;
        samples += o.samples, nonfinite_samples += o.nonfinite_samples;
        light_paths += o.light_paths, light_rays += o.light_rays, camera_connections += o.camera_connections;
        dropped_splats += o.dropped_splats, photons += o.photons;
        return *this;
    }
};

}  // namespace wt

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

    uint64_t total_rays() const { return camera_rays + bounce_rays + shadow_rays; }
    RayCounts& operator+=(const RayCounts& o) {
        camera_rays += o.camera_rays, bounce_rays += o.bounce_rays, shadow_rays += o.shadow_rays;
        samples += o.samples, nonfinite_samples += o.nonfinite_samples;
        return *this;
    }
};

}  // namespace wt

#include "kernels/scene_intersect.h"
#include "kernels/stages.h"

namespace wt {

void intersect_closest_stage(const Scene& scene, const RayQueue& rays, HitQueue& hits) {
    for (std::size_t i = 0; i < rays.count; ++i) hits.set(i, intersect_closest(scene, rays.ray(i)));
}

}  // namespace wt

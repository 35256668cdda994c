#include "kernels/scene_intersect.h"
#include "kernels/stages.h"

namespace wt {

void shadow_stage(const Scene& scene, const ShadowQueue& shadows, PathTable& paths) {
    for (std::size_t i = 0; i < shadows.count; ++i) {
        if (!intersect_any(scene, shadows.ray(i), shadows.tmax[i])) paths.add_radiance(shadows.path[i], shadows.contribution(i));
    }
}

}  // namespace wt

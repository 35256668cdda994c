#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_DECLARE_SHADE_QUEUE(sampler, lights, clamps) extern template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps));
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_DECLARE_SHADE_QUEUE)

void shade_stage(const Scene& scene, uint32_t bounce, const RayQueue& rays, const HitQueue& hits, PathTable& paths,
                 RayQueue& next_rays, ShadowQueue& shadows) {
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        shade_queue<decltype(estimator)>(scene, bounce, rays, hits, paths, next_rays, shadows);
    });
}

}  // namespace wt

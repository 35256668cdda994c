#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_DECLARE_SHADE_QUEUE(sampler, lights, clamps)                                          \
    extern template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), false, false); \
    extern template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), true, false);  \
    extern template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), false, true);  \
    extern template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), true, true);   \
    extern template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(WT_ESTIMATOR(sampler, lights, clamps), false); \
    extern template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(WT_ESTIMATOR(sampler, lights, clamps), true);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_DECLARE_SHADE_QUEUE)
extern template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, true, false);
extern template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, false, true);
extern template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, true, true);
extern template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(DefaultEstimator, false);
extern template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(DefaultEstimator, true);

// One loop per kind of scene, chosen once per queue: with a lights list (which also tests for
// rough materials at run time), with rough materials or textures, or neither; with or without
// the AOVs.
void shade_stage(const Scene& scene, const ShadeKernels& kernels, uint32_t bounce, const RayQueue& rays, const HitQueue& hits,
                 PathTable& paths, ShadeChunks& chunks, RayQueue& next_rays, ShadowQueue& shadows,
                 const PhotonMaps* photons) {
    const bool record_aovs = !paths.first_surface.empty();
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        using E = decltype(estimator);
        if (!scene.listed_lights.empty()) {
            if (record_aovs)
                shade_queue<E, true, true, true>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
            else
                shade_queue<E, false, true, true>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
        } else if (scene.has_rough_materials || scene.has_textures()) {
            if (record_aovs)
                shade_queue<E, true, true>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
            else
                shade_queue<E, false, true>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
        } else if (record_aovs) {
            shade_queue<E, true, false>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
        } else {
            shade_queue<E, false, false>(scene, kernels, bounce, rays, hits, paths, chunks, next_rays, shadows, photons);
        }
    });
}

}  // namespace wt

// The shade stage of a scene with a "lights" list (shade_queue.h, kListedLights), for every
// estimator, with and without the AOVs: a translation unit of its own, so the loops of scenes
// without the list compile as they did before it existed.
#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_INSTANTIATE_SHADE_QUEUE_LIGHTS(sampler, lights, clamps)                                    \
    template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(WT_ESTIMATOR(sampler, lights, clamps), false); \
    template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(WT_ESTIMATOR(sampler, lights, clamps), true);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_INSTANTIATE_SHADE_QUEUE_LIGHTS)
template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(DefaultEstimator, false);
template WT_SHADE_QUEUE_SIGNATURE_LIGHTS(DefaultEstimator, true);

}  // namespace wt

// The shade stage for scenes with rough materials (Scene::has_rough_materials), every estimator,
// with and without the AOVs: the rough vertices' light samples and the pdfs their emission is
// weighted by (shade_queue.h). In a unit of its own, so the loops of the other scenes compile as
// they did before rough materials existed.
#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_INSTANTIATE_SHADE_QUEUE_ROUGH(sampler, lights, clamps)                            \
    template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), false, true); \
    template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), true, true);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_INSTANTIATE_SHADE_QUEUE_ROUGH)
template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, false, true);
template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, true, true);

}  // namespace wt

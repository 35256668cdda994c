// The shade stage recording the AOVs' first surface, for every estimator but the default (see
// stage_shade_aovs.cpp and WT_FOR_EACH_OPTIONAL_ESTIMATOR).
#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_INSTANTIATE_SHADE_QUEUE_AOVS(sampler, lights, clamps) \
    template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), true, false);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_INSTANTIATE_SHADE_QUEUE_AOVS)

}  // namespace wt

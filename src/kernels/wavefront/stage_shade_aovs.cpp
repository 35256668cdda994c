// The shade stage recording the AOVs' first surface, for every estimator, in a translation unit
// of its own so that the loops without AOVs compile as they did before (see shade_queue.h).
#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_INSTANTIATE_SHADE_QUEUE_AOVS(sampler, lights, clamps) \
    template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), true);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_INSTANTIATE_SHADE_QUEUE_AOVS)
template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, true);

}  // namespace wt

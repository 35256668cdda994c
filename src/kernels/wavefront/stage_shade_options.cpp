// The shade stage for every estimator but the default (see WT_FOR_EACH_OPTIONAL_ESTIMATOR).
#include "kernels/wavefront/shade_queue.h"

namespace wt {

#define WT_INSTANTIATE_SHADE_QUEUE(sampler, lights, clamps) template WT_SHADE_QUEUE_SIGNATURE(WT_ESTIMATOR(sampler, lights, clamps), false, false);
WT_FOR_EACH_OPTIONAL_ESTIMATOR(WT_INSTANTIATE_SHADE_QUEUE)

}  // namespace wt

// The shade stage recording the AOVs' first surface, for the default estimator, in a translation
// unit of its own: beside other instantiations g++ stops inlining the vertex helpers into it
// (offset_ray_origin, the shadow queue's push ...: +5 % instructions in the perf gate's render
// with --aov all), and the loops without AOVs keep compiling as they did before (shade_queue.h).
#include "kernels/wavefront/shade_queue.h"

namespace wt {

template WT_SHADE_QUEUE_SIGNATURE(DefaultEstimator, true, false);

}  // namespace wt

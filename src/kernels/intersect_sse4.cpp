// The intersection kernels at width 4, compiled with the sse4 target flags (src/kernels/CMakeLists.txt).
#include "kernels/packet_intersect.h"

namespace wt {

const IntersectKernels kIntersectSse4 = packet::make_intersect_kernels<4>(Isa::sse4);

}  // namespace wt

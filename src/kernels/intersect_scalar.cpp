// The intersection kernels at width 1, compiled with the scalar target flags (src/kernels/CMakeLists.txt).
#include "kernels/packet_intersect.h"

namespace wt {

const IntersectKernels kIntersectScalar = packet::make_intersect_kernels<1>(Isa::scalar);

}  // namespace wt

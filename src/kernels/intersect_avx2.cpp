// The intersection kernels at width 8, compiled with the avx2 target flags (src/kernels/CMakeLists.txt).
#include "kernels/packet_intersect.h"

namespace wt {

const IntersectKernels kIntersectAvx2 = packet::make_intersect_kernels<8>(Isa::avx2);

}  // namespace wt

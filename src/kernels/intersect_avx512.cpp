// The intersection kernels at width 16, compiled with the avx512 target flags (src/kernels/CMakeLists.txt).
#include "kernels/packet_intersect.h"

namespace wt {

const IntersectKernels kIntersectAvx512 = packet::make_intersect_kernels<16>(Isa::avx512);

}  // namespace wt

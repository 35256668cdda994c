// The intersection kernels at width 4, compiled with the sse4 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/kernel_table.h"

namespace wt {

constexpr packet::KernelVariants<4> kVariantsSse4 = packet::make_intersect_kernels<4>(Isa::sse4);
const IntersectKernels kIntersectSse4[kKernelVariantCount] = {kVariantsSse4.variants[0], kVariantsSse4.variants[1],
                                                               kVariantsSse4.variants[2], kVariantsSse4.variants[3]};

}  // namespace wt

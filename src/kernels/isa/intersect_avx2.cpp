// The intersection kernels at width 8, compiled with the avx2 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/kernel_table.h"

namespace wt {

constexpr packet::KernelVariants<8> kVariantsAvx2 = packet::make_intersect_kernels<8>(Isa::avx2);
const IntersectKernels kIntersectAvx2[kKernelVariantCount] = {kVariantsAvx2.variants[0], kVariantsAvx2.variants[1],
                                                               kVariantsAvx2.variants[2], kVariantsAvx2.variants[3]};

}  // namespace wt

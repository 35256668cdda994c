// The intersection kernels at width 16, compiled with the avx512 target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/kernel_table.h"

namespace wt {

constexpr packet::KernelVariants<16> kVariantsAvx512 = packet::make_intersect_kernels<16>(Isa::avx512);
const IntersectKernels kIntersectAvx512[kKernelVariantCount] = {kVariantsAvx512.variants[0], kVariantsAvx512.variants[1],
                                                               kVariantsAvx512.variants[2], kVariantsAvx512.variants[3]};

}  // namespace wt

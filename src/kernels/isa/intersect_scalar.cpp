// The intersection kernels at width 1, compiled with the scalar target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/kernel_table.h"

namespace wt {

constexpr packet::KernelVariants<1> kVariantsScalar = packet::make_intersect_kernels<1>(Isa::scalar);
const IntersectKernels kIntersectScalar[kKernelVariantCount] = {kVariantsScalar.variants[0], kVariantsScalar.variants[1],
                                                               kVariantsScalar.variants[2], kVariantsScalar.variants[3]};

}  // namespace wt

// The shade kernels at width 1, compiled with the scalar target flags (src/kernels/CMakeLists.txt).
#include "kernels/isa/shade_kernels.h"
#include "kernels/shading/diffuse_continuation.h"

namespace wt {

const ShadeKernels kShadeScalar = {Isa::scalar, 1, &shading::continue_diffuse_vertices<1>};

}  // namespace wt

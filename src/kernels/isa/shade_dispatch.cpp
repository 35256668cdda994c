#include <stdexcept>
#include <string>

#include "kernels/isa/intersect_dispatch.h"
#include "kernels/isa/shade_kernels.h"

namespace wt {

const ShadeKernels& shade_kernels(Isa isa) {
    if (!cpu_supports(isa)) throw std::runtime_error(std::string("this CPU does not support the ") + isa_name(isa) + " kernels");
    switch (isa) {
        case Isa::sse4: return kShadeSse4;
        case Isa::avx2: return kShadeAvx2;
        case Isa::avx512:
#ifdef WT_WITHOUT_AVX512_KERNELS
            break;  // not reached: cpu_supports() said no
#else
            return kShadeAvx512;
#endif
        case Isa::scalar: break;
    }
    return kShadeScalar;
}

}  // namespace wt

#include "kernels/primitives/triangle_view.h"

namespace wt {

TriangleView triangle_view(const TriangleSoA& t) {
    return {t.v0x.data(),       t.v0y.data(),       t.v0z.data(),       t.e1x.data(), t.e1y.data(), t.e1z.data(),
            t.e2x.data(),       t.e2y.data(),       t.e2z.data(),       t.scaled_nx.data(), t.scaled_ny.data(),
            t.scaled_nz.data(), t.v1x.data(),       t.v1y.data(),       t.v1z.data(), t.v2x.data(), t.v2y.data(),
            t.v2z.data(),       uint32_t(t.size()), t.parallelogram_count};
}

}  // namespace wt

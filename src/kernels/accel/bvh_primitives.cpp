#include "kernels/accel/bvh_primitives.h"

#include <cstring>

namespace wt {
namespace {
float id_bits(uint32_t id) {
    float f;
    std::memcpy(&f, &id, sizeof f);
    return f;
}
}  // namespace

void BvhPrimitives::write_record(const TriangleSoA& t, const SphereSoA& s, std::size_t i, float* out) const {
    if (i >= t.size()) {
        const std::size_t k = i - t.size();
        const float row[] = {s.cx[k], s.cy[k], s.cz[k], s.radius[k]};
        std::memcpy(out, row, sizeof row);
    } else if (test == TriangleTest::watertight) {
        const float row[] = {t.v0x[i], t.v0y[i], t.v0z[i], t.v1x[i], t.v1y[i], t.v1z[i], t.v2x[i], t.v2y[i], t.v2z[i]};
        std::memcpy(out, row, sizeof row);
    } else {
        const float row[] = {t.v0x[i], t.v0y[i], t.v0z[i], t.e1x[i], t.e1y[i], t.e1z[i],
                             t.e2x[i], t.e2y[i], t.e2z[i], t.scaled_nx[i], t.scaled_ny[i], t.scaled_nz[i]};
        std::memcpy(out, row, sizeof row);
    }
}

void BvhPrimitives::fill_leaf(const float* records, uint32_t first, const uint32_t* ids, uint32_t count, bool spheres) {
    const uint32_t stride = rows() - 1;
    const uint32_t data_rows = spheres ? kSphereRows - 1 : stride;
    const uint32_t id_row = spheres ? kSphereRows - 1 : stride;
    float* block = blocks.data() + std::size_t(first) * rows();
    for (uint32_t l = 0; l < count; ++l) {
        const float* r = records + std::size_t(ids[l]) * stride;
        for (uint32_t row = 0; row < data_rows; ++row) block[row * count + l] = r[row];
        block[id_row * count + l] = id_bits(ids[l]);
    }
}

}  // namespace wt

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

void BvhPrimitives::fill_leaf(const Scene& scene, uint32_t first, const uint32_t* ids, uint32_t count, bool spheres) {
    float* block = blocks.data() + std::size_t(first) * rows();
    auto put = [&](uint32_t row, uint32_t lane, float value) { block[row * count + lane] = value; };
    const TriangleSoA& t = scene.triangles;
    const SphereSoA& s = scene.spheres;
    for (uint32_t l = 0; l < count; ++l) {
        const uint32_t id = ids[l];
        if (spheres) {
            const std::size_t i = id - t.size();
            const float row[] = {s.cx[i], s.cy[i], s.cz[i], s.radius[i]};
            for (uint32_t r = 0; r < 4; ++r) put(r, l, row[r]);
            put(kSphereRows - 1, l, id_bits(id));
            continue;
        }
        if (test == TriangleTest::watertight) {
            const float row[] = {t.v0x[id], t.v0y[id], t.v0z[id], t.v1x[id], t.v1y[id], t.v1z[id], t.v2x[id], t.v2y[id], t.v2z[id]};
            for (uint32_t r = 0; r < 9; ++r) put(r, l, row[r]);
        } else {
            const float row[] = {t.v0x[id], t.v0y[id], t.v0z[id], t.e1x[id], t.e1y[id], t.e1z[id],
                                 t.e2x[id], t.e2y[id], t.e2z[id], t.scaled_nx[id], t.scaled_ny[id], t.scaled_nz[id]};
            for (uint32_t r = 0; r < 12; ++r) put(r, l, row[r]);
        }
        put(rows() - 1, l, id_bits(id));
    }
}

}  // namespace wt

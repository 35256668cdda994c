#include "kernels/accel/bvh_primitives.h"

#include <cstring>

namespace wt {

void BvhPrimitives::reserve(std::size_t planar_prims, std::size_t sphere_prims) {
    planar.reserve(planar_prims * planar_rows());
    spheres.reserve(sphere_prims * kSphereRows);
}

namespace {
float id_bits(uint32_t id) {
    float f;
    std::memcpy(&f, &id, sizeof f);
    return f;
}
}  // namespace

void BvhPrimitives::append_leaf(const Scene& scene, const uint32_t* ids, uint32_t count, bool sphere) {
    AlignedVector<float>& out = sphere ? spheres : planar;
    const uint32_t rows = sphere ? kSphereRows : planar_rows();
    const std::size_t base = out.size();
    out.resize(base + std::size_t(rows) * count);
    float* block = out.data() + base;
    auto put = [&](uint32_t row, uint32_t lane, float value) { block[row * count + lane] = value; };
    const TriangleSoA& t = scene.triangles;
    const SphereSoA& s = scene.spheres;
    for (uint32_t l = 0; l < count; ++l) {
        const uint32_t id = ids[l];
        if (sphere) {
            const std::size_t i = id - t.size();
            const float row[] = {s.cx[i], s.cy[i], s.cz[i], s.radius[i]};
            for (uint32_t r = 0; r < 4; ++r) put(r, l, row[r]);
        } else if (test == TriangleTest::watertight) {
            const float row[] = {t.v0x[id], t.v0y[id], t.v0z[id], t.v1x[id], t.v1y[id], t.v1z[id], t.v2x[id], t.v2y[id], t.v2z[id]};
            for (uint32_t r = 0; r < 9; ++r) put(r, l, row[r]);
        } else {
            const float row[] = {t.v0x[id], t.v0y[id], t.v0z[id], t.e1x[id], t.e1y[id], t.e1z[id],
                                 t.e2x[id], t.e2y[id], t.e2z[id], t.scaled_nx[id], t.scaled_ny[id], t.scaled_nz[id]};
            for (uint32_t r = 0; r < 12; ++r) put(r, l, row[r]);
        }
        put(rows - 1, l, id_bits(id));
    }
    (sphere ? sphere_count : planar_count) += count;
}

}  // namespace wt

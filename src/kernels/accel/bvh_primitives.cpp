#include "kernels/accel/bvh_primitives.h"

#include <algorithm>
#include <cstring>

namespace wt {
namespace {
float id_bits(uint32_t id) {
    float f;
    std::memcpy(&f, &id, sizeof f);
    return f;
}
}  // namespace

namespace {
// Primitive i's rows but the id: rows() - 1 floats for a triangle, kSphereRows - 1 for a sphere.
void primitive_rows(const TriangleSoA& t, const SphereSoA& s, TriangleTest test, std::size_t i, float* out) {
    if (i >= t.size()) {
        const std::size_t k = i - t.size();
        const float row[] = {s.cx[k], s.cy[k], s.cz[k], s.radius[k]};
        std::memcpy(out, row, sizeof row);
    } else if (test == TriangleTest::watertight) {
        const glm::vec3 row[] = {t.vertex0(i), t.vertex1(i), t.vertex2(i)};
        std::memcpy(out, row, sizeof row);
    } else {
        const TriangleSoA::Corner c = t.corner(i);
        const glm::vec3 row[] = {c.v0, c.e1, c.e2};  // the test takes cross(e1, e2) itself (bvh_view.h)
        std::memcpy(out, row, sizeof row);
    }
}
}  // namespace

void BvhPrimitives::fill_leaf(const TriangleSoA& t, const SphereSoA& s, uint32_t first, const uint32_t* ids, uint32_t count) {
    const bool spheres = ids[0] >= t.size();  // a leaf holds one kind
    const uint32_t data_rows = spheres ? kSphereRows - 1 : rows() - 1;
    float* block = blocks.data() + std::size_t(first) * rows();
    for (uint32_t l = 0; l < count; ++l) {
        float r[kWatertightRows > kMollerTrumboreRows ? kWatertightRows : kMollerTrumboreRows];
        primitive_rows(t, s, test, ids[l], r);
        for (uint32_t row = 0; row < data_rows; ++row) block[row * count + l] = r[row];
        block[data_rows * count + l] = id_bits(ids[l]);
    }
    // A sphere leaf uses only its first rows; the rest of its floats are written too, so no
    // byte of the blocks is left uninitialised (resize() does not zero them).
    if (spheres) std::fill(block + kSphereRows * count, block + rows() * count, 0.0f);
}

}  // namespace wt

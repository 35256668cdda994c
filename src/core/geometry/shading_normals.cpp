#include "core/geometry/shading_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

void ShadingNormalTable::push(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2) {
    record_of_.push_back(uint32_t(records_.size()));
    records_.push_back({n0, n1, n2});
}

glm::vec3 blend_normals(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, float u, float v, const glm::vec3& geometric) {
    const glm::vec3 blended = (1.0f - u - v) * n0 + u * n1 + v * n2;
    const float length2 = glm::dot(blended, blended);
    // Below 1e-12 the direction is the rounding noise of the cancellation.
    if (!(length2 > 1e-12f) || !std::isfinite(length2)) return geometric;
    return blended / std::sqrt(length2);
}

glm::vec3 ShadingNormalTable::at(std::size_t i, float u, float v, const glm::vec3& geometric) const {
    const uint32_t r = record_of_[i];
    if (r == kFlat) return geometric;
    const VertexNormals& n = records_[r];
    return blend_normals(n.n0, n.n1, n.n2, u, v, geometric);
}

bool ShadingNormalTable::vertex_normals(std::size_t i, glm::vec3 out[3]) const {
    const uint32_t r = record_of_[i];
    if (r == kFlat) return false;
    out[0] = records_[r].n0, out[1] = records_[r].n1, out[2] = records_[r].n2;
    return true;
}

}  // namespace wt

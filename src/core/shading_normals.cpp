#include "core/shading_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

void ShadingNormalTable::push(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2) {
    record_of_.push_back(uint32_t(records_.size()));
    records_.push_back({n0, n1, n2});
}

glm::vec3 ShadingNormalTable::at(std::size_t i, float u, float v, const glm::vec3& geometric) const {
    const uint32_t r = record_of_[i];
    if (r == kFlat) return geometric;
    const VertexNormals& n = records_[r];
    const glm::vec3 blended = (1.0f - u - v) * n.n0 + u * n.n1 + v * n.n2;
    const float length2 = glm::dot(blended, blended);
    // Below 1e-12 the direction is the rounding noise of the cancellation.
    if (!(length2 > 1e-12f) || !std::isfinite(length2)) return geometric;
    return blended / std::sqrt(length2);
}

}  // namespace wt

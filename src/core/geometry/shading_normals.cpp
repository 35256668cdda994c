#include "core/geometry/shading_normals.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace wt {

uint32_t ShadingNormalTable::add_vertex_normals(const std::vector<glm::vec3>& normals) {
    // kFlat is the one index no normal may have.
    if (normals.size() >= std::size_t(kFlat) - normals_.size())
        throw std::length_error("shading normals: more than 2^32 - 1 vertex normals in one table");
    const uint32_t first = uint32_t(normals_.size());
    normals_.insert(normals_.end(), normals.begin(), normals.end());
    return first;
}

glm::vec3 blend_normals(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, float u, float v, const glm::vec3& geometric) {
    const glm::vec3 blended = (1.0f - u - v) * n0 + u * n1 + v * n2;
    const float length2 = glm::dot(blended, blended);
    // Below 1e-12 the direction is the rounding noise of the cancellation.
    if (!(length2 > 1e-12f) || !std::isfinite(length2)) return geometric;
    return blended / std::sqrt(length2);
}

glm::vec3 ShadingNormalTable::at(std::size_t i, float u, float v, const glm::vec3& geometric) const {
    const Corners& c = corners_[i];
    if (c.n0 == kFlat) return geometric;
    return blend_normals(normals_[c.n0], normals_[c.n1], normals_[c.n2], u, v, geometric);
}

bool ShadingNormalTable::vertex_normals(std::size_t i, glm::vec3 out[3]) const {
    const Corners& c = corners_[i];
    if (c.n0 == kFlat) return false;
    out[0] = normals_[c.n0], out[1] = normals_[c.n1], out[2] = normals_[c.n2];
    return true;
}

}  // namespace wt

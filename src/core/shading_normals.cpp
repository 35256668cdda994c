#include "core/shading_normals.h"

namespace wt {

void ShadingNormalTable::push(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2) {
    record_of_.push_back(uint32_t(records_.size()));
    records_.push_back({n0, n1, n2});
}

}  // namespace wt

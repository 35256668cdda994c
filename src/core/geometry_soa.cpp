#include "core/geometry_soa.h"

#include <glm/geometric.hpp>

namespace wt {

void TriangleSoA::push_back(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id) {
    const glm::vec3 e1 = b - a;
    const glm::vec3 e2 = c - a;
    const glm::vec3 cross = glm::cross(e1, e2);
    const float length = glm::length(cross);
    // A degenerate triangle keeps a zero normal; Moller-Trumbore never reports a hit on it.
    const glm::vec3 n = length > 0.0f ? cross / length : glm::vec3(0.0f);
    v0x.push_back(a.x), v0y.push_back(a.y), v0z.push_back(a.z);
    v1x.push_back(b.x), v1y.push_back(b.y), v1z.push_back(b.z);
    v2x.push_back(c.x), v2y.push_back(c.y), v2z.push_back(c.z);
    e1x.push_back(e1.x), e1y.push_back(e1.y), e1z.push_back(e1.z);
    e2x.push_back(e2.x), e2y.push_back(e2.y), e2z.push_back(e2.z);
    nx.push_back(n.x), ny.push_back(n.y), nz.push_back(n.z);
    material.push_back(material_id);
}

void SphereSoA::push_back(const glm::vec3& c, float r, uint32_t material_id) {
    cx.push_back(c.x), cy.push_back(c.y), cz.push_back(c.z);
    radius.push_back(r);
    material.push_back(material_id);
}

}  // namespace wt

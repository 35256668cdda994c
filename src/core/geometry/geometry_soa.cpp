#include "core/geometry/geometry_soa.h"

#include <algorithm>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/ext/vector_double3.hpp>

namespace wt {

bool is_sliver(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
    constexpr double kResolvableSine = 32.0 * 0x1p-24;
    return glm::length(glm::cross(e1, e2)) <= kResolvableSine * glm::length(e1) * glm::length(e2);
}

uint32_t TriangleSoA::add_vertices(const std::vector<glm::vec3>& vertices) {
    // The kernels gather by signed 32-bit index.
    if (vertices.size() > std::size_t(INT32_MAX) - vertex_count())
        throw std::length_error("TriangleSoA: more than 2^31 - 1 vertices in all");
    const uint32_t first = uint32_t(vertex_count());
    for (const glm::vec3& v : vertices) px.push_back(v.x), py.push_back(v.y), pz.push_back(v.z);
    return first;
}

void TriangleSoA::push(uint32_t a, uint32_t b, uint32_t c, uint32_t material_id) {
    // Collapsed, a sliver has zero edges: det = 0 in Moller-Trumbore and every edge function is
    // 0 in the watertight test, so no kernel can report a hit on it.
    const bool sliver = is_sliver(position(a), position(b), position(c));
    i0.push_back(a), i1.push_back(sliver ? a : b), i2.push_back(sliver ? a : c);
    material.push_back(material_id);
}

void TriangleSoA::push_parallelogram(uint32_t a, uint32_t b, uint32_t d, uint32_t material_id) {
    if (size() != parallelogram_count) throw std::logic_error("TriangleSoA: a parallelogram pushed after a triangle");
    // A sliver parallelogram collapses like a sliver triangle: same edges, same criterion.
    push(a, b, d, material_id);
    ++parallelogram_count;
}

void TriangleSoA::push_back(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id) {
    const uint32_t first = add_vertices({a, b, c});
    push(first, first + 1, first + 2, material_id);
}

void TriangleSoA::push_parallelogram(const glm::vec3& a, const glm::vec3& b, const glm::vec3& d, uint32_t material_id) {
    const uint32_t first = add_vertices({a, b, d});
    push_parallelogram(first, first + 1, first + 2, material_id);
}

void TriangleSoA::store_only_for(TriangleTest test) {
    if (size() > 0) throw std::logic_error("TriangleSoA: the test to store for is chosen before the first triangle");
    keeps_vertices_ = test == TriangleTest::watertight;
    keeps_scaled_normal_ = test == TriangleTest::moller_trumbore;
}

std::size_t TriangleSoA::bytes() const {
    return vertex_count() * 3 * sizeof(float) + size() * 4 * sizeof(uint32_t);
}

void SphereSoA::push_back(const glm::vec3& c, float r, uint32_t material_id) {
    cx.push_back(c.x), cy.push_back(c.y), cz.push_back(c.z);
    radius.push_back(r);
    material.push_back(material_id);
}

}  // namespace wt

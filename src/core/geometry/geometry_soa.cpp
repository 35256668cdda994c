#include "core/geometry/geometry_soa.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/ext/vector_double3.hpp>

namespace wt {

bool is_sliver(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
    constexpr double kResolvableSine = 32.0 * 0x1p-24;
    return glm::length(glm::cross(e1, e2)) <= kResolvableSine * glm::length(e1) * glm::length(e2);
}

void TriangleSoA::push_back(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t material_id) {
    push(a, b, c, material_id);
}

void TriangleSoA::push_parallelogram(const glm::vec3& a, const glm::vec3& b, const glm::vec3& d, uint32_t material_id) {
    if (size() != parallelogram_count) throw std::logic_error("TriangleSoA: a parallelogram pushed after a triangle");
    // A sliver parallelogram collapses like a sliver triangle: same edges, same criterion.
    push(a, b, d, material_id);
    ++parallelogram_count;
}

void TriangleSoA::push(const glm::vec3& a, const glm::vec3& given_b, const glm::vec3& given_c, uint32_t material_id) {
    // Collapsed, a sliver has zero edges: det = 0 in Moller-Trumbore and every edge function is
    // 0 in the watertight test, so no kernel can report a hit on it.
    const bool sliver = is_sliver(a, given_b, given_c);
    const glm::vec3 b = sliver ? a : given_b;
    const glm::vec3 c = sliver ? a : given_c;
    const glm::vec3 e1 = b - a;
    const glm::vec3 e2 = c - a;
    v0x.push_back(a.x), v0y.push_back(a.y), v0z.push_back(a.z);
    if (keeps_vertices_) {
        v1x.push_back(b.x), v1y.push_back(b.y), v1z.push_back(b.z);
        v2x.push_back(c.x), v2y.push_back(c.y), v2z.push_back(c.z);
    }
    e1x.push_back(e1.x), e1y.push_back(e1.y), e1z.push_back(e1.z);
    e2x.push_back(e2.x), e2y.push_back(e2.y), e2z.push_back(e2.z);
    if (keeps_scaled_normal_) {
        const glm::vec3 cross = glm::cross(e1, e2);
        scaled_nx.push_back(cross.x), scaled_ny.push_back(cross.y), scaled_nz.push_back(cross.z);
    }
    material.push_back(material_id);
}

void TriangleSoA::store_only_for(TriangleTest test) {
    if (size() > 0) throw std::logic_error("TriangleSoA: the rows to store are chosen before the first triangle");
    keeps_vertices_ = test == TriangleTest::watertight;
    keeps_scaled_normal_ = test == TriangleTest::moller_trumbore;
}

std::size_t TriangleSoA::bytes() const {
    const std::size_t float_rows = 9 + (keeps_vertices_ ? 6 : 0) + (keeps_scaled_normal_ ? 3 : 0);
    return size() * (float_rows * sizeof(float) + sizeof(uint32_t));
}

TriangleSoA TriangleSoA::first(std::size_t n) const {
    if (n > size()) throw std::logic_error("TriangleSoA::first: more entries than stored");
    TriangleSoA out;
    out.keeps_vertices_ = keeps_vertices_, out.keeps_scaled_normal_ = keeps_scaled_normal_;
    const auto prefix = [n](const auto& row) { return std::decay_t<decltype(row)>(row.begin(), row.begin() + std::ptrdiff_t(std::min(n, row.size()))); };
    out.v0x = prefix(v0x), out.v0y = prefix(v0y), out.v0z = prefix(v0z);
    out.v1x = prefix(v1x), out.v1y = prefix(v1y), out.v1z = prefix(v1z);
    out.v2x = prefix(v2x), out.v2y = prefix(v2y), out.v2z = prefix(v2z);
    out.e1x = prefix(e1x), out.e1y = prefix(e1y), out.e1z = prefix(e1z);
    out.e2x = prefix(e2x), out.e2y = prefix(e2y), out.e2z = prefix(e2z);
    out.scaled_nx = prefix(scaled_nx), out.scaled_ny = prefix(scaled_ny), out.scaled_nz = prefix(scaled_nz);
    out.material = prefix(material);
    out.parallelogram_count = uint32_t(std::min<std::size_t>(parallelogram_count, n));
    return out;
}

void SphereSoA::push_back(const glm::vec3& c, float r, uint32_t material_id) {
    cx.push_back(c.x), cy.push_back(c.y), cz.push_back(c.z);
    radius.push_back(r);
    material.push_back(material_id);
}

}  // namespace wt

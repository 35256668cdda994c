#include "core/geometry/shading_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

void ShadingNormalTable::add_vertex_normals(const std::vector<glm::vec3>& normals) {
    normals_.insert(normals_.end(), normals.begin(), normals.end());
    smooth_count_ += normals.size();
}

void ShadingNormalTable::add_flat_vertices(std::size_t count) { normals_.resize(normals_.size() + count, glm::vec3(NAN)); }

glm::vec3 blend_normals(const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, float u, float v, const glm::vec3& geometric) {
    const glm::vec3 blended = (1.0f - u - v) * n0 + u * n1 + v * n2;
    const float length2 = glm::dot(blended, blended);
    // Below 1e-12 the direction is the rounding noise of the cancellation.
    if (!(length2 > 1e-12f) || !std::isfinite(length2)) return geometric;
    return blended / std::sqrt(length2);
}

uint32_t add_mesh_vertices(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& vertex_normals, bool smooth,
                           TriangleSoA& triangles, ShadingNormalTable& normals) {
    const uint32_t first = triangles.add_vertices(positions);
    if (smooth && vertex_normals.empty()) normals.add_flat_vertices(positions.size());
    if (smooth && !vertex_normals.empty()) normals.add_vertex_normals(vertex_normals);
    return first;
}

namespace {
bool is_flat(const glm::vec3& n) { return std::isnan(n.x); }
}  // namespace

glm::vec3 ShadingNormalTable::at(const TriangleSoA& t, std::size_t i, float u, float v, const glm::vec3& geometric) const {
    const glm::vec3& n0 = normals_[t.i0[i]];
    if (is_flat(n0)) return geometric;
    return blend_normals(n0, normals_[t.i1[i]], normals_[t.i2[i]], u, v, geometric);
}

bool ShadingNormalTable::vertex_normals(const TriangleSoA& t, std::size_t i, glm::vec3 out[3]) const {
    const glm::vec3& n0 = normals_[t.i0[i]];
    if (is_flat(n0)) return false;
    out[0] = n0, out[1] = normals_[t.i1[i]], out[2] = normals_[t.i2[i]];
    return true;
}

}  // namespace wt

#include "core/import/vertex_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace wt {

std::vector<glm::vec3> angle_weighted_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
    std::vector<glm::vec3> any_face(positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (const auto& tri : triangles) {
        const glm::dvec3 p[3] = {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(n);
        if (!(length > 0.0)) continue;
        const glm::dvec3 unit = n / length;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
            // atan2 of |a x b| and a . b: accurate for angles near 0 and pi, where acos is not.
            const double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
            sum[tri[std::size_t(k)]] += angle * unit;
            any_face[tri[std::size_t(k)]] = glm::vec3(unit);
        }
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const double length = glm::length(sum[v]);
        normals[v] = length > 0.0 ? glm::vec3(sum[v] / length) : any_face[v];
    }
    return normals;
}

}  // namespace wt

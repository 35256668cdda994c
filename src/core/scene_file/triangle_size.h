#pragma once
// Whether a triangle has zero area, judged in double so float round-off cannot hide it.

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace wt {

// Twice the triangle's area, and its longest edge.
struct TriangleSize {
    double cross_length;
    double longest_edge;
    bool degenerate() const { return cross_length <= 1e-12 * longest_edge * longest_edge; }
};

inline TriangleSize triangle_size(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a), db(b), dc(c);
    const double longest = std::max({glm::length(db - da), glm::length(dc - db), glm::length(da - dc)});
    return {glm::length(glm::cross(db - da, dc - da)), longest};
}

}  // namespace wt
